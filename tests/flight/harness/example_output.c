/* flight_write_line of examples/flight_software/output.hpp on the target: semihosting. */
#include "semihosting.h"

void flight_write_line(const char* text);

void flight_write_line(const char* text) {
  semihosting_write(text);
  semihosting_write("\n");
}
