// A brute-force reference of MODEL §12's chain, for the tests and the benchmark only. It shares no
// code with include/conescan/sensor_physics.hpp and its helpers: every step is written again from
// the definitions, in long double, the simple way:
//  - heights: the line's closest approach as vectors (sphere: |t d - c|, t = d.c; ellipsoid: the
//    same in the scaled space, mapped back along the normal);
//  - radiance: the formula as printed, L0 [1 - exp(-ln 2 exp(-(delta - delta50)/H))];
//  - field: a dense 2-D Gauss quadrature over (a, b) (24 nodes per piece across, composite 8-node
//    Gauss along), its pieces split where the surface (or the step) crosses the field, found by
//    bisection on the heights: the definition of field_of_view.hpp integrated directly;
//  - detector: the exact first-order-hold update on a uniform grid over the whole turn (step h),
//    the grid also at 2 h, the crossings extrapolated (Richardson, h^2);
//  - locator: crossings inside a step by bisection on the held signal's closed form; the peak as
//    the grid's maximum refined inside its cell.
// Cost: seconds per row (the fast method's accuracy is measured against it, never its speed).
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "conescan/cone_angle.hpp"
#include "conescan/crossings.hpp"
#include "conescan/vector.hpp"

namespace conescan_test {

using ld = long double;
using vec3l = conescan::vec3<ld>;

/// The scene of one head and row, in the head's scan frame (satellite at the origin).
struct reference_scene {
  ld gamma, sigma, phi_a;  ///< the true cone (rad)
  bool ellipsoid;
  vec3l centre;    ///< the surface's centre from the satellite (m)
  vec3l polar;     ///< unit polar axis
  ld a_eq, b_pol;  ///< semi-axes (m); a sphere has a_eq = b_pol = R + h_h
  ld sin_sun;      ///< sine of the Sun's declination
};

/// The physics settings, as in sensor_physics_settings (SI, radians).
struct reference_settings {
  ld fov;
  bool circle;
  ld lag;       ///< Lambda = 2 pi spin tau (rad)
  int locator;  ///< 0 normalised, 1 fixed, 2 slope
  ld threshold;
  ld scale_m, offset_m, disk, amplitude, plateau;
};

struct reference_height {
  ld height;  ///< signed closest approach (m)
  ld sin_latitude;
};

/// The closest approach of the ray t d (t >= 0) to the surface, and the latitude of its point.
inline reference_height reference_height_of(const reference_scene& s, const vec3l& d) {
  using conescan::dot;
  using conescan::norm;
  // Scaled space: x' = x + (a/b - 1)(x.z) z, divided by a (the unit sphere is the surface).
  const ld k = s.a_eq / s.b_pol - 1;
  auto scale = [&](const vec3l& v) { return (v + s.polar * (k * dot(v, s.polar))) / s.a_eq; };
  const vec3l c = scale(s.centre), dd = scale(d);
  ld t = dot(c, dd) / dot(dd, dd);
  if (t < 0) t = 0;
  const vec3l x = dd * t - c;  // from the centre to the closest point, scaled
  const ld rho = norm(x);
  vec3l u = rho > 0 ? x / rho : vec3l(-c / norm(c));
  // The real normal at the surface point a N^-1 u is N u / |N u|.
  const vec3l n = u + s.polar * (k * dot(u, s.polar));
  const ld n_length = norm(n);
  return {s.a_eq * (rho - 1) / n_length, dot(n, s.polar) / n_length};
}

/// The line of sight at scan azimuth phi and polar offset b (the field's point (phi, psi + b)).
inline vec3l reference_direction(const reference_scene& s, ld phi, ld b) {
  const ld psi = conescan::misaligned_cone_angle<ld>(s.gamma, s.sigma, phi - s.phi_a).value;
  const ld polar = psi + b;
  return vec3l(std::sin(polar) * std::cos(phi), std::sin(polar) * std::sin(phi), std::cos(polar));
}

inline ld reference_radiance(const reference_scene& s, const reference_settings& p,
                             const reference_height& h) {
  const ld obliquity = 23.44L * 3.14159265358979323846264338327950288L / 180;
  const ld l0 = p.plateau * (1 + p.amplitude * h.sin_latitude * s.sin_sun / std::sin(obliquity));
  if (h.height < 0) return l0 * p.disk;
  if (p.scale_m == 0) return h.height < p.offset_m ? l0 : h.height > p.offset_m ? 0 : l0 / 2;
  const ld x = (h.height - p.offset_m) / p.scale_m;
  if (x > 80) return 0;
  return l0 * (1 - std::exp(-std::log(2.0L) * std::exp(-x)));
}

namespace reference_detail {

/// Gauss-Legendre nodes and weights by Newton's method (written again, long double).
inline void gauss(int n, std::vector<ld>& x, std::vector<ld>& w) {
  x.assign(n, 0);
  w.assign(n, 0);
  const ld pi = 3.14159265358979323846264338327950288L;
  for (int i = 0; i < n; ++i) {
    ld z = std::cos(pi * (i + 0.75L) / (n + 0.5L)), dp = 1;
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
    x[i] = -z;
    w[i] = 2 / ((1 - z * z) * dp * dp);
  }
}

struct rules {
  std::vector<ld> x8, w8, x24, w24;
  rules() {
    gauss(8, x8, w8);
    gauss(24, x24, w24);
  }
};

inline const rules& rule() {
  static const rules r;
  return r;
}

/// Roots of f on [lo, hi] found by sampling (n cells) and bisection, sorted.
template <class F>
void roots(const F& f, ld lo, ld hi, int n, std::vector<ld>& out) {
  ld a = lo, fa = f(lo);
  for (int i = 1; i <= n; ++i) {
    const ld b = lo + (hi - lo) * i / n, fb = f(b);
    if ((fa < 0) != (fb < 0)) {
      ld l = a, h = b, fl = fa;
      for (int it = 0; it < 80; ++it) {
        const ld m = (l + h) / 2, fm = f(m);
        if ((fm < 0) == (fl < 0)) {
          l = m;
          fl = fm;
        } else {
          h = m;
        }
      }
      out.push_back((l + h) / 2);
    }
    a = b;
    fa = fb;
  }
}

}  // namespace reference_detail

/// The field's mean radiance at scan azimuth phi, by dense quadrature of the definition.
inline ld reference_field_mean(const reference_scene& s, const reference_settings& p, ld phi) {
  using namespace reference_detail;
  const rules& r = rule();
  auto radiance_at = [&](ld at, ld b) {
    return reference_radiance(s, p, reference_height_of(s, reference_direction(s, at, b)));
  };
  if (p.fov == 0) return radiance_at(phi, 0);
  const ld half = p.fov / 2, sin_gamma = std::sin(s.gamma);
  // The levels where the radiance jumps.
  std::vector<ld> levels{0};
  if (p.scale_m == 0 && p.offset_m > 0) levels.push_back(p.offset_m);
  // Along a line at across-offset b: [phi - A_b, phi + A_b], split at the jumps, composite
  // 8-point Gauss (pieces of at most A/4).
  auto along = [&](ld b, ld a) {
    if (!(a > 0)) return radiance_at(phi, b);
    std::vector<ld> cuts{phi - a, phi + a};
    for (ld level : levels)
      roots(
          [&](ld x) { return reference_height_of(s, reference_direction(s, x, b)).height - level; },
          phi - a, phi + a, 8, cuts);
    std::sort(cuts.begin(), cuts.end());
    ld sum = 0;
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
      const int pieces = 1 + static_cast<int>(4 * (cuts[i + 1] - cuts[i]) / a);
      const ld width = (cuts[i + 1] - cuts[i]) / pieces;
      for (int k = 0; k < pieces; ++k) {
        const ld lo = cuts[i] + k * width;
        for (int q = 0; q < 8; ++q)
          sum += r.w8[q] * width / 2 * radiance_at(lo + (r.x8[q] + 1) * width / 2, b);
      }
    }
    return sum / (2 * a);
  };
  // Across: the parameter t in [-1, 1] (square b = half t; circle b = half sin(pi t / 2)),
  // split where a jump crosses the box ends phi +- A_b, 24-point Gauss on each piece.
  const ld pi = 3.14159265358979323846264338327950288L;
  auto point = [&](ld t, ld& b, ld& a, ld& density) {
    if (!p.circle) {
      b = half * t;
      a = half / sin_gamma;
      density = 0.5L;
    } else {
      b = half * std::sin(pi * t / 2);
      a = half * std::cos(pi * t / 2) / sin_gamma;
      density = std::cos(pi * t / 2) * std::cos(pi * t / 2);
    }
  };
  std::vector<ld> cuts{-1, 1};
  for (ld level : levels)
    for (int sign = -1; sign <= 1; sign += 2)
      roots(
          [&](ld t) {
            ld b, a, d;
            point(t, b, a, d);
            return reference_height_of(s, reference_direction(s, phi + sign * a, b)).height - level;
          },
          -1, 1, 16, cuts);
  std::sort(cuts.begin(), cuts.end());
  ld sum = 0, total = 0;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i)
    for (int q = 0; q < 24; ++q) {
      const ld t = cuts[i] + (r.x24[q] + 1) * (cuts[i + 1] - cuts[i]) / 2;
      const ld weight = r.w24[q] * (cuts[i + 1] - cuts[i]) / 2;
      ld b, a, d;
      point(t, b, a, d);
      sum += weight * d * along(b, a);
      total += weight * d;
    }
  return sum / total;
}

/// The result of the reference: crossings, the peak, and the grid.
struct reference_result {
  conescan::crossings<ld> crossings;
  ld peak;
  ld level;
};

namespace reference_detail {

/// y inside a first-order-hold step of length h from y0, s0 to s1, at x in [0, h].
inline ld held_output(ld y0, ld s0, ld s1, ld h, ld lag, ld x) {
  const ld m = (s1 - s0) / h;
  if (lag == 0) return s0 + m * x;
  const ld e = std::exp(-x / lag);
  return s0 + m * x - m * lag * (1 - e) + (y0 - s0) * e;
}

struct grid_result {
  ld in, out, peak, level;
  bool ok;
};

/// The chain on the grid phi_k = start + k h (k = 0 .. n): s given, y by the exact hold.
inline grid_result on_grid(const std::vector<ld>& s, ld start, ld h, const reference_settings& p) {
  const std::size_t n = s.size();
  std::vector<ld> y(n);
  y[0] = s[0];
  for (std::size_t k = 0; k + 1 < n; ++k) y[k + 1] = held_output(y[k], s[k], s[k + 1], h, p.lag, h);
  grid_result g{0, 0, 0, 0, false};
  // The peak: the largest sample, then the largest value inside its two cells.
  std::size_t best = 0;
  for (std::size_t k = 1; k < n; ++k)
    if (y[k] > y[best]) best = k;
  g.peak = y[best];
  // The grid's cells are defined below (cell_value); the peak inside the best sample's cells.
  std::size_t peak_cell = best;

  // Without lag the held signal is the samples joined by lines, whose crossing error depends on
  // where the crossing falls in its cell (not a smooth function of h: no extrapolation); the
  // crossing is then the root of the cubic through the four samples about the cell, O(h^4).
  auto cubic = [&](std::size_t c, ld x) {
    const std::size_t k0 = c >= 1 ? (c + 2 < n ? c - 1 : n - 4) : 0;
    ld sum = 0;
    for (int i = 0; i < 4; ++i) {
      ld term = s[k0 + i];
      for (int m = 0; m < 4; ++m)
        if (m != i) term *= (x - (ld(k0 + m) - ld(c)) * h) / ((ld(i) - ld(m)) * h);
      sum += term;
    }
    return sum;
  };
  auto cell_value = [&](std::size_t c, ld x) {
    return p.lag > 0 ? held_output(y[c], s[c], s[c + 1], h, p.lag, x) : cubic(c, x);
  };
  auto cell_root = [&](std::size_t c, ld level) {
    ld lo = 0, hi = h;
    const bool rising = y[c] < level;
    for (int it = 0; it < 90; ++it) {
      const ld m = (lo + hi) / 2;
      const ld v = cell_value(c, m);
      if ((v < level) == rising)
        lo = m;
      else
        hi = m;
    }
    return start + c * h + (lo + hi) / 2;
  };
  for (std::size_t c = peak_cell > 0 ? peak_cell - 1 : 0; c <= peak_cell && c + 1 < n; ++c)
    for (int i = 1; i < 400; ++i) {
      const ld v = cell_value(c, h * i / 400);
      if (v > g.peak) g.peak = v;
    }
  if (p.locator == 2) {
    // The extremum of y' = (s - y) / lag (or s' without lag) at the nodes, vertex of a parabola.
    std::vector<ld> d(n);
    for (std::size_t k = 0; k < n; ++k)
      d[k] = p.lag > 0 ? (s[k] - y[k]) / p.lag
                       : (k + 1 < n ? (s[k + 1] - s[k]) / h : (s[k] - s[k - 1]) / h);
    // The largest node, then the extremum of the quartic through the five nodes about it (by
    // golden section on [-h, h] about the node): O(h^4) for a smooth y'.
    auto extremum = [&](int sign) {
      std::size_t b = 2;
      for (std::size_t k = 2; k + 2 < n; ++k)
        if (sign * d[k] > sign * d[b]) b = k;
      auto quartic = [&](ld x) {  // x in units of h from node b
        ld sum = 0;
        for (int i = -2; i <= 2; ++i) {
          ld term = d[b + i];
          for (int m = -2; m <= 2; ++m)
            if (m != i) term *= (x - m) / ld(i - m);
          sum += term;
        }
        return sign * sum;
      };
      ld lo = -1, hi = 1;
      const ld ratio = (std::sqrt(5.0L) - 1) / 2;
      for (int it = 0; it < 90; ++it) {
        const ld x1 = hi - ratio * (hi - lo), x2 = lo + ratio * (hi - lo);
        if (quartic(x1) < quartic(x2))
          lo = x1;
        else
          hi = x2;
      }
      const ld shift = p.lag > 0 ? 0 : h / 2;  // the difference sits between its nodes
      return start + (b + (lo + hi) / 2) * h + shift;
    };
    g.in = extremum(1);
    g.out = extremum(-1);
    g.ok = true;
    return g;
  }
  g.level = p.locator == 0 ? p.threshold * g.peak : p.threshold;
  bool found_in = false, found_out = false;
  for (std::size_t k = 0; k + 1 < n && !found_in; ++k)
    if (y[k] < g.level && y[k + 1] >= g.level) {
      g.in = cell_root(k, g.level);
      found_in = true;
    }
  for (std::size_t k = n - 1; k > 0 && !found_out; --k)
    if (y[k - 1] >= g.level && y[k] < g.level) {
      g.out = cell_root(k - 1, g.level);
      found_out = true;
    }
  g.ok = found_in && found_out;
  return g;
}

}  // namespace reference_detail

/// The reference crossings: s on a uniform grid of step h_rad over the whole turn, starting
/// opposite the Earth (the field quadrature skipped where all the field's corners lie more than
/// 60 H above the profile, where the radiance is below e^-60), y by the exact hold from y = s
/// there, the crossings on the grid of h and of 2 h extrapolated.
inline reference_result reference_crossings(const reference_scene& s, const reference_settings& p,
                                            ld phi_middle, ld h_rad) {
  const ld pi = 3.14159265358979323846264338327950288L;
  const ld start = phi_middle - pi;
  const std::size_t n = static_cast<std::size_t>(std::ceil(2 * pi / h_rad));
  const ld h = 2 * pi / n;
  const ld half = p.fov / 2, a = half / std::sin(s.gamma);
  const ld far = p.offset_m + 60 * (p.scale_m > 0 ? p.scale_m : 1);
  std::vector<ld> signal(n + 1);
  for (std::size_t k = 0; k <= n; ++k) {
    const ld phi = start + k * h;
    // The field's corners, edge midpoints and centre: all far above the profile (space), or all
    // well below the surface (the disk, where the radiance is L_disk L0 without the season term).
    ld highest = -1e300L, lowest = 1e300L;
    for (int i = -1; i <= 1; ++i)
      for (int j = -1; j <= 1; ++j) {
        const ld height =
            reference_height_of(s, reference_direction(s, phi + i * a, j * half)).height;
        highest = std::max(highest, height);
        lowest = std::min(lowest, height);
      }
    if (lowest > far)
      signal[k] = 0;
    else if (highest < -5000 && p.amplitude == 0)
      signal[k] = p.plateau * p.disk;
    else
      signal[k] = reference_field_mean(s, p, phi);
  }
  const reference_detail::grid_result fine = reference_detail::on_grid(signal, start, h, p);
  std::vector<ld> coarse(n / 2 + 1);
  for (std::size_t k = 0; k < coarse.size(); ++k) coarse[k] = signal[2 * k];
  const reference_detail::grid_result rough = reference_detail::on_grid(coarse, start, 2 * h, p);
  reference_result r;
  r.peak = fine.peak;
  r.level = fine.level;
  if (!fine.ok || !rough.ok) {
    r.crossings = conescan::crossings<ld>::failed(conescan::status::miss);
    return r;
  }
  // The held signal's error is h^2 times a smooth function with lag (or for the slope's
  // differences): extrapolated. Without lag the crossings come from the cubic, O(h^4): kept.
  if (p.lag > 0 || p.locator == 2)
    r.crossings = {fine.in + (fine.in - rough.in) / 3, fine.out + (fine.out - rough.out) / 3,
                   conescan::status::ok, 0};
  else
    r.crossings = {fine.in, fine.out, conescan::status::ok, 0};
  return r;
}

}  // namespace conescan_test
