// flight_write_line on a hosted platform: standard output.
#include <cstdio>

#include "output.hpp"

extern "C" void flight_write_line(const char* text) {
  std::fputs(text, stdout);
  std::fputc('\n', stdout);
}
