// The real forward model of the calibration (MODEL §11): a scene's heads seen through the §5 scan
// model, on the scene's sphere or inflated/apparent ellipsoid, predicting each telemetry row's
// chord and phase from the parameters (per head: the misalignment's components, the cone-angle
// bias; for the Earth: horizon-km, horizon-pole-km, horizon-shift-km). The crossing biases are
// the estimator's to add (forward_model.hpp).
//
// Split for speed (docs/CALIBRATION.md, bench/calibration_speed.cpp): everything the parameters
// do not change is computed once, in double, when the model is built — the truth of each row
// (scene_geometry.hpp: orbit, reference attitude, Sun), and per head and row the true nadir
// (sphere) or the satellite's position and the polar axis (ellipsoid) in the head's scan frame:
// 16 bytes per row and 24 (sphere) or 48 (ellipsoid) per head and row, plus a float latitude
// per row (a month of 1 Hz, two heads, sphere: 176 MB).
// predict<T> then builds only the Earth for the parameters and calls the core's prediction
// (conescan/head_calibration.hpp: the scan circle of misalignment_components.hpp, the crossings):
// the same core functions for double and for ceres::Jet, and for --apply's correction.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "calibration/estimator.hpp"
#include "calibration/forward_model.hpp"
#include "calibration/layout.hpp"
#include "calibration/parameters.hpp"
#include "calibration/telemetry.hpp"
#include "conescan/head_calibration.hpp"
#include "scene/scene_config.hpp"
#include "scene_calibration/scene_geometry.hpp"
#include "text/diagnostic.hpp"

namespace conescan::calibration {

class scene_model {
 public:
  /// The model of a validated scene at the given times (measurement rows index them). Errors
  /// (exit 2): the scene's --model bias (the calibration fits the scan model, MODEL §11), and
  /// scene_truth_at's. The rows' truth is computed on `threads` threads.
  static checked<scene_model> of(const scene::scene_config& scene, std::span<const double> times_s,
                                 int threads = 2);
  /// The model of a telemetry: its rows' truth at their times, each measurement's row (the
  /// telemetry's) looked up through a map when some rows hold no measurement. Errors as of(),
  /// a time's error naming the telemetry's file and line.
  static checked<scene_model> of_telemetry(const scene::scene_config& scene, const telemetry& data,
                                           int threads = 2);

  std::size_t head_count() const noexcept { return gamma_rad_.size(); }
  std::size_t row_count() const noexcept { return rows_.size(); }
  /// The satellite's geocentric latitude (deg) at a measurement's row.
  double latitude_deg(std::size_t row) const noexcept { return latitude_deg_[row_of(row)]; }

 private:
  // (Defined before its callers: its return type is deduced.)
  /// f(gamma, surface) on the ellipsoid, f(gamma, nadir, disk) on the sphere: head sample.head's
  /// nominal cone (rad) and the Earth of the parameters `earth` in its scan frame at sample.row.
  template <class T, class F>
  auto seen(const telemetry_sample& sample, const earth_geometry<T>& earth, F&& f) const {
    const T gamma(gamma_rad_[sample.head]);
    const std::size_t r = row_of(sample.row);
    const row_geometry& row = rows_[r];
    const double* view = &views_[(r * head_count() + sample.head) * view_size()];
    if (ellipsoid_) {
      // The apparent surface: semi-axes a + h0 and b + h0 + h_pole, centre moved along
      // the polar axis by h_shift sin(declination) (simulation.cpp's truth).
      const T a_eq = equatorial_m_ + earth.horizon_km * 1000.0;
      const T b_pol = polar_m_ + (earth.horizon_km + earth.horizon_pole_km) * 1000.0;
      const T shift_m = earth.horizon_shift_km * (1000.0 * row.sin_declination);
      const double* polar_scan = view + 3;
      const vec3<T> p(T(view[0] - shift_m * polar_scan[0]), T(view[1] - shift_m * polar_scan[1]),
                      T(view[2] - shift_m * polar_scan[2]));
      const vec3<T> polar{T(polar_scan[0]), T(polar_scan[1]), T(polar_scan[2])};
      return f(gamma, ellipsoid_horizon_of(p, polar, a_eq, b_pol));
    }
    const T radius = sphere_radius_m_ + earth.horizon_km * 1000.0;
    const vec3<T> nadir{T(view[0]), T(view[1]), T(view[2])};
    return f(gamma, nadir, disk_trig_of(radius, T(row.r_m)));
  }

 public:
  template <class T>
  predicted_measurement<T> predict(const telemetry_sample& sample, const head_geometry<T>& head,
                                   const earth_geometry<T>& earth) const {
    return seen(sample, earth, [&](const T& gamma_rad, const auto&... earth_seen) {
      return predicted_chord_phase(gamma_rad, head, earth_seen...);
    });
  }

  /// A measurement corrected by a head's calibration at the row's geometry (conescan-sim
  /// --apply): the core's rule (calibrated_crossings, conescan/head_calibration.hpp) with the
  /// Earth of the fitted horizon terms as the head sees it.
  crossings<double> corrected(const telemetry_sample& sample,
                              const head_calibration<double>& calibration,
                              const earth_geometry<double>& earth,
                              const crossings<double>& measured) const {
    return seen(sample, earth, [&](const double& gamma_rad, const auto&... earth_seen) {
      return calibrated_crossings(measured, gamma_rad, calibration, earth_seen...);
    });
  }

 private:
  struct row_geometry {
    double r_m;
    double sin_declination;
  };

  std::size_t row_of(std::size_t row) const noexcept {
    return row_map_.empty() ? row : row_map_[row];
  }
  // Per head and row, in the head's scan frame: the unit true nadir (sphere), or the satellite
  // from the Earth's centre and the polar axis (ellipsoid): only what the Earth model reads.
  std::size_t view_size() const noexcept { return ellipsoid_ ? 6 : 3; }

  bool ellipsoid_ = false;
  double sphere_radius_m_ = 0;  // sphere: R without the horizon
  double equatorial_m_ = 0;     // ellipsoid: a and b without the horizon terms
  double polar_m_ = 0;
  std::vector<double> gamma_rad_;  // nominal cone angle per head
  std::vector<row_geometry> rows_;
  std::vector<float> latitude_deg_;     // per row, for the residuals' file (float: 1e-5 deg)
  std::vector<double> views_;           // row-major: row k, head h at (k heads + h) view_size()
  std::vector<std::uint32_t> row_map_;  // the telemetry's row -> rows_'s; empty: the same
};

/// The parameter set of a scene: every parameter at the scene's value (each head's sigma,
/// phase, dgamma, bias-in, bias-out; horizon-km, horizon-pole-km, horizon-shift-km), all held.
parameter_set scene_parameters(const scene::scene_config& scene);

/// Each head's stated noise (its noise= and lsb=).
std::vector<head_noise> scene_noise(const scene::scene_config& scene);

}  // namespace conescan::calibration
