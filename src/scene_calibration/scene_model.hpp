// The real forward model of the calibration (MODEL §11): a scene's heads seen through the §5 scan
// model, on the scene's sphere or inflated/apparent ellipsoid, predicting each telemetry row's
// chord and phase from the parameters (per head: the misalignment's components, the cone-angle
// bias, and where the head runs MODEL §12's chain its tau-ms and threshold; for the Earth:
// horizon-km, horizon-pole-km, horizon-shift-km, and the limb's radiance-offset-km and
// radiance-scale-km). The crossing biases are the estimator's to add (forward_model.hpp).
//
// Split for speed (docs/CALIBRATION.md, bench/calibration_speed.cpp): everything the parameters
// do not change is computed once, in double, when the model is built — the truth of each row
// (scene_geometry.hpp: orbit, reference attitude, Sun), and per head and row the true nadir
// (sphere; with the polar axis for the radiance's season term) or the satellite's position and
// the polar axis (ellipsoid) in the head's scan frame: 16 bytes per row and 24 (sphere) or 48
// (ellipsoid) per head and row, plus a float latitude per row (a month of 1 Hz, two heads,
// sphere: 176 MB).
// predict<T> then builds only the Earth for the parameters and calls the core's prediction
// (conescan/head_calibration.hpp: the scan circle of misalignment_components.hpp, the crossings),
// and for a head with physics the core's chain (conescan/sensor_physics.hpp) from them: the same
// core functions for double and for ceres::Jet, and for --apply's correction. A physics row costs
// what the chain costs (a pencil with lag ~0.05 ms in double, ~0.5 ms in the fit's Jet; a 1.5 deg
// field ~9 ms and ~0.16 s, docs/CALIBRATION.md), so from physics_series_least_rows rows on a
// physics head's rows take the chain's shifts from a time series (physics_time_series.hpp) that
// runs the chain at some 20 rows in each 20 minutes, at each step's own parameters.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <type_traits>
#include <vector>

#include "calibration/estimator.hpp"
#include "calibration/forward_model.hpp"
#include "calibration/layout.hpp"
#include "calibration/parameters.hpp"
#include "calibration/telemetry.hpp"
#include "conescan/head_calibration.hpp"
#include "conescan/sensor_physics.hpp"
#include "scene/head_spec.hpp"
#include "scene/loaded_scene.hpp"
#include "scene/scene_config.hpp"
#include "scene_calibration/physics_time_series.hpp"
#include "scene_calibration/scene_geometry.hpp"
#include "text/diagnostic.hpp"

namespace conescan::calibration {

class scene_model {
 public:
  /// The model of a validated scene at the given times (measurement rows index them). Errors
  /// (exit 2): the scene's --model bias (the calibration fits the scan model, MODEL §11), and
  /// scene_truth_at's. The rows' truth is computed on `threads` threads.
  static checked<scene_model> of(const scene::loaded_scene& scene, std::span<const double> times_s,
                                 int threads = 2);
  /// The model of a telemetry: its rows' truth at their times, each measurement's row (the
  /// telemetry's) looked up through a map when some rows hold no measurement. Errors as of(),
  /// a time's error naming the telemetry's file and line.
  static checked<scene_model> of_telemetry(const scene::loaded_scene& scene, const telemetry& data,
                                           int threads = 2);

  std::size_t head_count() const noexcept { return gamma_rad_.size(); }
  std::size_t row_count() const noexcept { return rows_.size(); }
  /// The satellite's geocentric latitude (deg) at a measurement's row.
  double latitude_deg(std::size_t row) const noexcept { return latitude_deg_[row_of(row)]; }
  /// True when head k runs MODEL §12's chain (scene_physics.hpp's physics_on).
  bool runs_physics(std::size_t head) const noexcept { return physics_[head].on; }

  /// The chord and phase of head sample.head at sample.row before its crossing biases: MODEL
  /// §5's scan model on the Earth of `earth`, and for a head that runs the chain MODEL §12's
  /// crossings on it (the head's tau-ms and threshold, the limb's height and scale height from
  /// the parameters, the rest of its physics from the scene). Derivatives (T = ceres::Jet): the
  /// chain's own, by automatic differentiation through every step (docs/CALIBRATION.md).
  template <class T>
  predicted_measurement<T> predict(const telemetry_sample& sample, const head_geometry<T>& head,
                                   const earth_geometry<T>& earth) const {
    const std::size_t row = row_of(sample.row), k = sample.head;
    if (!physics_[k].on) return chord_phase_deg_of(geometric_crossings(row, k, head, earth));
    if (series_[k]) {
      const crossings<T> geometric = geometric_crossings(row, k, head, earth);
      crossings<T> served;
      if (geometric.state == status::ok && series_crossings(row, k, head, earth, geometric, served))
        return chord_phase_deg_of(served);
    }
    if constexpr (std::is_same_v<T, parameter_jet>)
      return chord_phase_deg_of(compact_physics_crossings(row, k, head, earth));
    else
      return chord_phase_deg_of(physics_crossings(row, k, head, earth));
  }

  /// From `least_rows` rows on (of() sets physics_series_least_rows), each head that runs the
  /// chain takes its crossings from a time series of the chain's where it can
  /// (physics_time_series.hpp); with fewer rows, or times not strictly increasing, every row
  /// runs the chain.
  void use_physics_series(std::size_t least_rows, physics_time_series_settings settings = {});
  /// The chain evaluations the heads' time series have made so far.
  std::size_t physics_series_evaluations() const noexcept;
  /// The rows the heads' time series have served so far.
  std::size_t physics_series_served() const noexcept;

  /// A measurement corrected by a head's calibration at the row's geometry (conescan-sim
  /// --apply): the core's rule (corrected_crossings, conescan/head_calibration.hpp) with the
  /// Earth of the fitted horizon terms as the head sees it. The modelled measurement is
  /// predict's with the crossing biases: with the sensor physics where the head runs the chain
  /// and the fit modelled it (its tau-ms is a number), so that the physics' shifts are
  /// subtracted with the head's errors; the ideal one is MODEL §5's geometry of a head without
  /// errors.
  crossings<double> corrected(const telemetry_sample& sample, const head_geometry<double>& head,
                              double bias_in_deg, double bias_out_deg,
                              const earth_geometry<double>& earth,
                              const crossings<double>& measured) const;

 private:
  struct row_geometry {
    double r_m;
    double sin_declination;
  };
  /// A head's physics from the scene (scene_physics.hpp): its settings, of which the
  /// parameters replace tau, the threshold, the limb's offset and scale height.
  struct head_physics {
    bool on = false;
    sensor_physics_settings<double> settings;
  };
  template <class T>
  struct sphere_view {
    vec3<T> nadir;  ///< unit true nadir, scan-frame components
    disk_trig<T> disk;
    T radius_m;     ///< the horizon sphere's radius
    vec3<T> polar;  ///< the polar axis (the season term), else the nadir
  };
  template <class T>
  struct ellipsoid_view {
    ellipsoid_horizon<T> horizon;
    T a_eq_m;  ///< the horizon surface's equatorial semi-axis
  };
  template <class T>
  struct calibrated_cone {
    T gamma_rad, x_rad, y_rad;  ///< gamma + dgamma and the misalignment's components (rad)
  };

  template <class T>
  static calibrated_cone<T> cone_of(const T& gamma_rad, const cone_calibration<T>& cone) {
    const T degree = calibration_degree<T>();
    return {T(gamma_rad + cone.dgamma_deg * degree), T(cone.misalignment_x_deg * degree),
            T(cone.misalignment_y_deg * degree)};
  }

  const double* view_of(std::size_t row, std::size_t k) const noexcept {
    return &views_[(row * head_count() + k) * view_size()];
  }

  /// Head k's view of the sphere of the parameters `earth` at internal row `row`.
  template <class T>
  sphere_view<T> sphere_seen(std::size_t row, std::size_t k, const earth_geometry<T>& earth) const {
    const double* view = view_of(row, k);
    const T radius = sphere_radius_m_ + earth.horizon_km * 1000.0;
    const vec3<T> nadir{T(view[0]), T(view[1]), T(view[2])};
    const vec3<T> polar = sphere_polar_ ? vec3<T>{T(view[3]), T(view[4]), T(view[5])} : nadir;
    return {nadir, disk_trig_of(radius, T(rows_[row].r_m)), radius, polar};
  }

  /// The apparent surface: semi-axes a + h0 and b + h0 + h_pole, centre moved along the polar
  /// axis by h_shift sin(declination) (simulation.cpp's truth).
  template <class T>
  ellipsoid_view<T> ellipsoid_seen(std::size_t row, std::size_t k,
                                   const earth_geometry<T>& earth) const {
    const double* view = view_of(row, k);
    const T a_eq = equatorial_m_ + earth.horizon_km * 1000.0;
    const T b_pol = polar_m_ + (earth.horizon_km + earth.horizon_pole_km) * 1000.0;
    const T shift_m = earth.horizon_shift_km * (1000.0 * rows_[row].sin_declination);
    const double* polar_scan = view + 3;
    const vec3<T> p(T(view[0] - shift_m * polar_scan[0]), T(view[1] - shift_m * polar_scan[1]),
                    T(view[2] - shift_m * polar_scan[2]));
    const vec3<T> polar{T(polar_scan[0]), T(polar_scan[1]), T(polar_scan[2])};
    return {ellipsoid_horizon_of(p, polar, a_eq, b_pol), a_eq};
  }

  /// Head k's geometric crossings at internal row `row` (MODEL §5's scan model).
  template <class T>
  crossings<T> geometric_crossings(std::size_t row, std::size_t k, const head_geometry<T>& head,
                                   const earth_geometry<T>& earth) const {
    const calibrated_cone<T> cone = cone_of(T(gamma_rad_[k]), head);
    if (ellipsoid_)
      return component_crossings_ellipsoid(cone.gamma_rad, cone.x_rad, cone.y_rad,
                                           ellipsoid_seen(row, k, earth).horizon);
    const sphere_view<T> v = sphere_seen(row, k, earth);
    return component_crossings_sphere(cone.gamma_rad, cone.x_rad, cone.y_rad, v.nadir, v.disk);
  }

  /// MODEL §12's crossings of head k, which runs the chain, at internal row `row`.
  template <class T>
  crossings<T> physics_crossings(std::size_t row, std::size_t k, const head_geometry<T>& head,
                                 const earth_geometry<T>& earth) const {
    const calibrated_cone<T> cone = cone_of(T(gamma_rad_[k]), head);
    if (ellipsoid_) {
      const ellipsoid_view<T> e = ellipsoid_seen(row, k, earth);
      return chain_crossings(
          row, k, head, earth, cone, ellipsoid_surface_of(e.horizon, e.a_eq_m),
          component_crossings_ellipsoid(cone.gamma_rad, cone.x_rad, cone.y_rad, e.horizon));
    }
    const sphere_view<T> v = sphere_seen(row, k, earth);
    return chain_crossings(
        row, k, head, earth, cone, sphere_surface_of(v.nadir, v.disk, v.radius_m, v.polar),
        component_crossings_sphere(cone.gamma_rad, cone.x_rad, cone.y_rad, v.nadir, v.disk));
  }

  /// physics_crossings with the fit's Jets, run on a scalar of only the inputs whose derivatives
  /// they carry (the free parameters'): double for none, the compact Jet for at most
  /// compact_jet_size, a Jet of the twelve otherwise, the derivatives carried back by the chain
  /// rule: the same derivatives (each slot's arithmetic is its own), at the cost of a Jet of
  /// fewer slots.
  crossings<parameter_jet> compact_physics_crossings(
      std::size_t row, std::size_t k, const head_geometry<parameter_jet>& head,
      const earth_geometry<parameter_jet>& earth) const;

  /// MODEL §12's crossings (sensor_physics_crossings) of head k on `surface`, from its geometric
  /// crossings there.
  template <class T, class Surface>
  crossings<T> chain_crossings(std::size_t row, std::size_t k, const head_geometry<T>& head,
                               const earth_geometry<T>& earth, const calibrated_cone<T>& cone,
                               const Surface& surface, const crossings<T>& geometric) const;

  /// Head k's crossings from its time series: the geometric ones plus the series' shifts at the
  /// inputs' values, carrying the inputs' derivatives through the series' gradients. False: the
  /// row is the chain's.
  template <class T>
  bool series_crossings(std::size_t row, std::size_t k, const head_geometry<T>& head,
                        const earth_geometry<T>& earth, const crossings<T>& geometric,
                        crossings<T>& out) const;
  /// The chain's shifts at internal row `row` for the inputs `key`, with their gradients (Jets)
  /// when asked: the time series' evaluator.
  series_sample series_sample_at(std::size_t row, std::size_t k, const series_inputs& key,
                                 series_mask gradient) const;

  std::size_t row_of(std::size_t row) const noexcept {
    return row_map_.empty() ? row : row_map_[row];
  }
  // Per head and row, in the head's scan frame: the unit true nadir (sphere; and the polar axis
  // with the radiance's season term), or the satellite from the Earth's centre and the polar
  // axis (ellipsoid): only what the Earth model reads.
  std::size_t view_size() const noexcept { return ellipsoid_ || sphere_polar_ ? 6 : 3; }

  bool ellipsoid_ = false;
  bool sphere_polar_ = false;   // sphere with the radiance's season term: the polar axis kept
  double sphere_radius_m_ = 0;  // sphere: R without the horizon
  double equatorial_m_ = 0;     // ellipsoid: a and b without the horizon terms
  double polar_m_ = 0;
  std::vector<double> gamma_rad_;  // nominal cone angle per head
  std::vector<head_physics> physics_;
  std::vector<row_geometry> rows_;
  std::vector<float> latitude_deg_;     // per row, for the residuals' file (float: 1e-5 deg)
  std::vector<double> views_;           // row-major: row k, head h at (k heads + h) view_size()
  std::vector<std::uint32_t> row_map_;  // the telemetry's row -> rows_'s; empty: the same
  std::vector<double> times_s_;         // per row
  std::vector<std::shared_ptr<const physics_time_series>> series_;  // per head; null: the chain
};

/// The rows from which a fit's physics heads take their crossings from time series (of()): a
/// day of 1 Hz telemetry does, the README's three orbits at 10 s (619 rows) and the tests' short
/// scenes run the chain on every row.
inline constexpr std::size_t physics_series_least_rows = 4096;

/// The ten inputs a physics head's crossings read (physics_time_series.hpp's order), as
/// pointers into a head's and the Earth's parameters (const or not).
template <class Head, class Earth>
auto series_fields(Head& head, Earth& earth) {
  return std::array{&head.misalignment_x_deg,  &head.misalignment_y_deg,
                    &head.dgamma_deg,          &head.tau_ms,
                    &head.threshold,           &earth.horizon_km,
                    &earth.horizon_pole_km,    &earth.horizon_shift_km,
                    &earth.radiance_offset_km, &earth.radiance_scale_km};
}

/// The inputs whose derivatives the Jets `head` and `earth` carry (a free parameter's: its value
/// is a number and its gradient not zero); none for doubles.
template <class T>
series_mask derivative_inputs(const head_geometry<T>& head, const earth_geometry<T>& earth) {
  series_mask mask = 0;
  if constexpr (!std::is_same_v<T, double>) {
    const auto fields = series_fields(head, earth);
    for (std::size_t i = 0; i < series_input_count; ++i)
      if (!std::isnan(fields[i]->a) && !fields[i]->v.isZero()) mask |= series_mask(1u << i);
  }
  return mask;
}

/// Each input's Jet slot: its place among the inputs of a mask (-1: none, no derivative).
struct input_slots {
  std::array<int, series_input_count> slot;
  int count;  ///< the slots taken
};
input_slots input_slots_of(series_mask mask) noexcept;

/// A head's and the Earth's inputs as scalars T at `values`: a Jet seeded in its slot where
/// `slots` gives it one, a plain number otherwise (NaN: an absent input).
template <class T>
void seed_inputs(const series_inputs& values, const input_slots& slots, head_geometry<T>& head,
                 earth_geometry<T>& earth) {
  const auto fields = series_fields(head, earth);
  for (std::size_t i = 0; i < series_input_count; ++i) {
    if constexpr (std::is_same_v<T, double>)
      *fields[i] = values[i];
    else
      *fields[i] = slots.slot[i] >= 0 ? T(values[i], slots.slot[i]) : T(values[i]);
  }
}

/// The Jet of few slots the fit's physics runs on where its free inputs fit (compact_physics_
/// crossings, the time series' samples): the misalignment's two components, tau and the limb's
/// height are four. A chain's Jet costs about its slots (docs/CALIBRATION.md).
inline constexpr int compact_jet_size = 4;
using compact_jet = ceres::Jet<double, compact_jet_size>;

namespace scene_model_detail {

/// The chain's head and workspace for scalar T, one per thread (the fit's passes evaluate on
/// several threads at once), built on the thread's first physics evaluation and re-targeted at
/// each (sensor_physics_head_set): a Jet's are 7.0 MB, too large to build per evaluation.
template <class T>
struct chain_state {
  sensor_physics_head<T> head;
  sensor_physics_workspace<T> work;
};

template <class T>
chain_state<T>& thread_chain_state() {
  thread_local const std::unique_ptr<chain_state<T>> state = [] {
    auto s = std::make_unique<chain_state<T>>();
    sensor_physics_head_build(s->head, sensor_physics_settings<T>{});
    return s;
  }();
  return *state;
}

}  // namespace scene_model_detail

template <class T, class Surface>
crossings<T> scene_model::chain_crossings(std::size_t row, std::size_t k,
                                          const head_geometry<T>& head,
                                          const earth_geometry<T>& earth,
                                          const calibrated_cone<T>& cone, const Surface& surface,
                                          const crossings<T>& geometric) const {
  const sensor_physics_settings<double>& base = physics_[k].settings;
  sensor_physics_settings<T> settings;
  settings.field = {T(base.field.fov_rad), base.field.shape};
  settings.spin_hz = T(base.spin_hz);
  settings.tau_s = head.tau_ms / 1000.0;
  settings.locator = {base.locator.kind, head.threshold};
  settings.scale_m = earth.radiance_scale_km * 1000.0;
  settings.offset_m = earth.radiance_offset_km * 1000.0;
  settings.disk = T(base.disk);
  settings.season_amplitude = T(base.season_amplitude);
  scene_model_detail::chain_state<T>& state = scene_model_detail::thread_chain_state<T>();
  sensor_physics_head_set(state.head, settings);
  return sensor_physics_crossings(
      state.head, scan_circle_from_components(cone.gamma_rad, cone.x_rad, cone.y_rad), surface,
      T(rows_[row].sin_declination), geometric, state.work);
}

template <class T>
bool scene_model::series_crossings(std::size_t row, std::size_t k, const head_geometry<T>& head,
                                   const earth_geometry<T>& earth, const crossings<T>& geometric,
                                   crossings<T>& out) const {
  constexpr bool jets = !std::is_same_v<T, double>;
  const auto fields = series_fields(head, earth);
  series_inputs key{};
  for (std::size_t i = 0; i < series_input_count; ++i) key[i] = value_of(*fields[i]);
  series_sample s;
  const series_evaluator evaluate = [this, k](std::size_t r, const series_inputs& at,
                                              series_mask gradient) {
    return series_sample_at(r, k, at, gradient);
  };
  const series_mask gradient = derivative_inputs(head, earth);
  if (!series_[k]->shift_at(row, key, gradient, value_of(geometric.chord()), evaluate, s))
    return false;
  T shift[2] = {T(s.shift[0]), T(s.shift[1])};
  if constexpr (jets)
    for (std::size_t c = 0; c < 2; ++c)
      for (std::size_t i = 0; i < series_input_count; ++i)
        if (!std::isnan(key[i])) shift[c] += s.gradient[c][i] * (*fields[i] - key[i]);
  out = crossings_from_azimuths(T(geometric.phi_in + shift[0]), T(geometric.phi_out + shift[1]),
                                geometric.iterations);
  return true;
}

/// The head key a fit's head parameter is (the key of the same name, head_spec.hpp: a number
/// key, whose field the parameter reads and sets), so the fit and the scene read one list.
const scene::head_key& head_parameter_key(head_parameter p);

/// The parameter set of a scene: every parameter at the scene's value (each head's sigma,
/// phase, dgamma, bias-in, bias-out, tau-ms, threshold; horizon-km, horizon-pole-km,
/// horizon-shift-km, radiance-offset-km, radiance-scale-km), all held; the physics' NaN where
/// the scene runs no chain (parameters.hpp).
parameter_set scene_parameters(const scene::scene_config& scene);

/// Each head's stated noise (its noise= and lsb=).
std::vector<head_noise> scene_noise(const scene::scene_config& scene);

}  // namespace conescan::calibration
