// libFuzzer target: conescan-sim's command line (its CLI11 parser of the option table), with an
// optional scene file, through the scene plan, the simulation and --print-config's round trip
// (options_harness.hpp).
#include <cstdio>
#include <cstdlib>

#include "fuzz/options_harness.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string failure = conescan_fuzz::check_command_line(data, size);
  if (!failure.empty()) {
    std::fprintf(stderr, "invariant broken: %s\n", failure.c_str());
    std::abort();
  }
  return 0;
}
