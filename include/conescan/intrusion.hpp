// The Sun and the Moon in a head's scan (MODEL §13): where a body sits against the scan cone,
// the pulse it makes, whether the Earth hides it, and the head's verdict.
//
// The steps, and where each runs (the caller's row loop; sources give X and r_X):
//   per row and body   body_angular_radius       r_X from the body's radius and distance
//                      body_hidden_by_sphere |    its centre behind the horizon surface
//                      body_hidden_by_ellipsoid
//   per head and body  body_intrusion_of         the signed angle from the cone, and whether
//                                                its pulse meets the Earth pulse
//   per head           intrusion_status          ok, sun or moon (or the crossings' own status)
// Built on the blocks cone_offset, body_pulse_of, earth_pulse_of, arcs_overlap. The rule, with
// eps = fov/2 + r_X: a visible body within eps of the cone whose pulse (half-width eps / sin gamma)
// meets the Earth pulse (widened by (fov/2) / sin gamma), closed arcs mod 2 pi: the outer bound of
// any signal of the body in the field. The widths are first order (exact to 5e-5 deg at
// eps = 1 deg, gamma = 45 deg), the centres exact. Each formula, and why this bound:
// docs/SUN_MOON.md, "The rule".
#pragma once

#include "conescan/crossings.hpp"
#include "conescan/ellipsoid_horizon.hpp"
#include "conescan/scan_model.hpp"

namespace conescan {

/// The angular radius asin(radius / distance) (rad) of a sphere of `radius` whose centre lies at
/// `distance` (same unit). Domain: finite, 0 < radius < distance; otherwise invalid.
/// Accuracy: one asin, a few ulp.
template <class T>
result<T> body_angular_radius(const T& radius, const T& distance) noexcept {
  using std::asin;
  if (!is_finite(radius) || !is_finite(distance) || !(radius > T(0)) || !(radius < distance))
    return result<T>::bad(status::invalid);
  return result<T>::good(asin(radius / distance));
}

/// The signed angle of a direction X from the scan cone, angle(A, X) - gamma (rad, in
/// [-gamma, pi - gamma]): > 0 outside the cone (away from A), < 0 inside. A and gamma are the
/// circle's (the true optical axis and cone: scan_circle_of the true optics, MODEL §4). X in
/// scan-frame components, any length > 0. Written as one atan2 of the difference's sine and
/// cosine (angle(A, X) from |A x X| and A.X), so that it keeps its digits where X lies on the
/// cone. Statuses: invalid for a circle that is not ok, or X zero or not finite.
/// Accuracy: 4.3e-16 rad at most in double against long double over 20 000 random heads and
/// directions (tests/scene/test_intrusion.cpp).
template <class T>
result<T> cone_offset(const scan_circle<T>& circle, const vec3<T>& x_scan) noexcept {
  using std::atan2;
  if (circle.state != status::ok || !is_finite(x_scan.x) || !is_finite(x_scan.y) ||
      !is_finite(x_scan.z))
    return result<T>::bad(status::invalid);
  const T along = dot(circle.axis, x_scan);
  const T across = norm(cross(circle.axis, x_scan));
  if (!(across > T(0)) && !(along != T(0))) return result<T>::bad(status::invalid);
  // sin and cos of angle(A, X) - gamma, times |X|.
  return result<T>::good(atan2(T(across * circle.cos_gamma - along * circle.sin_gamma),
                               T(along * circle.cos_gamma + across * circle.sin_gamma)));
}

/// A body's pulse on one head's scan: the scan azimuths within eps = fov/2 + r_X of it.
template <class T>
struct body_pulse {
  T azimuth;     ///< phi_X: scan azimuth about S (from e1) of the line of sight nearest X, rad
  T half_width;  ///< w_X = eps / sin gamma, rad (pi when X lies on A: every azimuth is as near)
  status state;  ///< ok, or invalid
};

/// The pulse of a body in direction X (scan-frame components, any length > 0) of angular radius
/// r_X, seen through a field of full width fov (rad; 0 a pencil beam), on the scan circle
/// (MODEL §13). The nearest line of sight is cos gamma A + sin gamma X_perp / |X_perp|, X_perp the
/// part of X normal to A; its azimuth about S is phi_X (atan2, in [-pi, pi]). Domain: circle ok,
/// X finite and not zero, r_X and fov finite and >= 0; otherwise invalid. Accuracy: phi_X to a
/// few ulp where |X_perp| is not small against |X| (X near A or -A: the azimuth is ill-posed, and
/// only a body on a cone of gamma <= eps could be there).
template <class T>
body_pulse<T> body_pulse_of(const scan_circle<T>& circle, const vec3<T>& x_scan,
                            const T& angular_radius, const T& fov) noexcept {
  using std::atan2;
  using std::sqrt;
  const T nan = not_a_number<T>();
  if (circle.state != status::ok || !is_finite(x_scan.x) || !is_finite(x_scan.y) ||
      !is_finite(x_scan.z) || !is_finite(angular_radius) || !is_finite(fov) ||
      !(angular_radius >= T(0)) || !(fov >= T(0)))
    return {nan, nan, status::invalid};
  const T reach = fov / T(2) + angular_radius;
  const T width = reach / circle.sin_gamma;
  const T half_width = width < pi<T>() ? width : pi<T>();
  const T along_u = dot(circle.u, x_scan), along_v = dot(circle.v, x_scan);
  const T across = sqrt(along_u * along_u + along_v * along_v);
  if (!(across > T(0))) {
    if (!(dot(circle.axis, x_scan) != T(0))) return {nan, nan, status::invalid};
    return {T(0), pi<T>(), status::ok};
  }
  const vec3<T> nearest = scan_circle_direction(circle, T(along_u / across), T(along_v / across));
  return {atan2(nearest.y, nearest.x), half_width, status::ok};
}

/// The Earth pulse as the field widens it, [phi_in - g, phi_out + g] with g = (fov/2) / sin gamma
/// (MODEL §13), by its centre (the phase) and half-width (half chord + g, at most pi). Domain:
/// crossings ok, circle ok, fov finite and >= 0; otherwise invalid.
template <class T>
body_pulse<T> earth_pulse_of(const crossings<T>& earth, const scan_circle<T>& circle,
                             const T& fov) noexcept {
  const T nan = not_a_number<T>();
  if (earth.state != status::ok || circle.state != status::ok || !is_finite(fov) || !(fov >= T(0)))
    return {nan, nan, status::invalid};
  const T width = earth.half_chord() + fov / T(2) / circle.sin_gamma;
  return {earth.phase(), width < pi<T>() ? width : pi<T>(), status::ok};
}

/// Whether two closed arcs of the scan circle meet, each by its centre and half-width (rad,
/// half-widths >= 0, centres any finite angle: any number of turns). They meet when the distance
/// of their centres on the circle, |wrap_pi(a - b)|, is at most the sum of the half-widths, or
/// when that sum reaches pi (together they cover the circle). Arcs that just touch meet. NaN
/// input: false (the callers check statuses first).
template <class T>
bool arcs_overlap(const T& centre_a, const T& half_width_a, const T& centre_b,
                  const T& half_width_b) noexcept {
  using std::abs;
  const T reach = half_width_a + half_width_b;
  if (reach >= pi<T>()) return true;
  return abs(wrap_pi(T(centre_a - centre_b))) <= reach;
}

/// Whether a body's centre is behind the horizon surface (MODEL §13: a hidden body's pulse is
/// none). On any state but ok, hidden is false.
struct body_visibility {
  bool hidden;
  status state;  ///< ok, or invalid
};

/// Whether a body's centre is hidden by a sphere of `radius` about the Earth's centre (MODEL §3's
/// sphere R + h_h): the line of sight from the satellite (satellite_from_centre, from the centre)
/// to the body (body_from_satellite, from the satellite; same frame and unit) passes strictly
/// inside the sphere in front of the satellite and enters it before the body. A line of sight
/// tangent to the sphere (the centre on the limb) is visible. The line's distance from the centre
/// is |p x d|, taken as (R - |p x d|)(R + |p x d|) against R (no cancellation at the limb).
/// `state` invalid unless all finite, radius > 0, the body not at the satellite and the
/// satellite outside the sphere. Accuracy: decided correctly 4096 eps from the limb (9e-13 rad in
/// double) on either side, in every scalar (tests/scene/test_intrusion.cpp).
template <class T>
body_visibility body_hidden_by_sphere(const vec3<T>& body_from_satellite,
                                      const vec3<T>& satellite_from_centre,
                                      const T& radius) noexcept {
  using std::sqrt;
  const T distance = norm(body_from_satellite);
  const T r = norm(satellite_from_centre);
  if (!is_finite(distance) || !is_finite(r) || !is_finite(radius) || !(radius > T(0)) ||
      !(distance > T(0)) || !(r > radius))
    return {false, status::invalid};
  const vec3<T> d = scaled(body_from_satellite, T(T(1) / distance));
  const T front = dot(d, satellite_from_centre);  // < 0: the sphere lies ahead
  // The squared distance of the line from the centre, |p x d|^2, without r^2 - front^2's
  // cancellation near the limb.
  const vec3<T> miss = cross(satellite_from_centre, d);
  const T inside = (radius - norm(miss)) * (radius + norm(miss));
  if (!(front < T(0)) || !(inside > T(0))) return {false, status::ok};
  const T entry = -front - sqrt(inside);  // the distance to where the line enters the sphere
  return {entry < distance, status::ok};
}

/// The same for the ellipsoid of MODEL §3, §5 as seen from the satellite (ellipsoid_horizon_of,
/// with the body direction in the same frame) and its equatorial semi-axis a_eq (m; the surface
/// holds positions in units of a_eq). The line of sight d hits it where a_eq^2 g =
/// (q.d)^2 - H (1 + kappa (z.d)^2) > 0 with q.d < 0 (tangent, g = 0: visible); it enters it at
/// the distance a_eq (-q.d - sqrt(a_eq^2 g)) / (1 + kappa (z.d)^2), which must lie before the
/// body. `state` invalid for a surface that is not ok, a_eq not finite and > 0, or the body
/// direction zero or not finite. Accuracy: decided correctly 1e-9 rad on either side of the
/// tangent line found by a long double bisection (tests/scene/test_intrusion.cpp); on a sphere
/// (a_eq = b_pol) it is body_hidden_by_sphere.
template <class T>
body_visibility body_hidden_by_ellipsoid(const ellipsoid_horizon<T>& surface, const T& a_eq,
                                         const vec3<T>& body_from_satellite) noexcept {
  using std::sqrt;
  const T distance = norm(body_from_satellite);
  if (surface.state != status::ok || !is_finite(a_eq) || !(a_eq > T(0)) || !is_finite(distance) ||
      !(distance > T(0)))
    return {false, status::invalid};
  const vec3<T> d = scaled(body_from_satellite, T(T(1) / distance));
  const T front = dot(surface.q, d);
  const T along = dot(surface.polar, d);
  const T stretch = T(1) + surface.kappa * along * along;
  const T tangency = front * front - surface.height * stretch;
  if (!(front < T(0)) || !(tangency > T(0))) return {false, status::ok};
  const T entry = a_eq * (-front - sqrt(tangency)) / stretch;
  return {entry < distance, status::ok};
}

/// One body against one head: its signed angle from the cone (the scene's hK_sun_deg and
/// hK_moon_deg, in rad) and whether it is on the cone and its pulse meets the Earth pulse.
template <class T>
struct body_intrusion {
  T cone_offset;           ///< angle(A, X) - gamma, rad (cone_offset)
  bool on_cone;            ///< |cone_offset| <= fov/2 + r_X
  bool meets_earth_pulse;  ///< on the cone and its pulse meets the widened Earth pulse
  status state;            ///< ok, or invalid (then cone_offset is NaN and both flags false)
};

/// cone_offset, then for a body on the cone its pulse (body_pulse_of) against the Earth pulse
/// (earth_pulse_of) by arcs_overlap. Crossings that are not ok have no Earth pulse:
/// meets_earth_pulse is then false (intrusion_status keeps their status). Statuses: invalid for
/// an invalid circle, X, r_X or fov (body_pulse_of's domain). The pulse is only computed for a
/// body on the cone: the offset alone costs one atan2.
template <class T>
body_intrusion<T> body_intrusion_of(const scan_circle<T>& circle, const crossings<T>& earth,
                                    const vec3<T>& x_scan, const T& angular_radius,
                                    const T& fov) noexcept {
  using std::abs;
  const body_intrusion<T> invalid{not_a_number<T>(), false, false, status::invalid};
  if (!is_finite(angular_radius) || !is_finite(fov) || !(angular_radius >= T(0)) || !(fov >= T(0)))
    return invalid;
  const result<T> offset = cone_offset(circle, x_scan);
  if (!offset.ok()) return invalid;
  const bool on_cone = abs(offset.value) <= fov / T(2) + angular_radius;
  if (!on_cone || earth.state != status::ok) return {offset.value, on_cone, false, status::ok};
  const body_pulse<T> body = body_pulse_of(circle, x_scan, angular_radius, fov);
  const body_pulse<T> planet = earth_pulse_of(earth, circle, fov);
  if (body.state != status::ok || planet.state != status::ok) return invalid;
  return {offset.value, true,
          arcs_overlap(body.azimuth, body.half_width, planet.azimuth, planet.half_width),
          status::ok};
}

/// A head's verdict (MODEL §13): the crossings' own status when it is not ok (a head that misses
/// the Earth has no Earth pulse to corrupt; a body's pulse in space is rejected by its width);
/// invalid when a body's state is; sun when the Sun is visible and meets the Earth pulse; else
/// moon when the Moon does; else ok. The Sun is decided first: where both meet the Earth pulse
/// (an eclipse season's rows), the Sun, 16 to 65 times the Earth's radiance, is the one that
/// corrupts the crossings whatever the Moon does. `sun_hidden`, `moon_hidden`: body_hidden_by_*
/// of each body's centre (computed once per row, for all heads).
template <class T>
status intrusion_status(const crossings<T>& earth, const body_intrusion<T>& sun, bool sun_hidden,
                        const body_intrusion<T>& moon, bool moon_hidden) noexcept {
  if (earth.state != status::ok) return earth.state;
  if (sun.state != status::ok || moon.state != status::ok) return status::invalid;
  if (sun.meets_earth_pulse && !sun_hidden) return status::sun;
  if (moon.meets_earth_pulse && !moon_hidden) return status::moon;
  return status::ok;
}

}  // namespace conescan
