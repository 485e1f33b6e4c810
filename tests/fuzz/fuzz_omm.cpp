// libFuzzer target: any bytes as the OMM readers read them (reader_harness.hpp's check_omm).
// Its dictionary (omm.dict) leans to the XML: comments, CDATA sections and processing
// instructions inside values and around the root, the elements of an <ndm> of <omm>s.
#include <cstdio>
#include <cstdlib>

#include "fuzz/reader_harness.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string failure = conescan_fuzz::check_omm(data, size);
  if (!failure.empty()) {
    std::fprintf(stderr, "invariant broken: %s\n", failure.c_str());
    std::abort();
  }
  return 0;
}
