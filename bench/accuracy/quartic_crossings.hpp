// The ellipsoid's crossings by solving the quartic: the alternative to the core's Newton
// iteration on the scan circle (scan_model.hpp), measured against it (docs/PERFORMANCE.md) and
// kept only here. Along the scan circle MODEL §5's g is a trigonometric polynomial of degree 2
// (tangency_on_circle); with x = tan((theta - theta_0)/2) it becomes a quartic in x, solved by
// Ferrari's method (a resolvent cubic by Cardano or Viete), its real roots polished by Newton
// steps on g itself (Ferrari's closed form loses digits where roots are close), then kept if in
// front of the satellite. theta_0 is the point of the scan circle farthest from the sphere's
// nadir, opposite the crossings, so no crossing sits near x = infinity.
#pragma once

#include <type_traits>

#include "conescan/scan_model.hpp"

namespace conescan::accuracy {

namespace quartic_detail {

template <class T>
T cube_root(const T& x) {
  using std::abs;
  using std::pow;
  if constexpr (std::is_floating_point_v<T>) {
    return std::cbrt(x);
  } else {
    const T r = pow(T(abs(x)), T(1) / T(3));
    return x < T(0) ? T(-r) : r;
  }
}

/// The largest real root of z^3 + a2 z^2 + a1 z + a0 (Cardano with one real root, Viete's
/// cosines with three).
template <class T>
T largest_cubic_root(const T& a2, const T& a1, const T& a0) {
  using std::abs;
  using std::acos;
  using std::cos;
  using std::sqrt;
  const T q = (a2 * a2 - T(3) * a1) / T(9);
  const T r = (T(2) * a2 * a2 * a2 - T(9) * a2 * a1 + T(27) * a0) / T(54);
  const T q3 = q * q * q;
  if (r * r < q3) {
    T ratio = r / sqrt(q3);
    if (ratio > T(1)) ratio = T(1);
    if (ratio < T(-1)) ratio = T(-1);
    const T theta = acos(ratio);
    return T(-2) * sqrt(q) * cos((theta + T(2) * pi<T>()) / T(3)) - a2 / T(3);
  }
  const T a = -cube_root(T(r + (r < T(0) ? T(-1) : T(1)) * sqrt(T(r * r - q3))));
  const T b = a == T(0) ? T(0) : T(q / a);
  return a + b - a2 / T(3);
}

/// Real roots of y^2 + b y + c, appended to out[count...]. Returns the new count.
template <class T>
int quadratic_roots(const T& b, const T& c, T* out, int count) {
  using std::sqrt;
  const T discriminant = b * b - T(4) * c;
  if (discriminant < T(0)) return count;
  const T root = sqrt(discriminant);
  // Without cancellation: the larger in magnitude first, the other from the product c.
  const T big = -(b + (b < T(0) ? T(-root) : root)) / T(2);
  out[count++] = big;
  out[count++] = big == T(0) ? T(0) : T(c / big);
  return count;
}

/// g (1 + x^2)^2 = a[4] x^4 + a[3] x^3 + a[2] x^2 + a[1] x + a[0], x = tan((theta - theta_0) / 2),
/// from g's harmonics turned to theta_0 (as in has_second_earth_arc).
template <class T>
void quartic_in_x(const tangency_on_circle<T>& t, const circle_point<T>& origin, T* a) noexcept {
  const T hk = t.height * t.kappa;
  const T g0 = t.f0 * t.f0 + (t.f1 * t.f1 + t.f2 * t.f2) / T(2) - t.height -
               hk * (t.z0 * t.z0 + (t.z1 * t.z1 + t.z2 * t.z2) / T(2));
  const T g1 = T(2) * (t.f0 * t.f1 - hk * t.z0 * t.z1);
  const T g2 = T(2) * (t.f0 * t.f2 - hk * t.z0 * t.z2);
  const T g3 = ((t.f1 * t.f1 - t.f2 * t.f2) - hk * (t.z1 * t.z1 - t.z2 * t.z2)) / T(2);
  const T g4 = t.f1 * t.f2 - hk * t.z1 * t.z2;
  const T c0 = origin.cos_theta, s0 = origin.sin_theta;
  const T cos_2 = c0 * c0 - s0 * s0, sin_2 = T(2) * s0 * c0;
  const T h1 = g1 * c0 + g2 * s0, h2 = g2 * c0 - g1 * s0;
  const T h3 = g3 * cos_2 + g4 * sin_2, h4 = g4 * cos_2 - g3 * sin_2;
  a[4] = g0 - h1 + h3;
  a[3] = T(2) * h2 - T(4) * h4;
  a[2] = T(2) * g0 - T(6) * h3;
  a[1] = T(2) * h2 + T(4) * h4;
  a[0] = g0 + h1 + h3;
}

/// The real roots y of the depressed quartic of a (Ferrari): x = y - a[3] / (4 a[4]), y^4 + p y^2
/// + q y + r = 0; their count (0, 2 or 4).
template <class T>
int ferrari_roots(const T* a, T* y) noexcept {
  using std::sqrt;
  const T b = a[3] / a[4], c = a[2] / a[4], d = a[1] / a[4], e = a[0] / a[4];
  const T p = c - T(3) * b * b / T(8);
  const T q = d - b * c / T(2) + b * b * b / T(8);
  const T r = e - b * d / T(4) + b * b * c / T(16) - T(3) * b * b * b * b / T(256);
  int count = 0;
  const T m = largest_cubic_root(p, T(p * p / T(4) - r), T(-q * q / T(8)));
  if (m > T(0)) {
    const T w = sqrt(T(2) * m);
    count = quadratic_roots(T(-w), T(p / T(2) + m + q / (T(2) * w)), y, count);
    return quadratic_roots(w, T(p / T(2) + m - q / (T(2) * w)), y, count);
  }
  T z[2];  // biquadratic: q = 0
  const int n = quadratic_roots(p, r, z, 0);
  for (int i = 0; i < n; ++i)
    if (z[i] >= T(0)) {
      y[count++] = sqrt(z[i]);
      y[count++] = -sqrt(z[i]);
    }
  return count;
}

}  // namespace quartic_detail

/// Crossings on the ellipsoid by the quartic; same inputs, statuses and placement as
/// scan_model_crossings_ellipsoid (scan_model.hpp), except that a scene without a crossing is
/// miss or engulfed by the sign of g at theta_0 (and no fallback solver).
template <class T>
crossings<T> quartic_crossings_ellipsoid(const scan_circle<T>& circle,
                                         const ellipsoid_horizon<T>& surface) noexcept {
  using std::abs;
  using std::atan2;
  using std::sqrt;
  if (circle.state != status::ok || surface.state != status::ok)
    return crossings<T>::failed(status::invalid);
  const tangency_on_circle<T> t = tangency_on_circle_of(circle, surface);
  // theta_0 opposite the sphere's nadir about A: x = tan((theta - theta_0)/2) keeps the crossings
  // near x = 0.
  const vec3<T> nadir = unit(scaled(surface.position, T(-1)));
  const circle_point<T> towards = circle_point_of(circle, nadir);
  const circle_point<T> origin{T(-towards.cos_theta), T(-towards.sin_theta)};
  T a[5];
  quartic_detail::quartic_in_x(t, origin, a);
  T y[4];
  const int count = quartic_detail::ferrari_roots(a, y);
  const T shift = a[3] / a[4] / T(4);
  const T c0 = origin.cos_theta, s0 = origin.sin_theta;
  // Each real root on the circle, polished by two Newton steps on g, kept if in front.
  circle_point<T> in{T(0), T(0)}, out{T(0), T(0)};
  int ins = 0, outs = 0;
  for (int i = 0; i < count; ++i) {
    const T x = y[i] - shift;
    const T denominator = T(1) + x * x;
    const circle_point<T> local{(T(1) - x * x) / denominator, T(2) * x / denominator};
    circle_newton<T> polish{};
    polish.x = {local.cos_theta * c0 - local.sin_theta * s0,
                local.sin_theta * c0 + local.cos_theta * s0};
    polish.step(t);
    polish.step(t);
    if (polish.failed || !(polish.front < T(0))) continue;
    if (polish.slope > T(0)) {
      in = polish.x;
      ++ins;
    } else {
      out = polish.x;
      ++outs;
    }
  }
  if (ins > 1 || outs > 1) return crossings<T>::failed(status::multiple);
  if (ins == 0 || outs == 0) {
    T front, g, slope;
    t.at(origin, front, g, slope);
    return crossings<T>::failed(g > T(0) && front < T(0) ? status::engulfed : status::miss);
  }
  const vec3<T> d_in = scan_circle_direction(circle, in.cos_theta, in.sin_theta);
  const vec3<T> d_out = scan_circle_direction(circle, out.cos_theta, out.sin_theta);
  return crossings_from_azimuths(T(atan2(d_in.y, d_in.x)), T(atan2(d_out.y, d_out.x)), 4);
}

}  // namespace conescan::accuracy
