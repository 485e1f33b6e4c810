// libFuzzer target: any bytes as the oem reader reads them (reader_harness.hpp's check_oem).
#include <cstdio>
#include <cstdlib>

#include "fuzz/reader_harness.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string failure = conescan_fuzz::check_oem(data, size);
  if (!failure.empty()) {
    std::fprintf(stderr, "invariant broken: %s\n", failure.c_str());
    std::abort();
  }
  return 0;
}
