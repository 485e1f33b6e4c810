// The field's mean radiance at one scan azimuth (MODEL §12, "Field of view"): the mean of L over
// the rigid patch exp_d(x t + y c) about the line of sight d, (x, y) in the square |x|, |y| <=
// w/2 or the disk x^2 + y^2 <= (w/2)^2, weights uniform in (x, y); t the scan direction at d, c =
// d x t across it (towards the optical axis A).
//
// By level sets (docs/SENSOR_PHYSICS.md, "The field"): with G(zeta) the patch's share, weighted
// by the season factor L0, where the tangent height is below zeta,
//   s = (L_disk - l(0)) G(0) + G(inf) l(zeta_max) + int_{zeta_min}^{zeta_max} (-l'(zeta)) G(zeta),
// (zeta limited to >= 0), and for the step (H = 0) s = L_disk G(0) + G(delta50) - G(0): the exact
// area fraction. G is exact at any zeta: Green's theorem over the part of the patch below the
// level, its boundary the patch's own (straight edges or the circle, closed forms in the weight's
// polynomial) and the level curve, taken as its chord plus the thin lens between chord and curve
// (the curve found on exact heights by secant steps along the chord's normal, Gauss along it).
// G is analytic between the heights of the square's corners and the boundary's extremes, so a
// Chebyshev model of it on each such piece (a cosine substitution where G has the square-root
// ends of a tangent level curve: the circle's extremes) carries the integral against the
// profile's density -l' on panels of H; no quadrature crosses the knee or a jump.
#pragma once

#include <array>
#include <cmath>
#include <limits>

#include "conescan/gauss_panels.hpp"
#include "conescan/sensor_physics/field.hpp"
#include "conescan/sensor_physics/height.hpp"
#include "conescan/sensor_physics/profile.hpp"
#include "conescan/small_sort.hpp"
#include "conescan/vector.hpp"

namespace conescan {

namespace field_detail {

inline constexpr int edge_nodes = 17;      ///< Chebyshev-Lobatto nodes on a boundary piece, at most
inline constexpr int boundary_pieces = 4;  ///< the square's edges, or the circle's quarters
inline constexpr int lens_nodes = 4;       ///< Gauss nodes along a level curve's chord
inline constexpr int lens_most_parts = 64;   ///< parts of a long chord, each with lens_nodes
inline constexpr int lens_most_secants = 8;  ///< secant steps to the level curve, at most
inline constexpr int green_nodes = 6;        ///< Gauss nodes along a boundary arc (Green)
inline constexpr int max_extrema = 8;        ///< interior extremes of the boundary's heights
inline constexpr int max_crossings = 8;      ///< level crossings of the boundary
inline constexpr int model_nodes = 24;       ///< Chebyshev nodes of G on one piece, at most
inline constexpr int max_breaks = 16;        ///< breakpoints of G

/// Dot products with a surface's two probe directions (sensor_physics/height.hpp).
template <class T>
struct probe_dots {
  T d, t, c;
};

}  // namespace field_detail

/// The rigid patch at one scan azimuth, ready for heights: the frame's dot products with the
/// surface's probes, the shape, the half-width (rad).
template <class T, class Surface>
struct field_patch {
  const Surface* surface;
  surface_probe<T> probe;
  field_detail::probe_dots<T> first, second;
  field_detail::probe_dots<T> centre;  ///< the surface's centre direction (centre_direction)
  field_shape shape;
  T half;
  bool latitudes;  ///< the season term reads the tangent points' latitudes

  /// The tangent height at the patch point (x, y): exp_d(x t + y c) = cos r d + (sin r / r)(x t +
  /// y c), r = |(x, y)| (the series below r = 1e-4, where the ratio would lose digits); its
  /// latitude where `latitudes` and `with_latitude` (the height is the same without it).
  tangent_height<T> at(const T& x, const T& y, bool with_latitude = true) const noexcept {
    T cr, sr;
    exp_terms(x, y, cr, sr);
    return height_from(*surface, T(cr * first.d + sr * (x * first.t + y * first.c)),
                       T(cr * second.d + sr * (x * second.t + y * second.c)), probe.constant,
                       latitudes && with_latitude);
  }
  /// The line at (x, y): > 0 where its closest approach lies ahead of the satellite, not > 0
  /// behind it, where its height is the satellite's own (ahead_sign, height.hpp).
  T ahead(const T& x, const T& y) const noexcept {
    T cr, sr;
    exp_terms(x, y, cr, sr);
    return ahead_sign(*surface) * (cr * first.d + sr * (x * first.t + y * first.c));
  }
  /// cos r and sin r / r of exp_d at (x, y).
  static void exp_terms(const T& x, const T& y, T& cr, T& sr) noexcept {
    using std::cos;
    using std::sin;
    using std::sqrt;
    const T r2 = x * x + y * y;
    if (r2 < T(1) / T(100000000)) {
      cr = T(1) - r2 / T(2) + r2 * r2 / T(24);
      sr = T(1) - r2 / T(6) + r2 * r2 / T(120);
    } else {
      const T r = sqrt(r2);
      cr = cos(r);
      sr = sin(r) / r;
    }
  }
  /// The height alone: G's level sets read no latitude (the season factor is weight_model_of's).
  T height(const T& x, const T& y) const noexcept { return at(x, y, false).height_m; }
};

/// The patch about the true line of sight at scan azimuth phi (MODEL §4): d from the scan
/// circle, t = A x d / |A x d| (the cone about A is the scan's path; increasing phi), c = d x t.
template <class T, class Surface>
field_patch<T, Surface> field_patch_at(const scan_circle<T>& circle, const Surface& surface,
                                       const field_of_view<T>& field, const T& phi,
                                       bool latitudes) noexcept {
  using std::cos;
  using std::sin;
  using std::sqrt;
  const scan_point<T> q = scan_point_at(circle, phi);
  const vec3<T> d(q.sin_psi * q.cos_phi, q.sin_psi * q.sin_phi, q.cos_psi);
  vec3<T> t = cross(circle.axis, d);
  t = scaled(t, T(T(1) / sqrt(dot(t, t))));
  const vec3<T> c = cross(d, t);
  field_patch<T, Surface> p{};
  p.surface = &surface;
  p.probe = probe_of(surface);
  p.first = {T(dot(d, p.probe.first)), T(dot(t, p.probe.first)), T(dot(c, p.probe.first))};
  p.second = {T(dot(d, p.probe.second)), T(dot(t, p.probe.second)), T(dot(c, p.probe.second))};
  const vec3<T> centre = centre_direction(surface);
  p.centre = {T(dot(d, centre)), T(dot(t, centre)), T(dot(c, centre))};
  p.shape = field.shape;
  p.half = field.fov_rad / T(2);
  p.latitudes = latitudes;
  return p;
}

namespace field_detail {

inline constexpr int square_edge_nodes = 11;   ///< a square's edge: a nearly linear height
inline constexpr int square_model_nodes = 12;  ///< G between two corners: nearly polynomial
inline constexpr int fine_model_nodes = 24;    ///< G over the circle's whole span, or a square's
                                               ///< piece whose 12 nodes did not converge
static_assert(fine_model_nodes <= model_nodes, "the fine model fits the tables");

/// Cosine tables of the Chebyshev transforms, made once per head: the Lobatto nodes' DCT-I for
/// the boundary (n nodes: cos(pi j k / (n - 1))) and the first-kind nodes' DCT-II for G's model
/// (cos(pi j (k + 1/2) / n)), for the two node counts of each.
template <class T>
struct chebyshev_tables {
  std::array<std::array<T, edge_nodes>, edge_nodes> lobatto_square, lobatto_circle;
  std::array<std::array<T, model_nodes>, model_nodes> first_coarse, first_fine;

  /// The first-kind table of G's model on `nodes` nodes (square_model_nodes or
  /// fine_model_nodes).
  const std::array<std::array<T, model_nodes>, model_nodes>& first_kind(int nodes) const noexcept {
    return nodes == square_model_nodes ? first_coarse : first_fine;
  }
};

/// G's model nodes on one piece of a patch of `shape`, at first: a square's pieces between
/// corners are nearly polynomial, the circle's one piece spans all its heights.
constexpr int model_nodes_of(field_shape shape) noexcept {
  return shape == field_shape::circle ? fine_model_nodes : square_model_nodes;
}

/// The patch's area in (x, y): a square of half-width `half`, or a circle of radius `half`.
template <class T>
T patch_area(field_shape shape, const T& half) noexcept {
  return shape == field_shape::square ? T(T(4) * half * half) : T(pi<T>() * half * half);
}

template <class T>
void lobatto_table(int n, std::array<std::array<T, edge_nodes>, edge_nodes>& t) noexcept {
  using std::cos;
  for (int j = 0; j < n; ++j)
    for (int k = 0; k < n; ++k) t[j][k] = cos(pi<T>() * T(j * k) / T(n - 1));
}

template <class T>
void first_kind_table(int n, std::array<std::array<T, model_nodes>, model_nodes>& t) noexcept {
  using std::cos;
  for (int j = 0; j < n; ++j)
    for (int k = 0; k < n; ++k) t[j][k] = cos(pi<T>() * T(j) * (T(k) + T(1) / T(2)) / T(n));
}

/// A point of the patch plane.
template <class T>
struct point2 {
  T x, y;
};

/// The patch's boundary, counter-clockwise in (x, y), as four pieces on u in [-1, 1]: the
/// square's edges (bottom, right, top, left) or the circle's quarters from angle 0; and the
/// heights along each as a Chebyshev series of degree edge_nodes - 1 on Lobatto nodes.
template <class T>
struct boundary {
  field_shape shape;
  T half;
  int nodes;  ///< Lobatto nodes per piece: a square's edge carries a nearly linear height, a
              ///< quarter circle a cosine's (measured: docs/SENSOR_PHYSICS.md, "The field")
  std::array<std::array<T, edge_nodes>, boundary_pieces> series;  ///< Chebyshev coefficients
  std::array<std::array<T, edge_nodes>, boundary_pieces> values;  ///< heights at the nodes
  T corner_low, corner_high;  ///< the lowest and highest node height (the extremes' first guess)

  /// The circle's angle at u on a quarter.
  static T circle_angle(int piece, const T& u) noexcept {
    return pi<T>() / T(2) * (T(piece) + (u + T(1)) / T(2));
  }

  point2<T> point(int piece, const T& u) const noexcept {
    using std::cos;
    using std::sin;
    if (shape == field_shape::square) {
      switch (piece) {
        case 0:
          return {T(half * u), T(-half)};
        case 1:
          return {half, T(half * u)};
        case 2:
          return {T(-half * u), half};
        default:
          return {T(-half), T(-half * u)};
      }
    }
    const T angle = circle_angle(piece, u);
    return {T(half * cos(angle)), T(half * sin(angle))};
  }
  /// d x / d u along the piece.
  T dx_du(int piece, const T& u) const noexcept {
    using std::sin;
    if (shape == field_shape::square) return piece == 0 ? half : piece == 2 ? T(-half) : T(0);
    const T angle = circle_angle(piece, u);
    return -half * sin(angle) * pi<T>() / T(4);
  }
  /// d y / d u along the piece (Green's theorem integrates Q dy).
  T dy_du(int piece, const T& u) const noexcept {
    using std::cos;
    if (shape == field_shape::square) return piece == 1 ? half : piece == 3 ? T(-half) : T(0);
    const T angle = circle_angle(piece, u);
    return half * cos(angle) * pi<T>() / T(4);
  }
  /// The height model and its slope in u (Clenshaw).
  void height(int piece, const T& u, T& value, T& slope) const noexcept {
    const std::array<T, edge_nodes>& a = series[piece];
    T b1 = T(0), b2 = T(0), d1 = T(0), d2 = T(0);
    const T two_u = u * integer_factor<T>(2);
    for (int k = nodes - 1; k >= 1; --k) {
      const T b0 = two_u * b1 - b2 + a[k];
      const T d0 = two_u * d1 - d2 + b1 * integer_factor<T>(2);
      b2 = b1;
      b1 = b0;
      d2 = d1;
      d1 = d0;
    }
    value = u * b1 - b2 + a[0];
    slope = u * d1 - d2 + b1;
  }
  T height_at(int piece, const T& u) const noexcept {
    T v, s;
    height(piece, u, v, s);
    return v;
  }
};

/// The boundary's heights at the nodes (exact), and their Chebyshev series (DCT-I).
template <class T, class Surface>
boundary<T> boundary_of(const field_patch<T, Surface>& patch,
                        const chebyshev_tables<T>& tables) noexcept {
  boundary<T> b{};
  b.shape = patch.shape;
  b.half = patch.half;
  const bool square = patch.shape == field_shape::square;
  b.nodes = square ? square_edge_nodes : edge_nodes;
  const auto& cosines = square ? tables.lobatto_square : tables.lobatto_circle;
  const int n = b.nodes - 1;
  for (int piece = 0; piece < boundary_pieces; ++piece) {
    for (int k = 0; k <= n; ++k) {
      // The pieces share their ends: the last node of one is the first of the next.
      if (k == 0 && piece > 0) {
        b.values[piece][0] = b.values[piece - 1][n];
        continue;
      }
      if (k == n && piece == boundary_pieces - 1) {
        b.values[piece][n] = b.values[0][0];
        continue;
      }
      const point2<T> q = b.point(piece, T(-cosines[1][k]));
      b.values[piece][k] = patch.height(q.x, q.y);
    }
    // a_j = (2 / n) sum'' f_k T_j(u_k), the ends halved (and a_0, a_n halved again).
    for (int j = 0; j <= n; ++j) {
      T sum = T(0);
      for (int k = 0; k <= n; ++k) {
        // T_j(u_k) = cos(j (pi - pi k / n)) = (-1)^j cos(pi j k / n).
        T term = b.values[piece][k] * cosines[j][k];
        if (j % 2 == 1) term = -term;
        if (k == 0 || k == n) term = term / T(2);
        sum += term;
      }
      sum = sum * T(2) / T(n);
      if (j == 0 || j == n) sum = sum / T(2);
      b.series[piece][j] = sum;
    }
  }
  b.corner_low = b.corner_high = b.values[0][0];
  for (int piece = 0; piece < boundary_pieces; ++piece)
    for (int k = 0; k <= n; ++k) {
      if (b.values[piece][k] < b.corner_low) b.corner_low = b.values[piece][k];
      if (b.values[piece][k] > b.corner_high) b.corner_high = b.values[piece][k];
    }
  return b;
}

/// A place on the boundary: a piece and its parameter.
template <class T>
struct boundary_place {
  int piece;
  T u;
};

/// The monotone runs of the boundary's heights: each piece cut at the interior zeros of its
/// slope. Their ends are the candidates for the extremes, and each run holds at most one
/// crossing of any level.
template <class T>
struct monotone_runs {
  int count;
  std::array<boundary_place<T>, boundary_pieces*(max_extrema + 1)> start, end;
  std::array<T, boundary_pieces*(max_extrema + 1)> low, high;
  std::array<T, boundary_pieces*(max_extrema + 1)> start_height, end_height;  ///< every level's
  int interior_extrema;  ///< runs cut inside a piece (a tangent level curve: singular ends of G)
  std::array<T, boundary_pieces * max_extrema> extremum_height;
};

/// Whether the whole patch lies on the disk: every boundary height below the surface (the
/// heights' largest lies on the boundary: they grow away from the centre's line).
template <class T>
bool patch_on_disk(const monotone_runs<T>& runs) noexcept {
  for (int i = 0; i < runs.count; ++i)
    if (!(runs.high[i] < T(0))) return false;
  return runs.count > 0;
}

/// Where the slope of piece `piece` vanishes inside (-1, 1). The slope's Chebyshev series bounds
/// it: where its constant term exceeds the sum of the others' magnitudes (a nearly linear height,
/// the usual case) it has no zero; else sign changes on 4n samples, refined by bisection to
/// 1e-14 of the parameter. The last interval too: a circle crossing a limb head-on has its
/// heights' extremes within a sample of its quarters' ends, and G's ends were then not taken as
/// singular (a 1 deg circle on H = 1.1 km, 33 000 km out: 1.5e-6 of L0 off, now 2e-13).
template <class T>
int slope_zeros(const boundary<T>& b, int piece, T* out) noexcept {
  using std::abs;
  // The derivative's coefficients: d_{k-1} = d_{k+1} + 2 k a_k (d_0 halved).
  const std::array<T, edge_nodes>& a = b.series[piece];
  T d[edge_nodes + 1] = {};
  for (int k = b.nodes - 1; k >= 1; --k) d[k - 1] = d[k + 1] + T(2 * k) * a[k];
  d[0] = d[0] / T(2);
  T rest = T(0);
  for (int k = 1; k < b.nodes - 1; ++k) rest += abs(d[k]);
  if (abs(d[0]) > rest) return 0;
  const int samples = 4 * (b.nodes - 1);
  int n = 0;
  T u0 = T(-1), v, s0;
  b.height(piece, u0, v, s0);
  for (int i = 1; i <= samples && n < max_extrema; ++i) {
    const T u1 = T(-1) + T(2 * i) / T(samples);
    T s1;
    b.height(piece, u1, v, s1);
    if ((s0 < T(0)) != (s1 < T(0))) {
      T lo = u0, hi = u1, slo = s0;
      for (int it = 0; it < 50 && hi - lo > T(1) / T(100000000000000LL); ++it) {
        const T mid = (lo + hi) / T(2);
        T sm;
        b.height(piece, mid, v, sm);
        if ((sm < T(0)) == (slo < T(0))) {
          lo = mid;
          slo = sm;
        } else {
          hi = mid;
        }
      }
      out[n++] = (lo + hi) / T(2);
    }
    u0 = u1;
    s0 = s1;
  }
  return n;
}

template <class T>
monotone_runs<T> monotone_runs_of(const boundary<T>& b) noexcept {
  monotone_runs<T> r{};
  r.count = 0;
  r.interior_extrema = 0;
  for (int piece = 0; piece < boundary_pieces; ++piece) {
    T zeros[max_extrema];
    const int n = slope_zeros(b, piece, zeros);
    T from = T(-1);
    for (int i = 0; i <= n; ++i) {
      const T to = i < n ? zeros[i] : T(1);
      const T h0 = b.height_at(piece, from), h1 = b.height_at(piece, to);
      r.start[r.count] = {piece, from};
      r.end[r.count] = {piece, to};
      r.start_height[r.count] = h0;
      r.end_height[r.count] = h1;
      r.low[r.count] = h0 < h1 ? h0 : h1;
      r.high[r.count] = h0 < h1 ? h1 : h0;
      ++r.count;
      if (i < n) r.extremum_height[r.interior_extrema++] = h1;
      from = to;
    }
  }
  return r;
}

/// A level's crossing of the boundary: its place and point.
template <class T>
struct crossing_point {
  boundary_place<T> place;
  point2<T> at;
  bool entering;  ///< along the boundary (counter-clockwise) the height falls through the level
};

/// The level's crossings, in boundary order: a run holds one where its ends lie on either side
/// of zeta ("below" is height < zeta; the runs share their ends, so every change of side around
/// the boundary is counted once and the count is even), found by Illinois on the height model.
template <class T>
int level_crossings(const boundary<T>& b, const monotone_runs<T>& runs, const T& zeta,
                    crossing_point<T>* out) noexcept {
  int n = 0;
  for (int i = 0; i < runs.count && n < max_crossings; ++i) {
    const int piece = runs.start[i].piece;
    T lo = runs.start[i].u, hi = runs.end[i].u;
    T flo = runs.start_height[i] - zeta, fhi = runs.end_height[i] - zeta;
    if ((flo < T(0)) == (fhi < T(0))) continue;
    const bool falling = fhi < T(0);
    // Newton on the model, kept inside the bracket (bisection where it would leave it): the run
    // is monotone, so a few steps reach rounding.
    T u = flo == fhi ? T((lo + hi) / T(2)) : T((lo * fhi - hi * flo) / (fhi - flo));
    for (int it = 0; it < 40; ++it) {
      T f, slope;
      b.height(piece, u, f, slope);
      f = f - zeta;
      if (f == T(0)) break;
      if ((f < T(0)) == (flo < T(0)))
        lo = u;
      else
        hi = u;
      T next = slope != T(0) ? T(u - f / slope) : T((lo + hi) / T(2));
      if (!(next > lo && next < hi)) next = (lo + hi) / T(2);
      const T step = next - u;
      u = next;
      if (!(step > T(4) * std::numeric_limits<T>::epsilon() ||
            -step > T(4) * std::numeric_limits<T>::epsilon()))
        break;
    }
    out[n++] = {{piece, u}, b.point(piece, u), falling};
  }
  return n;
}

/// The season factor over the patch as a polynomial in each of x, y (its samples at n x n
/// Chebyshev points: sin(latitude) is analytic across a field), and Q = int_0^x F dx, what Green's
/// theorem integrates: int int F dA = oint Q dy. Without the season term F is the plateau.
/// Coordinates scaled by the half-width (u = x / h) keep the monomials' digits. Degree 4 (5 x 5)
/// leaves ~(fov/2)^5 / 120 of it, 1e-12 at 2 deg, where a biquadratic left 5e-9; a patch near the
/// line through the Earth's centre (far out, a wide field) sees the latitude turn about that line,
/// and degree 4 left 1e-5 of L0 on a 13 deg circle 17 000 km out (the crossing 6.7e-5 deg off the
/// reference): there the degree rises, 8 then 12 (weight_terms_steps), until the samples'
/// Chebyshev tail is within weight_tolerance (docs/SENSOR_PHYSICS.md, "The field").
inline constexpr int weight_most_terms = 13;   ///< coefficients per axis, at most
inline constexpr int weight_coarse_terms = 5;  ///< the first step; a 5-node Gauss rule is exact
inline constexpr int weight_terms_steps[] = {weight_coarse_terms, 9, weight_most_terms};

template <class T>
struct weight_model {
  T half;
  int terms;                                  ///< coefficients per axis
  T f[weight_most_terms][weight_most_terms];  ///< F = sum f[i][j] u^i v^j, u = x / h, v = y / h
  bool constant;

  T at(const T& x, const T& y) const noexcept {
    if (constant) return f[0][0];
    const T u = x / half, v = y / half;
    T sum = T(0), up = T(1);
    for (int i = 0; i < terms; ++i, up = up * u) {
      T row = T(0);
      for (int j = terms - 1; j >= 0; --j) row = row * v + f[i][j];
      sum += up * row;
    }
    return sum;
  }
  T q(const T& x, const T& y) const noexcept {
    if (constant) return f[0][0] * x;
    const T u = x / half, v = y / half;
    T sum = T(0), up = u;
    for (int i = 0; i < terms; ++i, up = up * u) {
      T row = T(0);
      for (int j = terms - 1; j >= 0; --j) row = row * v + f[i][j];
      sum += up / integer_factor<T>(i + 1) * row;
    }
    return sum * half;
  }
};

/// The monomial coefficients of the polynomial of degree n - 1 through (u_k, values[k]), u_k the
/// n Chebyshev points cos(pi (k + 1/2) / n), by Gaussian elimination on the Vandermonde system
/// (condition ~30 at n = 5; the monomials of degree 12 carry some 4e4 times the rounding of
/// their values, 2e-12 of the season factor at most).
template <class T>
void monomials_through(const T* u, const T* values, T* out, int n) noexcept {
  T a[weight_most_terms][weight_most_terms + 1];
  for (int r = 0; r < n; ++r) {
    T p = T(1);
    for (int c = 0; c < n; ++c, p = p * u[r]) a[r][c] = p;
    a[r][n] = values[r];
  }
  for (int c = 0; c < n; ++c) {
    int pivot = c;
    for (int r = c + 1; r < n; ++r)
      if ((a[r][c] < T(0) ? T(-a[r][c]) : a[r][c]) >
          (a[pivot][c] < T(0) ? T(-a[pivot][c]) : a[pivot][c]))
        pivot = r;
    for (int k = 0; k <= n; ++k) {
      const T t = a[c][k];
      a[c][k] = a[pivot][k];
      a[pivot][k] = t;
    }
    for (int r = 0; r < n; ++r) {
      if (r == c) continue;
      const T factor = a[r][c] / a[c][c];
      for (int k = c; k <= n; ++k) a[r][k] = a[r][k] - factor * a[c][k];
    }
  }
  for (int c = 0; c < n; ++c) out[c] = a[c][n] / a[c][c];
}

/// The polynomial's error estimate from its samples, values[j][i] at (u_i, u_j), u_i the n
/// Chebyshev points: the size of the next Chebyshev coefficient, from the last two degrees' (n - 1
/// and n - 2 in either variable, every degree in the other) as last^2 / before, their ratio the
/// series' rate of convergence (the last alone, where it does not fall). The last alone
/// overstated it a hundredfold on a 1.5 deg field (7e-11 of L0 where the polynomial was within
/// 1e-12).
template <class T>
T weight_tail(const T (&values)[weight_most_terms][weight_most_terms], const T* u, int n) noexcept {
  using std::abs;
  T chebyshev[weight_most_terms][weight_most_terms];  // T_k(u_i) = cos(k theta_i)
  for (int i = 0; i < n; ++i) {
    chebyshev[0][i] = T(1);
    chebyshev[1][i] = u[i];
    for (int k = 2; k < n; ++k)
      chebyshev[k][i] = T(2) * u[i] * chebyshev[k - 1][i] - chebyshev[k - 2][i];
  }
  T size[2] = {T(0), T(0)};  // the degree n - 1 and n - 2 coefficients' sizes
  for (int degree = 0; degree < 2; ++degree)
    for (int across = 0; across < 2; ++across) {
      T along[weight_most_terms];  // the coefficient of that degree in one variable, per node
      for (int j = 0; j < n; ++j) {
        T sum = T(0);
        for (int i = 0; i < n; ++i)
          sum += (across == 0 ? values[j][i] : values[i][j]) * chebyshev[n - 1 - degree][i];
        along[j] = sum * T(2) / T(n);
      }
      for (int b = 0; b < n; ++b) {
        T sum = T(0);
        for (int j = 0; j < n; ++j) sum += along[j] * chebyshev[b][j];
        size[degree] += abs(sum) * T(b == 0 ? 1 : 2) / T(n);
      }
    }
  return size[0] < size[1] ? T(size[0] * size[0] / size[1]) : size[0];
}

/// The largest error weight_tail may estimate for the season factor's polynomial, in units of
/// the plateau: 1e-10, some 1e-10 deg of crossing where the field is wide and the slope shallow
/// (a mean 1e-5 of L0 off moved a 13 deg circle's crossing by 6.7e-5 deg). The benchmark's
/// 1.5 deg fields estimate up to 5e-11 at degree 4, and 2 deg circles 2e-10 (degree 8 moved
/// their crossings by less than 1e-11 deg).
template <class T>
T weight_tolerance() noexcept {
  const T floor = T(1024) * std::numeric_limits<T>::epsilon();
  const T target = T(1) / T(10000000000LL);  // 1e-10
  return floor > target ? floor : target;
}

}  // namespace field_detail

/// What the field's mean needs besides the patch: the profile, the plateau, the season term.
template <class T>
struct field_radiance {
  const radiance_profile<T>* profile;
  T plateau;
  T season;  ///< A sin(delta_sun) / sin 23.44 deg: L0 = plateau (1 + season sin(phi_t))
};

namespace field_detail {

template <class T, class Surface>
weight_model<T> weight_model_of(const field_patch<T, Surface>& patch,
                                const field_radiance<T>& radiance) noexcept {
  using std::abs;
  using std::cos;
  weight_model<T> w{};
  w.half = patch.half;
  w.terms = 1;
  w.constant = radiance.season == T(0);
  if (w.constant) {
    w.f[0][0] = radiance.plateau;
    return w;
  }
  T values[weight_most_terms][weight_most_terms];  // [y node][x node]
  T u[weight_most_terms];
  for (int n : weight_terms_steps) {
    for (int k = 0; k < n; ++k) u[k] = cos(pi<T>() * (T(k) + T(1) / T(2)) / T(n));
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        values[j][i] =
            radiance.plateau *
            (T(1) +
             radiance.season * patch.at(T(patch.half * u[i]), T(patch.half * u[j])).sin_latitude);
    w.terms = n;
    if (n == weight_most_terms ||
        !(weight_tail(values, u, n) > weight_tolerance<T>() * abs(radiance.plateau)))
      break;
  }
  const int n = w.terms;
  T by_x[weight_most_terms][weight_most_terms];  // [y node][power of u]
  for (int j = 0; j < n; ++j) monomials_through(u, values[j], by_x[j], n);
  for (int i = 0; i < n; ++i) {
    T column[weight_most_terms];
    for (int j = 0; j < n; ++j) column[j] = by_x[j][i];
    monomials_through(u, column, w.f[i], n);
  }
  return w;
}

/// Within how many half-widths of the patch's centre the centre's line must lie for the season
/// factor's integral to be taken by fans (fan_latitude_integral) rather than from the weight's
/// polynomial: the latitude of decision 2 turns about that line, so the polynomial's error falls
/// only as a power of the distance (measured, a 2.25 deg square 33 000 km out, in the mean: 2e-3
/// of L0 with the line inside the patch, 3.5e-9 at 4.3 half-widths, 2.2e-10 at 6.8, 5e-11 at
/// 8.7: as the sixth power). Fans cost some 3000 heights a mean: 8 half-widths keeps them to the
/// patches the polynomial would leave more than ~1e-10 off.
inline constexpr int fan_reach = 8;
inline constexpr int fan_nodes = 12;  ///< Gauss nodes along a fan's base and along its rays

/// The patch coordinates of the line through the surface's centre (log_d of centre_direction);
/// false where it points away from the satellite's half of the sky (no patch near it).
template <class T, class Surface>
bool centre_point_of(const field_patch<T, Surface>& p, point2<T>& apex) noexcept {
  using std::atan2;
  using std::sqrt;
  if (!(p.centre.d > T(0))) return false;
  const T across = sqrt(p.centre.t * p.centre.t + p.centre.c * p.centre.c);
  const T r = atan2(across, p.centre.d);
  apex = across > T(0) ? point2<T>{T(r * p.centre.t / across), T(r * p.centre.c / across)}
                       : point2<T>{T(0), T(0)};
  return true;
}

/// The place u on boundary piece `piece` nearest the apex, and the distance there in units of u
/// (at least 1e-12: an apex on the boundary).
template <class T>
void nearest_on_piece(const boundary<T>& b, int piece, const point2<T>& apex, T& u_near,
                      T& reach_u) noexcept {
  using std::atan2;
  using std::sqrt;
  T speed;
  if (b.shape == field_shape::square) {
    const point2<T> start = b.point(piece, T(-1)), end = b.point(piece, T(1));
    const T ex = (end.x - start.x) / T(2), ey = (end.y - start.y) / T(2);
    u_near =
        ((apex.x - (start.x + ex)) * ex + (apex.y - (start.y + ey)) * ey) / (ex * ex + ey * ey);
    speed = b.half;
  } else {
    const T middle = b.circle_angle(piece, T(0));
    T turn = atan2(apex.y, apex.x) - middle;  // brought into (-pi, pi]
    while (turn < -pi<T>()) turn = turn + T(2) * pi<T>();
    while (turn > pi<T>()) turn = turn - T(2) * pi<T>();
    u_near = turn / (pi<T>() / T(4));
    speed = b.half * pi<T>() / T(4);
  }
  u_near = u_near < T(-1) ? T(-1) : u_near > T(1) ? T(1) : u_near;
  const point2<T> near = b.point(piece, u_near);
  const T dx = near.x - apex.x, dy = near.y - apex.y;
  reach_u = sqrt(dx * dx + dy * dy) / speed;
  if (reach_u < T(1) / T(1000000000000LL)) reach_u = T(1) / T(1000000000000LL);
}

/// int int sin(latitude) dA over the patch as signed fans from the apex (the centre's line,
/// centre_point_of) to each boundary piece: int du ((E - a) x E') int_0^1 f(a + l (E - a)) l dl,
/// exact for any apex (the fans of a closed boundary tile the patch, with signs outside it).
/// In polar coordinates about the apex the latitude is smooth (decision 2), so Gauss converges
/// along the rays; along a base it turns on the scale of the apex's distance, so each piece is
/// cut into panels graded geometrically from its place nearest the apex (widths r, r, 2r, 4r, ...
/// with r that distance: each panel's singularity lies at least its own width away). Measured
/// against the reference's polar rule (16 nodes, long double): within 6e-15 with 12 nodes, where
/// 8 left 1.4e-11 on a circle 2.5 half-widths from the point (docs/SENSOR_PHYSICS.md, "The
/// field").
template <class T, class Surface>
T fan_latitude_integral(const field_patch<T, Surface>& patch, const boundary<T>& b,
                        const point2<T>& apex,
                        const gauss_legendre_rule<T, fan_nodes>& rule) noexcept {
  auto ray = [&](const point2<T>& e) {  // int_0^1 f(a + l (e - a)) l dl
    return gauss_integral(rule, T(0), T(1), [&](const T& l) {
      return T(
          l *
          patch.at(T(apex.x + l * (e.x - apex.x)), T(apex.y + l * (e.y - apex.y))).sin_latitude);
    });
  };
  T total = T(0);
  for (int piece = 0; piece < boundary_pieces; ++piece) {
    auto panel = [&](const T& u0, const T& u1) {
      return gauss_integral(rule, u0, u1, [&](const T& u) {
        const point2<T> e = b.point(piece, u);
        return T(((e.x - apex.x) * b.dy_du(piece, u) - (e.y - apex.y) * b.dx_du(piece, u)) *
                 ray(e));
      });
    };
    T u_near, reach_u;
    nearest_on_piece(b, piece, apex, u_near, reach_u);
    for (int side = -1; side <= 1; side += 2) {
      T at = u_near;
      T width = reach_u;
      while (side > 0 ? at < T(1) : at > T(-1)) {
        T next = at + T(side) * width;
        if (side > 0 ? !(next < T(1)) : !(next > T(-1))) next = T(side);
        total += side > 0 ? panel(at, next) : panel(next, at);
        width = side > 0 ? T(next - u_near) : T(u_near - next);
        at = next;
      }
    }
  }
  return total;
}

/// The patch's boundary as a shape alone, without its heights: what the fans and Green's
/// theorem over the whole patch read.
template <class T, class Surface>
boundary<T> shape_of(const field_patch<T, Surface>& patch) noexcept {
  boundary<T> b{};
  b.shape = patch.shape;
  b.half = patch.half;
  return b;
}

/// The mean of sin(latitude) over the patch by fans where the line through the centre lies
/// within fan_reach half-widths of its centre (true, into mean), else false: the caller's rule
/// (a polynomial or a few points) serves there.
template <class T, class Surface>
bool fan_latitude_mean(const field_patch<T, Surface>& patch,
                       const gauss_legendre_rule<T, fan_nodes>& rule, T& mean) noexcept {
  point2<T> apex;
  const T reach = T(fan_reach) * patch.half;
  if (!centre_point_of(patch, apex) || !(apex.x * apex.x + apex.y * apex.y < reach * reach))
    return false;
  mean = fan_latitude_integral(patch, shape_of(patch), apex, rule) /
         patch_area(patch.shape, patch.half);
  return true;
}

/// The Gauss rules Green's theorem integrates Q with: `coarse` and `segment` for a weight of at
/// most weight_coarse_terms coefficients an axis, `fine` for more (Q of degree 2 n - 1 along a
/// straight line: exact with n nodes).
template <class T>
struct green_rules {
  const gauss_legendre_rule<T, green_nodes>* coarse;
  const gauss_legendre_rule<T, 5>* segment;
  const gauss_legendre_rule<T, weight_most_terms>* fine;
};

/// int_a^b f by the weight's rule: `coarse` up to weight_coarse_terms coefficients an axis, else
/// the fine one.
template <class T, int N, class F>
T green_gauss(const weight_model<T>& w, const gauss_legendre_rule<T, N>& coarse,
              const green_rules<T>& rules, const T& a, const T& b, const F& f) noexcept {
  return w.terms > weight_coarse_terms ? gauss_integral(*rules.fine, a, b, f)
                                       : gauss_integral(coarse, a, b, f);
}

/// int Q dy along a boundary piece from u0 to u1 (Gauss; exact on the square's edges).
template <class T>
T boundary_green(const boundary<T>& b, const weight_model<T>& w, int piece, const T& u0,
                 const T& u1, const green_rules<T>& rules) noexcept {
  if (!(u1 > u0) || (b.shape == field_shape::square && (piece == 0 || piece == 2))) return T(0);
  const auto integrand = [&](const T& u) {
    const point2<T> q = b.point(piece, u);
    return T(w.q(q.x, q.y) * b.dy_du(piece, u));
  };
  return green_gauss(w, *rules.coarse, rules, u0, u1, integrand);
}

/// int int F dA over the whole patch: int Q dy around its boundary.
template <class T>
T weight_integral(const boundary<T>& b, const weight_model<T>& w,
                  const green_rules<T>& rules) noexcept {
  T whole = T(0);
  for (int piece = 0; piece < boundary_pieces; ++piece)
    whole += boundary_green(b, w, piece, T(-1), T(1), rules);
  return whole;
}

/// int Q dy along the straight segment from a to b (Gauss, exact: Q is of degree 2 n - 1 along
/// it, n the weight's coefficients an axis).
template <class T>
T segment_green(const weight_model<T>& w, const point2<T>& a, const point2<T>& b,
                const green_rules<T>& rules) noexcept {
  const T dy = b.y - a.y;
  if (dy == T(0)) return T(0);
  const auto integrand = [&](const T& s) {
    return T(w.q(T(a.x + s * (b.x - a.x)), T(a.y + s * (b.y - a.y))));
  };
  return dy * green_gauss(w, *rules.segment, rules, T(0), T(1), integrand);
}

/// The level-set machinery of one patch: its boundary, runs, weight, rules, the gradient at the
/// centre (the lens's first secant step).
template <class T, class Surface>
struct level_sets {
  const field_patch<T, Surface>& patch;
  boundary<T> edges;
  monotone_runs<T> runs;
  weight_model<T> weight;
  green_rules<T> green;
  gauss_legendre_rule<T, lens_nodes> lens;
  T gx, gy;  ///< the height's gradient at the centre (m/rad)
  T area;    ///< the patch's area in (x, y)
  T total;   ///< G above every height: the weight's mean over the patch
  T whole;   ///< G above every height times the area
};

/// The longest chord a lens integrates as one part, by lens_nodes Gauss nodes and two secant
/// steps (rad): every chord of a square up to 2.8 deg, where the rule leaves 4e-12 of L0 in the
/// mean. One rule and two secants over a longer chord left 9.4e-8 of L0 in a 10.5 deg square's
/// mean, growing as fov^7 (a 5.3 deg square 5.4e-10).
template <class T>
T lens_longest_part() noexcept {
  return T(7) / T(100);
}

/// The parts a lens's chord of `length` (rad) is cut into, each at most lens_longest_part.
template <class T>
int lens_parts(const T& length) noexcept {
  int parts = 1;
  while (parts < lens_most_parts && length > lens_longest_part<T>() * T(parts)) ++parts;
  return parts;
}

/// int_0^mu F(c + t m) dt, across a lens from its chord's point c along the unit normal m: the
/// plateau times mu where F is constant, else 2-point Gauss (exact for F cubic across). The
/// midpoint alone left mu^3 F'' / 24: 5e-9 of L0 in a 20 deg circle's mean under the season
/// term (chords of 0.3 rad, offsets of some 3e-3 rad), 1.7e-8 in a 20 deg square's.
template <class T>
T across_lens(const weight_model<T>& w, const T& cx, const T& cy, const T& mx, const T& my,
              const T& mu) noexcept {
  using std::sqrt;
  if (w.constant) return w.f[0][0] * mu;
  const T half = mu / T(2), spread = mu / (T(2) * sqrt(T(3)));
  const T near = half - spread, far = half + spread;
  return half *
         (w.at(T(cx + near * mx), T(cy + near * my)) + w.at(T(cx + far * mx), T(cy + far * my)));
}

/// The lens between the chord a -> b of the level zeta and the level curve: |b - a| int F mu,
/// mu the curve's offset from the chord along its unit normal m (towards greater heights), by
/// secant steps on the exact heights: a linear step, then two secants, where the offset is a
/// small part of the chord and the heights nearly linear across it (the last leaves ~1e-15
/// rad; a third would step on rounding). A chord longer than lens_longest_part (a wide field's,
/// its curve's offset a percent of it) is cut into parts and takes up to lens_most_secants
/// steps, until one moves mu by less than 1e-13 of the chord: two left 5e-11 of L0 in a 10.5
/// deg square's mean and 5.6e-9 in a 20 deg one's; now 3e-12 and 3.2e-10.
template <class T, class Surface>
T lens_area(const level_sets<T, Surface>& s, const point2<T>& a, const point2<T>& b,
            const T& zeta) noexcept {
  using std::abs;
  using std::sqrt;
  const T lx = b.x - a.x, ly = b.y - a.y;
  const T length = sqrt(lx * lx + ly * ly);
  if (!(length > T(0))) return T(0);
  T mx = -ly / length, my = lx / length;
  if (mx * s.gx + my * s.gy < T(0)) {
    mx = -mx;
    my = -my;
  }
  const T rate = mx * s.gx + my * s.gy;  // d height / d mu, the secant's first slope
  const int parts = lens_parts(length);
  const int secants = parts > 1 ? lens_most_secants : 2;
  const T settled = length / T(10000000000000LL);
  T sum = T(0);
  for (int j = 0; j < parts; ++j)
    for (int k = 0; k < lens_nodes; ++k) {
      const T lambda = (T(j) + (s.lens.nodes[k] + T(1)) / T(2)) / T(parts);
      const T cx = a.x + lambda * lx, cy = a.y + lambda * ly;
      T mu0 = T(0), f0 = s.patch.height(cx, cy) - zeta;
      T mu1 = rate > T(0) ? T(-f0 / rate) : T(0);
      for (int it = 0; it < secants && mu1 != mu0; ++it) {
        const T f1 = s.patch.height(T(cx + mu1 * mx), T(cy + mu1 * my)) - zeta;
        if (f1 == f0) break;
        const T next = mu1 - f1 * (mu1 - mu0) / (f1 - f0);
        const T step = next - mu1;
        mu0 = mu1;
        f0 = f1;
        mu1 = next;
        if (it >= 1 && !(abs(step) > settled)) break;
      }
      sum += s.lens.weights[k] / T(2) * across_lens(s.weight, cx, cy, mx, my, mu1);
    }
  return sum * length / T(parts);
}

/// G(zeta) times the area: int int_{patch, height < zeta} F dx dy.
template <class T, class Surface>
T weighted_area_below(const level_sets<T, Surface>& s, const T& zeta) noexcept {
  const boundary<T>& b = s.edges;
  crossing_point<T> cross[max_crossings];
  const int n = level_crossings(b, s.runs, zeta, cross);
  if (n < 2) return b.values[0][0] < zeta ? T(s.total * s.area) : T(0);  // all or none
  T sum = T(0);
  // The boundary's arcs below the level, counter-clockwise: from each crossing where the height
  // falls through the level to the next crossing.
  for (int i = 0; i < n; ++i) {
    if (!cross[i].entering) continue;
    const crossing_point<T>& from = cross[i];
    const crossing_point<T>& to = cross[(i + 1) % n];
    int piece = from.place.piece;
    T u = from.place.u;
    for (int guard = 0; guard <= boundary_pieces; ++guard) {
      const bool last = piece == to.place.piece && to.place.u >= u;
      sum += boundary_green(b, s.weight, piece, u, last ? to.place.u : T(1), s.green);
      if (last) break;
      piece = (piece + 1) % boundary_pieces;
      u = T(-1);
    }
  }
  // The level curve's arcs, traversed with the lower side on their left: along (-gy, gx).
  // Sorted along that direction, consecutive crossings bound one arc.
  int order[max_crossings];
  for (int i = 0; i < n; ++i) order[i] = i;
  auto along = [&](int i) { return -s.gy * cross[i].at.x + s.gx * cross[i].at.y; };
  for (int i = 1; i < n; ++i)
    for (int k = i; k > 0 && along(order[k]) < along(order[k - 1]); --k) {
      const int swap = order[k];
      order[k] = order[k - 1];
      order[k - 1] = swap;
    }
  for (int i = 0; i + 1 < n; i += 2) {
    const point2<T>& a = cross[order[i]].at;
    const point2<T>& c = cross[order[i + 1]].at;
    sum += segment_green(s.weight, a, c, s.green) + lens_area(s, a, c, zeta);
  }
  return sum;
}

/// A piece [p, q] of heights on which G is analytic, and the substitution that keeps it so at a
/// singular end (a level curve tangent to the boundary there: G ~ (zeta - p)^(3/2)):
/// zeta = p + (q - p)(1 - cos theta) near p, symmetric near q, both on the circle's extremes.
template <class T>
struct height_piece {
  T p, q;
  bool singular_low, singular_high;

  /// zeta - origin and d zeta / du at u in [-1, 1], the difference taken from the end it is near
  /// (q - origin and p - origin exact where the origin is near them: the knee's delta50): 1 - cos
  /// theta as 2 sin^2(theta / 2). Near a singular end the plain form cancelled to span x eps of
  /// height (1e-11 m on a 70 km piece) and the height itself rounds to its own ulp (7e-12 m at 40
  /// km), which a knee of H = 1 um turned into 4e-6 of L0 in the field's mean as a circle's top
  /// passed it (density_integral).
  void at_offset(const T& u, const T& origin, T& from_origin, T& rate) const noexcept {
    using std::cos;
    using std::sin;
    const T span = q - p;
    if (singular_low && singular_high) {
      const T theta = (u + T(1)) * pi<T>() / T(2);
      // p + span sin^2(theta / 2) = q - span cos^2(theta / 2), each from its own end.
      const T half_sin = sin(T(theta / T(2))), half_cos = cos(T(theta / T(2)));
      from_origin = u < T(0) ? T((p - origin) + span * half_sin * half_sin)
                             : T((q - origin) - span * half_cos * half_cos);
      rate = span / T(2) * sin(theta) * pi<T>() / T(2);
    } else if (singular_low) {
      const T theta = (u + T(1)) * pi<T>() / T(4);
      const T half_sin = sin(T(theta / T(2)));
      from_origin = (p - origin) + span * T(2) * half_sin * half_sin;
      rate = span * sin(theta) * pi<T>() / T(4);
    } else if (singular_high) {
      const T theta = (T(1) - u) * pi<T>() / T(4);
      const T half_sin = sin(T(theta / T(2)));
      from_origin = (q - origin) - span * T(2) * half_sin * half_sin;
      rate = span * sin(theta) * pi<T>() / T(4);
    } else {
      from_origin = (p - origin) + span * (u + T(1)) / T(2);
      rate = span / T(2);
    }
  }
  /// zeta and d zeta / du at u.
  void at(const T& u, T& zeta, T& rate) const noexcept { at_offset(u, T(0), zeta, rate); }
  /// The u of the height origin + from_origin in [p, q]: acos near 1 as 2 asin(sqrt((1 - r) /
  /// 2)), 1 - r from the end it is near (at_offset's cancellations, the other way).
  T u_of_offset(const T& from_origin, const T& origin) const noexcept {
    using std::asin;
    using std::sqrt;
    const T span = q - p;
    if (!(span > T(0))) return T(-1);
    const T r = (from_origin - (p - origin)) / span;
    const T from_top = ((q - origin) - from_origin) / span;  // 1 - r without the cancellation
    // The ends exactly (every map sends them to -1 and 1): the derivatives are infinite there,
    // and a Jet (the calibration's derivatives) would carry 0 x inf = NaN from a clamped r.
    if (!(r > T(0))) return T(-1);
    if (!(from_top > T(0))) return T(1);
    auto half_angle = [](const T& x) {  // acos(1 - x)
      return T(T(2) * asin(T(sqrt(T(x / T(2))))));
    };
    if (singular_low && singular_high) {
      // acos(1 - 2 r): from the low end below the middle, pi - acos(1 - 2 (1 - r)) above it.
      const T angle =
          r < T(1) / T(2) ? half_angle(T(T(2) * r)) : T(pi<T>() - half_angle(T(T(2) * from_top)));
      return T(2) * angle / pi<T>() - T(1);
    }
    if (singular_low) return T(4) * half_angle(r) / pi<T>() - T(1);
    if (singular_high) return T(1) - T(4) * half_angle(from_top) / pi<T>();
    return T(2) * r - T(1);
  }
  /// The u of a height in [p, q].
  T u_of(const T& zeta) const noexcept { return u_of_offset(zeta, T(0)); }
};

/// G times the area on a piece, as a Chebyshev series in the piece's u (first-kind nodes).
template <class T>
struct piece_model {
  height_piece<T> piece;
  int nodes;
  std::array<T, model_nodes> series;

  T at(const T& u) const noexcept {
    T b1 = T(0), b2 = T(0);
    const T two_u = u * integer_factor<T>(2);
    for (int k = nodes - 1; k >= 1; --k) {
      const T b0 = two_u * b1 - b2 + series[k];
      b2 = b1;
      b1 = b0;
    }
    return u * b1 - b2 + series[0];
  }
};

/// The model of G times the area on a piece from its values at the first-kind nodes (DCT-II).
template <class T>
piece_model<T> piece_model_from(
    const height_piece<T>& piece, int nodes, const T* values,
    const std::array<std::array<T, model_nodes>, model_nodes>& cosines) noexcept {
  piece_model<T> m{piece, nodes, {}};
  for (int j = 0; j < nodes; ++j) {
    T sum = T(0);
    for (int k = 0; k < nodes; ++k) sum += values[k] * cosines[j][k];
    m.series[j] = sum * T(2) / T(nodes) / (j == 0 ? T(2) : T(1));
  }
  return m;
}

/// G times the area at a piece's first-kind nodes, on exact heights.
template <class T, class Surface>
void piece_values(const level_sets<T, Surface>& s, const height_piece<T>& piece, int nodes,
                  const std::array<std::array<T, model_nodes>, model_nodes>& cosines,
                  T* values) noexcept {
  for (int k = 0; k < nodes; ++k) {
    T zeta, rate;
    piece.at(cosines[1][k], zeta, rate);
    values[k] = weighted_area_below(s, zeta);
  }
}

template <class T, class Surface>
piece_model<T> piece_model_of(
    const level_sets<T, Surface>& s, const height_piece<T>& piece, int nodes,
    const std::array<std::array<T, model_nodes>, model_nodes>& cosines) noexcept {
  std::array<T, model_nodes> values;
  piece_values(s, piece, nodes, cosines, values.data());
  return piece_model_from(piece, nodes, values.data(), cosines);
}

/// How much of the field's mean a piece's G carries (level_set_sum): the profile's density over
/// the part of the piece the sum integrates, l(from) - l(to) (l falls with height; its density is
/// -l'), and the disk's jump L_disk - l(0) where the piece holds the surface.
template <class T>
T piece_weight(const radiance_profile<T>& profile, const height_piece<T>& piece) noexcept {
  using std::abs;
  T weight = T(0);
  if (!(piece.p > T(0)) && !(piece.q < T(0)))
    weight = abs(T(profile.disk - limb_fraction(profile, T(0))));
  if (!(profile.scale_m > T(0))) return weight;  // the step: no model is read
  const T cut = profile.offset_m + T(40) * profile.scale_m;
  const T from = piece.p > T(0) ? piece.p : T(0), to = piece.q < cut ? piece.q : cut;
  if (to > from) weight += limb_fraction(profile, from) - limb_fraction(profile, to);
  return weight;
}

/// Whether a model of G on `nodes` nodes (its values at them) is converged: the size of its last
/// two Chebyshev coefficients, weighted by the piece's share of the mean (piece_weight), within
/// 1e-12 of `whole` (G times the area above every height: the plateau's scale). 1e-13 moved no
/// crossing of 1100 random scenes by more than 4e-10 deg beyond it (but a flat-topped slope's)
/// and cost the benchmark's square 11 % more of G's values, 1e-12 1 %. A square's piece
/// between corners is nearly polynomial, but where a side's heights turn just beyond a corner G
/// has a square-root branch point just beyond the piece's end, and 12 nodes leave up to 1e-7 of
/// it (a 1.95 deg square 28 800 km out: the mean 1.3e-8 of L0 off, the slope locator 1.5e-5 deg).
template <class T>
bool model_converged(const T* values, int nodes,
                     const std::array<std::array<T, model_nodes>, model_nodes>& cosines,
                     const T& weight, const T& whole) noexcept {
  using std::abs;
  T tail = T(0);
  for (int j = nodes - 2; j < nodes; ++j) {
    T sum = T(0);
    for (int k = 0; k < nodes; ++k) sum += values[k] * cosines[j][k];
    tail += abs(sum);
  }
  return !(tail * T(2) / T(nodes) * weight > abs(whole) / T(1000000000000LL));
}

/// G's model on a piece of a patch of `shape`: on model_nodes_of(shape) nodes, or on
/// fine_model_nodes where those do not converge (model_converged).
template <class T, class Surface>
piece_model<T> converged_piece_model(const level_sets<T, Surface>& s, const height_piece<T>& piece,
                                     field_shape shape, const radiance_profile<T>& profile,
                                     const chebyshev_tables<T>& tables) noexcept {
  const int first = model_nodes_of(shape);
  std::array<T, model_nodes> values;
  piece_values(s, piece, first, tables.first_kind(first), values.data());
  if (first < fine_model_nodes && !model_converged(values.data(), first, tables.first_kind(first),
                                                   piece_weight(profile, piece), s.whole))
    return piece_model_of(s, piece, fine_model_nodes, tables.first_kind(fine_model_nodes));
  return piece_model_from(piece, first, values.data(), tables.first_kind(first));
}

/// The profile's density in x = (zeta - delta50) / H, -dl/dx = v e^{-v}, v = ln 2 e^{-x} (in
/// height, divided by H): in x, not zeta, because a height near the knee rounds to its ulp (7e-12
/// m at 40 km), a part in 1e5 of a knee of 1 um.
template <class T>
T profile_density_in_x(const radiance_profile<T>& profile, const T& x) noexcept {
  using std::exp;
  if (x < profile.x_saturated) return T(0);
  const T v = profile.ln2 * exp(-x);
  return v * exp(-v);
}

/// The panels of x = (zeta - delta50) / H the density is integrated on: one H across its knee,
/// wider in its tail (e^-x: 1e-17 of the plateau at x = 40).
template <class T>
int density_panels(T* x) noexcept {
  const int marks[] = {-4, -3, -2, -1, 0, 1, 2, 3, 4, 5, 6, 8, 10, 13, 16, 20, 25, 32, 40};
  int n = 0;
  for (int m : marks) x[n++] = T(m);
  return n;
}

/// int (-l') G dzeta over [from, to] within a piece, on its model. Each panel of x = (zeta -
/// delta50) / H is integrated in x itself, so that a knee of any width is resolved however wide the
/// piece (a nanometre of H in a piece of 100 km: its u would not resolve it); a panel within its
/// own width of a singular end, in the piece's variable u, whose substitution makes G smooth there.
template <class T>
T density_integral(const piece_model<T>& m, const radiance_profile<T>& profile, const T& from,
                   const T& to, const gauss_legendre_rule<T, 10>& rule) noexcept {
  T marks[24];
  const int count = density_panels(marks);
  const T h = profile.scale_m, lo_x = (from - profile.offset_m) / h,
          hi_x = (to - profile.offset_m) / h;
  T cuts[26];
  int n = 0;
  cuts[n++] = lo_x;
  for (int i = 0; i < count; ++i)
    if (marks[i] > lo_x && marks[i] < hi_x) cuts[n++] = marks[i];
  cuts[n++] = hi_x;
  const height_piece<T>& piece = m.piece;
  T sum = T(0);
  // Heights as offsets from delta50 (h x), as profile_density_in_x reads them.
  const T origin = profile.offset_m;
  for (int i = 0; i + 1 < n; ++i) {
    const T xa = cuts[i], xb = cuts[i + 1];
    if (!(xb > xa)) continue;
    const T za = origin + h * xa, zb = origin + h * xb, width = zb - za;
    const bool near_singular = (piece.singular_low && za - piece.p < width) ||
                               (piece.singular_high && piece.q - zb < width);
    if (near_singular) {
      const T ua = piece.u_of_offset(T(h * xa), origin), ub = piece.u_of_offset(T(h * xb), origin);
      sum += gauss_integral(rule, ua, ub, [&](const T& u) {
        T from_origin, rate;
        piece.at_offset(u, origin, from_origin, rate);
        return T(profile_density_in_x(profile, T(from_origin / h)) / h * m.at(u) * rate);
      });
      continue;
    }
    sum += gauss_integral(rule, xa, xb, [&](const T& x) {
      return T(profile_density_in_x(profile, x) * m.at(piece.u_of_offset(T(h * x), origin)));
    });
  }
  return sum;
}

/// The heights where G is not analytic, sorted, with whether each is singular.
template <class T>
int height_breaks(const boundary<T>& b, const monotone_runs<T>& runs, T* at,
                  bool* singular) noexcept {
  int n = 0;
  auto add = [&](const T& h, bool is_singular) {
    for (int i = 0; i < n; ++i)
      if (at[i] == h) {
        singular[i] = singular[i] || is_singular;
        return;
      }
    if (n < max_breaks) {
      at[n] = h;
      singular[n++] = is_singular;
    }
  };
  T low = runs.low[0], high = runs.high[0];
  for (int i = 0; i < runs.count; ++i) {
    if (runs.low[i] < low) low = runs.low[i];
    if (runs.high[i] > high) high = runs.high[i];
  }
  add(low, false);
  add(high, false);
  if (b.shape == field_shape::square)
    for (int piece = 0; piece < boundary_pieces; ++piece) add(b.values[piece][0], false);
  for (int i = 0; i < runs.interior_extrema; ++i) add(runs.extremum_height[i], true);
  for (int i = 1; i < n; ++i)
    for (int k = i; k > 0 && at[k] < at[k - 1]; --k) {
      const T h = at[k];
      at[k] = at[k - 1];
      at[k - 1] = h;
      const bool f = singular[k];
      singular[k] = singular[k - 1];
      singular[k - 1] = f;
    }
  return n;
}

}  // namespace field_detail

/// The rules the field's mean integrates with, made once per head (no function-local statics).
template <class T>
struct field_rules {
  gauss_legendre_rule<T, field_detail::green_nodes> green;
  gauss_legendre_rule<T, field_detail::lens_nodes> lens;
  gauss_legendre_rule<T, 10> density;
  gauss_legendre_rule<T, 5> segment;
  gauss_legendre_rule<T, field_detail::weight_most_terms> fine;  ///< Green's, past 5 terms
  gauss_legendre_rule<T, field_detail::fan_nodes> fan;
  field_detail::chebyshev_tables<T> tables;
};

template <class T>
void field_rules_build(field_rules<T>& r) noexcept {
  using namespace field_detail;
  r.green = gauss_legendre_rule_of<T, green_nodes>();
  r.lens = gauss_legendre_rule_of<T, lens_nodes>();
  r.density = gauss_legendre_rule_of<T, 10>();
  r.segment = gauss_legendre_rule_of<T, 5>();
  r.fine = gauss_legendre_rule_of<T, weight_most_terms>();
  r.fan = gauss_legendre_rule_of<T, fan_nodes>();
  lobatto_table(square_edge_nodes, r.tables.lobatto_square);
  lobatto_table(edge_nodes, r.tables.lobatto_circle);
  first_kind_table(square_model_nodes, r.tables.first_coarse);
  first_kind_table(fine_model_nodes, r.tables.first_fine);
}

template <class T>
field_rules<T> field_rules_of() noexcept {
  field_rules<T> r{};
  field_rules_build(r);
  return r;
}

namespace field_detail {

template <class T>
green_rules<T> green_rules_of(const field_rules<T>& r) noexcept {
  return {&r.green, &r.segment, &r.fine};
}

/// The level sets of the patch (boundary, runs, weight, gradient at the centre, area, G above
/// every height) and G's breaks (height_breaks): what G needs at any level.
template <class T, class Surface>
level_sets<T, Surface> level_sets_of(const field_patch<T, Surface>& patch,
                                     const field_radiance<T>& radiance,
                                     const field_rules<T>& rules) noexcept {
  level_sets<T, Surface> s{patch,
                           boundary_of(patch, rules.tables),
                           {},
                           weight_model_of(patch, radiance),
                           green_rules_of(rules),
                           rules.lens,
                           T(0),
                           T(0),
                           T(0),
                           T(0),
                           T(0)};
  s.runs = monotone_runs_of(s.edges);
  const T h = patch.half;
  s.gx = (patch.height(T(h / T(2)), T(0)) - patch.height(T(-h / T(2)), T(0))) / h;
  s.gy = (patch.height(T(0), T(h / T(2))) - patch.height(T(0), T(-h / T(2)))) / h;
  s.area = patch_area(patch.shape, h);
  T whole = weight_integral(s.edges, s.weight, s.green);
  // A patch wholly on the disk near the centre's line: the weight's polynomial cannot follow
  // the latitude turning about it (fan_reach); G there is all or nothing, so the fans' integral
  // is the patch's whole share.
  T mean;
  if (!s.weight.constant && patch_on_disk(s.runs) && fan_latitude_mean(patch, rules.fan, mean))
    whole = radiance.plateau * s.area * (T(1) + radiance.season * mean);
  s.whole = whole;
  s.total = whole / s.area;
  return s;
}

/// The mean of sin(latitude) over the patch (the season factor's part of a patch wholly on the
/// disk): by fans within fan_reach half-widths of the line through the centre, else from the
/// weight's polynomial (weight_model_of; at degree 4 its error falls as the distance's sixth power,
/// 5e-11 at 8.7 half-widths of a 2.25 deg square; at low orbits the centre lies 60 deg away).
/// Four points exact for cubics served the plateau between separate windows before: 5.6e-7 off
/// 15 half-widths from the centre's line, 21 760 km out.
template <class T, class Surface>
T patch_latitude_mean(const field_patch<T, Surface>& patch, const field_rules<T>& rules) noexcept {
  T mean;
  if (fan_latitude_mean(patch, rules.fan, mean)) return mean;
  const field_radiance<T> unit{nullptr, T(1), T(1)};  // F = 1 + sin(latitude)
  const T whole =
      weight_integral(shape_of(patch), weight_model_of(patch, unit), green_rules_of(rules));
  return whole / patch_area(patch.shape, patch.half) - T(1);
}

/// s times the area from G's structure (the level-set sum of the file comment): its nb sorted
/// breaks (singular ends flagged), G times the area above them all (`whole`), at a level
/// (`below(zeta)`), and as a model on the piece between breaks i and i + 1 (`model(i, piece)`).
template <class T, class Below, class Model>
T level_set_sum(const radiance_profile<T>& profile, const T* breaks, const bool* singular, int nb,
                const T& whole, const Below& below, const Model& model,
                const gauss_legendre_rule<T, 10>& rule) noexcept {
  const T high = breaks[nb - 1];
  const T disk = profile.disk;
  if (!(profile.scale_m > T(0))) {  // the step: exact area fractions
    T sum = disk * below(T(0));
    if (profile.offset_m > T(0)) sum += below(profile.offset_m) - below(T(0));
    return sum;
  }
  T sum = (disk - limb_fraction(profile, T(0))) * below(T(0));
  sum += whole * limb_fraction(profile, high > T(0) ? high : T(0));
  const T cut = profile.offset_m + T(40) * profile.scale_m;
  for (int i = 0; i + 1 < nb; ++i) {
    const T from = breaks[i] > T(0) ? breaks[i] : T(0);
    const T to = breaks[i + 1] < cut ? breaks[i + 1] : cut;
    if (!(to > from)) continue;
    const height_piece<T> piece{breaks[i], breaks[i + 1], singular[i], singular[i + 1]};
    sum += density_integral(model(i, piece), profile, from, to, rule);
  }
  return sum;
}

}  // namespace field_detail

namespace field_detail {

/// Bounds on ahead() over the patch (field_patch::ahead: > 0 where a line's closest approach lies
/// ahead of the satellite): its linear part a + x b + y c at its least and most over the patch,
/// less and plus a bound on the rest, |(cos r - 1) a + (sin r / r - 1)(x b + y c)| <= r^2 (|a| +
/// r g) / 2 (g = |(b, c)|); `reach`, the linear part's half-range over the patch.
template <class T>
struct ahead_range {
  T least, most, reach;
};

template <class T, class Surface>
ahead_range<T> ahead_range_of(const field_patch<T, Surface>& p) noexcept {
  using std::abs;
  using std::sqrt;
  const T a = ahead_sign(*p.surface) * p.first.d;
  const T b = p.first.t, c = p.first.c;
  const T g = sqrt(b * b + c * c);
  const bool square = p.shape == field_shape::square;
  const T reach = square ? T(p.half * (abs(b) + abs(c))) : T(p.half * g);
  const T r = square ? T(p.half * sqrt(T(2))) : p.half;
  const T rest = r * r * (abs(a) + r * g) / T(2);
  return {T(a - reach - rest), T(a + reach + rest), reach};
}

/// Whether some line of the patch may point behind the satellite or come within `margin` of it
/// (in ahead()'s units, ~rad).
template <class T, class Surface>
bool patch_near_behind(const field_patch<T, Surface>& p, const T& margin) noexcept {
  return !(ahead_range_of(p).least > margin);
}

/// Where G's level sets serve a patch: no line within the patch's own reach of ahead() (about its
/// width) of pointing behind the satellite. Nearer, the heights' ridge along the horizontal
/// (their gradient falls to 0 there) costs the level sets digits: 6e-12 of L0 for a 1.5 deg
/// square a fifth of its reach away, 4e-14 at its reach (against behind_quadrature and a 400 x
/// 800 Gauss product split at the kink, which agree to 1e-21).
template <class T, class Surface>
bool level_sets_serve(const field_patch<T, Surface>& p) noexcept {
  const ahead_range<T> r = ahead_range_of(p);
  return r.least > r.reach;
}

/// Whether every line of the patch points behind the satellite: its heights and latitudes are
/// then the satellite's own, one value over the patch.
template <class T, class Surface>
bool patch_all_behind(const field_patch<T, Surface>& p) noexcept {
  return !(ahead_range_of(p).most > T(0));
}

inline constexpr int max_bend_levels = 24;  ///< the surface, a step, the knee's marks

/// The heights in (low, high) where the radiance bends or jumps, sorted: the surface, a step's
/// delta50, the knee's marks delta50 + m H (density_panels).
template <class T>
int bend_levels(const radiance_profile<T>& profile, const T& low, const T& high, T* out) noexcept {
  int n = 0;
  auto add = [&](const T& level) {
    if (level > low && level < high && n < max_bend_levels) out[n++] = level;
  };
  add(T(0));
  if (!(profile.scale_m > T(0))) {
    add(profile.offset_m);
  } else {
    T marks[24];
    const int count = density_panels(marks);
    for (int i = 0; i < count; ++i) add(T(profile.offset_m + marks[i] * profile.scale_m));
  }
  sort_ascending(out, n);
  return n;
}

/// The root of f in [a, b] (f(a) = fa, f(b) = fb of opposite signs) by the Illinois method, to
/// the bracket's rounding or 80 steps.
template <class T, class F>
T illinois_root(const F& f, T a, T b, T fa, T fb) noexcept {
  using std::abs;
  const T tolerance = T(8) * std::numeric_limits<T>::epsilon() * (abs(a) + abs(b));
  int side = 0;
  for (int it = 0; it < 80 && b - a > tolerance; ++it) {
    T x = (a * fb - b * fa) / (fb - fa);
    if (!(x > a && x < b)) x = (a + b) / T(2);
    const T fx = f(x);
    if (fx == T(0)) return x;
    if ((fx < T(0)) == (fa < T(0))) {
      a = x;
      fa = fx;
      if (side < 0) fb = fb / T(2);
      side = -1;
    } else {
      b = x;
      fb = fx;
      if (side > 0) fa = fa / T(2);
      side = 1;
    }
  }
  return (a + b) / T(2);
}

/// The field's mean over a patch that reaches (or nearly reaches) the satellite's horizontal:
/// lines behind it have the satellite's own height (docs/SENSOR_PHYSICS.md, decision 5), flat,
/// so the heights have a kink where ahead() = 0 and G a jump, outside the level sets' domain
/// (analytic heights). An iterated Gauss quadrature of L on exact heights and latitudes instead:
/// inner lines along the patch axis nearer ahead()'s gradient (along which the heights rise
/// monotonically to the flat part), cut where they pass ahead() = 0 and the bend levels
/// (bend_levels); the outer integral cut where those meet the patch's boundary (found on 16
/// samples of each side), the circle's in the angle (x = h sin t: no square-root ends).
template <class T, class Surface>
struct behind_quadrature {
  const field_patch<T, Surface>& patch;
  const field_radiance<T>& radiance;
  const gauss_legendre_rule<T, 10>& rule;
  bool inner_x;  ///< the inner lines run along x (else along y)
  T levels[max_bend_levels];
  int level_count;

  point2<T> point(const T& o, const T& i) const noexcept {
    return inner_x ? point2<T>{i, o} : point2<T>{o, i};
  }
  T ahead(const T& o, const T& i) const noexcept {
    const point2<T> q = point(o, i);
    return patch.ahead(q.x, q.y);
  }
  T height(const T& o, const T& i) const noexcept {
    const point2<T> q = point(o, i);
    return patch.height(q.x, q.y);
  }
  T value(const T& o, const T& i) const noexcept {
    const point2<T> q = point(o, i);
    const tangent_height<T> h = patch.at(q.x, q.y);
    const T l0 = radiance.plateau * (T(1) + radiance.season * h.sin_latitude);
    return h.height_m < T(0) ? T(l0 * radiance.profile->disk)
                             : T(l0 * limb_fraction(*radiance.profile, h.height_m));
  }
  /// Where f(t) - level changes sign in [a, b] (fa, fb at the ends): its root into cuts.
  template <class F>
  void cut_at(const F& f, const T& a, const T& b, const T& fa, const T& fb, T* cuts,
              int& n) const noexcept {
    if ((fa > T(0)) == (fb > T(0)) || n >= max_bend_levels + 2) return;
    cuts[n++] = illinois_root(f, a, b, fa, fb);
  }
  /// int L di along the inner line at o over [lo, hi].
  T inner(const T& o, const T& lo, const T& hi) const noexcept {
    T cuts[max_bend_levels + 4];
    int n = 0;
    cuts[n++] = lo;
    auto ahead_at = [&](const T& i) { return ahead(o, i); };
    const T a_lo = ahead(o, lo), a_hi = ahead(o, hi);
    cut_at(ahead_at, lo, hi, a_lo, a_hi, cuts, n);
    // The part ahead of the satellite, where the heights vary: cut at the bend levels.
    const bool kink = n > 1;
    const T p = kink ? (a_lo > T(0) ? lo : cuts[1]) : lo;
    const T q = kink ? (a_lo > T(0) ? cuts[1] : hi) : hi;
    if (kink || a_lo > T(0)) {
      const T hp = height(o, p), hq = height(o, q);
      for (int k = 0; k < level_count; ++k) {
        auto f = [&](const T& i) { return height(o, i) - levels[k]; };
        cut_at(f, p, q, T(hp - levels[k]), T(hq - levels[k]), cuts, n);
      }
    }
    cuts[n++] = hi;
    sort_ascending(cuts, n);
    return gauss_integral_over_cuts(rule, cuts, n, [&](const T& x) { return T(value(o, x)); });
  }
  /// The outer variable t's place o, the inner half-length w and do/dt.
  void outer_at(const T& t, T& o, T& w, T& jacobian) const noexcept {
    using std::cos;
    using std::sin;
    if (patch.shape == field_shape::square) {
      o = t;
      w = patch.half;
      jacobian = T(1);
      return;
    }
    o = patch.half * sin(t);
    w = patch.half * cos(t);
    jacobian = w;
  }
  /// The outer cuts over [t0, t1]: where ahead() = 0 or a bend level meets either side.
  int outer_cuts(const T& t0, const T& t1, T* cuts, int capacity) const noexcept;
  T mean() const noexcept;
};

template <class T, class Surface>
int behind_quadrature<T, Surface>::outer_cuts(const T& t0, const T& t1, T* cuts,
                                              int capacity) const noexcept {
  constexpr int samples = 16;
  int n = 0;
  for (int side = -1; side <= 1; side += 2) {
    auto edge = [&](const T& t, int what) {  // what: -1 ahead(), else the level's excess
      T o, w, jacobian;
      outer_at(t, o, w, jacobian);
      return what < 0 ? ahead(o, T(T(side) * w)) : T(height(o, T(T(side) * w)) - levels[what]);
    };
    for (int what = -1; what < level_count; ++what) {
      T ta = t0, fa = edge(t0, what);
      for (int k = 1; k <= samples && n < capacity; ++k) {
        const T tb = t0 + (t1 - t0) * T(k) / T(samples), fb = edge(tb, what);
        if ((fa > T(0)) != (fb > T(0)))
          cuts[n++] = illinois_root([&](const T& t) { return edge(t, what); }, ta, tb, fa, fb);
        ta = tb;
        fa = fb;
      }
    }
  }
  return n;
}

template <class T, class Surface>
T behind_quadrature<T, Surface>::mean() const noexcept {
  const bool square = patch.shape == field_shape::square;
  const T t0 = square ? T(-patch.half) : T(-pi<T>() / T(2));
  const T t1 = -t0;
  constexpr int capacity = 2 * (max_bend_levels + 1);
  T cuts[capacity + 2];
  int n = outer_cuts(t0, t1, cuts + 1, capacity) + 1;
  cuts[0] = t0;
  cuts[n++] = t1;
  sort_ascending(cuts, n);
  const T sum = gauss_integral_over_cuts(rule, cuts, n, [&](const T& t) {
    T o, w, jacobian;
    outer_at(t, o, w, jacobian);
    return T(jacobian * inner(o, T(-w), w));
  });
  return sum / patch_area(patch.shape, patch.half);
}

/// The field's mean over a patch that reaches the satellite's horizontal (behind_quadrature); one
/// line's radiance where every line points behind it (one height and latitude, the satellite's).
/// Accuracy: against the brute-force reference, tests/core/test_sensor_physics_field_mean.cpp.
template <class T, class Surface>
T behind_patch_mean(const field_patch<T, Surface>& patch, const field_radiance<T>& radiance,
                    const field_rules<T>& rules) noexcept {
  using std::abs;
  using std::cos;
  using std::sin;
  using std::sqrt;
  behind_quadrature<T, Surface> q{patch, radiance, rules.density, false, {}, 0};
  if (patch_all_behind(patch)) return q.value(T(0), T(0));
  q.inner_x = abs(patch.first.t) > abs(patch.first.c);
  // The patch's heights lie between its corners' (or its boundary's) and the satellite's own.
  T low = patch.height(T(0), T(0)), high = low;
  for (int k = 0; k < 8; ++k) {
    const T angle = pi<T>() * T(k) / T(4);
    const T reach =
        patch.shape == field_shape::square && k % 2 == 1 ? T(patch.half * sqrt(T(2))) : patch.half;
    const T h = patch.height(T(reach * cos(angle)), T(reach * sin(angle)));
    if (h < low) low = h;
    if (h > high) high = h;
  }
  const T span = high - low;
  q.level_count = bend_levels(*radiance.profile, T(low - span), T(high + span), q.levels);
  return q.mean();
}

}  // namespace field_detail

/// The field's mean radiance s at one scan azimuth (MODEL §12), for a patch of fov > 0.
/// Domain: a patch small enough that its heights have no interior extreme (fields below ~10 deg
/// near the limb) and at most max_crossings crossings of a level with its boundary; a patch
/// within its own reach of the satellite's horizontal (level_sets_serve) by behind_quadrature.
/// Accuracy: docs/SENSOR_PHYSICS.md ("The field"), against the brute-force reference.
template <class T, class Surface>
T field_mean_at(const field_patch<T, Surface>& patch, const field_radiance<T>& radiance,
                const field_rules<T>& rules) noexcept {
  using namespace field_detail;
  // A patch that reaches the satellite's horizontal has flat heights (decision 5) outside the
  // level sets' domain, and one near it a ridge: MODEL §12's mean by behind_quadrature.
  if (!level_sets_serve(patch)) return behind_patch_mean(patch, radiance, rules);
  const level_sets<T, Surface> s = level_sets_of(patch, radiance, rules);
  T breaks[max_breaks];
  bool singular[max_breaks];
  const int nb = height_breaks(s.edges, s.runs, breaks, singular);
  const T low = breaks[0], high = breaks[nb - 1];
  auto below = [&](const T& zeta) {  // G(zeta) times the area
    if (!(zeta > low)) return T(0);
    if (!(zeta < high)) return s.whole;
    return weighted_area_below(s, zeta);
  };
  // The circle's one piece spans all its heights (24 nodes: 1e-13 of the plateau); the
  // square's pieces between corners are nearly polynomial (12 nodes, 24 where those do not
  // converge; measured: docs/SENSOR_PHYSICS.md).
  auto model = [&](int, const height_piece<T>& piece) {
    return converged_piece_model(s, piece, patch.shape, *radiance.profile, rules.tables);
  };
  return level_set_sum(*radiance.profile, breaks, singular, nb, s.whole, below, model,
                       rules.density) /
         s.area;
}

}  // namespace conescan
