// The real forward model of the calibration (MODEL §11): a scene's heads seen through the §5 scan
// model, on the scene's sphere or inflated/apparent ellipsoid, predicting each telemetry row's
// chord and phase from the parameters (per head: the misalignment's components, the cone-angle
// bias; for the Earth: horizon-km, horizon-pole-km, horizon-shift-km). The crossing biases are
// the estimator's to add (forward_model.hpp).
//
// Split for speed (docs/CALIBRATION.md, bench/calibration_speed.cpp): everything the parameters
// do not change is computed once, in double, when the model is built — the truth of each row
// (scene_geometry.hpp: orbit, reference attitude, Sun), and per head and row the true nadir
// (sphere) or the satellite's position and the polar axis (ellipsoid) in the head's scan frame.
// predict<T> then builds only the scan circle (misalignment_components.hpp) and the Earth for the
// parameters, and solves the crossings: the same core functions for double and for ceres::Jet.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "calibration/estimator.hpp"
#include "calibration/forward_model.hpp"
#include "calibration/layout.hpp"
#include "calibration/parameters.hpp"
#include "conescan/misalignment_components.hpp"
#include "scene/scene_config.hpp"
#include "scene_calibration/scene_geometry.hpp"
#include "text/diagnostic.hpp"

namespace conescan::calibration {

class scene_model {
 public:
  /// The model of a validated scene at the telemetry's times. Errors (exit 2): the scene's
  /// --model bias (the calibration fits the scan model, MODEL §11), and scene_truth_at's.
  static checked<scene_model> of(const scene::scene_config& scene, std::span<const double> times_s);

  std::size_t head_count() const noexcept { return gamma_rad_.size(); }
  std::size_t row_count() const noexcept { return rows_.size(); }

  template <class T>
  predicted_measurement<T> predict(const telemetry_sample& sample, const head_geometry<T>& head,
                                   const earth_geometry<T>& earth) const {
    const T gamma = gamma_rad_[sample.head] + head.dgamma_deg * radians_per_degree;
    const T x = head.misalignment_x_deg * radians_per_degree;
    const T y = head.misalignment_y_deg * radians_per_degree;
    const row_geometry& row = rows_[sample.row];
    const head_view& view = views_[sample.row * head_count() + sample.head];
    crossings<T> c = crossings<T>::failed(status::invalid);
    if (ellipsoid_) {
      // The apparent surface: semi-axes a + h0 and b + h0 + h_pole, centre moved along
      // the polar axis by h_shift sin(declination) (simulation.cpp's truth).
      const T a_eq = equatorial_m_ + earth.horizon_km * 1000.0;
      const T b_pol = polar_m_ + (earth.horizon_km + earth.horizon_pole_km) * 1000.0;
      const T shift_m = earth.horizon_shift_km * (1000.0 * row.sin_declination);
      const vec3<T> p(T(view.position_scan_m.x - shift_m * view.polar_scan.x),
                      T(view.position_scan_m.y - shift_m * view.polar_scan.y),
                      T(view.position_scan_m.z - shift_m * view.polar_scan.z));
      const vec3<T> polar(T(view.polar_scan.x), T(view.polar_scan.y), T(view.polar_scan.z));
      c = component_crossings_ellipsoid(gamma, x, y, ellipsoid_horizon_of(p, polar, a_eq, b_pol));
    } else {
      const T radius = sphere_radius_m_ + earth.horizon_km * 1000.0;
      const vec3<T> nadir(T(view.nadir_scan.x), T(view.nadir_scan.y), T(view.nadir_scan.z));
      c = component_crossings_sphere(gamma, x, y, nadir, disk_trig_of(radius, T(row.r_m)));
    }
    if (c.state != status::ok) return {T(0.0), T(0.0), c.state};
    return {T(c.chord() / radians_per_degree), T(c.phase() / radians_per_degree), status::ok};
  }

 private:
  struct row_geometry {
    double r_m;
    double sin_declination;
  };
  // One head in one row, in the head's scan frame.
  struct head_view {
    vec3<double> nadir_scan;       // sphere: the unit true nadir
    vec3<double> position_scan_m;  // ellipsoid: the satellite from the Earth's centre
    vec3<double> polar_scan;       // ellipsoid: the polar axis
  };

  bool ellipsoid_ = false;
  double sphere_radius_m_ = 0;  // sphere: R without the horizon
  double equatorial_m_ = 0;     // ellipsoid: a and b without the horizon terms
  double polar_m_ = 0;
  std::vector<double> gamma_rad_;  // nominal cone angle per head
  std::vector<row_geometry> rows_;
  std::vector<head_view> views_;  // row-major: row k, head h at k * heads + h
};

/// The parameter set of a scene: every parameter at the scene's value (each head's sigma,
/// phase, dgamma, bias-in, bias-out; horizon-km, horizon-pole-km, horizon-shift-km), all held.
parameter_set scene_parameters(const scene::scene_config& scene);

/// Each head's stated noise (its noise= and lsb=).
std::vector<head_noise> scene_noise(const scene::scene_config& scene);

}  // namespace conescan::calibration
