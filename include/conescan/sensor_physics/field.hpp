// The detector's field of view (MODEL §12, "Field of view"): the signal s(phi) is the mean of the
// radiance over the field about the line of sight. The field is rigid about the true line of
// sight d (docs/SENSOR_PHYSICS.md, "The field"): at scan azimuth phi the patch of directions
// exp_d(x t + y c), t along the scan, c across it, (x, y) in the square |x|, |y| <= fov/2 or the
// disc of radius fov/2, the mean taken with a uniform weight in (x, y). field_mean.hpp computes
// the patch's mean; this file holds:
//  - field_of_view: the field's full width and shape (fov = 0 is a pencil beam);
//  - field_half_along and patch_half_along: its extent along the scan in scan azimuth, for the
//    row's check that the pulse is wider than the field and for the windows' margins;
//  - straight_limb_field_mean: the mean for a straight limb (the height a linear function of the
//    field's offsets), as a 1-D quadrature over the height offset with the field's exact weight:
//    a trapezoid for the square, a semicircle (the chord length sqrt(1 - x^2)) for the circle. It
//    shows the field's effect in closed form (a symmetric field on a straight step moves
//    nothing; the 50 % point moves up by at most 0.2107 H) and is checked against a dense 2-D
//    quadrature.
#pragma once

#include <cmath>

#include "conescan/gauss_panels.hpp"
#include "conescan/scan_model.hpp"
#include "conescan/sensor_physics/profile.hpp"
#include "conescan/small_sort.hpp"
#include "conescan/status.hpp"

namespace conescan {

enum class field_shape : unsigned char { square, circle };

/// The narrowest field the chain computes, 0.001 deg of full width (degrees; a pencil, fov = 0,
/// aside): the field's line is cut in cells of the larger of H and an eighth of the patch's
/// heights' span across the scan, so that a field far narrower than H's kilometres of height
/// costs cells as 1/fov (a 1e-4 deg field on H = 1 m took 8 s a row, one of 1e-7 deg never
/// finished), while a real field is a degree or so (docs/SENSOR_PHYSICS.md, decision 17).
template <class T>
T narrowest_field_deg() noexcept {
  return T(1) / T(1000);
}

/// The field's full width (rad) and shape. fov = 0 is a pencil beam.
template <class T>
struct field_of_view {
  T fov_rad;
  field_shape shape;
};

/// The field's along-scan half-width at its centre in scan azimuth (rad), (fov/2) / sin gamma for
/// both shapes: the row's check that the pulse is wider than the field (`grazing`).
template <class T>
T field_half_along(const field_of_view<T>& field, const T& sin_gamma) noexcept {
  return field.fov_rad / T(2) / sin_gamma;
}

/// The rigid patch's half extent along the scan in scan azimuth (rad): its corners nearest the
/// optical axis lie on the cone gamma - fov/2 about it, where fov/2 of arc spans (fov/2) /
/// sin(gamma - fov/2) of azimuth; a tenth more for the misalignment's change of the azimuth's
/// rate along the scan. The windows' margin only (field_mean.hpp integrates the exact patch).
template <class T>
T patch_half_along(const field_of_view<T>& field, const scan_circle<T>& circle) noexcept {
  using std::atan2;
  using std::sin;
  const T half = field.fov_rad / T(2);
  if (!(half > T(0))) return T(0);
  const T gamma = atan2(circle.sin_gamma, circle.cos_gamma);
  const T inner = gamma - half > T(1) / T(100) ? T(gamma - half) : T(T(1) / T(100));
  return T(11) / T(10) * half / sin(inner);
}

/// The mean radiance over the field for a straight limb: the height at the field offsets
/// (x along the scan, y across, rad) is centre_m + along_m_per_rad x + across_m_per_rad y, and the
/// radiance is that of sensor_physics/profile.hpp (L_disk L0 below the surface, a jump at height
/// 0). One-dimensional quadrature over the height offset u with the field's exact density of u: for
/// the square the convolution of two boxes of half-widths p = |g_x| fov/2 and q = |g_y| fov/2 (a
/// trapezoid), for the circle a semicircle of radius |g| fov/2 (written u = r sin theta, density
/// (2/pi) cos^2 theta d theta, so that the chord's square root leaves no singularity). Panels
/// break at the density's kinks (+-(p+q), +-|p-q|), at the surface's jump (u = -centre) and at the
/// knee (every H around delta50), each with a 16-point Gauss rule. Exact for the step (H = 0, area
/// fractions). Accuracy: 1e-14 of L0 for H >= fov |g| / 200
/// (tests/core/test_sensor_physics_field.cpp, against a 2-D tensor quadrature).
template <class T>
T straight_limb_field_mean(const radiance_profile<T>& profile, const T& plateau, const T& centre_m,
                           const T& along_m_per_rad, const T& across_m_per_rad,
                           const field_of_view<T>& field) noexcept;

namespace field_detail {

/// Sorted breakpoints of the radiance in the height offset u within [lo, hi]: the surface jump
/// and the knee (delta50 + H x for x in -8 .. 6 every unit, 10 .. 40 every 4 in the tail).
template <class T>
int radiance_breakpoints(const radiance_profile<T>& profile, const T& centre_m, const T& lo,
                         const T& hi, T* out, int capacity) noexcept {
  int n = 0;
  auto add = [&](const T& u) {
    if (u > lo && u < hi && n < capacity) out[n++] = u;
  };
  add(T(-centre_m));
  if (profile.scale_m > T(0)) {
    // Panels of one H where the profile bends; wider (4 H) in its exponential tail.
    for (int x = -8; x <= 6; ++x) add(T(profile.offset_m + T(x) * profile.scale_m - centre_m));
    for (int x = 10; x <= 40; x += 4) add(T(profile.offset_m + T(x) * profile.scale_m - centre_m));
  } else {
    add(T(profile.offset_m - centre_m));
  }
  sort_ascending(out, n);
  return n;
}

/// The square field's mean over its trapezoid density of u (p, q: |g_x|, |g_y| times fov/2).
template <class T>
T square_field_mean(const radiance_profile<T>& profile, const T& plateau, const T& centre_m,
                    const T& p, const T& q, const gauss_legendre_rule<T, 16>& rule) noexcept {
  using std::abs;
  auto radiance_at = [&](const T& u) { return radiance(profile, plateau, T(centre_m + u)); };
  T cuts[64];
  const T outer = p + q, inner = abs(p - q), longer = p > q ? p : q;
  if (!(outer > T(0))) return radiance_at(T(0));
  // Density of u (integrating to 1): (outer - |u|) / (4 p q) outside |u| < inner, 1 / (2
  // longer) inside; for a degenerate box (p or q zero) the uniform 1 / (2 outer).
  auto density = [&](const T& u) {
    if (!(p > T(0)) || !(q > T(0))) return T(T(1) / (T(2) * outer));
    const T a = abs(u);
    return a <= inner ? T(T(1) / (T(2) * longer)) : T((outer - a) / (T(4) * p * q));
  };
  int n = 0;
  cuts[n++] = -outer;
  if (inner > T(0) && inner < outer) cuts[n++] = -inner;
  if (inner > T(0) && inner < outer) cuts[n++] = inner;
  n += radiance_breakpoints(profile, centre_m, T(-outer), outer, cuts + n, 60 - n);
  cuts[n++] = outer;
  sort_ascending(cuts, n);
  return gauss_integral_over_cuts(rule, cuts, n,
                                  [&](const T& u) { return T(density(u) * radiance_at(u)); });
}

/// The circular field's mean (straight_limb_field_mean) over u = r sin theta, r = |g| fov/2.
template <class T>
T circle_field_mean(const radiance_profile<T>& profile, const T& plateau, const T& centre_m,
                    const T& r, const gauss_legendre_rule<T, 16>& rule) noexcept {
  using std::asin;
  using std::cos;
  using std::sin;
  auto radiance_at = [&](const T& u) { return radiance(profile, plateau, T(centre_m + u)); };
  if (!(r > T(0))) return radiance_at(T(0));
  T cuts[64];
  int n = 0;
  cuts[n++] = -pi<T>() / T(2);
  T heights[60];
  const int m = radiance_breakpoints(profile, centre_m, T(-r), r, heights, 58);
  for (int i = 0; i < m; ++i) cuts[n++] = asin(heights[i] / r);
  cuts[n++] = pi<T>() / T(2);
  return gauss_integral_over_cuts(rule, cuts, n, [&](const T& theta) {
    const T c = cos(theta);
    return T((T(2) / pi<T>()) * c * c * radiance_at(T(r * sin(theta))));
  });
}

}  // namespace field_detail

template <class T>
T straight_limb_field_mean(const radiance_profile<T>& profile, const T& plateau, const T& centre_m,
                           const T& along_m_per_rad, const T& across_m_per_rad,
                           const field_of_view<T>& field) noexcept {
  using std::abs;
  using std::sqrt;
  auto radiance_at = [&](const T& u) { return radiance(profile, plateau, T(centre_m + u)); };
  const T half = field.fov_rad / T(2);
  if (!(half > T(0))) return radiance_at(T(0));
  // Made at each call (no function-local static: a flight build has no thread-safe guard).
  const gauss_legendre_rule<T, 16> rule = gauss_legendre_rule_of<T, 16>();
  if (field.shape == field_shape::square)
    return field_detail::square_field_mean(profile, plateau, centre_m,
                                           T(abs(along_m_per_rad) * half),
                                           T(abs(across_m_per_rad) * half), rule);
  // Circle: u = r sin theta, theta in [-pi/2, pi/2], density (2 / pi) cos^2 theta d theta.
  const T r = sqrt(along_m_per_rad * along_m_per_rad + across_m_per_rad * across_m_per_rad) * half;
  return field_detail::circle_field_mean(profile, plateau, centre_m, r, rule);
}

}  // namespace conescan
