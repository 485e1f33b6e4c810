// Sorting the few values the sensor physics keeps in fixed arrays (cuts of a quadrature, breaks
// of a window, the locator's samples): no heap and no <algorithm> on the flight target's
// freestanding build, and a handful of values, where insertion is the fastest sort.
#pragma once

namespace conescan {

/// Sorts v[0 .. n-1] ascending by insertion (stable; NaN-free input: a NaN stays where it is and
/// leaves its neighbours unsorted).
template <class T>
void sort_ascending(T* v, int n) noexcept {
  for (int i = 1; i < n; ++i)
    for (int k = i; k > 0 && v[k] < v[k - 1]; --k) {
      const T t = v[k];
      v[k] = v[k - 1];
      v[k - 1] = t;
    }
}

}  // namespace conescan
