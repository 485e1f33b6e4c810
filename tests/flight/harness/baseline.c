/* The harness without a probe: what every target program carries besides its probe's code. */
#include "probe.h"

void probe_main(void) {}
