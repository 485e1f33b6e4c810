// Wall-clock time per sample: a median of repeated runs, with a guard against the optimiser
// removing the work. Never used as a pass/fail criterion (timings vary by machine and load).
#pragma once

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <vector>

namespace conescan::bench {

/// Makes `value` observable: the compiler must assume the asm reads it from memory, so the
/// computation that produced it cannot be removed or hoisted out of the timing loop.
template <class T>
inline void keep(const T& value) noexcept {
  asm volatile("" : : "m"(value) : "memory");
}

struct sample_time {
  double median_ns;  ///< per sample
  double min_ns;
  double max_ns;
};

/// Times `pass`, a callable that processes `samples` samples once. Each run repeats the pass
/// enough times to last at least `min_run_s`, so the clock's resolution does not matter; the
/// result is the median over `runs` runs (robust to a run interrupted by another process).
template <class Pass>
sample_time time_per_sample(std::size_t samples, const Pass& pass, int runs = 15,
                            double min_run_s = 0.02) {
  using clock = std::chrono::steady_clock;
  pass();  // warm the caches and the branch predictors
  int passes_per_run = 1;
  for (;;) {
    const clock::time_point start = clock::now();
    for (int i = 0; i < passes_per_run; ++i) pass();
    const double elapsed = std::chrono::duration<double>(clock::now() - start).count();
    if (elapsed >= min_run_s || passes_per_run >= (1 << 20)) break;
    passes_per_run *= 2;
  }
  std::vector<double> ns_per_sample;
  for (int r = 0; r < runs; ++r) {
    const clock::time_point start = clock::now();
    for (int i = 0; i < passes_per_run; ++i) pass();
    const double elapsed_ns =
        std::chrono::duration<double, std::nano>(clock::now() - start).count();
    ns_per_sample.push_back(elapsed_ns /
                            (static_cast<double>(passes_per_run) * static_cast<double>(samples)));
  }
  std::sort(ns_per_sample.begin(), ns_per_sample.end());
  return {ns_per_sample[ns_per_sample.size() / 2], ns_per_sample.front(), ns_per_sample.back()};
}

}  // namespace conescan::bench
