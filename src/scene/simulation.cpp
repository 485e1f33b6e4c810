#include "scene/simulation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "conescan/attitude.hpp"
#include "conescan/bias_model.hpp"
#include "conescan/earth_disk.hpp"
#include "conescan/horizon_vector.hpp"
#include "conescan/measurement_errors.hpp"
#include "conescan/orbital_frame.hpp"
#include "conescan/processing.hpp"
#include "conescan/scan_model.hpp"
#include "orbit/geodetic.hpp"
#include "orbit/wgs84.hpp"
#include "scene/degrees.hpp"
#include "scene/random.hpp"

namespace conescan::scene {

namespace {

scan_frame<double> rotate_frame(const mat3<double>& m, const scan_frame<double>& f,
                                bool transpose) {
  auto r = [&](const vec3<double>& v) { return transpose ? apply_transpose(m, v) : apply(m, v); };
  return {r(f.e1), r(f.e2), r(f.e3), f.state};
}

}  // namespace

simulation::simulation(const scene_config& scene) {
  if (const checked<void> valid = validate(scene); !valid.ok())
    throw std::invalid_argument(valid.error().message);
  const orbit::earth_constants& w = orbit::wgs84();
  const orbit::elements elements{scene.a_km * 1000,
                                 scene.e,
                                 deg_to_rad(effective_inclination_deg(scene)),
                                 deg_to_rad_reduced(scene.raan_deg),
                                 deg_to_rad_reduced(scene.argp_deg),
                                 deg_to_rad_reduced(scene.m0_deg)};
  orbit_ = orbit::kepler_orbit(elements,
                               scene.j2 ? orbit::j2_secular_rates(elements, w.gm_m3_s2, w.j2, w.a_m)
                                        : orbit::two_body_rates(elements, w.gm_m3_s2),
                               w.gm_m3_s2);
  step_s_ = scene.step_s;
  rows_ = row_count(scene);
  earth_ = scene.earth;
  model_ = scene.model;
  horizon_m_ = scene.horizon_km * 1000;
  truth_radius_m_ = scene.radius_km ? *scene.radius_km * 1000 : w.a_m;
  // SPEC §3's inflated ellipsoid, or issue 7's apparent horizon surface.
  a_eq_m_ = w.a_m + horizon_m_;
  b_pol_m_ =
      (scene.geodetic_flattening ? w.b_m : w.a_m) + horizon_m_ + scene.horizon_pole_km * 1000;
  centre_z_m_ = scene.horizon_shift_km == 0
                    ? 0
                    : scene.horizon_shift_km * 1000 *
                          std::sin(deg_to_rad(scene.sun_declination_deg.value_or(0)));
  processing_horizon_m_ = scene.processing_horizon_km.value_or(scene.horizon_km) * 1000;
  seed_ = scene.seed;
  processing_ = scene.processing;
  processing_kind_ = scene.processing_radius;
  processing_value_m_ = scene.processing_radius_km * 1000;
  roll_true_ = deg_to_rad_reduced(scene.roll_deg);
  pitch_true_ = deg_to_rad(scene.pitch_deg);

  const mat3<double> body_from_orbit =
      dcm_body_from_orbit(roll_true_, pitch_true_, deg_to_rad_reduced(scene.yaw_deg));
  const vec3<double> nadir_body = nadir_in_body(roll_true_, pitch_true_);
  for (const head_config& h : scene.heads) {
    head_geometry g;
    g.optics = {deg_to_rad(h.gamma_deg), deg_to_rad(h.sigma_deg), deg_to_rad_reduced(h.phase_deg)};
    g.frame_body =
        scan_frame_from_mounting(deg_to_rad(h.alpha_deg), deg_to_rad_reduced(h.beta_deg));
    g.frame_orbit = rotate_frame(body_from_orbit, g.frame_body, true);
    const scan_angles<double> nadir = scan_angles_of(g.frame_body, nadir_body);
    g.eta_true = nadir.polar;
    g.phi_n_true = nadir.azimuth;
    g.eta0 = nominal_nadir_angle(g.frame_body);
    g.psi_bias = bias_cone_angle(g.optics);
    g.noise_rad = deg_to_rad(h.noise_deg);
    g.lsb_rad = deg_to_rad(h.lsb_deg);
    heads_.push_back(g);
  }
}

double simulation::processing_radius_m(const vec3<double>& r_eci) const noexcept {
  switch (processing_kind_) {
    case processing_radius_kind::truth:
      return earth_ == earth_model::sphere ? truth_radius_m_ : orbit::wgs84().a_m;
    case processing_radius_kind::equatorial:
      return orbit::wgs84().a_m;
    case processing_radius_kind::local:
      return orbit::wgs84_radius_along(r_eci);
    case processing_radius_kind::value:
      return processing_value_m_;
  }
  return processing_value_m_;
}

void simulation::compute_rows(std::uint64_t first_k, std::size_t count, row* out,
                              std::uint64_t run) const noexcept {
  for (std::size_t first = 0; first < count; first += rows_per_block) {
    const std::size_t n = std::min(rows_per_block, count - first);
    vec3<double> positions[rows_per_block];
    orbit::geodetic_position geodetic[rows_per_block];
    double times[rows_per_block];
    orbit::orbit_state states[rows_per_block];
    for (std::size_t i = 0; i < n; ++i)  // SPEC §3: a product, never a sum
      times[i] = static_cast<double>(first_k + first + i) * step_s_;
    orbit_.states_at(times, states, n);
    for (std::size_t i = 0; i < n; ++i) {
      compute_from_state(times[i], states[i], out[first + i], run, first_k + first + i);
      positions[i] = states[i].r_eci_m;
    }
    orbit::geodetic_from_eci(positions, geodetic, n);
    for (std::size_t i = 0; i < n; ++i) {
      out[first + i].alt_m = geodetic[i].alt_m;
      out[first + i].lat_rad = geodetic[i].lat_rad;
    }
  }
}

void simulation::compute_from_state(double t, const orbit::orbit_state& st, row& out,
                                    std::uint64_t run, std::uint64_t k) const noexcept {
  const double r = norm(st.r_eci_m);
  out.t_s = t;
  out.true_anomaly_rad = st.true_anomaly_rad;
  out.r_m = r;
  const double processing_radius = processing_radius_m(st.r_eci_m) + processing_horizon_m_;
  const double rho_p = disk_angular_radius(processing_radius, r).value;
  out.rho_p_rad = rho_p;
  // The truth sphere is usually the one the processing assumes (the paper's scene): reuse it.
  const double truth_radius = truth_radius_m_ + horizon_m_;
  const double rho_truth = earth_ != earth_model::sphere ? not_a_number<double>()
                           : truth_radius == processing_radius
                               ? rho_p
                               : disk_angular_radius(truth_radius, r).value;
  const mat3<double> eci_from_orbit = earth_ == earth_model::wgs84
                                          ? dcm_eci_from_orbit(st.r_eci_m, st.v_eci_m_s)
                                          : mat3<double>(1.0);

  std::array<head_estimate<double>, max_heads> estimates;
  std::array<vec3<double>, 2 * max_heads> horizons;
  std::size_t horizon_count = 0;
  int heads_ok = 0;
  std::size_t last_ok = 0;
  for (std::size_t h = 0; h < heads_.size(); ++h) {
    const head_geometry& g = heads_[h];
    crossings<double> c;
    if (earth_ == earth_model::wgs84) {
      const vec3<double> from_centre = st.r_eci_m - vec3<double>(0, 0, centre_z_m_);
      c = scan_model_crossings_ellipsoid(g.optics,
                                         rotate_frame(eci_from_orbit, g.frame_orbit, false),
                                         from_centre, a_eq_m_, b_pol_m_);
    } else if (model_ == forward_model::scan) {
      c = scan_model_crossings_sphere(g.optics, g.eta_true, g.phi_n_true, rho_truth);
    } else {
      c = g.psi_bias.ok()
              ? bias_model_crossings(g.psi_bias.value, g.eta_true, g.phi_n_true, rho_truth)
              : crossings<double>::failed(g.psi_bias.state);
    }
    // What the detector and telemetry make of the crossings (issue 7): noise on each crossing,
    // then the chord and phase quantised. Each draw is a pure function of (seed, run, row, head,
    // crossing), so runs are reproducible on any machine and independent of evaluation order.
    if (g.noise_rad > 0)
      c = with_crossing_noise(c, g.noise_rad * standard_normal(seed_, run, k, h, 0),
                              g.noise_rad * standard_normal(seed_, run, k, h, 1));
    c = quantised(c, g.lsb_rad);
    // Only the horizon-vector processing reads them; on the chord/phase path they would cost
    // four sincos per head and row for nothing (docs/PERFORMANCE.md).
    if (processing_ == processing_method::horizon_vector)
      horizon_count = append_horizon_vectors(g.frame_body, g.optics.gamma, c, horizons.data(),
                                             horizon_count, horizons.size());
    const head_estimate<double>& est = estimates[h] =
        process_head(g.frame_body, g.optics.gamma, rho_p, c, g.eta0);
    head_row& hr = out.heads[h];
    hr.iterations = c.iterations;
    hr.state = est.state;
    if (est.state != status::ok) {
      const double nan = not_a_number<double>();
      hr.chord_rad = hr.phase_rad = hr.eta_err_rad = hr.roll_err_rad = hr.pitch_err_rad = nan;
      continue;
    }
    const roll_pitch<double> sensed = roll_pitch_from_nadir(est.nadir);
    hr.chord_rad = c.chord();
    hr.phase_rad = c.phase();
    hr.eta_err_rad = est.eta_s - g.eta_true;
    hr.roll_err_rad = wrap_pi(sensed.roll - roll_true_);
    hr.pitch_err_rad = sensed.pitch - pitch_true_;
    ++heads_ok;
    last_ok = h;
  }
  head_estimate<double> system =
      combine_heads<double>(estimates.begin(), estimates.begin() + heads_.size());
  out.condition = not_a_number<double>();
  if (processing_ == processing_method::horizon_vector) {
    // One least-squares nadir from every crossing, seeded from the chord/phase solution (which
    // picks the right mirror image when a single head is left), else from the nominal nadir.
    const vec3<double> seed_nadir =
        system.state == status::ok ? system.nadir : vec3<double>(0, 0, 1);
    if (horizon_count == 0) {
      system.state = status::none;
    } else {
      const horizon_nadir_fit<double> fit =
          nadir_from_horizon_vectors(horizons.data(), horizon_count, std::cos(rho_p), seed_nadir);
      out.condition = fit.condition;
      system.nadir = fit.nadir;
      system.state = fit.state;
    }
  }
  out.state = system.state;
  if (system.state != status::ok) {
    out.roll_err_rad = out.pitch_err_rad = not_a_number<double>();
    return;
  }
  if (processing_ == processing_method::chord_phase && heads_ok == 1) {
    // The normalised mean of one unit vector is that vector: the system's errors are the
    // head's, already computed (saves the atan2s of a second roll/pitch).
    out.roll_err_rad = out.heads[last_ok].roll_err_rad;
    out.pitch_err_rad = out.heads[last_ok].pitch_err_rad;
    return;
  }
  const roll_pitch<double> sensed = roll_pitch_from_nadir(system.nadir);
  out.roll_err_rad = wrap_pi(sensed.roll - roll_true_);
  out.pitch_err_rad = sensed.pitch - pitch_true_;
}

}  // namespace conescan::scene
