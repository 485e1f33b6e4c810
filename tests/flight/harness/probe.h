/* What a probe (tests/flight/probes/) tells its harness: the values and statuses of its cases,
 * its entry points to measure, the limits and tolerances the test asserts. Two harnesses
 * implement it with the same output: the Cortex-M7 under QEMU (target.c, through semihosting)
 * and the host (host.c, through stdout). tests/flight/compare.py reads both and compares them.
 *
 * The output, one item a line:
 *   value  CASE FIELD f|d HEX   a float or double result, its bits in hexadecimal (exact)
 *   status CASE FIELD N         a conescan status (its value, status.hpp's order)
 *   count  CASE FIELD N         an integer result (iterations)
 *   tolerance FIELD ULPS        values named FIELD may differ between target and host by ULPS
 *   limit  ENTRY WHAT N         a budget the test asserts (WHAT: instructions, stack, code)
 *   budget ENTRY instructions N stack N   measured, on the target only
 *   text   ...                  free text (the flight example), shown, not compared
 * C, so that a probe in C (the C interface's) uses it as well as one in C++ (flight_probe.hpp).
 */
#ifndef CONESCAN_FLIGHT_PROBE_H
#define CONESCAN_FLIGHT_PROBE_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

void probe_value_f(const char* case_name, int index, const char* field, float x);
void probe_value_d(const char* case_name, int index, const char* field, double x);
void probe_status(const char* case_name, int index, const char* field, int status);
void probe_count(const char* case_name, int index, const char* field, int32_t n);
void probe_tolerance(const char* field, uint32_t ulps);
void probe_limit(const char* entry, const char* what, uint32_t n);
void probe_text(const char* line);

/* Measures one entry point on the target: `call(context)` repeated to count its instructions
 * (SysTick under QEMU -icount, calibrated at start-up, the harness's own overhead removed),
 * then once more over a painted stack for its stack. The call must not print. On the host
 * nothing is measured and nothing printed. */
void probe_measure(const char* entry, void (*call)(void* context), void* context);

/* Bytes the size-only build reads its inputs from (flight_probe.hpp's opaque). */
extern unsigned char probe_opaque_bytes[4096];

/* Each probe defines it: its cases (or, built with CONESCAN_PROBE_SIZE_ONLY, one call of its
 * entry point on inputs the compiler cannot see, for the code size). */
void probe_main(void);

#ifdef __cplusplus
}
#endif

#endif
