// libFuzzer target: src/text/shortest_double.hpp against std::to_chars on any bit pattern.
// The text must be std::to_chars' byte for byte (MODEL §9's round-trip form) and fit its room.
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "text/shortest_double.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < sizeof(double)) return 0;
  double value;
  std::memcpy(&value, data, sizeof value);
  char ours[conescan::text::shortest_double_room];
  char standard[64];
  const char* ours_end = conescan::text::write_shortest_double(ours, value);
  const char* standard_end = std::to_chars(standard, standard + sizeof standard, value).ptr;
  const auto length = static_cast<std::size_t>(ours_end - ours);
  if (length != static_cast<std::size_t>(standard_end - standard) ||
      std::memcmp(ours, standard, length) != 0) {
    std::fprintf(stderr, "%a: ours %.*s, std::to_chars %.*s\n", value, static_cast<int>(length),
                 ours, static_cast<int>(standard_end - standard), standard);
    std::abort();
  }
  return 0;
}
