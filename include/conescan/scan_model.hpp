// The exact forward model (SPEC §5, "scan") in closed form: the lines of sight of a misaligned
// head lie on a circle about the optical axis A, so on a sphere the crossings are the two
// intersections of that circle with the horizon circle. The bracketed solver on the scan
// azimuth (scan_model_iterative.hpp) is the tests' oracle.
#pragma once

#include "conescan/cone_angle.hpp"
#include "conescan/crossings.hpp"
#include "conescan/earth_disk.hpp"
#include "conescan/ellipsoid_horizon.hpp"
#include "conescan/half_chord.hpp"
#include "conescan/scan_frame.hpp"
#include "conescan/scan_model_iterative.hpp"

namespace conescan {

/// The scan circle of one head (SPEC §4): every true line of sight d makes the angle gamma with
/// the optical axis A, d(theta) = cos gamma A + sin gamma (cos theta u + sin theta v). Components
/// in the head's scan frame (e1, e2, e3 = S). u points from A away from S in the plane of S and A
/// (at phi_A; for sigma = 0, u = e1 rotated by phi_A), v = A x u, so theta grows with the scan
/// azimuth phi (A lies within sigma < gamma of S, inside the circle) and theta = phi - phi_A
/// when sigma = 0. Depends on the optics only: built once per head.
template <class T>
struct scan_circle {
  vec3<T> axis;  ///< A, unit
  vec3<T> u;     ///< unit, normal to A, towards phi_A
  vec3<T> v;     ///< A x u
  T cos_gamma;
  T sin_gamma;
  T versine_gamma;  ///< 1 - cos gamma, without cancellation (tiny cones)
  status state;     ///< ok, or invalid for optics outside cone_in_domain or a non-finite phi_A
};

/// The circle of `optics` (rad): A = (sin sigma cos phi_A, sin sigma sin phi_A, cos sigma),
/// u = (cos sigma cos phi_A, cos sigma sin phi_A, -sin sigma), v = (-sin phi_A, cos phi_A, 0).
template <class T>
scan_circle<T> scan_circle_of(const head_optics<T>& optics) noexcept {
  using std::cos;
  using std::sin;
  if (!cone_in_domain(optics.gamma, optics.sigma) || !is_finite(optics.phi_a)) {
    const T nan = not_a_number<T>();
    return {vec3<T>(nan), vec3<T>(nan), vec3<T>(nan), nan, nan, nan, status::invalid};
  }
  const T cos_sigma = cos(optics.sigma), sin_sigma = sin(optics.sigma);
  const T cos_phi_a = cos(optics.phi_a), sin_phi_a = sin(optics.phi_a);
  const T cos_gamma = cos(optics.gamma), sin_gamma = sin(optics.gamma);
  return {vec3<T>(sin_sigma * cos_phi_a, sin_sigma * sin_phi_a, cos_sigma),
          vec3<T>(cos_sigma * cos_phi_a, cos_sigma * sin_phi_a, T(-sin_sigma)),
          vec3<T>(T(-sin_phi_a), cos_phi_a, T(0)),
          cos_gamma,
          sin_gamma,
          T(sin_gamma * sin_gamma / (T(1) + cos_gamma)),
          status::ok};
}

/// The line of sight at theta on the circle, given (cos theta, sin theta): scan-frame components.
template <class T>
vec3<T> scan_circle_direction(const scan_circle<T>& circle, const T& cos_theta,
                              const T& sin_theta) noexcept {
  return scaled(circle.axis, circle.cos_gamma) +
         scaled(scaled(circle.u, cos_theta) + scaled(circle.v, sin_theta), circle.sin_gamma);
}

/// Where the scan circle meets the horizon circle of a sphere: the lines of sight at angle rho
/// from the true nadir n. Directions not normalised (|d| = sin^2 delta, delta the angle from A to
/// n); only their azimuths are wanted.
template <class T>
struct circle_crossings {
  vec3<T> earth_in;   ///< where d.n rises through cos rho as theta grows
  vec3<T> earth_out;  ///< where it falls through cos rho
  status state;       ///< ok, miss, engulfed, invalid (non-finite input)
};

/// The two intersections of the circles d.A = cos gamma and d.n = cos rho on the unit sphere
/// (SPEC §5). With c = A.n = cos delta and w = A x n (|w| = sin delta),
///   d sin^2 delta = (cos gamma - c cos rho) A + (cos rho - c cos gamma) n -+ sqrt(D) w,
///   D = (sin delta sin gamma)^2 - (cos rho - c cos gamma)^2
///     = (cos(delta - gamma) - cos rho) (cos rho - cos(delta + gamma)),
/// the '-' root Earth-in (d/dtheta (d.n) = -d.w > 0 there). The factors decide the statuses
/// exactly as the half-angle form of Eq. (3) does: the nearest line of sight (delta - gamma from
/// n) off the disk is miss, the farthest (delta + gamma) on it engulfed.
/// Written against cancellation: sin delta from n's components across A (not 1 - c^2); every
/// cosine as 1 - versine, v = 1 - cos = sin^2 / (1 + cos), so that
///   cos rho - c cos gamma = v_gamma + v_delta - v_rho - v_delta v_gamma (and its mirror),
/// keeps its digits for small angles (a cone and a disk of 1e-8 rad: cosines of 1 - 1e-16 would
/// leave nothing); and the first two terms regrouped as
///   (cos gamma - c cos rho)(A - n) + (cos gamma + cos rho) v_delta n,
/// because near-concentric circles (n close to A) make both terms O(delta) and their sum
/// O(delta^2): as written in the first line it would lose 1 / delta more digits than the
/// geometry's own conditioning.
///   nadir: unit true nadir, scan-frame components; disk: the sine and cosine of its radius rho.
template <class T>
circle_crossings<T> scan_circle_meets_disk(const scan_circle<T>& circle, const vec3<T>& nadir,
                                           const disk_trig<T>& disk) noexcept {
  using std::sqrt;
  const T nan = not_a_number<T>();
  const T c = dot(circle.axis, nadir);
  const T across_u = dot(circle.u, nadir), across_v = dot(circle.v, nadir);
  const T sin_delta_squared = across_u * across_u + across_v * across_v;
  const T versine_delta = c >= T(0) ? T(sin_delta_squared / (T(1) + c)) : T(T(1) - c);
  const T versine_rho = disk.sin_rho * disk.sin_rho / (T(1) + disk.cos_rho);
  const T& versine_gamma = circle.versine_gamma;
  const T reach = sqrt(sin_delta_squared) * circle.sin_gamma;
  // cos rho - c cos gamma and cos gamma - c cos rho.
  const T towards_n = versine_gamma + versine_delta - versine_rho - versine_delta * versine_gamma;
  const T towards_a = versine_rho + versine_delta - versine_gamma - versine_delta * versine_rho;
  const T near_gap = reach - towards_n;  // cos(delta - gamma) - cos rho
  const T far_gap = reach + towards_n;   // cos rho - cos(delta + gamma)
  if (!is_finite(near_gap) || !is_finite(far_gap))
    return {vec3<T>(nan), vec3<T>(nan), status::invalid};
  if (!(near_gap > T(0))) return {vec3<T>(nan), vec3<T>(nan), status::miss};
  if (!(far_gap > T(0))) return {vec3<T>(nan), vec3<T>(nan), status::engulfed};
  const T root = sqrt(near_gap * far_gap);
  const vec3<T> middle = scaled(circle.axis - nadir, towards_a) +
                         scaled(nadir, T((circle.cos_gamma + disk.cos_rho) * versine_delta));
  const vec3<T> across = scaled(cross(circle.axis, nadir), root);
  return {middle - across, middle + across, status::ok};
}

/// Crossings from the raw azimuths of the Earth-in and Earth-out lines of sight (any branch):
/// phi_in is kept, phi_out = phi_in + W with the chord W in (0, 2 pi]. Status grazing for a half
/// chord within grazing_half_chord_min() of 0 or pi (classify_half_chord).
template <class T>
crossings<T> crossings_from_azimuths(const T& phi_in, const T& phi_out, int iterations) noexcept {
  T chord = phi_out - phi_in;
  if (!(chord > T(0))) chord += T(2) * pi<T>();
  const status s = classify_half_chord(T(chord / T(2)));
  if (s != status::ok) return crossings<T>::failed(s);
  return {phi_in, T(phi_in + chord), status::ok, iterations};
}

/// Scan model on a sphere in closed form (SPEC §5): the circle's intersections with the horizon
/// circle of angular radius rho (`disk`) about the unit true nadir (scan-frame components), at
/// their azimuths about S (two atan2). phi_in is in [-pi, pi], phi_out = phi_in + W. Statuses:
/// miss, engulfed (scan_circle_meets_disk), grazing (crossings_from_azimuths), invalid (circle not
/// ok, non-finite input). `iterations` is 0. Accuracy (double, against cpp_bin_float_50 through the
/// whole head, docs/ACCURACY.md): that of the geometry, a few ulp divided by the sine of the angle
/// at which the circles cross; against scan_model_crossings_sphere_iterative within 1e-13 rad
/// (tests/test_scan_model.cpp).
template <class T>
crossings<T> scan_model_crossings_sphere(const scan_circle<T>& circle, const vec3<T>& nadir,
                                         const disk_trig<T>& disk) noexcept {
  using std::atan2;
  if (circle.state != status::ok || disk.state != status::ok)
    return crossings<T>::failed(status::invalid);
  const circle_crossings<T> x = scan_circle_meets_disk(circle, nadir, disk);
  if (x.state != status::ok) return crossings<T>::failed(x.state);
  return crossings_from_azimuths(T(atan2(x.earth_in.y, x.earth_in.x)),
                                 T(atan2(x.earth_out.y, x.earth_out.x)), 0);
}

/// Scan model on a sphere from the angles of the true nadir: eta from S and azimuth phi_n about S
/// (rad), disk radius rho (rad). The crossings are placed about phi_n: their phase lies within pi
/// of it (of phi_n reduced to (-pi, pi] when |phi_n| > 2 pi, whose whole turns would eat the
/// azimuths' digits). Domain: cone_in_domain, finite phi_A and phi_n, and
/// disk_geometry_in_domain(gamma, eta, rho); otherwise invalid. Statuses and accuracy: those of
/// the closed form above.
template <class T>
crossings<T> scan_model_crossings_sphere(const head_optics<T>& optics, const T& eta, const T& phi_n,
                                         const T& rho) noexcept {
  using std::abs;
  using std::cos;
  using std::sin;
  if (!cone_in_domain(optics.gamma, optics.sigma) || !is_finite(optics.phi_a) ||
      !is_finite(phi_n) || !disk_geometry_in_domain(optics.gamma, eta, rho))
    return crossings<T>::failed(status::invalid);
  const T centre = abs(phi_n) <= T(2) * pi<T>() ? phi_n : wrap_pi(phi_n);
  const T sin_eta = sin(eta);
  const vec3<T> nadir(sin_eta * cos(centre), sin_eta * sin(centre), cos(eta));
  crossings<T> c =
      scan_model_crossings_sphere(scan_circle_of(optics), nadir, disk_trig_of_angle(rho));
  if (c.state != status::ok) return c;
  const T offset = c.phase() - centre;
  const T turns = wrap_pi(offset) - offset;  // a whole number of turns, 0 mostly
  c.phi_in += turns;
  c.phi_out += turns;
  return c;
}

/// Scan model on an ellipsoid of revolution (SPEC §3, §5): for now the bracketed solver on the
/// scan azimuth (scan_model_crossings_ellipsoid_iterative), with the head's scan frame and the
/// satellite position in ECI (m, from the ellipsoid's centre), semi-axes a_eq, b_pol (m).
template <class T>
crossings<T> scan_model_crossings_ellipsoid(const head_optics<T>& optics,
                                            const scan_frame<T>& frame_eci, const vec3<T>& p_eci,
                                            const T& a_eq, const T& b_pol) noexcept {
  return scan_model_crossings_ellipsoid_iterative(optics, frame_eci, p_eci, a_eq, b_pol);
}

}  // namespace conescan
