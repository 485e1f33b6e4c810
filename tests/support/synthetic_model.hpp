// An analytic forward model with the shape of the real one, for testing and timing the
// estimator before the scene's head model is wired to it (and as the example of a model: see
// forward_model.hpp's contract).
//
// Geometry (double, from the sample's time and head only; no orbit propagation): true anomaly
// nu = 2 pi t / period, orbit radius r = a (1 - e^2) / (1 + e cos nu), latitude
// asin(sin i sin nu); head k's nadir angle eta = 90 deg + w sin(3 nu + k) and nadir azimuth
// phi_n = w cos(2 nu + 2 k), w the attitude wobble; a season-like factor s = cos(nu / 2 + 0.3).
// Earth: a sphere of radius R + h0 + h_pole sin^2(lat) + h_shift s sin(lat), rho = asin(that / r).
// Head: cone angle gamma + dgamma about the optical axis A (misalignment.hpp); the line of sight
// at scan azimuth phi has angle psi(phi) from S, MODEL §4's corrected Eq. (1) with
// h = sin sigma cos(phi - phi_A) = A_x cos phi + A_y sin phi; psi is taken at the aligned
// crossings phi_n -+ Phi0 (Phi0 = half_chord(gamma + dgamma, eta, rho)), and each crossing's half
// chord is half_chord(psi, eta, rho) (the core's, for any scalar). Chord = Phi_in + Phi_out,
// phase = phi_n + (Phi_out - Phi_in) / 2. One step of the exact scan model: close to it, not it.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "calibration/forward_model.hpp"
#include "calibration/layout.hpp"
#include "calibration/misalignment.hpp"
#include "conescan/half_chord.hpp"
#include "simulation/random.hpp"

namespace conescan::calibration {

struct synthetic_scene {
  std::size_t head_count = 2;
  double period_s = 6000;
  double a_km = 7280;
  double e = 0.1;
  double inclination_deg = 97.7;
  double radius_km = 6378.137;
  double gamma_deg = 45;
  double wobble_deg = 2;
};

class synthetic_model {
 public:
  explicit synthetic_model(const synthetic_scene& scene) : scene_(scene) {}
  const synthetic_scene& scene() const noexcept { return scene_; }

  template <class T>
  predicted_measurement<T> predict(const telemetry_sample& sample, const head_geometry<T>& head,
                                   const earth_geometry<T>& earth) const {
    using std::acos;
    using std::asin;
    using std::atan2;
    using std::cos;
    using std::hypot;
    using std::sin;
    const row_geometry g = geometry(sample);
    const T earth_km = scene_.radius_km + earth.horizon_km +
                       earth.horizon_pole_km * (g.sin_lat * g.sin_lat) +
                       earth.horizon_shift_km * (g.season * g.sin_lat);
    const T rho = asin(T(earth_km / g.r_km));
    const T gamma = (scene_.gamma_deg + head.dgamma_deg) * radians_per_degree;
    const optical_axis<T> axis =
        optical_axis_from_components(T(head.misalignment_x_deg * radians_per_degree),
                                     T(head.misalignment_y_deg * radians_per_degree));
    const T eta(g.eta_rad);
    const result<T> aligned = half_chord(gamma, eta, rho);
    if (!aligned.ok()) return failed<T>(aligned.state);
    auto cone_at = [&](const T& phi) {  // MODEL §4, corrected Eq. (1)
      const T h = axis.x * cos(phi) + axis.y * sin(phi);
      return T(atan2(h, axis.z) + acos(cos(gamma) / hypot(axis.z, h)));
    };
    const result<T> in = half_chord(cone_at(T(g.phi_n_rad - aligned.value)), eta, rho);
    const result<T> out = half_chord(cone_at(T(g.phi_n_rad + aligned.value)), eta, rho);
    if (!in.ok()) return failed<T>(in.state);
    if (!out.ok()) return failed<T>(out.state);
    return {T((in.value + out.value) / radians_per_degree),
            T((g.phi_n_rad + (out.value - in.value) / 2.0) / radians_per_degree), status::ok};
  }

 private:
  struct row_geometry {
    double r_km, sin_lat, season, eta_rad, phi_n_rad;
  };

  row_geometry geometry(const telemetry_sample& sample) const {
    const double nu = 2 * std::numbers::pi * sample.t_s / scene_.period_s;
    const double k = static_cast<double>(sample.head);
    const double wobble = scene_.wobble_deg * radians_per_degree;
    return {scene_.a_km * (1 - scene_.e * scene_.e) / (1 + scene_.e * std::cos(nu)),
            std::sin(scene_.inclination_deg * radians_per_degree) * std::sin(nu),
            std::cos(nu / 2 + 0.3), std::numbers::pi / 2 + wobble * std::sin(3 * nu + k),
            wobble * std::cos(2 * nu + 2 * k)};
  }

  template <class T>
  static predicted_measurement<T> failed(status s) {
    return {T(std::nan("")), T(std::nan("")), s};
  }

  synthetic_scene scene_;
};

/// Measurements of `model` with the parameters `truth` at t = start + i step (i < rows) for every
/// head: the crossings of the prediction with their biases, each moved by crossing noise
/// (scene::standard_normal of (seed, run, row, head, 0 | 1) times noise_deg). Rows where a head
/// cannot measure are left out.
template <class Model>
std::vector<observation> simulate_observations(const Model& model, const parameter_set& truth,
                                               double start_s, double step_s, std::size_t rows,
                                               double noise_deg, std::uint64_t seed,
                                               std::uint64_t run) {
  std::vector<observation> out;
  out.reserve(rows * truth.head_count);
  const earth_geometry<double> earth = earth_geometry_of(truth);
  for (std::size_t i = 0; i < rows; ++i) {
    for (std::size_t k = 0; k < truth.head_count; ++k) {
      const telemetry_sample sample{i, start_s + static_cast<double>(i) * step_s, k};
      predicted_measurement<double> p =
          model.template predict<double>(sample, head_geometry_of(truth, k), earth);
      if (p.state != status::ok) continue;
      p = with_crossing_biases(p, truth.values[parameter_index(k, head_parameter::bias_in)],
                               truth.values[parameter_index(k, head_parameter::bias_out)]);
      const double in =
          p.phase_deg - p.chord_deg / 2 + noise_deg * scene::standard_normal(seed, run, i, k, 0);
      const double out_deg =
          p.phase_deg + p.chord_deg / 2 + noise_deg * scene::standard_normal(seed, run, i, k, 1);
      out.push_back({sample, out_deg - in, (in + out_deg) / 2});
    }
  }
  return out;
}

/// The recovery scene of the engine's tests and benchmarks in this model: two heads, sigma 0.05
/// and 0.03 deg at phi_A 60 and 200 deg, a cone-angle bias of 0.02 deg on head 1, a horizon
/// 2 km above the nominal 40 km.
inline parameter_set recovery_truth() {
  parameter_set p = parameter_set::nominal(2);
  p.value(0, head_parameter::sigma) = 0.05;
  p.value(0, head_parameter::phase) = 60;
  p.value(1, head_parameter::sigma) = 0.03;
  p.value(1, head_parameter::phase) = 200;
  p.value(0, head_parameter::dgamma) = 0.02;
  p.value(earth_parameter::horizon) = 42;
  return p;
}

/// Its nominal start: sigma 0, no bias, horizon 40 km; both heads' sigma and phi_A, head 1's
/// dgamma and the horizon freed.
inline parameter_set recovery_start() {
  parameter_set p = parameter_set::nominal(2);
  p.value(earth_parameter::horizon) = 40;
  for (std::size_t index :
       {parameter_index(0, head_parameter::sigma), parameter_index(0, head_parameter::phase),
        parameter_index(1, head_parameter::sigma), parameter_index(1, head_parameter::phase),
        parameter_index(0, head_parameter::dgamma), parameter_index(2, earth_parameter::horizon)})
    p.free[index] = true;
  return p;
}

}  // namespace conescan::calibration
