/* The probe harness on the host: the same lines on stdout (output.c), nothing measured. */
#include <stdio.h>

#include "output.h"
#include "probe.h"

void put_line(const char* text) {
  fputs(text, stdout);
}

void probe_measure(const char* entry, void (*call)(void* context), void* context) {
  (void)entry;
  call(context);
}

int main(void) {
  probe_main();
  put_line("end\n");
  return fflush(stdout) == 0 ? 0 : 1;
}
