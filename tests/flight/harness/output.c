/* The probe's output lines (probe.h), formatted without printf (no heap, no stdio) and written
 * by the harness's put_line: semihosting on the target, stdout on the host. */
#include <stdint.h>
#include <string.h>

#include "output.h"
#include "probe.h"

unsigned char probe_opaque_bytes[4096];

/* A line being built in a fixed buffer (longer lines are cut, never overrun). */
typedef struct {
  char text[160];
  unsigned length;
} line;

static void add(line* l, const char* s) {
  while (*s && l->length + 1 < sizeof l->text) l->text[l->length++] = *s++;
  l->text[l->length] = '\0';
}

static void add_unsigned(line* l, uint32_t n) {
  char digits[11];
  int count = 0;
  do {
    digits[count++] = (char)('0' + n % 10);
    n /= 10;
  } while (n);
  char s[12];
  for (int i = 0; i < count; ++i) s[i] = digits[count - 1 - i];
  s[count] = '\0';
  add(l, s);
}

static void add_signed(line* l, int32_t n) {
  if (n < 0) {
    add(l, "-");
    add_unsigned(l, (uint32_t)(-(n + 1)) + 1u);
  } else {
    add_unsigned(l, (uint32_t)n);
  }
}

static void add_hex(line* l, uint64_t bits, int digits) {
  char s[17];
  for (int i = 0; i < digits; ++i)
    s[i] = "0123456789abcdef"[(bits >> (4 * (digits - 1 - i))) & 15u];
  s[digits] = '\0';
  add(l, s);
}

static void start(line* l, const char* kind, const char* case_name, int index, const char* field) {
  l->length = 0;
  l->text[0] = '\0';
  add(l, kind);
  add(l, " ");
  add(l, case_name);
  add(l, "[");
  add_signed(l, index);
  add(l, "] ");
  add(l, field);
  add(l, " ");
}

static void finish(line* l) {
  add(l, "\n");
  put_line(l->text);
}

void probe_value_f(const char* case_name, int index, const char* field, float x) {
  uint32_t bits;
  memcpy(&bits, &x, sizeof bits);
  line l;
  start(&l, "value", case_name, index, field);
  add(&l, "f ");
  add_hex(&l, bits, 8);
  finish(&l);
}

void probe_value_d(const char* case_name, int index, const char* field, double x) {
  uint64_t bits;
  memcpy(&bits, &x, sizeof bits);
  line l;
  start(&l, "value", case_name, index, field);
  add(&l, "d ");
  add_hex(&l, bits, 16);
  finish(&l);
}

void probe_status(const char* case_name, int index, const char* field, int status) {
  line l;
  start(&l, "status", case_name, index, field);
  add_signed(&l, status);
  finish(&l);
}

void probe_count(const char* case_name, int index, const char* field, int32_t n) {
  line l;
  start(&l, "count", case_name, index, field);
  add_signed(&l, n);
  finish(&l);
}

void probe_tolerance(const char* field, uint32_t ulps) {
  line l = {{0}, 0};
  add(&l, "tolerance ");
  add(&l, field);
  add(&l, " ");
  add_unsigned(&l, ulps);
  finish(&l);
}

void probe_limit(const char* entry, const char* what, uint32_t n) {
  line l = {{0}, 0};
  add(&l, "limit ");
  add(&l, entry);
  add(&l, " ");
  add(&l, what);
  add(&l, " ");
  add_unsigned(&l, n);
  finish(&l);
}

void probe_text(const char* text) {
  line l = {{0}, 0};
  add(&l, "text ");
  add(&l, text);
  finish(&l);
}

void output_budget(const char* entry, uint32_t instructions, uint32_t stack_bytes) {
  line l = {{0}, 0};
  add(&l, "budget ");
  add(&l, entry);
  add(&l, " instructions ");
  add_unsigned(&l, instructions);
  add(&l, " stack ");
  add_unsigned(&l, stack_bytes);
  finish(&l);
}

void output_pair(const char* what, uint32_t a, uint32_t b) {
  line l = {{0}, 0};
  add(&l, what);
  add(&l, " ");
  add_unsigned(&l, a);
  add(&l, " ");
  add_unsigned(&l, b);
  finish(&l);
}
