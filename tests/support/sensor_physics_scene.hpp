// One head and one row for the sensor physics tests: a head mounted as MODEL §4 says, a true
// attitude, the horizon surface (sphere, inflated ellipsoid or apparent horizon) seen from the
// satellite in the head's scan frame, the geometric crossings of MODEL §5, and the same scene for
// the brute-force reference (sensor_physics_reference.hpp).
#pragma once

#include <cmath>

#include "conescan/scan_model.hpp"
#include "conescan/sensor_head.hpp"
#include "conescan/sensor_physics.hpp"
#include "support/sensor_physics_reference.hpp"

namespace conescan_test {

/// A scene's parameters (degrees, metres), with the paper's head and orbit radius as defaults.
struct physics_scene_options {
  long double alpha_deg = 0, beta_deg = 90, gamma_deg = 45, sigma_deg = 0.02L, phi_a_deg = 0;
  long double roll_deg = 0, pitch_deg = 0;
  long double distance_m = 7280000;      ///< |p| from the surface's centre
  long double a_m = 6378137.0L + 40000;  ///< equatorial semi-axis (the sphere's radius)
  long double b_m = 6378137.0L + 40000;  ///< polar semi-axis (ellipsoid only)
  bool ellipsoid = false;
  long double centre_shift_m = 0;  ///< the apparent horizon's centre along the pole
  long double polar_x = 0.3L, polar_y = 0.5L, polar_z = 0.8L;  ///< body axes, normalised
};

/// A random scene of the "300 random scenes" properties (the reduction settings against the
/// geometry): scene i, drawn from `uniform(lo, hi)` in a fixed order (odd i on the ellipsoid, every
/// fourth on a flattened, shifted apparent horizon).
template <class Uniform>
physics_scene_options random_reduction_scene(Uniform& uniform, int i) {
  physics_scene_options o;
  o.alpha_deg = uniform(-30, 30);
  o.beta_deg = uniform(-180, 180);
  o.gamma_deg = uniform(30, 60);
  o.sigma_deg = uniform(0, 0.5);
  o.phi_a_deg = uniform(-180, 180);
  o.roll_deg = uniform(-10, 10);
  o.pitch_deg = uniform(-10, 10);
  o.distance_m = uniform(6.9e6, 8.0e6);
  const double horizon = uniform(0, 60000);
  o.ellipsoid = i % 2 == 1;
  o.a_m = 6378137.0 + horizon;
  o.b_m = 6356752.314245 + horizon - (i % 4 == 3 ? uniform(0, 20000) : 0);
  o.centre_shift_m = i % 4 == 3 ? uniform(-8000, 8000) : 0;
  o.polar_x = uniform(-1, 1);
  o.polar_y = uniform(-1, 1);
  o.polar_z = uniform(-1, 1);
  return o;
}

/// The scene in scalar T.
template <class T>
struct physics_scene {
  physics_scene_options options;
  conescan::sensor_head<T> head;
  conescan::vec3<T> nadir_scan, polar_scan, position_scan;  ///< position: from the centre
  conescan::sphere_surface<T> sphere;
  conescan::ellipsoid_horizon<T> horizon;
  conescan::ellipsoid_surface<T> ellipsoid;
  conescan::crossings<T> geometric;

  template <class Workspace>
  conescan::crossings<T> physics(const conescan::sensor_physics_head<T>& physics_head,
                                 const T& sin_sun, Workspace& work) const {
    return options.ellipsoid ? conescan::sensor_physics_crossings(
                                   physics_head, head.circle(), ellipsoid, sin_sun, geometric, work)
                             : conescan::sensor_physics_crossings(physics_head, head.circle(),
                                                                  sphere, sin_sun, geometric, work);
  }

  /// The true line of sight at scan azimuth phi (MODEL §4), scan-frame components.
  conescan::vec3<T> line_of_sight(const T& phi) const {
    const conescan::head_optics<T>& o = head.optics();
    const T psi = conescan::misaligned_cone_angle(o.gamma, o.sigma, T(phi - o.phi_a)).value;
    const conescan::scan_frame<T> axes{conescan::vec3<T>(T(1), T(0), T(0)),
                                       conescan::vec3<T>(T(0), T(1), T(0)),
                                       conescan::vec3<T>(T(0), T(0), T(1)), conescan::status::ok};
    return conescan::direction_in_scan_frame(axes, psi, phi);
  }

  /// The tangent height of the line of sight at phi (sensor_physics/height.hpp).
  conescan::tangent_height<T> height_at(const T& phi) const {
    return options.ellipsoid ? conescan::tangent_height_of(ellipsoid, line_of_sight(phi))
                             : conescan::tangent_height_of(sphere, line_of_sight(phi));
  }

  reference_scene reference(long double sin_sun) const {
    const auto& o = head.optics();
    const long double a = options.a_m, b = options.ellipsoid ? options.b_m : options.a_m;
    return {static_cast<ld>(o.gamma),
            static_cast<ld>(o.sigma),
            static_cast<ld>(o.phi_a),
            options.ellipsoid,
            vec3l(-static_cast<ld>(position_scan.x), -static_cast<ld>(position_scan.y),
                  -static_cast<ld>(position_scan.z)),
            vec3l(static_cast<ld>(polar_scan.x), static_cast<ld>(polar_scan.y),
                  static_cast<ld>(polar_scan.z)),
            a,
            b,
            sin_sun};
  }
};

template <class T>
T scene_value(long double v) {
  if constexpr (std::is_arithmetic_v<T>)
    return static_cast<T>(v);
  else
    return T::from_long_double(v);
}

template <class T>
physics_scene<T> make_physics_scene(const physics_scene_options& o) {
  using conescan::vec3;
  const long double deg = 3.14159265358979323846264338327950288L / 180;
  auto v = [](long double x) { return scene_value<T>(x); };
  physics_scene<T> s{o,
                     conescan::sensor_head<T>::from_mounting(
                         v(o.alpha_deg * deg), v(o.beta_deg * deg),
                         {v(o.gamma_deg * deg), v(o.sigma_deg * deg), v(o.phi_a_deg * deg)}),
                     {},
                     {},
                     {},
                     {},
                     {},
                     {},
                     {}};
  const long double roll = o.roll_deg * deg, pitch = o.pitch_deg * deg;
  // MODEL §2: the true nadir in body axes.
  const long double nx = -std::sin(pitch), ny = std::sin(roll) * std::cos(pitch),
                    nz = std::cos(roll) * std::cos(pitch);
  const long double pl =
      std::sqrt(o.polar_x * o.polar_x + o.polar_y * o.polar_y + o.polar_z * o.polar_z);
  const vec3<T> nadir_body(v(nx), v(ny), v(nz));
  const vec3<T> polar_body(v(o.polar_x / pl), v(o.polar_y / pl), v(o.polar_z / pl));
  // The satellite from the surface's centre: against the nadir, then off the shifted centre.
  const vec3<T> position_body(v(-o.distance_m * nx - o.centre_shift_m * o.polar_x / pl),
                              v(-o.distance_m * ny - o.centre_shift_m * o.polar_y / pl),
                              v(-o.distance_m * nz - o.centre_shift_m * o.polar_z / pl));
  s.nadir_scan = s.head.in_scan_frame(nadir_body);
  s.polar_scan = s.head.in_scan_frame(polar_body);
  s.position_scan = s.head.in_scan_frame(position_body);
  if (!o.ellipsoid) {
    const conescan::disk_trig<T> disk = conescan::disk_trig_of(v(o.a_m), v(o.distance_m));
    s.sphere = conescan::sphere_surface_of(s.nadir_scan, v(o.a_m), v(o.distance_m), s.polar_scan);
    s.geometric = s.head.scan_crossings(s.nadir_scan, disk);
  } else {
    s.horizon = conescan::ellipsoid_horizon_of(s.position_scan, s.polar_scan, v(o.a_m), v(o.b_m));
    s.ellipsoid = conescan::ellipsoid_surface_of(s.horizon, v(o.a_m));
    s.geometric = s.head.scan_crossings(s.horizon);
  }
  return s;
}

/// The reference's settings from the chain's (long double).
template <class T>
reference_settings reference_settings_of(const conescan::sensor_physics_settings<T>& s) {
  const int locator = s.locator.kind == conescan::locator_kind::normalised ? 0
                      : s.locator.kind == conescan::locator_kind::fixed    ? 1
                                                                           : 2;
  return {static_cast<ld>(s.field.fov_rad),
          s.field.shape == conescan::field_shape::circle,
          2 * 3.14159265358979323846264338327950288L * static_cast<ld>(s.spin_hz) *
              static_cast<ld>(s.tau_s),
          locator,
          static_cast<ld>(s.locator.threshold),
          static_cast<ld>(s.scale_m),
          static_cast<ld>(s.offset_m),
          static_cast<ld>(s.disk),
          static_cast<ld>(s.season_amplitude),
          static_cast<ld>(s.plateau)};
}

/// The reference's crossings of a scene's row with the chain's settings s: reference_crossings
/// from the geometric crossings' mean, on a grid of step h_deg.
template <class T>
reference_result reference_crossings_of(const physics_scene<T>& scene,
                                        const conescan::sensor_physics_settings<T>& s,
                                        long double sin_sun, double h_deg) {
  return reference_crossings(scene.reference(sin_sun), reference_settings_of(s),
                             (scene.geometric.phi_in + scene.geometric.phi_out) / 2,
                             conescan::deg_to_rad(h_deg));
}

/// The sensor-physics benchmark's orbit (bench/sensor_physics_speed.cpp; its row i of 360 is
/// nu_deg = i): the paper's ellipse (a = 7280 km, e = 0.1), the pole in the orbit's plane turning
/// with the true anomaly nu, WGS84's apparent horizon 40 km up; `distance_m` overrides the
/// ellipse's radius (0: the ellipse's).
inline physics_scene_options benchmark_row(double nu_deg, double distance_m = 0) {
  const double nu = conescan::deg_to_rad(nu_deg), a = 7280000, e = 0.1;
  physics_scene_options o;
  o.distance_m = distance_m > 0 ? distance_m : a * (1 - e * e) / (1 + e * std::cos(nu));
  o.ellipsoid = true;
  o.b_m = 6356752.314245L + 40000;
  o.polar_x = std::cos(nu);
  o.polar_y = 0;
  o.polar_z = std::sin(nu);
  return o;
}

/// The benchmark's physics: a 1.5 deg field, 1 ms of lag at 1 rev/s, delta50 = 40 km, H = 7 km,
/// the season term A = 0.2 with the Sun at 20 deg (benchmark_sin_sun), the normalised locator.
inline conescan::sensor_physics_settings<double> benchmark_physics(conescan::field_shape shape) {
  conescan::sensor_physics_settings<double> s;
  s.field = {conescan::deg_to_rad(1.5), shape};
  s.spin_hz = 1;
  s.tau_s = 1e-3;
  s.offset_m = 40000;
  s.season_amplitude = 0.2;
  return s;
}
inline const double benchmark_sin_sun = std::sin(conescan::deg_to_rad(20.0));

/// conescan-sensor-physics-scan --seed 30 --scenes 22 --only 21 --any-altitude 1: a sphere
/// 33 160 km out, the scan (a cone of 86.5 deg) passing within 0.07 deg of the nadir, so that a
/// wide field's patch crosses the line through the Earth's centre; the limb crossed head-on.
inline physics_scene_options far_scene_across_the_nadir() {
  physics_scene_options o;
  o.alpha_deg = 0.56061475020333962;
  o.beta_deg = -54.187889871846778;
  o.gamma_deg = 86.531079621639591;
  o.sigma_deg = 0.041236472193597162;
  o.phi_a_deg = -148.26888790334542;
  o.roll_deg = -2.9546235342799738;
  o.pitch_deg = -0.81870474580785135;
  o.distance_m = 33161898.61895794;
  o.a_m = 6411059.4638445387;
  o.b_m = 6389674.7780895382;
  o.polar_x = 0.0015205813798697676;
  o.polar_y = -0.13645156042396289;
  o.polar_z = -0.89776854873702117;
  return o;
}

}  // namespace conescan_test
