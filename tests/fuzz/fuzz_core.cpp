// libFuzzer target: the core routines on any scalars (core_harness.hpp).
#include <cstdio>
#include <cstdlib>

#include "fuzz/core_harness.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string failure = conescan_fuzz::check_core(data, size);
  if (!failure.empty()) {
    std::fprintf(stderr, "invariant broken: %s\n", failure.c_str());
    std::abort();
  }
  return 0;
}
