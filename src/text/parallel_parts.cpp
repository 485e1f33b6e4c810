#include "text/parallel_parts.hpp"

#include <sched.h>

#include <algorithm>
#include <thread>

namespace conescan::text {

unsigned available_cores() noexcept {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof set, &set) == 0)
    return static_cast<unsigned>(std::max(1, CPU_COUNT(&set)));
  return std::max(1u, std::thread::hardware_concurrency());
}

}  // namespace conescan::text
