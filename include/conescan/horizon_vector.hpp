// Horizon-vector processing: the nadir fitted to every measured horizon crossing at once, as an
// alternative to MODEL §6's chord/phase inversion per head followed by the mean of the heads.
//
// Each measured crossing azimuth phi_i of a head, read on the nominal cone (half-angle gamma, no
// knowledge of any misalignment: what the electronics assume), is a horizon direction in body axes
//   h_i = cos gamma e3 + sin gamma (cos phi_i e1 + sin phi_i e2)          (MODEL §4, §6)
// and the nadir n of the assumed spherical Earth (angular radius rho_p, MODEL §6) is the unit
// vector with n . h_i = cos rho_p for every crossing, fitted by Gauss-Newton on the unit sphere.
// With exactly two crossings (one head) the fit is exact and has the chord inversion's two roots,
// mirror images about the plane of h_1 and h_2: the initial guess selects one, and seeded from the
// per-head solution (process_head) the fit returns exactly it. With more crossings it weights the
// heads by geometry and keeps a head near its fold that the mean must drop; with biased crossings
// the two methods differ by the order of the biases. When each is better, and the measured
// accuracy: docs/CLI.md, "Horizon-vector processing", and docs/ACCURACY.md.
#pragma once

#include <cstddef>

#include "conescan/crossings.hpp"
#include "conescan/scan_frame.hpp"
#include "conescan/status.hpp"
#include "conescan/vector.hpp"

namespace conescan {

/// Largest geometry condition figure (see horizon_nadir_fit::condition) accepted before a fit is
/// called a fold: 1000.
///
/// Why 1000 and not the 30 of fold_amplification_max(): the condition figure measures how
/// unequally the crossings' *residuals* n . h_i - cos rho_p pin the two tangent directions of n;
/// the chord inversion's amplification measures eta's sensitivity to the *chord*. For one head the
/// two are related by condition ~= amplification x sin rho / (sin gamma sin eta sin Phi), and
/// this factor was measured at 1.1 to 2.6 near real folds (a scan over gamma in 30..60 deg and
/// rho in 10..75 deg made when choosing the value; ~1.5 in
/// tests/simulation/test_horizon_vector.cpp's walk up to a fold at gamma 45 deg, rho 20 deg): at
/// 1000 the fit calls a fold where the chord inversion's amplification passes ~400 to ~900, later
/// than process_head (30): with one head the fit accepts a narrow band beside the fold that
/// process_head refuses. The factor is large where the residuals are insensitive to the crossings:
/// near grazing (the condition reaches 200 to 1100 at MODEL §7's grazing half chord of 0.1 deg,
/// where the chord inversion is still ok) and when eta -> 0 with gamma ~ rho (both crossings
/// opposite each other about n). A threshold of 100 would refuse chords up to a half chord of ~1
/// deg that the per-head method accepts; 1000 puts the fit's refusal next to MODEL §7's grazing
/// boundary. Rounding: the fit's rounding error is ~eps x
/// condition, so at 1000 double keeps ~13 digits and float ~4 (1e-4 rad), which is why a larger
/// value such as 1e6 (float: 0.1 rad of pure rounding) is not used. The same value for every scalar
/// type, as the threshold is about the measurement, not the arithmetic.
template <class T>
T horizon_condition_max() noexcept {
  return T(1000);
}

/// Largest number of Gauss-Newton steps of nadir_from_horizon_vectors. From a seed within a few
/// degrees the fit converges quadratically in 3 to 5 steps when the crossings are consistent, and
/// linearly (rate ~ cos rho_p |sum r_i| / lambda_min) when they are not; 50 steps bound the time.
constexpr int horizon_fit_max_iterations = 50;

/// The nadir fitted to a set of horizon vectors. For a scalar whose vec3 GLM cannot copy
/// (Boost.Multiprecision without GLM_FORCE_XYZW_ONLY; see detail::assign) it can be received
/// (`const horizon_nadir_fit<T> fit = nadir_from_horizon_vectors(...)`) but not copied.
template <class T>
struct [[nodiscard]] horizon_nadir_fit {
  vec3<T> nadir;   ///< fitted nadir n, unit, same axes as the horizon vectors (body); NaN unless ok
  T condition;     ///< sqrt(cond(J^T J)) at the solution: 1 is ideal, +inf when the crossings do
                   ///< not determine n; NaN for invalid inputs
  int iterations;  ///< Gauss-Newton steps taken
  status state;    ///< ok, invalid or fold

  bool ok() const noexcept { return state == status::ok; }

  /// A failed fit: NaN nadir, with the condition and steps reported for diagnosis.
  static horizon_nadir_fit failed(status s, const T& condition, int iterations) noexcept {
    return {vec3<T>(not_a_number<T>()), condition, iterations, s};
  }
};

namespace detail {

/// to = from, one component at a time. GLM's vec3 keeps x, y, z in anonymous unions, which
/// delete its copy constructor and copy assignment for a scalar with non-trivial special members
/// (Boost.Multiprecision) unless GLM_FORCE_XYZW_ONLY is defined; assigning the scalars works for
/// any T, so this file never copies or assigns a whole vec3 (same values: no arithmetic).
template <class T>
void assign(vec3<T>& to, const vec3<T>& from) noexcept {
  to.x = from.x;
  to.y = from.y;
  to.z = from.z;
}

}  // namespace detail

/// The horizon direction of one measured crossing as the electronics assume it (MODEL §6): the
/// line of sight on the nominal cone, h = cos gamma e3 + sin gamma (cos phi e1 + sin phi e2).
///   frame_body: the head's scan frame in body axes; gamma: nominal half-apex cone angle (rad);
///   phi: measured crossing azimuth (rad, about e3 from e1). Unit to rounding. No status: the
///   inputs' validity is that of the crossings and frame it is built from.
template <class T>
vec3<T> horizon_vector(const scan_frame<T>& frame_body, const T& gamma, const T& phi) noexcept {
  return direction_in_scan_frame(frame_body, gamma, phi);
}

/// Appends the horizon vectors of a head's two crossings (Earth-in, then Earth-out) to
/// out[used], out[used + 1] and returns the new count. Appends nothing (returns `used`) when the
/// crossings or the frame are not ok, or when fewer than two places remain below `capacity`: a
/// head contributes both crossings or none. Nothing is allocated.
template <class T>
std::size_t append_horizon_vectors(const scan_frame<T>& frame_body, const T& gamma,
                                   const crossings<T>& measured, vec3<T>* out, std::size_t used,
                                   std::size_t capacity) noexcept {
  if (out == nullptr || measured.state != status::ok || frame_body.state != status::ok ||
      used > capacity || capacity - used < 2)
    return used;
  detail::assign(out[used], horizon_vector(frame_body, gamma, measured.phi_in));
  detail::assign(out[used + 1], horizon_vector(frame_body, gamma, measured.phi_out));
  return used + 2;
}

namespace detail {

/// An orthonormal basis (t1, t2) of the plane normal to the unit vector n, with t1 x t2 = n.
/// t1 is n crossed with the body axis least aligned with n, so |n x axis| >= sqrt(2/3): no
/// cancellation, whatever n.
template <class T>
void tangent_basis(const vec3<T>& n, vec3<T>& t1, vec3<T>& t2) noexcept {
  using std::abs;
  const T ax = abs(n.x), ay = abs(n.y), az = abs(n.z);
  vec3<T> axis(T(0));
  if (ax <= ay && ax <= az)
    axis.x = T(1);
  else if (ay <= az)
    axis.y = T(1);
  else
    axis.z = T(1);
  assign(t1, unit(cross(axis, n)));
  assign(t2, cross(n, t1));
}

/// The Gauss-Newton normal equations of the residuals r_i = n . h_i - cos rho at a unit n, in the
/// tangent coordinates (d1, d2) of n <- unit(n + d1 t1 + d2 t2): row i of J is (h_i . t1, h_i .
/// t2).
template <class T>
struct horizon_normal_equations {
  T a;           ///< (J^T J)_11
  T b;           ///< (J^T J)_12
  T c;           ///< (J^T J)_22
  T det;         ///< det(J^T J), by Cauchy-Binet (see below)
  T g1;          ///< (J^T r)_1
  T g2;          ///< (J^T r)_2
  T lambda_max;  ///< largest eigenvalue of J^T J
  T lambda_min;  ///< smallest eigenvalue of J^T J (det / lambda_max; 0 or less when singular)
};

template <class T>
horizon_normal_equations<T> horizon_normal_equations_at(const vec3<T>* horizons, std::size_t count,
                                                        const T& cos_rho, const vec3<T>& n,
                                                        const vec3<T>& t1,
                                                        const vec3<T>& t2) noexcept {
  using std::hypot;
  horizon_normal_equations<T> e{T(0), T(0), T(0), T(0), T(0), T(0), T(0), T(0)};
  for (std::size_t i = 0; i < count; ++i) {
    const T j1 = dot(horizons[i], t1), j2 = dot(horizons[i], t2);
    const T r = dot(horizons[i], n) - cos_rho;
    e.a += j1 * j1;
    e.b += j1 * j2;
    e.c += j2 * j2;
    e.g1 += j1 * r;
    e.g2 += j2 * r;
    // det(J^T J) = sum over pairs of the squared 2x2 minors of J (Cauchy-Binet). The naive
    // a c - b^2 loses eps x condition^2 relative digits as the rows turn parallel; each minor
    // loses only eps x condition, so the condition figure stays accurate up to the fold
    // threshold in float too. O(count^2), for the handful of crossings of a few heads.
    for (std::size_t k = 0; k < i; ++k) {
      const T minor = dot(horizons[k], t1) * j2 - dot(horizons[k], t2) * j1;
      e.det += minor * minor;
    }
  }
  e.lambda_max = (e.a + e.c) / T(2) + hypot((e.a - e.c) / T(2), e.b);
  // lambda_min from the product of the eigenvalues: a + c - lambda_max would cancel.
  e.lambda_min = e.lambda_max > T(0) ? e.det / e.lambda_max : T(0);
  return e;
}

}  // namespace detail

/// The geometry condition figure at a unit nadir n: sqrt(lambda_max / lambda_min) of the 2x2
/// normal matrix J^T J, row i of J being the tangent-plane part of h_i at n (the residual's
/// gradient). It is the ratio of how strongly the crossings pin n in its best- and worst-pinned
/// tangent directions: 1 when they pin both equally, growing as the crossings bunch together
/// (~ 2 / theta for two crossings theta apart about n) or line up opposite each other through n
/// (~ 2 / (pi - theta): the fold, where the two mirror solutions merge). +inf when they do not
/// determine n (fewer than two distinct directions); NaN for invalid inputs (count < 2, a null
/// pointer, non-finite or zero n). Independent of cos rho_p. Relative accuracy ~eps x condition.
template <class T>
T horizon_condition(const vec3<T>* horizons, std::size_t count, const vec3<T>& n) noexcept {
  using std::sqrt;
  if (horizons == nullptr || count < 2 || !is_finite(n.x) || !is_finite(n.y) || !is_finite(n.z) ||
      !(dot(n, n) > T(0)))
    return not_a_number<T>();
  const vec3<T> nu = unit(n);
  vec3<T> t1(T(0)), t2(T(0));
  detail::tangent_basis(nu, t1, t2);
  const detail::horizon_normal_equations<T> e =
      detail::horizon_normal_equations_at(horizons, count, T(0), nu, t1, t2);
  if (!(e.lambda_min > T(0))) return std::numeric_limits<T>::infinity();
  return sqrt(e.lambda_max / e.lambda_min);
}

/// The nadir n (unit) that minimises sum_i (n . h_i - cos rho_p)^2 over the unit sphere, by
/// Gauss-Newton on the sphere: at each step the residuals r_i = n . h_i - cos rho_p are
/// linearised in the tangent coordinates (d1, d2) of a basis (t1, t2) of the plane normal to n,
/// the 2x2 normal equations J^T J d = -J^T r are solved, and n <- unit(n + d1 t1 + d2 t2).
///
///   horizons, count: the horizon unit vectors h_i (horizon_vector; body axes, or any common
///     axes: n comes back in the same axes). Unit length is assumed, not checked.
///   cos_rho: cos rho_p, the cosine of the Earth's angular radius that the processing assumes
///     (MODEL §6: sin rho_p = (R_p + h_h) / r).
///   guess: initial nadir, any non-zero finite vector (normalised here). With two crossings it
///     selects which of the two mirror solutions is returned (see the top of this file): seed it
///     with process_head's nadir to get exactly the chord/phase solution. With more crossings any
///     guess within a few tens of degrees of the truth converges to the same minimum; the
///     nominal nadir (body +z) is fine for small attitudes.
///
/// Stops when the step |d| is below its rounding floor 8 eps (1 + sqrt(count / lambda_min)) (the
/// residuals are each computed to ~4 eps, so a step this small is rounding noise), or after
/// horizon_fit_max_iterations steps.
///
/// Statuses:
///  - invalid: count < 2, a null pointer, a non-finite horizon vector, cos_rho not in (0, 1)
///    (rho_p must lie in (0, pi/2)), a non-finite or zero guess. nadir and condition NaN.
///  - fold: the normal matrix is singular on the way (condition +inf), the condition at the
///    solution exceeds horizon_condition_max() (1000), or the steps did not settle within
///    horizon_fit_max_iterations (a minimum too flat to locate). nadir NaN; condition and
///    iterations reported for diagnosis.
///  - ok: nadir is the fitted unit nadir.
/// Accuracy: with consistent crossings (exact data) the fit reproduces the nadir to a few eps x
/// condition / sin rho_p. Measured in double for one head walking up to a fold (gamma 45 deg,
/// rho 20 deg, conditions 6 to 145) against a long double chord/phase reference: at most
/// 3 eps x condition (4e-14 rad); tests/simulation/test_horizon_vector.cpp checks 1e-12 rad against
/// process_head on ~12000 one-head geometries and the true nadir for several heads, in float,
/// double, long double and an ADL-only scalar. Against the same fit in cpp_bin_float_50, end to
/// end from scenes given in degrees (tests/core/test_horizon_vector_accuracy.cpp, docs/ACCURACY.md;
/// 12 scenes, conditions 1 to 711): at most 0.97 eps x condition in double (6.1e-12 deg at a
/// condition of 500), 1.6 in long double, 8.3 in float (0.036 deg at 658: near a fold float's
/// step floor stops Gauss-Newton before it has converged); where the condition is below 4, at
/// most 4.1e-14 deg in double and 1.6e-5 deg in float. Gauss-Newton takes 3 to 5 steps from a
/// seed within a few degrees. Cost: O(count^2) per step (the determinant), count being the number
/// of crossings (2 per head). Nothing is allocated.
template <class T>
horizon_nadir_fit<T> nadir_from_horizon_vectors(const vec3<T>* horizons, std::size_t count,
                                                const T& cos_rho, const vec3<T>& guess) noexcept {
  using std::hypot;
  using std::sqrt;
  const T nan = not_a_number<T>();
  using fit = horizon_nadir_fit<T>;
  if (horizons == nullptr || count < 2) return fit::failed(status::invalid, nan, 0);
  if (!is_finite(cos_rho) || !(cos_rho > T(0)) || !(cos_rho < T(1)))
    return fit::failed(status::invalid, nan, 0);
  for (std::size_t i = 0; i < count; ++i)
    if (!is_finite(horizons[i].x) || !is_finite(horizons[i].y) || !is_finite(horizons[i].z))
      return fit::failed(status::invalid, nan, 0);
  if (!is_finite(guess.x) || !is_finite(guess.y) || !is_finite(guess.z) ||
      !(dot(guess, guess) > T(0)))
    return fit::failed(status::invalid, nan, 0);

  const T eps = std::numeric_limits<T>::epsilon();
  const T count_t = static_cast<T>(count);
  vec3<T> n = unit(guess);
  T condition = nan;
  int iterations = 0;
  bool settled = false;
  while (iterations < horizon_fit_max_iterations) {
    vec3<T> t1(T(0)), t2(T(0));
    detail::tangent_basis(n, t1, t2);
    const detail::horizon_normal_equations<T> e =
        detail::horizon_normal_equations_at(horizons, count, cos_rho, n, t1, t2);
    if (!(e.lambda_min > T(0)) || !(e.det > T(0))) {
      // All horizon vectors give parallel (or zero) gradients here: no 2x2 solve exists.
      return fit::failed(status::fold, std::numeric_limits<T>::infinity(), iterations);
    }
    condition = sqrt(e.lambda_max / e.lambda_min);
    // d = -(J^T J)^-1 J^T r by the adjugate, with the accurate determinant.
    const T d1 = -(e.c * e.g1 - e.b * e.g2) / e.det;
    const T d2 = -(e.a * e.g2 - e.b * e.g1) / e.det;
    detail::assign(n, unit(n + scaled(t1, d1) + scaled(t2, d2)));
    ++iterations;
    const T step = hypot(d1, d2);
    const T step_floor = T(8) * eps * (T(1) + sqrt(count_t / e.lambda_min));
    if (!is_finite(step)) break;
    if (step <= step_floor) {
      settled = true;
      break;
    }
  }
  // The condition of the last step's normal matrix: n moved by at most the step floor since. Near
  // a fold the condition is sensitive to n: against cpp_bin_float_50 it was measured off by a
  // relative 6e-10 in double and 6 % in float at conditions of 500 to 660 (9e-9 and 9 % at 960),
  // so there rounding decides the status within that band of the threshold.
  if (!settled || !(condition <= horizon_condition_max<T>()))
    return fit::failed(status::fold, condition, iterations);
  return {vec3<T>(n.x, n.y, n.z), condition, iterations, status::ok};  // by components: no copy
}

}  // namespace conescan
