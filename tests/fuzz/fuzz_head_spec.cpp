// libFuzzer target: parse_head_spec on any text, and the simulation of every head it accepts
// that validates (scene_harness.hpp).
#include <cstdio>
#include <cstdlib>

#include "fuzz/scene_harness.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string failure = conescan_fuzz::check_head_spec(data, size);
  if (!failure.empty()) {
    std::fprintf(stderr, "invariant broken: %s\n", failure.c_str());
    std::abort();
  }
  return 0;
}
