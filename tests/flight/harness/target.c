/* The probe harness on the Cortex-M7 (QEMU mps2-an500 with -icount shift=0): the output through
 * semihosting, and the budgets of probe_measure.
 *
 * Instructions: under -icount shift=0 QEMU advances its virtual clock by 1 ns per instruction,
 * and the SysTick counts that clock's cycles of the board's CPU clock. At start-up a loop of a
 * known number of instructions gives the instructions per SysTick tick (the ratio, printed as
 * "calibration"); an entry point is then run `repetitions` times, the same loop around an empty
 * call subtracted, and its ticks turned into instructions: exact to 1/repetitions of a tick.
 * Stack: the free stack below the caller is painted with a pattern, the entry point called
 * once, and the lowest word no longer holding the pattern gives its depth (a word that happens
 * to be written with the pattern would hide 4 bytes). */
#include <stdint.h>

#include "output.h"
#include "probe.h"
#include "semihosting.h"

#define SYST_CSR (*(volatile uint32_t*)0xE000E010u)
#define SYST_RVR (*(volatile uint32_t*)0xE000E014u)
#define SYST_CVR (*(volatile uint32_t*)0xE000E018u)

enum { repetitions = 100, stack_pattern = 0x5AC3E7A1u };

extern uint32_t __stack_limit[];

void put_line(const char* text) {
  semihosting_write(text);
}

/* 2 n + 1 instructions (and the caller's branch): the calibration's known workload. */
__attribute__((naked, noinline)) static void spin(uint32_t n) {
  (void)n;
  __asm__ volatile(
      "1: subs r0, r0, #1\n\t"
      "bne 1b\n\t"
      "bx lr\n\t");
}

static uint32_t now(void) {
  return SYST_CVR;
}

/* SysTick ticks between two readings (it counts down, 24 bits). */
static uint32_t elapsed(uint32_t start, uint32_t end) {
  return (start - end) & 0xFFFFFFu;
}

static uint32_t ticks_of_spin(uint32_t n) {
  const uint32_t start = now();
  spin(n);
  return elapsed(start, now());
}

/* Instructions per tick as a fraction: calibration_instructions / calibration_ticks. */
static uint32_t calibration_instructions, calibration_ticks;

static void calibrate(void) {
  SYST_RVR = 0xFFFFFFu;
  SYST_CVR = 0;
  SYST_CSR = 5u; /* enabled, the processor clock, no interrupt */
  const uint32_t short_run = 10000u, long_run = 210000u;
  const uint32_t ticks = ticks_of_spin(long_run) - ticks_of_spin(short_run);
  calibration_instructions = 2u * (long_run - short_run);
  calibration_ticks = ticks;
  output_pair("calibration", calibration_instructions, calibration_ticks);
}

static void empty_call(void* context) {
  (void)context;
  __asm__ volatile("" ::: "memory");
}

static uint32_t ticks_of(void (*call)(void*), void* context) {
  const uint32_t start = now();
  for (int i = 0; i < repetitions; ++i) call(context);
  return elapsed(start, now());
}

static uint32_t stack_bytes_of(void (*call)(void*), void* context) {
  uint32_t* sp;
  __asm__ volatile("mov %0, sp" : "=r"(sp));
  volatile uint32_t* const low = __stack_limit;
  /* Two words of margin below sp: nothing of this function lives there. */
  for (volatile uint32_t* p = low; p < sp - 2; ++p) *p = stack_pattern;
  call(context);
  volatile uint32_t* p = low;
  while (p < sp && *p == stack_pattern) ++p;
  return (uint32_t)((uintptr_t)sp - (uintptr_t)p);
}

void probe_measure(const char* entry, void (*call)(void* context), void* context) {
  const uint32_t ticks = ticks_of(call, context) - ticks_of(empty_call, context);
  /* instructions = ticks x (instructions per tick) / repetitions, rounded. */
  const uint64_t scaled = (uint64_t)ticks * calibration_instructions;
  const uint64_t divisor = (uint64_t)calibration_ticks * repetitions;
  const uint32_t instructions = (uint32_t)((scaled + divisor / 2) / divisor);
  output_budget(entry, instructions, stack_bytes_of(call, context));
}

int main(void) {
  calibrate();
  probe_main();
  put_line("end\n");
  return 0;
}
