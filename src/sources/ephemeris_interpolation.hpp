// Polynomial interpolation of sampled 3-vectors (positions, velocities, rotation vectors) as the
// OEM and AEM readers use it, with an estimate of its own error.
//
// Form: Newton's divided differences on the nodes nearest the query, nearest first (the order in
// which the terms decrease, which keeps the sum stable). Lagrange takes distinct nodes; Hermite
// takes every node twice, its first divided difference there being the sampled derivative
// (confluent divided differences: Stoer & Bulirsch, Introduction to Numerical Analysis,
// section 2.1.5). The interpolant of the first `head` nodes and that of all nodes are summed in
// one pass: their difference is the Newton series' next term(s), the classical a-posteriori
// estimate of the head interpolant's error (Stoer & Bulirsch 2.1.4).
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>

#include "conescan/vector.hpp"
#include "sources/kvn.hpp"

namespace conescan::sources {

/// Most nodes an interpolant takes: Hermite doubles each of its points, and one point more
/// gives the estimate.
inline constexpr std::size_t max_interpolation_nodes = 2 * (max_interpolation_degree + 3);

/// Per-node scratch on the stack. Not value-initialised: a call writes the entries it reads,
/// the first m of 68, and zeroing all of them cost more than the interpolation (a LINEAR
/// state took 268 ns with them zeroed, 76 ns without; HERMITE 7 320 and 155 ns).
template <class T>
using node_array = std::array<T, max_interpolation_nodes>;

/// Up to `count` sample indices of a series of n samples (n >= 1) around the interval
/// [k, k + 1] (k < n), ordered nearest first: k, k + 1, k - 1, k + 2, k - 2, ..., continuing on
/// one side when the other runs out. Returns how many it wrote (min(count, n)).
inline std::size_t window_indices(std::size_t n, std::size_t k, std::size_t count,
                                  std::size_t* out) noexcept {
  count = std::min(count, n);
  std::size_t written = 0;
  std::size_t left = k + 1, right = k + 1;  // next candidates: left - 1, right
  bool take_left = true;
  while (written < count) {
    const bool left_ok = left > 0, right_ok = right < n;
    if (left_ok && (take_left || !right_ok)) {
      out[written++] = --left;
    } else {
      out[written++] = right++;
    }
    take_left = !take_left;
  }
  return written;
}

/// Full and head interpolants of a Newton sum, value and derivative at x.
struct newton_sums {
  vec3<double> full{0.0}, full_derivative{0.0};
  vec3<double> head{0.0}, head_derivative{0.0};
};

/// Interpolates at x through m nodes z[0..m) (m <= max_interpolation_nodes) with values f[i]; a
/// node equal to the one before it (Hermite) takes slope[i] as the derivative there (slope may
/// be null when no node repeats). `head` (1..m) is the number of leading nodes of the head
/// interpolant.
inline newton_sums newton_interpolate(const double* z, const vec3<double>* f,
                                      const vec3<double>* slope, std::size_t m, std::size_t head,
                                      double x) noexcept {
  node_array<vec3<double>> c;
  std::copy(f, f + m, c.begin());
  for (std::size_t j = 1; j < m; ++j) {
    for (std::size_t i = m - 1; i >= j; --i) {
      const double dz = z[i] - z[i - j];
      // dz == 0 only for j = 1 (Hermite). One division per entry, not one per component.
      c[i] = dz == 0.0 ? slope[i] : (c[i] - c[i - 1]) * (1.0 / dz);
    }
  }
  newton_sums s;
  vec3<double> value(0.0), derivative(0.0);
  double omega = 1, omega_derivative = 0;  // prod_{i<j} (x - z_i) and its derivative
  for (std::size_t j = 0; j < m; ++j) {
    value += c[j] * omega;
    derivative += c[j] * omega_derivative;
    if (j + 1 == head) {
      s.head = value;
      s.head_derivative = derivative;
    }
    omega_derivative = omega_derivative * (x - z[j]) + omega;
    omega *= x - z[j];
  }
  s.full = value;
  s.full_derivative = derivative;
  return s;
}

}  // namespace conescan::sources
