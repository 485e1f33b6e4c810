#include "semihosting.h"

#include <stdint.h>

enum {
  sys_write0 = 0x04,
  sys_exit_extended = 0x20,
  adp_stopped_application_exit = 0x20026,
};

static int semihosting_call(int operation, const void* argument) {
  register int r0 __asm__("r0") = operation;
  register const void* r1 __asm__("r1") = argument;
  __asm__ volatile("bkpt 0xAB" : "+r"(r0) : "r"(r1) : "memory");
  return r0;
}

void semihosting_write(const char* text) {
  semihosting_call(sys_write0, text);
}

_Noreturn void semihosting_exit(int status) {
  const uint32_t block[2] = {adp_stopped_application_exit, (uint32_t)status};
  semihosting_call(sys_exit_extended, block);
  for (;;) {
  }
}
