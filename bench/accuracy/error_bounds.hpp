// The documented accuracy of each method and precision (docs/ACCURACY.md): the largest error of
// the sensed eta, roll and pitch against the cpp_bin_float_50 reference of the same method,
// over the domain where the method's reference status is ok (for the paper's quadratic forms,
// also the stable closed form's: they have no fold guard of their own). The tests
// (tests/orbit/test_accuracy.cpp) hold every method to these numbers; the benchmark measures them.
#pragma once

#include <type_traits>

#include "accuracy/method.hpp"

namespace conescan::accuracy {

enum class precision { single, double_, extended };

template <class T>
constexpr precision precision_of() noexcept {
  static_assert(std::is_same_v<T, float> || std::is_same_v<T, double> ||
                std::is_same_v<T, long double>);
  if constexpr (std::is_same_v<T, float>) return precision::single;
  if constexpr (std::is_same_v<T, double>) return precision::double_;
  return precision::extended;
}

constexpr const char* precision_name(precision p) noexcept {
  switch (p) {
    case precision::single:
      return "float";
    case precision::double_:
      return "double";
    case precision::extended:
      return "long-double";
  }
  return "unknown";
}

/// Bound on |error| in degrees: the measured maxima over the benchmark grid and the boundary
/// sweeps of the tests (docs/ACCURACY.md), rounded up with a margin of about 2. The error grows
/// with the chord inversion's amplification |d eta / d Phi|, up to fold_amplification_max()
/// = 30 where the status turns fold; below it the double stable closed form stays within
/// 7.6e-13 deg (1e-12 deg wherever the status is ok).
constexpr double documented_error_bound_deg(method m, precision p) noexcept {
  constexpr double bounds[7][3] = {
      // float, double, long double
      {2e-3, 5e-12, 2e-15},  // paper_quadratic (where the stable closed form is ok)
      {1e-3, 1e-12, 2e-15},  // stable_closed_form
      {2e-3, 5e-12, 4e-15},  // scan_sphere
      {2e-3, 5e-12, 4e-15},  // scan_sphere_iterative
      {3e-3, 5e-12, 5e-15},  // scan_ellipsoid
      {3e-3, 5e-12, 5e-15},  // scan_ellipsoid_iterative
      {3e-3, 5e-12, 5e-15},  // scan_ellipsoid_quartic
  };
  return bounds[static_cast<int>(m)][static_cast<int>(p)];
}

}  // namespace conescan::accuracy
