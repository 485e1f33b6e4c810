// The library's one parallel-for: a range cut into contiguous parts, one thread each. The fit's
// passes over its measurements (calibration/passes.cpp) and the scene's truth at the telemetry's
// times (scene_calibration/scene_geometry.cpp) run on it. (A campaign's runs stream through their
// own pool, apps/conescan-sim/campaign_run.cpp: chunks claimed in order and written in order as
// they finish, which a fork-join over fixed parts cannot do.)
#pragma once

#include <algorithm>
#include <cstddef>
#include <thread>
#include <vector>

namespace conescan::text {

/// The parts parallel_parts cuts [0, n) into for `threads` threads: min(max(threads, 1), n), and
/// at least 1 (an empty range is one empty part).
inline std::size_t parallel_part_count(std::size_t n, int threads) noexcept {
  return std::clamp<std::size_t>(static_cast<std::size_t>(std::max(threads, 1)), 1,
                                 std::max<std::size_t>(n, 1));
}

/// Runs fn(begin, end, part) over parallel_part_count(n, threads) contiguous parts of [0, n),
/// part k being [n k / parts, n (k + 1) / parts), part 0 on the caller's thread; returns when all
/// have. fn must not throw.
template <class Fn>
void parallel_parts(std::size_t n, int threads, Fn fn) {
  const std::size_t parts = parallel_part_count(n, threads);
  std::vector<std::thread> workers;
  for (std::size_t part = 1; part < parts; ++part)
    workers.emplace_back(fn, n * part / parts, n * (part + 1) / parts, part);
  fn(std::size_t{0}, n / parts, std::size_t{0});
  for (std::thread& w : workers) w.join();
}

}  // namespace conescan::text
