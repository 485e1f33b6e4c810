// The brute-force reference of MODEL §12 (sensor_physics_reference.hpp), its first half: the
// scene, the heights, the season term, the profile and the field's mean radiance, written again
// from the definitions in long double, sharing no code with the production physics.
//
// Frames and units: one head and row in the head's scan frame (e3 = S, e1, e2 of MODEL §4), the
// satellite at the origin; lengths in metres, angles in radians, radiance in units of L0 = 1.
//  - line of sight d(phi): azimuth phi about S at angle psi(phi) from S (MODEL §4);
//  - heights (MODEL §12): the line's closest approach to the centre, in the scaled space of
//    MODEL §5 on the ellipsoid, |X| - 1 mapped back to metres along the surface normal at the
//    tangent point a N^-1 X/|X|; signed (< 0: the line meets the surface, MODEL's delta = -inf);
//  - season term: L0 = plateau (1 + A sin(phi_t) sin(dec_sun) / sin 23.44 deg), phi_t the WGS84
//    geodetic latitude (a = 6378137 m, f = 1/298.257223563) of the tangent point (the closest
//    approach mapped to the horizon surface along its scaled direction) seen from the Earth's
//    centre (the apparent horizon's centre is earth_shift_m from it along the pole), on every
//    Earth model, by a fixed-point iteration to 1e-18 rad;
//  - profile: MODEL §12's formula; 0 above delta50 + 36 H, where it is below 1.6e-16 L0;
//  - field: the rigid patch exp_d(x t + y c), t = A x d / |A x d| the scan direction at d (the
//    tangent of the true scan cone about the optical axis A, towards increasing phi), c = d x t,
//    (x, y) in the square |x|, |y| <= w/2 or the disk; the signal is the mean of L over it,
//    weights uniform in (x, y), by an iterated Gauss-Legendre quadrature (16 nodes a piece) whose
//    inner lines run along the patch axis nearer the height gradient; both integrals split where
//    the surface (delta = 0), the step (H = 0: delta50) or a knee level delta50 + k H (k = -4 ..
//    36: pieces of 2 H about the knee, up to 7 H in the tail) crosses the line or the patch's
//    boundary, where a level touches the boundary, and where the lines' closest approach passes
//    the satellite (behind it the height is the satellite's own, flat: a kink), found by Illinois
//    regula falsi on the exact heights. Between splits the integrand is smooth and spans a few H at
//    most, so the error does not depend on H: H = 0 gives the exact area fraction of the patch on
//    the Earth's side of delta50 (weighted by L0); a patch wholly on the disk within 8
//    half-widths of the line through the centre (where the season term's latitude turns with the
//    direction) in polar coordinates about that line instead (polar_disk_mean);
//
// Own error (tests/core/test_sensor_physics_closed_forms.cpp, measured by convergence and against
// closed forms):
//  - field mean: within 1e-18 of L0 of itself with twice the nodes, pieces and samples (300 random
//    patches: fields 0.1-20 deg, square and disk, H 0 or 1 m to 1000 km, sphere and apparent
//    horizon, season term, disk 0.7-1.3); exact area fractions of cut patches against an
//    independent 1-D Gauss-Kronrod oracle to 1e-14 (the oracle's tolerance);
// Cost (CPU, -O2, one core): a field mean 2-25 ms where the patch meets the profile (1.5 deg, H =
// 7 km: 3-8 ms; H of a metre: up to 25 ms), ~10 us where it does not.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "conescan/cone_angle.hpp"
#include "conescan/crossings.hpp"
#include "conescan/vector.hpp"

namespace conescan_test {

using ld = long double;
using vec3l = conescan::vec3<ld>;

inline constexpr ld reference_pi = 3.14159265358979323846264338327950288L;

/// The scene of one head and row, in the head's scan frame (satellite at the origin).
struct reference_scene {
  ld gamma;         ///< the true cone's half-angle about A (rad)
  ld sigma, phi_a;  ///< A's tilt from S and its azimuth about S (rad)
  bool ellipsoid;   ///< informative: a_eq == b_pol is the sphere either way
  vec3l centre;     ///< the horizon surface's centre from the satellite (m)
  vec3l polar;      ///< unit polar axis
  ld a_eq, b_pol;   ///< semi-axes (m); a sphere has a_eq = b_pol = R + h_h
  ld sin_sun;       ///< sine of the Sun's declination
  /// The surface's centre minus the Earth's, along `polar` (m): the apparent horizon's shift. The
  /// season term's latitude is the tangent point's as seen from the Earth's centre.
  ld earth_shift_m = 0;
};

/// The physics settings (SI, radians), as in sensor_physics_settings.
struct reference_settings {
  ld fov;        ///< full width w of the field (rad); 0: a pencil beam
  bool circle;   ///< disk |(x, y)| <= w/2, else the square |x|, |y| <= w/2
  ld lag;        ///< Lambda = 2 pi spin tau (rad of scan azimuth)
  int locator;   ///< 0 normalised, 1 fixed, 2 slope
  ld threshold;  ///< k (normalised) or T (fixed, units of L0 = 1)
  ld scale_m, offset_m, disk, amplitude, plateau;  ///< H, delta50, L_disk/L0, A, plateau
};

struct reference_height {
  ld height;        ///< signed tangent height (m), < 0: the line meets the surface
  ld sin_latitude;  ///< sine of the WGS84 geodetic latitude of the tangent point
};

/// WGS84 geodetic latitude (rad) of a point `rho_m` from the polar axis and `z_m` along it (from
/// the Earth's centre). The fixed point lat = atan2(z + e^2 N(lat) sin lat, rho) from the
/// latitude of the surface point below, iterated until it moves by < 1e-18 rad (~6 steps near
/// the surface; the contraction is about e^2). Domain: points more than ~100 km from the centre.
inline ld reference_geodetic_latitude(ld rho_m, ld z_m) {
  const ld a = 6378137.0L, f = 1 / 298.257223563L, e2 = f * (2 - f);
  ld latitude = std::atan2(z_m, rho_m * (1 - e2));
  for (int i = 0; i < 100; ++i) {
    const ld s = std::sin(latitude);
    const ld n = a / std::sqrt(1 - e2 * s * s);
    const ld next = std::atan2(z_m + e2 * n * s, rho_m);
    const bool done = std::fabs(next - latitude) < 1e-18L;
    latitude = next;
    if (done) break;
  }
  return latitude;
}

namespace reference_detail {

/// The height of the line t d (t >= 0) and, when asked, the latitude of its tangent point.
inline reference_height tangent(const reference_scene& s, const vec3l& d, bool with_latitude) {
  using conescan::dot;
  using conescan::norm;
  // Scaled space (MODEL §5): x' = (x + (a/b - 1)(x.z) z) / a, where the surface is the unit sphere.
  const ld k = s.a_eq / s.b_pol - 1;
  auto scale = [&](const vec3l& v) { return (v + s.polar * (k * dot(v, s.polar))) / s.a_eq; };
  const vec3l c = scale(s.centre), dd = scale(d);
  ld t = dot(c, dd) / dot(dd, dd);
  if (t < 0) t = 0;
  const vec3l x = dd * t - c;  // from the centre to the closest point, scaled
  const ld rho = norm(x);
  const vec3l u = rho > 0 ? x / rho : vec3l(-c / norm(c));
  // The real normal at the surface point a N^-1 u is N u / |N u|.
  const vec3l n = u + s.polar * (k * dot(u, s.polar));
  reference_height h{s.a_eq * (rho - 1) / norm(n), 0};
  if (with_latitude) {
    // The tangent point a N^-1 u from the surface's centre, then from the Earth's.
    const vec3l point = (u + s.polar * ((s.b_pol / s.a_eq - 1) * dot(u, s.polar))) * s.a_eq +
                        s.polar * s.earth_shift_m;
    const ld z = dot(point, s.polar);
    h.sin_latitude = std::sin(reference_geodetic_latitude(norm(point - s.polar * z), z));
  }
  return h;
}

/// Where the line t d's closest approach lies along it, in the scaled space (its t times
/// |dd|^2): <= 0 behind the satellite, where the height is the satellite's own, flat in d
/// (docs/SENSOR_PHYSICS.md, decision 5): the integrand has a kink where it passes 0.
inline ld approach(const reference_scene& s, const vec3l& d) {
  using conescan::dot;
  const ld k = s.a_eq / s.b_pol - 1;
  auto scale = [&](const vec3l& v) { return (v + s.polar * (k * dot(v, s.polar))) / s.a_eq; };
  return dot(scale(s.centre), scale(d));
}

}  // namespace reference_detail

/// The tangent height of the unit direction d and the latitude of its tangent point.
inline reference_height reference_height_of(const reference_scene& s, const vec3l& d) {
  return reference_detail::tangent(s, d, true);
}

/// MODEL §4's true line of sight at scan azimuth phi.
inline vec3l reference_line_of_sight(const reference_scene& s, ld phi) {
  const ld psi = conescan::misaligned_cone_angle<ld>(s.gamma, s.sigma, phi - s.phi_a).value;
  return vec3l(std::sin(psi) * std::cos(phi), std::sin(psi) * std::sin(phi), std::cos(psi));
}

/// MODEL §4's optical axis A.
inline vec3l reference_optical_axis(const reference_scene& s) {
  return vec3l(std::sin(s.sigma) * std::cos(s.phi_a), std::sin(s.sigma) * std::sin(s.phi_a),
               std::cos(s.sigma));
}

/// The field's axes at scan azimuth phi: d, the scan direction t (the true scan path is the cone
/// about A: its tangent A x d, towards increasing phi while sigma < gamma) and c = d x t.
struct reference_patch_axes {
  vec3l d, t, c;
};

inline reference_patch_axes reference_patch_axes_at(const reference_scene& s, ld phi) {
  const vec3l d = reference_line_of_sight(s, phi);
  const vec3l t = conescan::unit(conescan::cross(reference_optical_axis(s), d));
  return {d, t, conescan::cross(d, t)};
}

/// The patch's direction exp_d(x t + y c).
inline vec3l reference_patch_direction(const reference_patch_axes& f, ld x, ld y) {
  const ld r = std::hypot(x, y);
  if (r == 0) return f.d;
  return f.d * std::cos(r) + (f.t * x + f.c * y) * (std::sin(r) / r);
}

/// L0 at a tangent point of latitude sine `sin_latitude` (MODEL §12's season term).
inline ld reference_plateau(const reference_scene& s, const reference_settings& p,
                            ld sin_latitude) {
  const ld obliquity = 23.44L * reference_pi / 180;
  return p.plateau * (1 + p.amplitude * sin_latitude * s.sin_sun / std::sin(obliquity));
}

/// The limb profile l(delta) = L / L0 as printed in MODEL §12 (L_disk / L0 below the surface).
inline ld reference_profile(const reference_settings& p, ld height) {
  if (height < 0) return p.disk;
  if (p.scale_m == 0) return height < p.offset_m ? 1 : height > p.offset_m ? 0 : 0.5L;
  const ld z = (height - p.offset_m) / p.scale_m;
  if (z > 36) return 0;  // below ln 2 e^-36 = 1.6e-16: the sky (top_of_profile)
  return -std::expm1(-std::log(2.0L) * std::exp(-z));
}

inline ld reference_radiance(const reference_scene& s, const reference_settings& p,
                             const reference_height& h) {
  return reference_plateau(s, p, h.sin_latitude) * reference_profile(p, h.height);
}

namespace reference_detail {

/// The radiance along d (the latitude computed only where the season term needs it).
inline ld radiance_along(const reference_scene& s, const reference_settings& p, const vec3l& d) {
  return reference_radiance(s, p, tangent(s, d, p.amplitude != 0));
}

/// Gauss-Legendre nodes and weights on [-1, 1] by Newton's method (long double).
struct gauss_rule {
  std::vector<ld> x, w;
};

inline gauss_rule gauss_legendre(int n) {
  gauss_rule r{std::vector<ld>(static_cast<std::size_t>(n)),
               std::vector<ld>(static_cast<std::size_t>(n))};
  for (int i = 0; i < n; ++i) {
    ld z = std::cos(reference_pi * (i + 0.75L) / (n + 0.5L)), dp = 1;
    for (int it = 0; it < 100; ++it) {
      ld p0 = 1, p1 = z;
      for (int k = 2; k <= n; ++k) {
        const ld p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (z * p1 - p0) / (z * z - 1);
      const ld dz = p1 / dp;
      z -= dz;
      if (std::fabs(dz) < 1e-19L) break;
    }
    r.x[static_cast<std::size_t>(i)] = -z;
    r.w[static_cast<std::size_t>(i)] = 2 / ((1 - z * z) * dp * dp);
  }
  return r;
}

/// The rules of 1 to 64 nodes, built once (thread-safe).
inline const gauss_rule& gauss(int n) {
  static const std::vector<gauss_rule> rules = [] {
    std::vector<gauss_rule> r(65);
    for (int k = 1; k <= 64; ++k) r[static_cast<std::size_t>(k)] = gauss_legendre(k);
    return r;
  }();
  return rules[static_cast<std::size_t>(std::clamp(n, 1, 64))];
}

/// The root of f in [lo, hi], f(lo) and f(hi) of opposite signs: Illinois regula falsi with a
/// bisection every fourth step, until the bracket has no representable point inside or is below
/// 1e-18 (1 + |lo| + |hi|).
template <class F>
ld bracketed_root(const F& f, ld lo, ld hi, ld f_lo, ld f_hi) {
  int side = 0;
  for (int it = 0; it < 400; ++it) {
    if (hi - lo <= 1e-18L * (1 + std::fabs(lo) + std::fabs(hi))) break;
    ld x = it % 4 == 3 ? (lo + hi) / 2 : (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
    if (!(x > lo && x < hi)) x = (lo + hi) / 2;
    if (!(x > lo && x < hi)) break;
    const ld fx = f(x);
    if (fx == 0) return x;
    if ((fx < 0) == (f_lo < 0)) {
      lo = x;
      f_lo = fx;
      if (side == -1) f_hi /= 2;
      side = -1;
    } else {
      hi = x;
      f_hi = fx;
      if (side == 1) f_lo /= 2;
      side = 1;
    }
  }
  return (lo + hi) / 2;
}

/// The maximum of a unimodal g on [a, b] by golden section (to the last digits).
template <class G>
ld golden_maximum(const G& g, ld a, ld b, ld& where) {
  const ld ratio = (std::sqrt(5.0L) - 1) / 2;
  ld x1 = b - ratio * (b - a), x2 = a + ratio * (b - a), g1 = g(x1), g2 = g(x2);
  for (int it = 0; it < 120 && b - a > 1e-19L * (1 + std::fabs(a)); ++it) {
    if (g1 < g2) {
      a = x1;
      x1 = x2;
      g1 = g2;
      x2 = a + ratio * (b - a);
      g2 = g(x2);
    } else {
      b = x2;
      x2 = x1;
      g2 = g1;
      x1 = b - ratio * (b - a);
      g1 = g(x1);
    }
  }
  where = (a + b) / 2;
  return std::max(g1, g2);
}

/// Where f crosses any of `levels` on [lo, hi]: f sampled at n + 1 points, its local extrema
/// between them found by golden section, so that f is monotone between consecutive points and
/// crosses each level at most once there; each sign change of f - level refined by
/// bracketed_root. Roots are appended to out, and the extrema too when `extrema_too` (where a
/// level touches the line without crossing it the integrand is not smooth).
template <class F>
void level_roots(const F& f, ld lo, ld hi, int n, const std::vector<ld>& levels,
                 std::vector<ld>& out, bool extrema_too = false) {
  std::vector<ld> x, v;
  for (int i = 0; i <= n; ++i) {
    x.push_back(i == n ? hi : lo + (hi - lo) * i / n);
    v.push_back(f(x.back()));
    const std::size_t k = x.size() - 1;
    if (k < 2 || !((v[k - 1] - v[k - 2]) * (v[k] - v[k - 1]) < 0)) continue;
    const ld sign = v[k - 1] > v[k - 2] ? 1 : -1;
    ld where = x[k - 1];
    const ld extremum =
        sign * golden_maximum([&](ld t) { return sign * f(t); }, x[k - 2], x[k], where);
    const std::size_t at = where < x[k - 1] ? k - 1 : k;  // keep x sorted
    x.insert(x.begin() + static_cast<std::ptrdiff_t>(at), where);
    v.insert(v.begin() + static_cast<std::ptrdiff_t>(at), extremum);
    if (extrema_too) out.push_back(where);
  }
  for (ld level : levels)
    for (std::size_t i = 0; i + 1 < x.size(); ++i) {
      const ld a = v[i] - level, b = v[i + 1] - level;
      if ((a < 0) != (b < 0))
        out.push_back(bracketed_root([&](ld t) { return f(t) - level; }, x[i], x[i + 1], a, b));
    }
}

/// The quadrature's resolution: Gauss nodes per piece; pieces: an interval between splits is cut
/// into pieces no longer than 1/pieces of its line's (or the outer range's) full length; samples
/// per line for the splits' search. The defaults are the reference; tests double them to measure
/// its error.
struct quadrature_options {
  int nodes = 16;
  int pieces = 2;
  int samples = 16;
};

/// Gauss sum of g over [lo, hi] (part of a range of length `full`), in pieces of at most
/// full / q.pieces, `nodes` nodes each.
template <class G>
ld gauss_sum(const G& g, ld lo, ld hi, ld full, const quadrature_options& q) {
  const gauss_rule& r = gauss(q.nodes);
  const int count = std::max(1, static_cast<int>(std::ceil((hi - lo) / full * q.pieces - 1e-9L)));
  const ld width = (hi - lo) / count;
  ld sum = 0;
  for (int k = 0; k < count; ++k) {
    const ld a = lo + k * width;
    for (std::size_t i = 0; i < r.x.size(); ++i)
      sum += r.w[i] * width / 2 * g(a + (r.x[i] + 1) * width / 2);
  }
  return sum;
}

/// One patch at one scan azimuth: inner lines along coordinate a, outer coordinate b; (a, b) is
/// (x, y), or (y, x) when the height gradient is nearer y. The outer parameter q: the square
/// b = q in [-w/2, w/2], a in [-w/2, w/2]; the disk b = (w/2) sin q, q in [-pi/2, pi/2], a within
/// +-(w/2) cos q, db = (w/2) cos q dq (smooth at the disk's ends).
struct patch {
  const reference_scene* scene;
  const reference_settings* settings;
  reference_patch_axes axes;
  ld half;
  bool circle, swap;

  vec3l direction(ld a, ld b) const {
    return swap ? reference_patch_direction(axes, b, a) : reference_patch_direction(axes, a, b);
  }
  ld height(ld a, ld b) const { return tangent(*scene, direction(a, b), false).height; }
  ld ahead(ld a, ld b) const { return approach(*scene, direction(a, b)); }
  ld radiance(ld a, ld b) const { return radiance_along(*scene, *settings, direction(a, b)); }
  ld outer_end() const { return circle ? reference_pi / 2 : half; }
  ld across(ld q) const { return circle ? half * std::sin(q) : q; }
  ld reach(ld q) const { return circle ? half * std::cos(q) : half; }
  ld jacobian(ld q) const { return circle ? half * std::cos(q) : 1; }
  ld area() const { return circle ? reference_pi * half * half : 4 * half * half; }
};

inline patch patch_at(const reference_scene& s, const reference_settings& p, ld phi) {
  patch f{&s, &p, reference_patch_axes_at(s, phi), p.fov / 2, p.circle, false};
  const ld e = f.half * 1e-3L;
  const ld gx = f.height(e, 0) - f.height(-e, 0), gy = f.height(0, e) - f.height(0, -e);
  f.swap = std::fabs(gy) > std::fabs(gx);
  return f;
}

/// The heights where the integrand jumps or bends: the surface (0), the step (H = 0: delta50) or
/// the knee levels delta50 + k H above the surface; only those within the patch's range of heights
/// (sampled on a 9 x 9 grid, widened by the heights' curvature between the samples, |c| (w/8)^2).
struct patch_levels {
  std::vector<ld> levels;
  ld lowest, highest;  ///< the sampled range, widened
};

inline const std::vector<ld>& knee_steps() {
  static const std::vector<ld> k{-4, -2, 0, 2, 4, 7, 11, 16, 22, 29, 36};
  return k;
}

/// The heights where the profile jumps: the surface (0) and, for a step (H = 0), delta50.
inline std::vector<ld> jump_levels(const reference_settings& p) {
  std::vector<ld> levels{0};
  if (p.scale_m == 0 && p.offset_m > 0) levels.push_back(p.offset_m);
  return levels;
}

/// The heights where the profile jumps or bends: jump_levels, then the knee levels for H > 0.
inline std::vector<ld> bend_levels(const reference_settings& p) {
  std::vector<ld> levels = jump_levels(p);
  if (p.scale_m > 0)
    for (ld k : knee_steps())
      if (p.offset_m + k * p.scale_m > 0) levels.push_back(p.offset_m + k * p.scale_m);
  return levels;
}

inline patch_levels levels_of(const patch& f) {
  const reference_settings& p = *f.settings;
  patch_levels r{{}, 1e300L, -1e300L};
  for (int i = -4; i <= 4; ++i)
    for (int j = -4; j <= 4; ++j) {
      const ld h = f.height(f.half * i / 4, f.half * j / 4);
      r.lowest = std::min(r.lowest, h);
      r.highest = std::max(r.highest, h);
    }
  const ld margin = conescan::norm(f.scene->centre) * (f.half / 4) * (f.half / 4);
  r.lowest -= margin;
  r.highest += margin;
  for (ld level : bend_levels(p))
    if (level >= r.lowest && level <= r.highest) r.levels.push_back(level);
  return r;
}

/// The integral of L along the inner line at b, a in [-reach, reach], split at the levels and
/// where the line's closest approach passes the satellite (approach: the heights' kink).
inline ld inner_integral(const patch& f, const std::vector<ld>& levels, ld b, ld reach,
                         const quadrature_options& q) {
  if (!(reach > 0)) return 0;
  std::vector<ld> cuts{-reach, reach};
  level_roots([&](ld a) { return f.ahead(a, b); }, -reach, reach, q.samples, {0}, cuts);
  if (!levels.empty())
    level_roots([&](ld a) { return f.height(a, b); }, -reach, reach, q.samples, levels, cuts);
  std::sort(cuts.begin(), cuts.end());
  ld sum = 0;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i)
    sum += gauss_sum([&](ld a) { return f.radiance(a, b); }, cuts[i], cuts[i + 1], 2 * reach, q);
  return sum;
}

/// The patch's mean radiance: the outer integral split where a level or the heights' kink
/// (approach) crosses the patch's boundary (the ends a = +-reach of the inner lines), each outer
/// node an inner integral.
inline ld patch_mean(const patch& f, const std::vector<ld>& levels, const quadrature_options& q) {
  const ld end = f.outer_end();
  std::vector<ld> cuts{-end, end};
  for (int sign = -1; sign <= 1; sign += 2)
    level_roots([&](ld t) { return f.ahead(sign * f.reach(t), f.across(t)); }, -end, end,
                2 * q.samples, {0}, cuts);
  if (!levels.empty())
    for (int sign = -1; sign <= 1; sign += 2)
      level_roots([&](ld t) { return f.height(sign * f.reach(t), f.across(t)); }, -end, end,
                  2 * q.samples, levels, cuts, true);
  std::sort(cuts.begin(), cuts.end());
  ld sum = 0;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i)
    sum += gauss_sum(
        [&](ld t) { return f.jacobian(t) * inner_integral(f, levels, f.across(t), f.reach(t), q); },
        cuts[i], cuts[i + 1], 2 * end, q);
  return sum / f.area();
}

/// The patch's point (x, y) on the line through the horizon surface's centre, where the tangent
/// point's latitude (the closest approach's direction, decision 2) turns about the line: f
/// jumps there with the direction of approach, which the iterated rule above resolves only as
/// 1/n^2 (a 2.25 deg square 33 000 km out with that line inside: 1e-5 of L0 off). false where the
/// line lies behind the satellite or more than 8 half-widths from the patch's centre (the
/// iterated rule's pieces then converge as usual).
inline bool centre_point(const reference_scene& s, const reference_patch_axes& axes, ld half, ld& x,
                         ld& y) {
  using conescan::dot;
  const vec3l v = conescan::unit(s.centre);
  const ld along = dot(v, axes.d), xt = dot(v, axes.t), yc = dot(v, axes.c);
  const ld across = std::hypot(xt, yc);
  if (!(along > 0)) return false;
  const ld r = std::atan2(across, along);
  x = across > 0 ? r * xt / across : 0;
  y = across > 0 ? r * yc / across : 0;
  return std::hypot(x, y) < 8 * half;
}

/// The mean of L over a patch wholly on the disk (L = L_disk L0(latitude)) with the centre's line
/// at (cx, cy): polar coordinates about that point, where the latitude is smooth. The patch's
/// boundary (the square's four edges, or the circle as one closed curve), parametrised by its
/// arc, is swept by signed triangles from the point: int dtheta int_0^rho(theta) f r dr, as
/// int ds cross(B(s) - c, B'(s)) int_0^1 f(c + l (B(s) - c)) l dl. Along the boundary the
/// integrand turns on the scale of the point's distance, so each edge (or the circle) is cut at
/// its place nearest the point and graded geometrically from it (widths r, r, 2r, 4r, ..., r
/// that distance, floored at 1e-13 of the half-width); 16 Gauss nodes each way.
inline ld polar_disk_mean(const reference_scene& s, const reference_settings& p,
                          const reference_patch_axes& axes, ld cx, ld cy) {
  const ld h = p.fov / 2;
  const gauss_rule& g = gauss(16);
  auto f = [&](ld x, ld y) { return radiance_along(s, p, reference_patch_direction(axes, x, y)); };
  // The boundary B(s), s in [s0, s1], and its derivative; its place nearest the point.
  struct curve {
    ld x0, y0, x1, y1;  // an edge from (x0, y0) to (x1, y1); the circle when `round`
    bool round;
  };
  auto at = [&](const curve& b, ld t, ld& x, ld& y, ld& dx, ld& dy) {
    if (b.round) {
      x = h * std::cos(t), y = h * std::sin(t), dx = -y, dy = x;
    } else {
      x = b.x0 + (b.x1 - b.x0) * t, y = b.y0 + (b.y1 - b.y0) * t;
      dx = b.x1 - b.x0, dy = b.y1 - b.y0;
    }
  };
  auto panel = [&](const curve& b, ld t0, ld t1) {
    ld sum = 0;
    for (std::size_t i = 0; i < g.x.size(); ++i) {
      const ld t = t0 + (g.x[i] + 1) * (t1 - t0) / 2;
      ld x, y, dx, dy;
      at(b, t, x, y, dx, dy);
      ld ray = 0;
      for (std::size_t k = 0; k < g.x.size(); ++k) {
        const ld l = (g.x[k] + 1) / 2;
        ray += g.w[k] / 2 * l * f(cx + l * (x - cx), cy + l * (y - cy));
      }
      sum += g.w[i] * (t1 - t0) / 2 * ((x - cx) * dy - (y - cy) * dx) * ray;
    }
    return sum;
  };
  auto sweep = [&](const curve& b, ld lo, ld hi, ld nearest, ld scale) {
    ld sum = 0;
    for (int side = -1; side <= 1; side += 2) {
      ld from = nearest, width = std::max(scale, (hi - lo) * 1e-13L);
      while (side > 0 ? from < hi : from > lo) {
        const ld to = side > 0 ? std::min(hi, from + width) : std::max(lo, from - width);
        sum += side > 0 ? panel(b, from, to) : panel(b, to, from);
        width = std::fabs(to - nearest);
        from = to;
      }
    }
    return sum;
  };
  ld sum = 0;
  if (p.circle) {
    const curve b{0, 0, 0, 0, true};
    const ld angle = std::atan2(cy, cx), distance = std::fabs(std::hypot(cx, cy) - h);
    sum = sweep(b, angle - reference_pi, angle + reference_pi, angle, distance / h);
  } else {
    const ld corner[5][2] = {{-h, -h}, {h, -h}, {h, h}, {-h, h}, {-h, -h}};
    for (int e = 0; e < 4; ++e) {
      const curve b{corner[e][0], corner[e][1], corner[e + 1][0], corner[e + 1][1], false};
      const ld ex = b.x1 - b.x0, ey = b.y1 - b.y0, length2 = ex * ex + ey * ey;
      const ld t = std::clamp(((cx - b.x0) * ex + (cy - b.y0) * ey) / length2, 0.0L, 1.0L);
      const ld distance = std::hypot(b.x0 + ex * t - cx, b.y0 + ey * t - cy);
      sum += sweep(b, 0, 1, t, distance / std::sqrt(length2));
    }
  }
  return sum / (p.circle ? reference_pi * h * h : 4 * h * h);
}

/// The highest height where the radiance is above 1e-16 L0 (ln 2 e^-36): the sky beyond is 0.
inline ld top_of_profile(const reference_settings& p) {
  return std::max<ld>(p.offset_m + 36 * p.scale_m, 0);
}

/// The field mean with the quadrature's resolution q. Shortcuts, exact to 1e-16 L0: a patch
/// wholly above the profile's top is 0; wholly in the disk without the season term, L_disk L0.
inline ld field_mean(const reference_scene& s, const reference_settings& p, ld phi,
                     const quadrature_options& q) {
  if (p.fov == 0) return radiance_along(s, p, reference_line_of_sight(s, phi));
  const patch f = patch_at(s, p, phi);
  const patch_levels l = levels_of(f);
  if (l.levels.empty()) {
    if (l.lowest > top_of_profile(p)) return 0;
    if (l.highest < 0 && p.amplitude == 0) return p.disk * p.plateau;
    ld cx, cy;
    if (l.highest < 0 && centre_point(s, f.axes, f.half, cx, cy))
      return polar_disk_mean(s, p, f.axes, cx, cy);
  }
  return patch_mean(f, l.levels, q);
}

}  // namespace reference_detail

/// The signal s(phi): the field's mean radiance at scan azimuth phi (a pencil's radiance at d).
inline ld reference_field_mean(const reference_scene& s, const reference_settings& p, ld phi) {
  return reference_detail::field_mean(s, p, phi, reference_detail::quadrature_options{});
}

}  // namespace conescan_test
