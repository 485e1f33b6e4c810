// The 14-16 um CO2 limb radiance as a function of the tangent height (MODEL §12, "Radiance"):
//   L(delta) = L0 [1 - exp(-ln 2 e^{-(delta - delta50)/H})],  L(-inf) = L_disk L0,
//   L0 = 1 + A sin(phi_t) sin(delta_sun) / sin 23.44 deg,
// in relative units (the plateau of a scene without the season term is 1).
//
// The shape l(delta) = L / L0 is the survival function of a Gumbel distribution in
// x = (delta - delta50) / H: l = 1 - exp(-v), v = ln 2 e^{-x}. So l(delta50) = 1/2 for every H,
// the steepest point (the Gumbel mode) is at v = 1, x = ln ln 2 = -0.36651, where l = 1 - 1/e,
// and the 10-90 % width is ln(ln 10 / ln(10/9)) H = 3.0844 H.
#pragma once

#include <cmath>
#include <limits>

#include "conescan/scalar_expm1.hpp"
#include "conescan/status.hpp"

namespace conescan {

/// The profile's parameters and the constants derived from them once (radiance_profile_of).
template <class T>
struct radiance_profile {
  T scale_m;        ///< H >= 0 (m); 0 is the step edge (l = 1 below delta50, 0 above)
  T offset_m;       ///< delta50 (m), the height of the 50 % point
  T disk;           ///< L_disk / L0, the radiance of a line that meets the surface
  T ln2;            ///< ln 2 in T
  T inverse_scale;  ///< 1 / H (0 for the step)
  T x_saturated;    ///< below this x, l = 1 to rounding: ln(ln 2 / ln(2 / eps))
  status state;     ///< ok, or invalid (H < 0, a subnormal H, a non-finite parameter, disk < 0)
};

template <class T>
radiance_profile<T> radiance_profile_of(const T& scale_m, const T& offset_m,
                                        const T& disk) noexcept {
  using std::log;
  const T nan = not_a_number<T>();
  radiance_profile<T> p{scale_m, offset_m, disk, T(log(T(2))), nan, nan, status::invalid};
  if (!is_finite(scale_m) || !is_finite(offset_m) || !is_finite(disk) || !(scale_m >= T(0)) ||
      !(disk >= T(0)))
    return p;
  p.inverse_scale = scale_m > T(0) ? T(T(1) / scale_m) : T(0);
  // A subnormal H has no finite reciprocal: every height it scales would overflow (a crash of
  // the chain's piece bookkeeping before this check).
  if (!is_finite(p.inverse_scale)) return p;
  // exp(-v) < eps / 2 rounds 1 - exp(-v) to 1: v > ln(2 / eps).
  const T eps = std::numeric_limits<T>::epsilon();
  p.x_saturated = log(p.ln2 / T(log(T(2) / eps)));
  p.state = status::ok;
  return p;
}

/// l(delta) = L / L0 above the surface and its first three derivatives in delta (per m^k).
template <class T>
struct limb_fraction_derivatives {
  T value;
  T first;
  T second;
  T third;
};

/// l = 1 - exp(-v), v = ln 2 e^{-x}, x = (delta - delta50) / H, written as -expm1_of(-v) so that
/// the tail far above the knee (l ~ v ~ 1e-300) keeps its relative digits, and returned as exactly
/// 1 below x_saturated, before e^{-x} can overflow: the form saturates cleanly for every scalar.
/// The step (H = 0) returns 1, 1/2, 0 below, at and above delta50 (its derivatives 0).
/// Derivatives in x (dv/dx = -v): l' = -v e^{-v}, l'' = v e^{-v}(1 - v),
/// l''' = v e^{-v}(-1 + 3 v - v^2); divided by H^k for delta. Accuracy: a few ulp (expm1, exp).
template <class T>
limb_fraction_derivatives<T> limb_fraction_with_derivatives(const radiance_profile<T>& p,
                                                            const T& height_m) noexcept {
  using std::exp;
  if (p.scale_m == T(0)) {
    const T value = height_m < p.offset_m ? T(1) : height_m > p.offset_m ? T(0) : T(1) / T(2);
    return {value, T(0), T(0), T(0)};
  }
  const T x = (height_m - p.offset_m) * p.inverse_scale;
  if (x < p.x_saturated) return {T(1), T(0), T(0), T(0)};
  const T v = p.ln2 * exp(-x);
  const T e = exp(-v);
  const T k = p.inverse_scale;
  const T ve = v * e;
  return {T(-expm1_of(-v)), T(-ve * k), T(ve * (T(1) - v) * k * k),
          T(ve * (T(-1) + v * (T(3) - v)) * k * k * k)};
}

/// l(delta) alone (see limb_fraction_with_derivatives), the hot path of the field quadrature.
template <class T>
T limb_fraction(const radiance_profile<T>& p, const T& height_m) noexcept {
  using std::exp;
  if (p.scale_m == T(0))
    return height_m < p.offset_m ? T(1) : height_m > p.offset_m ? T(0) : T(1) / T(2);
  const T x = (height_m - p.offset_m) * p.inverse_scale;
  if (x < p.x_saturated) return T(1);
  return -expm1_of(-p.ln2 * exp(-x));
}

/// The season factor L0 = 1 + A sin(phi_t) sin(delta_sun) / sin 23.44 deg (MODEL §12): the
/// summer hemisphere (phi_t and delta_sun of one sign) is brighter. sin 23.44 deg is built from
/// the exact decimal 23.44. A = 0 gives exactly 1.
template <class T>
T season_factor(const T& amplitude, const T& sin_latitude, const T& sin_sun_declination) noexcept {
  using std::sin;
  if (amplitude == T(0)) return T(1);
  const T sin_obliquity = sin(T(2344) / T(100) * (pi<T>() / T(180)));
  return T(1) + amplitude * sin_latitude * sin_sun_declination / sin_obliquity;
}

/// The radiance L of a line of sight with signed tangent height delta (sensor_physics/height.hpp):
/// L0 l(delta) above the surface (delta >= 0), L_disk L0 on a line that meets it (delta < 0).
template <class T>
T radiance(const radiance_profile<T>& p, const T& plateau, const T& height_m) noexcept {
  return height_m < T(0) ? T(plateau * p.disk) : T(plateau * limb_fraction(p, height_m));
}

/// The height at which a pencil beam without lag passes a fixed threshold `fraction` = T/L0 in
/// (0, 1) (MODEL §12): delta50 + H ln(ln 2 / -ln(1 - T/L0)), written with log1p. NaN outside
/// (0, 1). (On the profile; a threshold the sky side never reaches is met at the surface.)
template <class T>
T fixed_threshold_height(const radiance_profile<T>& p, const T& fraction) noexcept {
  using std::log;
  if (!(fraction > T(0)) || !(fraction < T(1))) return not_a_number<T>();
  return p.offset_m + p.scale_m * log(p.ln2 / T(-log1p_of(-fraction)));
}

/// The height of the profile's steepest point, delta50 + H ln ln 2 = delta50 - 0.36651 H, where
/// l = 1 - 1/e (MODEL §12: the slope locator on a uniform sweep of delta).
template <class T>
T steepest_height(const radiance_profile<T>& p) noexcept {
  using std::log;
  return p.offset_m + p.scale_m * log(p.ln2);
}

}  // namespace conescan
