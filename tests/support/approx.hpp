// The project's own comparator: Catch2 v2's Approx converts to double, which would hide the
// digits of long double and multiprecision values.
#pragma once

#include <sstream>
#include <string>

namespace conescan_test {

/// |actual - expected| <= tolerance, for any scalar type with subtraction and comparison.
template <class T>
bool within(const T& actual, const T& expected, const T& tolerance) {
  T difference = actual - expected;
  if (difference < T(0)) difference = -difference;
  return difference <= tolerance;
}

template <class T>
std::string describe(const T& actual, const T& expected) {
  std::ostringstream s;
  s.precision(21);
  s << "actual " << static_cast<long double>(actual) << ", expected "
    << static_cast<long double>(expected) << ", difference "
    << static_cast<long double>(actual - expected);
  return s.str();
}

}  // namespace conescan_test

/// CHECK that |actual - expected| <= tolerance, printing all three on failure.
#define CHECK_WITHIN(actual, expected, tolerance)                      \
  do {                                                                 \
    INFO(::conescan_test::describe((actual), (expected))               \
         << " tolerance " << static_cast<long double>(tolerance));     \
    CHECK(::conescan_test::within((actual), (expected), (tolerance))); \
  } while (false)
