/* Between output.c (the lines' format) and the harness that writes them. */
#ifndef CONESCAN_FLIGHT_OUTPUT_H
#define CONESCAN_FLIGHT_OUTPUT_H

#include <stdint.h>

/* Writes one line (with its newline): the harness's. */
void put_line(const char* text);

/* "budget ENTRY instructions N stack N". */
void output_budget(const char* entry, uint32_t instructions, uint32_t stack_bytes);
/* "WHAT A B": the start-up calibration. */
void output_pair(const char* what, uint32_t a, uint32_t b);

#endif
