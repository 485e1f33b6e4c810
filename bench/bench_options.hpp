// What the accuracy benchmarks' command lines share: the usage line a bad argument gets (exit 2,
// as the programs') and the thread count an unset --threads takes.
#pragma once

#include <cstdio>
#include <cstdlib>
#include <thread>

namespace conescan::bench {

/// Prints "usage: PROGRAM OPTIONS" on stderr and exits with 2.
[[noreturn]] inline void exit_with_usage(const char* program, const char* options) {
  std::fprintf(stderr, "usage: %s %s\n", program, options);
  std::exit(2);
}

/// `threads`, or when 0 every hardware thread (at least 1).
inline unsigned threads_or_all(unsigned threads) {
  if (threads == 0) threads = std::thread::hardware_concurrency();
  return threads == 0 ? 1 : threads;
}

}  // namespace conescan::bench
