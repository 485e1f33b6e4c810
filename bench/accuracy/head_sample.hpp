// One head's inputs in the working scalar T, built from a scene_point in T itself: each
// precision rounds the same double scene values once, and the reference rounds nothing.
#pragma once

#include "accuracy/scene_grid.hpp"
#include "conescan/attitude.hpp"
#include "conescan/crossings.hpp"
#include "conescan/orbital_frame.hpp"
#include "conescan/scan_frame.hpp"

namespace conescan::accuracy {

/// The Earth's figure (m), given as doubles (GeographicLib's WGS84, MODEL §3).
struct earth_figure {
  double sphere_radius_m;  ///< truth and processing sphere R (WGS84 a)
  double a_eq_m;           ///< ellipsoid equatorial semi-axis (horizon height 0)
  double b_pol_m;          ///< ellipsoid polar semi-axis
};

/// Everything a head's pipeline reads per sample (rad, m). The orbit layer's work (frames,
/// positions) is done here, outside the timed pipeline.
template <class T>
struct head_sample {
  head_optics<T> optics;
  scan_frame<T> frame_body;  ///< scan frame in body axes (= orbital axes: zero attitude)
  T eta;                     ///< true nadir's angle from S
  T phi_n;                   ///< true nadir's azimuth about S (0 for zero attitude)
  T r_m;                     ///< orbit radius, sphere methods
  T radius_m;                ///< sphere radius, truth and processing
  vec3<T> nadir_body;        ///< true nadir in body axes (0, 0, 1): the scan model's input
  scan_frame<T> frame_eci;   ///< scan frame in ECI, ellipsoid method
  vec3<T> p_eci_m;           ///< satellite position, ellipsoid method
  vec3<T> p_body_m;          ///< the same in body axes (= orbital axes)
  vec3<T> polar_body;        ///< the Earth's polar axis in body axes
  T a_eq_m;
  T b_pol_m;
};

/// Builds the sample in T. The head is mounted at (alpha, beta = 90 deg) with zero true
/// attitude, so eta = 90 deg - alpha. For the ellipsoid, the satellite is at geocentric latitude
/// lat_deg on the x-z meridian, at radius WGS84 a + alt, moving north on a polar orbit.
template <class T>
head_sample<T> make_head_sample(const scene_point& s, const earth_figure& earth) {
  using std::cos;
  using std::sin;
  head_sample<T> out{};
  out.optics = {deg_to_rad(T(s.gamma_deg)), deg_to_rad(T(s.sigma_deg)), deg_to_rad(T(s.phi_a_deg))};
  out.frame_body = scan_frame_from_mounting(deg_to_rad(T(s.alpha_deg)), deg_to_rad(T(90)));
  const scan_angles<T> nadir = scan_angles_of(out.frame_body, vec3<T>(T(0), T(0), T(1)));
  out.eta = nadir.polar;
  out.phi_n = nadir.azimuth;
  out.radius_m = T(earth.sphere_radius_m);
  out.r_m = out.radius_m + T(s.alt_km) * T(1000);
  out.a_eq_m = T(earth.a_eq_m);
  out.b_pol_m = T(earth.b_pol_m);
  const T lat = deg_to_rad(T(s.lat_deg));
  const T cos_lat = cos(lat), sin_lat = sin(lat);
  out.p_eci_m = vec3<T>(out.r_m * cos_lat, T(0), out.r_m * sin_lat);
  const mat3<T> eci_from_orbit =
      dcm_eci_from_orbit(out.p_eci_m, vec3<T>(T(-sin_lat), T(0), cos_lat));
  out.frame_eci = {apply(eci_from_orbit, out.frame_body.e1),
                   apply(eci_from_orbit, out.frame_body.e2),
                   apply(eci_from_orbit, out.frame_body.e3), out.frame_body.state};
  out.nadir_body = vec3<T>(T(0), T(0), T(1));
  out.p_body_m = apply_transpose(eci_from_orbit, out.p_eci_m);
  out.polar_body = apply_transpose(eci_from_orbit, vec3<T>(T(0), T(0), T(1)));
  return out;
}

}  // namespace conescan::accuracy
