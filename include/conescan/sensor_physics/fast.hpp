// A fast method for MODEL §12's crossings: the same inputs and output as
// sensor_physics_crossings (sensor_physics.hpp, "the exact chain"), at a seventh to a tenth of its
// cost and the same accuracy (docs/SENSOR_PHYSICS.md, "The fast method").
//
// The exact chain integrates the field by lines across the scan, each line's pencil signal on
// pieces that resolve the profile's knee. This method does the across-scan integral in closed
// form instead, so that one signal of one variable is left to integrate along the scan:
//  1. Across the field (MODEL §12, "Field of view"). At scan azimuth psi the field's lines at
//     across-offsets b in [-B, B] see the heights delta(psi, b), smooth and monotone in b. With
//     b(zeta) the inverse of zeta = delta(psi, b) (the reversion of the height's Taylor series in
//     b to order 5: the jet of the tangent height), the field's across-mean of the radiance is
//       S(psi) = int_{-B}^{B} L db / 2B = int L(zeta) b'(zeta) dzeta / (b(zeta+) - b(zeta-)),
//     and with b' a quartic p, integration by parts with the limb's repeated antiderivatives
//     (sensor_physics/profile_antiderivatives.hpp) gives it exactly:
//       int l p = [sum_k (-1)^k p^(k) H^(k+1) l_(k+1)]; on the disk (zeta < 0) L_disk int p.
//     No quadrature across the knee: one table look-up per edge of the field. Where the series
//     converges slowly (a field nearly parallel to the limb) a Gauss sum across replaces it.
//  2. Along the scan, S is one signal of psi, smooth between its kinks (an edge crossing the
//     surface where the radiance jumps), resolved on Legendre pieces (10 nodes, ~2 H of height
//     each, doubling in the profile's tail, graded from 2 Lambda after each kink), whose integral
//     and lag are exact (the exact chain's pieces and lag matrices: sensor_physics/detector.hpp,
//     sensor_physics.hpp). The square field's along-scan average is a moving average of S over
//     psi +- A (A = fov / 2 / sin gamma), which commutes with the lag:
//       y(phi) = [Z(phi + A) - Z(phi - A)] / 2A,  Z = M - Lambda z  (M = int S, z its lag),
//     exact anywhere from the pieces. The exact heights are evaluated at every node: no Taylor
//     model of the sweep (a quartic one would still leave 5e-6 deg, measured).
//  3. The locator: y is monotone through each crossing (the radiance falls with height and every
//     line of the field rises through the limb together), so bracketed Newton on y = level
//     (y' = (s - y) / Lambda) finds it, and each window stops being built once its output has
//     passed the level; the normalised locator's peak is the disk's plateau L_disk L0, the output
//     settled on it. The slope locator: the root of y'' beside the largest sampled |y'|.
// Where this is exact: a square field (fov > 0), H > 0, no season term, L_disk >= 1 (monotone
// radiance), separated pulses (the plateau between the windows at least 20 Lambda long, so that
// the output settles to 2e-9). Elsewhere (a pencil, a circle, the season term, a step profile, a
// dimmer disk, a short pulse, a field nearly parallel to the limb, a row whose heights the window
// planning cannot bracket) the fast method calls the exact chain, and says so
// (sensor_physics_fast_workspace::last).
// Measured (docs/SENSOR_PHYSICS.md): within 3e-8 deg of the brute-force reference on the brief's
// case (1.5 deg square, 1 ms of lag at 1 rev/s, normalised 1/2), within 1.7e-8 deg of the exact
// chain on its tests' cases; ~30-45 us per head-row in double, 450-650 times the geometric
// crossings (the exact chain: 4000-5000 times).
#pragma once

#include <array>
#include <cmath>
#include <limits>

#include "conescan/sensor_physics/profile_antiderivatives.hpp"
#include "conescan/sensor_physics/chain.hpp"

namespace conescan {

/// The fast method's resolution (docs/SENSOR_PHYSICS.md, "The fast method", gives the error
/// each leaves).
template <class T>
struct sensor_physics_fast_accuracy {
  T piece_scales{2};        ///< a piece of S spans about this many H of the central line's height
  T slope_piece_scales{1};  ///< the same for the slope locator (it needs y'': twice finer)
  T tail_start{3};          ///< pieces double in width where the field's lowest line is this many H
                            ///< above delta50
  T tail_cut{14};  ///< S is 0 above delta50 + tail_cut H for every line (l < 5.7e-7 there, S
                   ///< below 1e-7 and the lag's memory of it at the crossing below e^-7)
  T out_reach{5};  ///< the Earth-out window first ends where its lowest line is this many H
                   ///< above delta50 (the output at the crossing sees no further)
};

/// Which method served a row.
enum class physics_method : unsigned char { fast, exact };

namespace fast_detail {

using physics_detail::lag_matrix;
using physics_detail::line_signal;
using physics_detail::nodes;

inline constexpr int jet_order = 6;         ///< Taylor coefficients 0 .. 5 of a height in b
inline constexpr int family_steps = 4;      ///< lag matrices per octave of piece width
inline constexpr int lag_families = 69;     ///< precomputed: widths Lambda 2^(m / 4)
inline constexpr int lag_family_low = -32;  ///< m = -32 .. 36: Lambda / 256 .. 512 Lambda

/// A truncated Taylor series in the across-offset b: c[k] = f^(k)(0) / k!.
template <class T>
struct jet {
  std::array<T, jet_order> c;
};

template <class T>
jet<T> jet_product(const jet<T>& a, const jet<T>& b) noexcept {
  jet<T> r{};
  for (int k = 0; k < jet_order; ++k) {
    T sum = T(0);
    for (int i = 0; i <= k; ++i) sum += a.c[i] * b.c[k - i];
    r.c[k] = sum;
  }
  return r;
}

template <class T>
jet<T> jet_quotient(const jet<T>& a, const jet<T>& b) noexcept {
  jet<T> q{};
  const T inverse = T(1) / b.c[0];
  for (int k = 0; k < jet_order; ++k) {
    T sum = a.c[k];
    for (int i = 1; i <= k; ++i) sum -= b.c[i] * q.c[k - i];
    q.c[k] = sum * inverse;
  }
  return q;
}

template <class T>
jet<T> jet_sqrt(const jet<T>& a) noexcept {
  using std::sqrt;
  jet<T> s{};
  s.c[0] = sqrt(a.c[0]);
  const T inverse = T(1) / (T(2) * s.c[0]);
  for (int k = 1; k < jet_order; ++k) {
    T sum = a.c[k];
    for (int i = 1; i < k; ++i) sum -= s.c[i] * s.c[k - i];
    s.c[k] = sum * inverse;
  }
  return s;
}

/// cos b c + sin b s as a jet in b.
template <class T>
jet<T> jet_of_pair(const physics_detail::dot_pair<T>& p) noexcept {
  return {{p.c, p.s, T(-p.c / T(2)), T(-p.s / T(6)), T(p.c / T(24)), T(p.s / T(120))}};
}

template <class T>
jet<T> jet_plus(const jet<T>& a, const T& constant, const T& scale) noexcept {
  jet<T> r{};
  for (int k = 0; k < jet_order; ++k) r.c[k] = a.c[k] * scale;
  r.c[0] += constant;
  return r;
}

/// A line's height alone (no latitude) from its two dot products, as sensor_physics/height.hpp's
/// sphere_tangent_height and ellipsoid_tangent_height compute it: the edges' heights.
template <class T>
T height_only(const sphere_surface<T>& s, const T& c, const T&, const T&) noexcept {
  using std::sqrt;
  if (!(c > T(0))) return s.distance_m - s.radius_m;
  const T c_clamped = c < T(1) ? c : T(1);
  return s.distance_m * sqrt((T(1) - c_clamped) * (T(1) + c_clamped)) - s.radius_m;
}
template <class T>
T height_only(const ellipsoid_surface<T>& s, const T& front, const T& along, const T& zp) noexcept {
  return ellipsoid_tangent_height(s, front, along, zp).height_m;
}

/// The height jet on the sphere (sensor_physics/height.hpp's sphere_tangent_height in jets): c = d.n,
/// delta = |p| sqrt((1 - c)(1 + c)) - (R + h_h). false where the line looks away (c <= 0).
template <class T>
bool height_jet(const sphere_surface<T>& s, const physics_detail::dot_pair<T>& first,
                const physics_detail::dot_pair<T>&, const T&, jet<T>& out) noexcept {
  const jet<T> c = jet_of_pair(first);
  if (!(c.c[0] > T(0)) || !(c.c[0] < T(1))) return false;
  const jet<T> one_minus = jet_plus(jet_product(c, c), T(1), T(-1));
  out = jet_plus(jet_sqrt(one_minus), T(-s.radius_m), s.distance_m);
  return true;
}

/// The height jet on the ellipsoid (ellipsoid_tangent_height in jets: the closest approach in
/// the scaled space, mapped back along the normal). false where the closest approach lies
/// behind the satellite or the line passes through the centre.
template <class T>
bool height_jet(const ellipsoid_surface<T>& s, const physics_detail::dot_pair<T>& first,
                const physics_detail::dot_pair<T>& second, const T& zp, jet<T>& out) noexcept {
  const ellipsoid_horizon<T>& e = s.horizon;
  const jet<T> front = jet_of_pair(first), along = jet_of_pair(second);
  if (!(front.c[0] < T(0))) return false;
  const jet<T> d_squared = jet_plus(jet_product(along, along), T(1), e.kappa);
  const jet<T> t = jet_plus(jet_quotient(front, d_squared), T(0), T(-1));
  const jet<T> excess =
      jet_plus(jet_quotient(jet_product(front, front), d_squared), e.height, T(-1));
  if (!(excess.c[0] > T(-1))) return false;
  const jet<T> norm_x = jet_sqrt(jet_plus(excess, T(1), T(1)));
  const jet<T> z_x = jet_plus(jet_product(t, along), zp, s.stretch);
  const jet<T> zeta = jet_quotient(z_x, norm_x);
  const jet<T> eps = jet_quotient(excess, jet_plus(norm_x, T(1), T(1)));
  const jet<T> normal = jet_sqrt(jet_plus(jet_product(zeta, zeta), T(1), e.kappa));
  out = jet_plus(jet_quotient(eps, normal), T(0), s.a_eq_m);
  return true;
}

}  // namespace fast_detail

/// One head's physics for the fast method, prepared once: the exact chain's head (its fallback,
/// and the pieces' rule), the antiderivative table, the radiance's values at the surface and
/// the lag matrices of the pieces' standard widths.
template <class T>
struct sensor_physics_fast_head {
  sensor_physics_head<T> exact;
  sensor_physics_fast_accuracy<T> accuracy;
  limb_antiderivatives<T> antiderivatives;
  bool native;                  ///< the settings are in the fast method's domain (file comment)
  std::array<T, 5> at_surface;  ///< l_(k)(-delta50 / H), k = 1 .. 5
  bool surface_jump;            ///< the radiance jumps at the surface (L_disk != l(0) to rounding)
  T constant_below;             ///< below this height (m) the radiance is L_disk L0 everywhere
  std::array<physics_detail::lag_matrix<T>, fast_detail::lag_families> lag_family;
  std::array<T, fast_detail::lag_families> lag_width;  ///< the family's widths (rad)
  /// cos and sin of each node's offset from its piece's start, per family width
  std::array<std::array<T, physics_detail::nodes>, fast_detail::lag_families> node_cos, node_sin;
  status state;  ///< ok, or invalid (the exact chain's settings check, or the table)
};

/// The fast head of a head's settings (sensor_physics_settings_status decides invalid).
template <class T>
sensor_physics_fast_head<T> sensor_physics_fast_head_of(
    const sensor_physics_settings<T>& s,
    const sensor_physics_fast_accuracy<T>& accuracy = sensor_physics_fast_accuracy<T>{},
    const sensor_physics_accuracy<T>& exact_accuracy = sensor_physics_accuracy<T>{}) noexcept {
  using std::cos;
  using std::exp;
  using std::log;
  using std::sin;
  sensor_physics_fast_head<T> h{};
  h.exact = sensor_physics_head_of(s, exact_accuracy);
  h.accuracy = accuracy;
  h.antiderivatives = limb_antiderivatives_of<T>();
  h.state = h.exact.state == status::ok && h.antiderivatives.state == status::ok ? status::ok
                                                                                 : status::invalid;
  if (h.state != status::ok) return h;
  const radiance_profile<T>& p = h.exact.profile;
  h.native = s.field.fov_rad > T(0) && s.field.shape == field_shape::square && p.scale_m > T(0) &&
             s.season_amplitude == T(0) && s.disk >= T(1);
  if (!h.native) return h;
  const T x_surface = -p.offset_m / p.scale_m;
  limb_antiderivatives_at(h.antiderivatives, x_surface, h.at_surface.data());
  const T saturated = p.offset_m + h.antiderivatives.x_low * p.scale_m;
  // l = 1 exactly below x_low: no jump at the surface when the disk is as bright and the
  // profile saturates above it.
  h.surface_jump = !(s.disk == T(1) && saturated >= T(0));
  h.constant_below = h.surface_jump ? T(0) : saturated;
  if (h.exact.lag_rad > T(0))
    for (int m = 0; m < fast_detail::lag_families; ++m) {
      h.lag_width[m] = h.exact.lag_rad * exp(T(m + fast_detail::lag_family_low) * log(T(2)) /
                                             T(fast_detail::family_steps));
      physics_detail::lag_matrix_of(h.lag_family[m], h.exact, h.lag_width[m]);
      for (int k = 0; k < physics_detail::nodes; ++k) {
        const T offset = (h.exact.rule.nodes[k] + T(1)) * h.lag_width[m] / T(2);
        h.node_cos[m][k] = cos(offset);
        h.node_sin[m][k] = sin(offset);
      }
    }
  return h;
}

namespace fast_detail {

inline constexpr int max_pieces = physics_detail::max_pieces;
inline constexpr int max_scratch = 8;  ///< lag matrices of odd widths per row

/// The signal S of one crossing's window on pieces, and what the locator needs around it.
template <class T>
struct fast_window {
  line_signal<T> line;  ///< S(psi) on pieces (line.start .. line.end), constant outside
  int sky_sign;         ///< -1 Earth-in (the sky before), +1 Earth-out (the sky after)
};

}  // namespace fast_detail

/// The memory one head-row works in: the exact chain's workspace (the fallback), two windows of
/// S, lag matrices of odd widths; and which method served the last row, with counts. ~0.7 MB in
/// double: keep one per thread and reuse it.
template <class T>
struct sensor_physics_fast_workspace {
  sensor_physics_workspace<T> exact;
  fast_detail::fast_window<T> window[2];
  std::array<physics_detail::lag_matrix<T>, fast_detail::max_scratch> scratch;
  int scratch_count{0};
  physics_method last{physics_method::fast};
  long fast_rows{0};   ///< rows the fast method served
  long exact_rows{0};  ///< rows it passed to the exact chain
};

namespace fast_detail {

/// The field's geometry at one scan azimuth: the heights of its across-edges (exact), and the
/// inverse of the height across it, b(zeta), as a series in u = zeta - delta(psi, 0).
template <class T>
struct across_geometry {
  T centre;       ///< delta(psi, 0) (m)
  T lower_m;      ///< delta(psi, -B)
  T upper_m;      ///< delta(psi, +B)
  T beta[6];      ///< b(u) = sum_{k=1}^5 beta[k] u^k (beta[0] unused)
  jet<T> height;  ///< delta(psi, b) = sum_k height.c[k] b^k
  bool series;    ///< the inverse series converges fast enough (else Gauss across the field)
};

/// The scan point (physics_detail::scan_point_at) from the cosine and sine of the scan azimuth,
/// which a piece's nodes get by rotating its start's (no sine or cosine per node).
template <class T>
physics_detail::scan_point<T> scan_point_from(const scan_circle<T>& c, const T& cp,
                                              const T& sp) noexcept {
  using std::abs;
  using std::sqrt;
  const T h = c.axis.x * cp + c.axis.y * sp;
  const T p = abs(c.axis.y * cp - c.axis.x * sp);
  const T a = c.axis.z;
  T radicand = (c.sin_gamma - p) * (c.sin_gamma + p);
  if (radicand < T(0)) radicand = T(0);
  const T r = sqrt(radicand);
  const T inverse = T(1) / (a * a + h * h);
  return {cp, sp, T((a * c.cos_gamma - h * r) * inverse), T((h * c.cos_gamma + a * r) * inverse)};
}

/// The edges' heights, the height's jet across the field and its inverse series at psi. The
/// series is used where it converges like 1e-2 per order or faster: its ratio, B times the
/// largest |h_k / h_1|^(1/(k-1)), below 1/50 (truncation ~3e-9 of the mean). A field nearly
/// parallel to the limb (h_1 small: the across spread of heights a few km or less) fails that
/// test; its mean is then a Gauss sum across the field (across_mean). false outside the jets'
/// domain (a line that looks away from the surface).
template <class T, class Surface>
bool across_geometry_at(const Surface& surface, const physics_detail::surface_probe<T>& probe,
                        const physics_detail::scan_point<T>& q, const T& cos_b, const T& sin_b,
                        across_geometry<T>& g) noexcept {
  using std::abs;
  using std::sqrt;
  const physics_detail::dot_pair<T> a = physics_detail::dot_pair_of(q, probe.first);
  const physics_detail::dot_pair<T> b = physics_detail::dot_pair_of(q, probe.second);
  jet<T>& h = g.height;
  if (!height_jet(surface, a, b, probe.constant, h)) return false;
  g.centre = h.c[0];
  g.lower_m = height_only(surface, T(cos_b * a.c - sin_b * a.s), T(cos_b * b.c - sin_b * b.s),
                          probe.constant);
  g.upper_m = height_only(surface, T(cos_b * a.c + sin_b * a.s), T(cos_b * b.c + sin_b * b.s),
                          probe.constant);
  if (!is_finite(g.lower_m) || !is_finite(g.upper_m)) return false;
  const T h1 = h.c[1], h2 = h.c[2], h3 = h.c[3], h4 = h.c[4], h5 = h.c[5];
  // The ratio, squared and to the fourth power to keep to square roots: (B |h2/h1|)^4,
  // (B^2 |h3/h1|)^2, (B^4 |h5/h1|) against 50^-4; h4 between them.
  const T b2 = sin_b * sin_b, limit = T(1) / T(6250000);  // 50^-4
  const T a1 = abs(h1);
  const T r2 = abs(h2) * sin_b, r3 = abs(h3) * b2, r5 = abs(h5) * b2 * b2;
  g.series = a1 > T(0) && r2 * r2 * r2 * r2 < limit * a1 * a1 * a1 * a1 &&
             r3 * r3 < limit * a1 * a1 && r5 < limit * a1 &&
             abs(h4) * b2 * sin_b * sqrt(sqrt(T(50))) < a1 / T(2500);
  if (!g.series) return true;
  // The reversion of zeta - h0 = h1 b + ... + h5 b^5 (Abramowitz and Stegun 3.6.25). Order 5:
  // the height's third derivative across (~|p|) makes each order ~1e-2 of the previous one on a
  // 1.5 deg field; truncating at 4 left 6e-9 of the mean, at 5 ~1e-10 (measured).
  const T i1 = T(1) / h1, i2 = i1 * i1, i3 = i2 * i1;
  const T h1s = h1 * h1, h2s = h2 * h2;
  g.beta[0] = T(0);
  g.beta[1] = i1;
  g.beta[2] = -h2 * i3;
  g.beta[3] = (T(2) * h2s - h1 * h3) * i3 * i2;
  g.beta[4] = (T(5) * h1 * h2 * h3 - T(5) * h2s * h2 - h1s * h4) * i3 * i3 * i1;
  g.beta[5] = (T(6) * h1s * h2 * h4 + T(3) * h1s * h3 * h3 + T(14) * h2s * h2s - h1s * h1 * h5 -
               T(21) * h1 * h2s * h3) *
              i3 * i3 * i3;
  return true;
}

/// The same at scan azimuth psi.
template <class T, class Surface>
bool across_geometry_at(const scan_circle<T>& circle, const Surface& surface,
                        const physics_detail::surface_probe<T>& probe, const T& psi, const T& cos_b,
                        const T& sin_b, across_geometry<T>& g) noexcept {
  return across_geometry_at(surface, probe, physics_detail::scan_point_at(circle, psi), cos_b,
                            sin_b, g);
}

/// b(u) and p = b'(u) with its derivatives p' .. p'''' at u.
template <class T>
void inverse_at(const across_geometry<T>& g, const T& u, T& b, T p[5]) noexcept {
  const T* c = g.beta;
  b = u * (c[1] + u * (c[2] + u * (c[3] + u * (c[4] + u * c[5]))));
  p[0] = c[1] + u * (T(2) * c[2] + u * (T(3) * c[3] + u * (T(4) * c[4] + u * T(5) * c[5])));
  p[1] = T(2) * c[2] + u * (T(6) * c[3] + u * (T(12) * c[4] + u * T(20) * c[5]));
  p[2] = T(6) * c[3] + u * (T(24) * c[4] + u * T(60) * c[5]);
  p[3] = T(24) * c[4] + u * T(120) * c[5];
  p[4] = T(120) * c[5];
}

/// sum_k (-1)^k p^(k) H^(k+1) l_(k+1): the sky's antiderivative of l p at a height.
template <class T>
T sky_antiderivative(const T p[5], const T l[5], const T& scale) noexcept {
  return scale * (p[0] * l[0] -
                  scale * (p[1] * l[1] -
                           scale * (p[2] * l[2] - scale * (p[3] * l[3] - scale * p[4] * l[4]))));
}

/// The height across the field from its jet at b (the jet's truncation, h_6 B^6, is below
/// 1e-7 m on a field of a few degrees).
template <class T>
T jet_value(const jet<T>& h, const T& b) noexcept {
  T sum = h.c[jet_order - 1];
  for (int k = jet_order - 2; k >= 0; --k) sum = h.c[k] + b * sum;
  return sum;
}

/// Whether the height is monotone across the whole field at this scan azimuth, so that its
/// extremes are the edges' heights (which the window planning and the surface's split rely on):
/// |h1| > sum_{k>=2} k |h_k| B^(k-1), a sufficient condition. A field nearly parallel to the
/// limb fails it where its interior dips below the edges: there the first contact with the
/// surface is a square-root point of S that no piece resolves, and the exact chain serves.
template <class T>
bool monotone_across(const across_geometry<T>& g, const T& b_max) noexcept {
  using std::abs;
  T bound = T(0), power = T(1);
  for (int k = 2; k < jet_order; ++k) {
    power = power * b_max;
    bound += T(k) * abs(g.height.c[k]) * power;
  }
  return abs(g.height.c[1]) > bound;
}

/// The across-mean where the inverse series converges too slowly (a field nearly parallel to
/// the limb, its heights spread over a few km at most across it): 16-point Gauss-Legendre in b,
/// split where the height crosses the surface (the root of the jet by bracketed Newton). The
/// integrand then varies over a fraction of the profile's scale: Gauss converges like
/// (pi H / spread)^-32, to rounding. Used by few samples of few rows; not the hot path.
template <class T>
T across_mean_by_gauss(const sensor_physics_fast_head<T>& head,
                       const across_geometry<T>& g) noexcept {
  static const gauss_legendre_rule<T, 16> rule = gauss_legendre_rule_of<T, 16>();
  const T b_max = head.exact.settings.field.fov_rad / T(2);
  const radiance_profile<T>& profile = head.exact.profile;
  T cuts[3] = {-b_max, b_max, b_max};
  int n = 2;
  if ((g.lower_m < T(0)) != (g.upper_m < T(0))) {
    auto f = [&](const T& b) {
      const T e = T(1) / T(1000000);  // the jet's slope by a central difference of itself
      return value_slope<T>{jet_value(g.height, b), T((jet_value(g.height, T(b + e * b_max)) -
                                                       jet_value(g.height, T(b - e * b_max))) /
                                                      (T(2) * e * b_max))};
    };
    cuts[1] = bracketed_newton(f, T(-b_max), b_max, T(0)).x;
    n = 3;
  }
  T sum = T(0);
  for (int c = 0; c + 1 < n; ++c) {
    const T half = (cuts[c + 1] - cuts[c]) / T(2), middle = (cuts[c + 1] + cuts[c]) / T(2);
    for (int i = 0; i < 16; ++i)
      sum += rule.weights[i] * half *
             radiance(profile, T(1), jet_value(g.height, T(middle + half * rule.nodes[i])));
  }
  return sum / (T(2) * b_max);
}

/// The across-mean of the radiance at one scan azimuth, in units of L0 (the plateau applied by
/// the caller): int_{zeta-}^{zeta+} L p dzeta / int p dzeta (file comment, step 1). The
/// antiderivative F of L p is G(zeta) - G(0) in the sky (G of sky_antiderivative) and
/// L_disk (b(zeta) - b(0)) on the disk; where both edges lie in the sky, G alone.
template <class T>
T across_mean(const sensor_physics_fast_head<T>& head, const across_geometry<T>& g) noexcept {
  const radiance_profile<T>& profile = head.exact.profile;
  const T scale = profile.scale_m;
  if (g.lower_m < head.constant_below && g.upper_m < head.constant_below) return profile.disk;
  if (!g.series) return across_mean_by_gauss(head, g);
  auto sky = [&](const T& zeta, const T p[5]) {
    T l[5];
    limb_antiderivatives_at(head.antiderivatives, T((zeta - profile.offset_m) / scale), l);
    return sky_antiderivative(p, l, scale);
  };
  T b_low, b_high, p_low[5], p_high[5];
  inverse_at(g, T(g.lower_m - g.centre), b_low, p_low);
  inverse_at(g, T(g.upper_m - g.centre), b_high, p_high);
  const T width = b_high - b_low;
  if (g.lower_m >= T(0) && g.upper_m >= T(0))
    return (sky(g.upper_m, p_high) - sky(g.lower_m, p_low)) / width;
  T b0, p0[5];
  inverse_at(g, T(-g.centre), b0, p0);
  const T sky_at_surface = sky_antiderivative(p0, head.at_surface.data(), scale);
  auto antiderivative = [&](const T& zeta, const T& b, const T p[5]) {
    return zeta < T(0) ? T(profile.disk * (b - b0)) : T(sky(zeta, p) - sky_at_surface);
  };
  return (antiderivative(g.upper_m, b_high, p_high) - antiderivative(g.lower_m, b_low, p_low)) /
         width;
}

/// The heights of the field's two across-edges at psi (exact): the lower and the higher.
template <class T, class Surface>
void edge_range(const scan_circle<T>& circle, const Surface& surface,
                const physics_detail::surface_probe<T>& probe, const T& psi, const T& cos_b,
                const T& sin_b, T& low, T& high) noexcept {
  const physics_detail::scan_point<T> q = physics_detail::scan_point_at(circle, psi);
  const physics_detail::dot_pair<T> a = physics_detail::dot_pair_of(q, probe.first);
  const physics_detail::dot_pair<T> b = physics_detail::dot_pair_of(q, probe.second);
  const T minus = height_only(surface, T(cos_b * a.c - sin_b * a.s), T(cos_b * b.c - sin_b * b.s),
                              probe.constant);
  const T plus = height_only(surface, T(cos_b * a.c + sin_b * a.s), T(cos_b * b.c + sin_b * b.s),
                             probe.constant);
  low = minus < plus ? minus : plus;
  high = minus < plus ? plus : minus;
}

/// One crossing's geometry for the window planning: t = sky_sign (psi - phi_g) grows towards
/// the sky, where every height grows.
template <class T, class Surface>
struct crossing_frame {
  const scan_circle<T>* circle;
  const Surface* surface;
  physics_detail::surface_probe<T> probe;
  T phi_g;  ///< the geometric crossing
  int sky_sign;
  T cos_b, sin_b;  ///< of the field's across half-width B
  T rate;          ///< d height / dt of the central line at phi_g (m/rad)
  T reach;         ///< |t| within which the heights are trusted monotone (half the shorter arc)

  T psi(const T& t) const noexcept { return phi_g + T(sky_sign) * t; }
  T edge(const T& t, bool upper) const noexcept {
    T low, high;
    edge_range(*circle, *surface, probe, psi(t), cos_b, sin_b, low, high);
    return upper ? high : low;
  }
};

/// The bracket [lo, hi] (lo < hi, hi - lo <= tolerance) of the place t where the field's upper
/// (or lower) edge passes `level`: edge(lo) <= level <= edge(hi). Grown from the linear guess by
/// doubling steps, then narrowed by the Illinois method on the exact heights. false when no
/// bracket lies within the frame's reach (a scan grazing the level: the exact chain decides).
template <class T, class Surface>
bool edge_place(const crossing_frame<T, Surface>& f, bool upper, const T& level, const T& tolerance,
                T& lo, T& hi) noexcept {
  using std::abs;
  auto g = [&](const T& t) { return T(f.edge(t, upper) - level); };
  const T guess = (level - f.edge(T(0), upper)) / f.rate;
  T t0 = guess, g0 = g(t0);
  T step = abs(g0) / f.rate + tolerance;
  T t1 = t0, g1 = g0;
  for (int i = 0; i < 40; ++i) {
    t1 = g0 > T(0) ? T(t0 - step) : T(t0 + step);
    if (!(abs(t1) < f.reach)) return false;
    g1 = g(t1);
    if ((g1 > T(0)) != (g0 > T(0))) break;
    t0 = t1;
    g0 = g1;
    step = step * T(2);
  }
  if ((g1 > T(0)) == (g0 > T(0))) return false;
  lo = t0 < t1 ? t0 : t1;
  hi = t0 < t1 ? t1 : t0;
  T glo = t0 < t1 ? g0 : g1, ghi = t0 < t1 ? g1 : g0;
  if (!(glo <= T(0)) || !(ghi >= T(0))) return false;  // not increasing: not a limb crossing
  int side = 0;
  for (int i = 0; i < 100 && hi - lo > tolerance; ++i) {
    T m = (lo * ghi - hi * glo) / (ghi - glo);
    if (!(m > lo && m < hi)) m = (lo + hi) / T(2);
    const T gm = g(m);
    if (gm > T(0)) {
      hi = m;
      ghi = gm;
      if (side == 1) glo = glo / T(2);
      side = 1;
    } else {
      lo = m;
      glo = gm;
      if (side == -1) ghi = ghi / T(2);
      side = -1;
    }
  }
  return true;
}

/// The pieces of one window in scan order: the first one's start, widths and the index of each
/// one's lag matrix in the head's family (-1: an odd width, computed for the row).
template <class T>
struct piece_plan {
  int count;
  T psi_start;  ///< the first piece's start (rad of scan azimuth)
  T t_cut;      ///< the tail cut in t: S is 0 beyond (nodes there are not evaluated)
  T width[max_pieces];
  int family[max_pieces];

  bool push(const T& w, int index) noexcept {
    if (count >= max_pieces) return false;
    width[count] = w;
    family[count] = index;
    ++count;
    return true;
  }
};

/// The places of one window in t (the sky's side up): t_a, the upper edge at the height below
/// which the radiance is the disk's (S constant before it; a kink of S where the radiance jumps
/// at the surface); kink, the lower edge at the surface (a kink of S, when it jumps); t_t, the
/// lower edge at delta50 + tail_start H (the profile's tail begins); t_b, the tail cut; t_end,
/// where the pieces end (t_b, or for the Earth-out window without its tail, the lower edge at
/// delta50 + out_reach H).
template <class T>
struct window_places {
  T t_a, kink, t_t, t_b, t_end;
  bool has_kink;
};

template <class T, class Surface>
bool places_of(const sensor_physics_fast_head<T>& head, const crossing_frame<T, Surface>& f,
               bool tail, window_places<T>& p) noexcept {
  const radiance_profile<T>& profile = head.exact.profile;
  const T scale = profile.scale_m;
  const T loose = scale / f.rate / T(100);
  const T tight = T(1000) * std::numeric_limits<T>::epsilon() * (T(1) + f.reach);
  T lo, hi;
  if (!edge_place(f, true, head.constant_below, head.surface_jump ? tight : loose, lo, hi))
    return false;
  p.t_a = lo;
  // The tail cut; a scan whose sky side never rises that high, or only where its heights flatten
  // (its farthest line of sight from the nadir, where the field's edges swap), is cut lower, down
  // to delta50 + 12 H (l < 4.3e-6 there, S a sixth of it on the brief's field, and the lag's
  // memory of it at the crossing below e^-6: < 1e-9), where the field's across spread is still
  // at least a twentieth of what it is at the crossing.
  T spread_low, spread_high;
  edge_range(*f.circle, *f.surface, f.probe, f.phi_g, f.cos_b, f.sin_b, spread_low, spread_high);
  const T spread = spread_high - spread_low;
  bool cut = false;
  for (T x = head.accuracy.tail_cut; !cut && x >= T(12); x = x - T(2)) {
    cut = edge_place(f, false, T(profile.offset_m + x * scale), loose, lo, hi);
    if (!cut) continue;
    T low, high;
    edge_range(*f.circle, *f.surface, f.probe, f.psi(hi), f.cos_b, f.sin_b, low, high);
    cut = high - low > spread / T(20);
  }
  if (!cut) return false;
  p.t_b = hi;
  if (!edge_place(f, false, T(profile.offset_m + head.accuracy.tail_start * scale), loose, lo, hi))
    return false;
  p.t_t = hi;
  p.t_end = p.t_b;
  if (!tail) {
    if (!edge_place(f, false, T(profile.offset_m + head.accuracy.out_reach * scale), loose, lo, hi))
      return false;
    p.t_end = hi < p.t_b ? hi : p.t_b;
  }
  p.has_kink =
      head.surface_jump && edge_place(f, false, T(0), tight, lo, hi) && lo > p.t_a && lo < p.t_end;
  p.kink = p.has_kink ? lo : p.t_end;
  // Heights monotone across the field where S leaves the disk's constant and where the lower
  // edge meets the surface: there the edges are the field's extremes (in the tail, S is small
  // and smooth whatever the field's shape).
  for (const T& t : {p.t_a, p.kink}) {
    across_geometry<T> g;
    if (!across_geometry_at(*f.circle, *f.surface, f.probe, f.psi(t), f.cos_b, f.sin_b, g) ||
        !monotone_across(g, T(head.exact.settings.field.fov_rad / T(2))))
      return false;
  }
  return true;
}

/// Lays pieces in scan order over [from, to] of t (forwards: t grows with the scan, the
/// Earth-out window; backwards: t falls, Earth-in), `to` reached exactly when `exact_end`
/// (an odd last piece) or overshot by the last piece. Widths: the family's `index` (or `width`
/// without lag); after a kink (`graded`) the detector's transient e^{-x/Lambda} is resolved by
/// pieces from 2 Lambda growing by 2^(1/2) up to the standard width (the exact chain's rule:
/// its interpolation error e^{-D/Lambda} (w / 2 Lambda)^10 / (2^9 10!) at distance D stays
/// below 1e-8 of it); `doubling`: each piece twice the last (the profile's tail).
template <class T>
bool lay_pieces(const sensor_physics_fast_head<T>& head, piece_plan<T>& plan, T from, const T& to,
                bool exact_end, bool graded, bool doubling, int& index, T& width) noexcept {
  const bool lag = head.exact.lag_rad > T(0);
  // The family's 2 Lambda is index family_steps - lag_family_low.
  int grade = graded && lag ? family_steps - lag_family_low : lag_families;
  const T length = to > from ? T(to - from) : T(from - to);
  T done = T(0);
  while (done < length) {
    int use = index;
    T w = lag ? head.lag_width[index] : width;
    if (grade < index) {
      use = grade;
      w = head.lag_width[grade];
      grade += 2;
    }
    int family = lag ? use : -1;
    if (exact_end && done + w >= length) {
      w = length - done;
      family = -1;
    }
    if (!plan.push(w, family)) return false;
    done = done + w;
    if (doubling) {
      if (lag && index + family_steps < lag_families) index += family_steps;
      if (!lag) width = width * T(2);
    }
  }
  return true;
}

/// The standard piece (plan_window's): family index m and width w for a height rate (m/rad).
template <class T>
bool standard_piece(const sensor_physics_fast_head<T>& head, const T& rate, int& m, T& w) noexcept {
  using std::floor;
  using std::log;
  const radiance_profile<T>& profile = head.exact.profile;
  const T lag = head.exact.lag_rad;
  const T scales = head.exact.settings.locator.kind == locator_kind::slope
                       ? head.accuracy.slope_piece_scales
                       : head.accuracy.piece_scales;
  const T target = scales * profile.scale_m / rate;
  w = target;
  m = 0;
  if (lag > T(0)) {
    const T position = floor(T(family_steps) * log(target / lag) / log(T(2)) + T(1) / T(2));
    if (!(position >= T(lag_family_low)) || !(position < T(lag_family_low + lag_families)))
      return false;
    m = static_cast<int>(static_cast<long double>(position)) - lag_family_low;
    w = head.lag_width[m];
  }
  return true;
}

/// Plans one window (places_of) in scan order. Earth-out (forwards): from t_a, graded after it
/// when the radiance jumps at the surface; standard pieces w (the head's family Lambda 2^(m/4)
/// nearest piece_scales H of the central line's height, H for the slope locator) to the kink,
/// graded again after it; doubling beyond t_t, to t_end. Earth-in (backwards): the doubling tail
/// from t_end down to t_t first (its widths falling), then standard pieces to the kink, graded
/// after it to t_a (reached exactly where S's slope jumps there). false when a place has no
/// bracket or the pieces outgrow the workspace.
template <class T, class Surface>
bool plan_window(const sensor_physics_fast_head<T>& head, const crossing_frame<T, Surface>& f,
                 bool tail, piece_plan<T>& plan) noexcept {
  window_places<T> p;
  if (!places_of(head, f, tail, p)) return false;
  T w = T(0);
  int m = 0;
  if (!standard_piece(head, f.rate, m, w)) return false;
  plan.count = 0;
  plan.t_cut = p.t_b;
  const bool jump = head.surface_jump;
  int index = m;
  T width = w;
  if (f.sky_sign > 0) {
    plan.psi_start = f.psi(p.t_a);
    const T knee_end = p.t_t < p.t_end ? p.t_t : p.t_end;
    if (p.has_kink) {
      if (!lay_pieces(head, plan, p.t_a, p.kink, true, jump, false, index, width)) return false;
      if (!lay_pieces(head, plan, p.kink, knee_end, false, true, false, index, width)) return false;
    } else if (!lay_pieces(head, plan, p.t_a, knee_end, false, jump, false, index, width)) {
      return false;
    }
    T reached = plan.psi_start;
    for (int i = 0; i < plan.count; ++i) reached = reached + plan.width[i];
    const T t_reached = reached - f.phi_g;
    return t_reached >= p.t_end ||
           lay_pieces(head, plan, t_reached, p.t_end, false, false, true, index, width);
  }
  // Earth-in: the tail's widths in t-order (doubling up from t_t), then reversed.
  piece_plan<T> tail_plan;
  tail_plan.count = 0;
  int tail_index = m;
  T tail_width = w;
  if (p.t_end > p.t_t &&
      !lay_pieces(head, tail_plan, p.t_t, p.t_end, false, false, true, tail_index, tail_width))
    return false;
  T tail_length = T(0);
  for (int i = tail_plan.count - 1; i >= 0; --i) {
    if (!plan.push(tail_plan.width[i], tail_plan.family[i])) return false;
    tail_length = tail_length + tail_plan.width[i];
  }
  const T knee_top = p.t_t < p.t_end ? p.t_t : p.t_end;
  plan.psi_start = f.psi(T(knee_top + tail_length));
  if (p.has_kink) {
    if (!lay_pieces(head, plan, knee_top, p.kink, true, false, false, index, width)) return false;
    return lay_pieces(head, plan, p.kink, p.t_a, jump, true, false, index, width);
  }
  return lay_pieces(head, plan, knee_top, p.t_a, jump, false, false, index, width);
}

/// Appends a polynomial piece of S to the line: its Legendre form, its integral, and its lag
/// at the nodes and the end from the piece's lag matrix (physics_detail::push_piece's algebra).
template <class T>
void push_piece(line_signal<T>& line, const sensor_physics_fast_head<T>& head,
                const lag_matrix<T>* matrix, const T& start, const T& width, const T* values,
                T& integral, T& lagged) noexcept {
  physics_detail::line_piece<T>& p = line.piece[line.count++];
  p.start = start;
  p.width = width;
  p.constant = false;
  p.value = T(0);
  p.integral_start = integral;
  p.lag_start = lagged;
  p.signal = legendre_panel_of(head.exact.rule, start, width, values);
  integral += p.signal.coefficients[0] * width;
  if (matrix == nullptr) {
    p.lagged = p.signal;
    lagged = panel_value(p.signal, T(start + width));
    return;
  }
  T z[nodes];
  for (int i = 0; i <= nodes; ++i) {
    T sum = matrix->decay[i] * p.lag_start;
    for (int k = 0; k < nodes; ++k) sum += matrix->row[i][k] * p.signal.coefficients[k];
    if (i < nodes)
      z[i] = sum;
    else
      lagged = sum;
  }
  p.lagged = legendre_panel_of(head.exact.rule, start, width, z);
}

/// The detector's output and its derivatives at phi from one window (file comment, step 2):
/// y = [Z(phi + A) - Z(phi - A)] / 2A, s = [M(phi + A) - M(phi - A)] / 2A, y' = (s - y) /
/// Lambda, y'' = (s' - y') / Lambda with s' = [S(phi + A) - S(phi - A)] / 2A; without lag y = s.
template <class T>
physics_detail::pulse_values<T> output_at(const line_signal<T>& line, const T& lag,
                                          const T& half_along, const T& phi) noexcept {
  const physics_detail::line_values<T> plus =
      physics_detail::evaluate_line(line, lag, T(phi + half_along));
  const physics_detail::line_values<T> minus =
      physics_detail::evaluate_line(line, lag, T(phi - half_along));
  const T inverse = T(1) / (T(2) * half_along);
  const T s = (plus.integral - minus.integral) * inverse;
  const T ds = (plus.value - minus.value) * inverse;
  if (!(lag > T(0))) {
    const T curvature = (physics_detail::line_slope(line, T(phi + half_along)) -
                         physics_detail::line_slope(line, T(phi - half_along))) *
                        inverse;
    return {s, s, ds, curvature};
  }
  const T y = (plus.integral - lag * plus.lagged - (minus.integral - lag * minus.lagged)) * inverse;
  const T slope = (s - y) / lag;
  return {y, s, slope, T((ds - slope) / lag)};
}

/// S (times the plateau) at the Gauss nodes of one piece [psi, psi + width], into values, and
/// whether it keeps rising towards the disk from `previous` (non-decreasing along psi for
/// Earth-in, non-increasing out; to the across-mean's rounding, ~3e-13 in double where the
/// antiderivatives are large). The nodes' cosines and sines rotate the start's by the family's
/// offsets (no sine or cosine per node); beyond the tail cut S is 0. false where the geometry
/// leaves the jets' domain or S turns back (heights that do not rise together).
template <class T, class Surface>
bool piece_values(const sensor_physics_fast_head<T>& head, const crossing_frame<T, Surface>& f,
                  const T& t_cut, const T& psi, const T& width, int family, T& previous,
                  T* values) noexcept {
  using std::cos;
  using std::sin;
  const T plateau = head.exact.settings.plateau;
  const T tolerance =
      (T(1) / T(1000000000) + T(1000) * std::numeric_limits<T>::epsilon()) * plateau;
  const T cos_start = cos(psi), sin_start = sin(psi);
  for (int k = 0; k < nodes; ++k) {
    const T at = psi + (head.exact.rule.nodes[k] + T(1)) * width / T(2);
    if (T(f.sky_sign) * (at - f.phi_g) > t_cut) {
      values[k] = T(0);
      continue;
    }
    T cp, sp;
    if (family >= 0) {
      cp = cos_start * head.node_cos[family][k] - sin_start * head.node_sin[family][k];
      sp = sin_start * head.node_cos[family][k] + cos_start * head.node_sin[family][k];
    } else {
      cp = cos(at);
      sp = sin(at);
    }
    across_geometry<T> g;
    if (!across_geometry_at(*f.surface, f.probe, scan_point_from(*f.circle, cp, sp), f.cos_b,
                            f.sin_b, g))
      return false;
    values[k] = plateau * across_mean(head, g);
    if ((values[k] - previous) * T(f.sky_sign < 0 ? 1 : -1) < -tolerance) return false;
    previous = values[k];
  }
  return true;
}

/// Builds one window's S: the plan's pieces in scan order, S at each piece's Gauss nodes
/// (piece_values), their integral and lag; a threshold locator's window stops where its output
/// has passed stop_level (NaN: never). false where piece_values fails or odd widths outnumber
/// the scratch matrices.
template <class T, class Surface>
bool build_window(fast_window<T>& window, sensor_physics_fast_workspace<T>& work,
                  const sensor_physics_fast_head<T>& head, const crossing_frame<T, Surface>& f,
                  const piece_plan<T>& plan, const T& stop_level, const T& half_along) noexcept {
  const T lag = head.exact.lag_rad;
  const T disk = head.exact.profile.disk * head.exact.settings.plateau;
  line_signal<T>& line = window.line;
  window.sky_sign = f.sky_sign;
  const bool in = f.sky_sign < 0;
  line.count = 0;
  line.edges = 0;
  line.jumps = false;
  line.start = plan.psi_start;
  line.value_before = in ? T(0) : disk;
  line.value_after = in ? disk : T(0);
  T integral = T(0), lagged = line.value_before, psi = line.start;
  T previous = line.value_before;
  T values[nodes];
  for (int i = 0; i < plan.count; ++i) {
    const T width = plan.width[i];
    if (!piece_values(head, f, plan.t_cut, psi, width, plan.family[i], previous, values))
      return false;
    const lag_matrix<T>* matrix = nullptr;
    if (lag > T(0)) {
      if (plan.family[i] >= 0) {
        matrix = &head.lag_family[plan.family[i]];
      } else {
        if (work.scratch_count >= max_scratch) return false;
        physics_detail::lag_matrix_of(work.scratch[work.scratch_count], head.exact, width);
        matrix = &work.scratch[work.scratch_count++];
      }
    }
    push_piece(line, head, matrix, psi, width, values, integral, lagged);
    psi = psi + width;
    line.end = psi;
    line.integral_end = integral;
    line.lag_end = lagged;
    // The output is final up to psi - A: once it has passed the level there, the crossing lies
    // before, and the rest of the window would serve no locator.
    if (is_finite(stop_level) && i + 1 < plan.count) {
      const T y = output_at(line, lag, half_along, T(psi - half_along)).output;
      if (in ? y >= stop_level : y < stop_level) break;
    }
  }
  return true;
}

/// A window seen by the locator algorithms (at(phi) = {y, y'}).
template <class T>
struct window_output {
  const line_signal<T>* line;
  T lag, half_along;
  lag_point<T> at(const T& phi) const noexcept {
    const physics_detail::pulse_values<T> v = output_at(*line, lag, half_along, phi);
    return {v.output, v.slope};
  }
};

/// What the fast path found: a row it served (the crossings, whatever their status), or one it
/// leaves to the exact chain.
template <class T>
struct fast_result {
  bool served;
  crossings<T> value;
};

/// The threshold locators (file comment, step 3): y rises through the level once in the
/// Earth-in window and falls through it once in the Earth-out window, or in the closed-form
/// relaxation just past them; the normalised peak is the plateau the output settles to.
template <class T>
fast_result<T> locate_threshold(const sensor_physics_fast_head<T>& head, const fast_window<T>& in,
                                const fast_window<T>& out, const T& half_along) noexcept {
  using std::exp;
  using std::log;
  const T lag = head.exact.lag_rad;
  const T disk = head.exact.profile.disk * head.exact.settings.plateau;
  const window_output<T> y_in{&in.line, lag, half_along}, y_out{&out.line, lag, half_along};
  const T in_end = in.line.end + half_along, out_start = out.line.start - half_along;
  const T gap = out_start - in_end;
  // The plateau must settle (e^-20 = 2e-9) before the out-window's signal falls.
  if (!(gap > T(20) * lag) || !(gap > T(0))) return {false, crossings<T>::failed(status::miss)};
  const T y_end = y_in.at(in_end).value;
  const T peak = lag > T(0) ? T(disk - (disk - y_end) * exp(-gap / lag)) : disk;
  const T level = locator_level(head.exact.settings.locator, peak);
  if (!(level > T(0)) || !(level < peak)) return {true, crossings<T>::failed(status::miss)};
  int iterations = 0;
  auto solve = [&](const window_output<T>& w, const T& lo, const T& hi) {
    auto f = [&](const T& phi) {
      const lag_point<T> p = w.at(phi);
      return value_slope<T>{T(p.value - level), p.slope};
    };
    const root<T> r = bracketed_newton(f, lo, hi, T((lo + hi) / T(2)));
    iterations += r.iterations;
    return r.x;
  };
  T phi_in;
  if (y_end >= level)
    phi_in = solve(y_in, T(in.line.start - half_along), in_end);
  else
    phi_in = in_end + lag * log((disk - y_end) / (disk - level));
  const T out_end = out.line.end + half_along;
  const T y_last = y_out.at(out_end).value;
  T phi_out;
  if (y_last < level)
    phi_out = solve(y_out, out_start, out_end);
  else if (lag > T(0))
    phi_out = out_end + lag * log(y_last / level);
  else
    return {true, crossings<T>::failed(status::miss)};
  return {true, crossings_from_azimuths(phi_in, phi_out, iterations)};
}

/// The slope locator: the extremum of sign y' (sign +1 Earth-in, -1 Earth-out) over a window,
/// the root of sign y'' (Illinois) beside the largest of 32 samples, as the exact chain's
/// steepest_place; golden section where y'' keeps its sign (a kink of y').
template <class T>
result<T> steepest(const fast_window<T>& w, const T& lag, const T& half_along, int sign) noexcept {
  constexpr int samples = 32;
  const T lo_end = w.line.start - half_along, hi_end = w.line.end + half_along + T(4) * lag;
  const T step = (hi_end - lo_end) / T(samples - 1);
  int best = -1;
  T best_slope = T(0);
  for (int i = 0; i < samples; ++i) {
    const T slope = T(sign) * output_at(w.line, lag, half_along, T(lo_end + T(i) * step)).slope;
    if (slope > best_slope) {
      best = i;
      best_slope = slope;
    }
  }
  if (best < 0) return result<T>::bad(status::miss);
  const T lo = lo_end + T(best > 0 ? best - 1 : 0) * step;
  const T hi = lo_end + T(best + 1 < samples ? best + 1 : samples - 1) * step;
  auto curvature = [&](const T& x) {
    return T(T(sign) * output_at(w.line, lag, half_along, x).curvature);
  };
  auto slope = [&](const T& x) { return T(T(sign) * output_at(w.line, lag, half_along, x).slope); };
  return result<T>::good(physics_detail::slope_maximum(curvature, slope, lo, hi));
}

/// The locator on the two windows (threshold or slope).
template <class T>
fast_result<T> locate(const sensor_physics_fast_head<T>& head, const fast_window<T>& in,
                      const fast_window<T>& out, const T& half_along) noexcept {
  if (head.exact.settings.locator.kind != locator_kind::slope)
    return locate_threshold(head, in, out, half_along);
  const T lag = head.exact.lag_rad;
  if (!(out.line.start - in.line.end > T(2) * half_along + T(8) * lag))
    return {false, crossings<T>::failed(status::invalid)};
  const result<T> a = steepest(in, lag, half_along, 1), b = steepest(out, lag, half_along, -1);
  if (!a.ok() || !b.ok()) return {true, crossings<T>::failed(status::miss)};
  return {true, crossings_from_azimuths(a.value, b.value, 0)};
}

/// The fast path for one row whose checks passed (row_status ok): the two windows, then the
/// locator. The Earth-out window is built first without its sky tail, which only the output
/// after the crossing sees; when the crossing is found within a half-width of the window's end,
/// the tail is built and the locator runs again. Not served (the exact chain's) when a window
/// cannot be planned or built.
template <class T, class Surface>
fast_result<T> fast_row(const sensor_physics_fast_head<T>& head, const scan_circle<T>& circle,
                        const Surface& surface, const crossings<T>& geometric,
                        sensor_physics_fast_workspace<T>& work) noexcept {
  using std::cos;
  using std::sin;
  const fast_result<T> not_served{false, crossings<T>::failed(status::invalid)};
  const physics_detail::surface_probe<T> probe = physics_detail::probe_of(surface);
  const T half = head.exact.settings.field.fov_rad / T(2);
  const T half_along = field_half_along(head.exact.settings.field, circle.sin_gamma);
  const T chord = geometric.chord();
  const T shorter = chord < T(2) * pi<T>() - chord ? chord : T(T(2) * pi<T>() - chord);
  work.scratch_count = 0;
  const T crossing[2] = {geometric.phi_in, geometric.phi_out};
  // The threshold locators stop each window where its output has passed the level (the
  // normalised level from the settled plateau, L_disk L0: the true peak is below it by at most
  // e^-20 of it, so the Earth-in stop waits 1e-9 above it and the Earth-out one 1e-8 below).
  const horizon_locator<T>& locator = head.exact.settings.locator;
  const bool slope = locator.kind == locator_kind::slope;
  const T disk = head.exact.profile.disk * head.exact.settings.plateau;
  const T level = locator_level(locator, disk);
  const T margin = T(1) / T(1000000000);
  const T stops[2] = {
      slope ? not_a_number<T>()
            : T(locator.kind == locator_kind::normalised ? level * (T(1) + margin) : level),
      slope
          ? not_a_number<T>()
          : T(locator.kind == locator_kind::normalised ? level * (T(1) - T(10) * margin) : level)};
  auto build = [&](int c, bool tail) {
    const T rate = physics_detail::height_rate(circle, surface, probe, crossing[c]);
    if (!(rate > T(0)) || !is_finite(rate)) return false;
    const crossing_frame<T, Surface> f{&circle,          &surface,     probe,        crossing[c],
                                       c == 0 ? -1 : 1,  T(cos(half)), T(sin(half)), rate,
                                       T(shorter / T(2))};
    piece_plan<T> plan;
    return plan_window(head, f, tail, plan) &&
           build_window(work.window[c], work, head, f, plan, stops[c], half_along);
  };
  // The slope locator's Earth-out window is built first without its sky tail (out_reach).
  if (!build(0, true) || !build(1, !slope)) return not_served;
  fast_result<T> r = locate(head, work.window[0], work.window[1], half_along);
  if (r.served && r.value.state == status::ok &&
      r.value.phi_out + half_along <= work.window[1].line.end)
    return r;
  if (!build(1, true)) return not_served;
  return locate(head, work.window[0], work.window[1], half_along);
}

}  // namespace fast_detail

/// The crossings of MODEL §12 for one head and row by the fast method (file comment): the same
/// arguments, statuses and meaning as sensor_physics_crossings, with a fast head and workspace.
///   head: sensor_physics_fast_head_of(settings); circle, surface, sin_sun_declination,
///   geometric: as sensor_physics_crossings; work: the caller's workspace (work.last says which
///   method served the row; work.fast_rows and work.exact_rows count them).
/// Domain of the fast path: a square field, H > 0, no season term, L_disk >= 1, pulses whose
/// plateau is at least 20 Lambda long; every other head or row goes to the exact chain, whose
/// statuses it returns (so do the row's own checks: invalid inputs, a field reaching S, a field
/// as wide as the chord, the geometry's statuses).
/// Statuses of the fast path: ok; miss (a fixed threshold at or above the plateau); grazing of
/// classify_half_chord on the result.
/// Accuracy (docs/SENSOR_PHYSICS.md, "The fast method"; tests/test_sensor_physics_fast.cpp):
/// against the brute-force reference within 3e-8 deg on the brief's case (1.5 deg square, 1 ms
/// of lag at 1 rev/s, normalised 1/2) along the e = 0.1 orbit, 2.3e-8 deg on the fixed and slope
/// locators, k = 0.3, delta50 = 0 and a brighter disk on the apparent horizon (h = 0.005-0.01
/// deg); within 1.7e-8 deg of the exact chain on its tests' cases, 3.4e-7 deg on 100 random
/// scenes (where the two differ by more than 3e-7 deg the reference sides with this method).
/// Float: 4e-6 deg from double.
template <class T, class Surface>
crossings<T> sensor_physics_fast_crossings(const sensor_physics_fast_head<T>& head,
                                           const scan_circle<T>& circle, const Surface& surface,
                                           const T& sin_sun_declination,
                                           const crossings<T>& geometric,
                                           sensor_physics_fast_workspace<T>& work) noexcept {
  if (head.state != status::ok) return crossings<T>::failed(status::invalid);
  if (head.native && physics_detail::row_status(head.exact, circle, surface, sin_sun_declination,
                                                geometric) == status::ok) {
    const fast_detail::fast_result<T> r =
        fast_detail::fast_row(head, circle, surface, geometric, work);
    if (r.served) {
      work.last = physics_method::fast;
      ++work.fast_rows;
      return r.value;
    }
  }
  work.last = physics_method::exact;
  ++work.exact_rows;
  return sensor_physics_crossings(head.exact, circle, surface, sin_sun_declination, geometric,
                                  work.exact);
}

}  // namespace conescan
