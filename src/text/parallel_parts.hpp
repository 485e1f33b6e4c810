// The library's one parallel-for: a range cut into contiguous parts, run on a few threads. The
// fit's passes over its measurements (calibration/passes.cpp), the scene's truth at the
// telemetry's times (scene_calibration/scene_geometry.cpp) and the chain's rows a physics table's
// build asks for together (simulation/physics_table.cpp) run on it. (A campaign's runs stream
// through their own pool, apps/conescan-sim/campaign_run.cpp: chunks claimed in order and written
// in order as they finish, which a fork-join over fixed parts cannot do.)
#pragma once

#include <algorithm>
#include <cstddef>
#include <system_error>
#include <thread>
#include <vector>

namespace conescan::text {

/// The cores this process may run on (sched_getaffinity; where that fails, the hardware's
/// concurrency), at least 1: the default of --threads in conescan-sim and conescan-fit.
unsigned available_cores() noexcept;

/// The parts parallel_parts cuts [0, n) into for `threads` threads: min(max(threads, 1), n), and
/// at least 1 (an empty range is one empty part).
inline std::size_t parallel_part_count(std::size_t n, int threads) noexcept {
  return std::clamp<std::size_t>(static_cast<std::size_t>(std::max(threads, 1)), 1,
                                 std::max<std::size_t>(n, 1));
}

/// The parts of a floating-point reduction: min(n, 64), at least 1, whatever the threads. Summed
/// part by part in their order, its result has the same bits on any number of threads (with one
/// part a thread, the sums' rounding changed with their count, and so did a fit's path: 8
/// iterations on one thread, 15 on two, on the same telemetry).
inline std::size_t reduction_part_count(std::size_t n) noexcept {
  return std::clamp<std::size_t>(n, 1, 64);
}

/// Runs fn(begin, end, part) over `parts` contiguous parts of [0, n), part k being
/// [n k / parts, n (k + 1) / parts), on min(max(threads, 1), parts) threads, thread t taking parts
/// t, t + threads, ... (thread 0 the caller's); returns when all have. A part runs on one thread
/// only. A worker the system cannot start (its thread or address-space limits: the default is
/// every core) leaves its parts to the caller, after the caller's own: a part gives the same
/// result on whichever thread runs it. fn must not throw.
template <class Fn>
void parallel_parts(std::size_t n, int threads, std::size_t parts, Fn fn) {
  parts = std::max<std::size_t>(parts, 1);
  const std::size_t runners = std::min(static_cast<std::size_t>(std::max(threads, 1)), parts);
  const auto run = [&](std::size_t first) {
    for (std::size_t part = first; part < parts; part += runners)
      fn(n * part / parts, n * (part + 1) / parts, part);
  };
  std::vector<std::thread> workers;
  workers.reserve(runners - 1);
  std::size_t started = 1;
  for (; started < runners; ++started) {
    try {
      workers.emplace_back(run, started);
    } catch (const std::system_error&) {
      break;
    }
  }
  run(0);
  for (std::size_t t = started; t < runners; ++t) run(t);
  for (std::thread& w : workers) w.join();
}

/// parallel_parts over parallel_part_count(n, threads) parts: one a thread.
template <class Fn>
void parallel_parts(std::size_t n, int threads, Fn fn) {
  parallel_parts(n, threads, parallel_part_count(n, threads), fn);
}

}  // namespace conescan::text
