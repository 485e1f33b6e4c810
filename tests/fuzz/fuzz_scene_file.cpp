// libFuzzer target: any text as a scene file (--config), through the scene plan (sweeps, heads,
// the error budget), the simulation and --print-config's round trip (options_harness.hpp).
#include <cstdio>
#include <cstdlib>

#include "fuzz/options_harness.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string failure = conescan_fuzz::check_scene_file(data, size);
  if (!failure.empty()) {
    std::fprintf(stderr, "invariant broken: %s\n", failure.c_str());
    std::abort();
  }
  return 0;
}
