/* Start-up of a bare-metal Cortex-M7 program on QEMU's mps2-an500 board: the vector table, the
 * reset handler (floating point on, .data copied from code memory, .bss zeroed, constructors,
 * then main and the exit status through semihosting) and the fault handler. No C library
 * start-up files and no system calls: a program that needs the heap (malloc, _sbrk) or the
 * C++ runtime's guards and exceptions does not link (tests/flight/CMakeLists.txt). */
#include <stdint.h>

#include "semihosting.h"

int main(void);

/* The linker script's symbols (mps2-an500.ld). */
extern uint32_t __stack_top[], __data_load[], __data_start[], __data_end[], __bss_start[],
    __bss_end[];
typedef void (*constructor)(void);
extern constructor __init_array_start[], __init_array_end[];

#define SCB_CPACR (*(volatile uint32_t*)0xE000ED88u)
#define SCB_CFSR (*(volatile uint32_t*)0xE000ED28u)
#define SCB_HFSR (*(volatile uint32_t*)0xE000ED2Cu)

_Noreturn void reset_handler(void) {
  /* CP10 and CP11 (the FPU) full access, then barriers so that the next instruction sees it
   * (ARMv7-M Architecture Reference Manual B3.2.20): before any floating-point instruction. */
  SCB_CPACR |= 0xFu << 20;
  __asm__ volatile("dsb\n\tisb" ::: "memory");
  for (uint32_t *from = __data_load, *to = __data_start; to < __data_end;) *to++ = *from++;
  for (uint32_t* to = __bss_start; to < __bss_end;) *to++ = 0;
  for (constructor* c = __init_array_start; c < __init_array_end; ++c) (*c)();
  semihosting_exit(main());
}

/* The libm functions report domain errors through errno; with no C library start-up the
 * program provides it (newlib's own would bring its reentrancy structure and stdio). */
int* __errno(void);
int* __errno(void) {
  static int error_number;
  return &error_number;
}

static void put_hex(char* at, uint32_t x) {
  for (int i = 0; i < 8; ++i) at[i] = "0123456789abcdef"[(x >> (28 - 4 * i)) & 15u];
}

/* Any fault (hard, memory, bus, usage: a stack overflow runs below RAM into unmapped memory)
 * says so with the fault status registers and ends the run with status 3. */
_Noreturn void fault_report(void) {
  char text[] = "harness: fault, CFSR 00000000 HFSR 00000000\n";
  put_hex(text + sizeof "harness: fault, CFSR " - 1, SCB_CFSR);
  put_hex(text + sizeof "harness: fault, CFSR 00000000 HFSR " - 1, SCB_HFSR);
  semihosting_write(text);
  semihosting_exit(3);
}

/* The fault handler first moves the stack back to its top: the fault may be its overflow. */
__attribute__((naked)) void fault_handler(void) {
  __asm__ volatile(
      "ldr r0, =__stack_top\n\t"
      "mov sp, r0\n\t"
      "b fault_report\n\t");
}

/* The Cortex-M vector table: the initial stack pointer, then the handlers of the 15 system
 * exceptions (no interrupt is enabled: the SysTick is read, never taken). */
__attribute__((section(".vectors"), used))
const uintptr_t vector_table[16] = {(uintptr_t)__stack_top,
                                    (uintptr_t)reset_handler,
                                    (uintptr_t)fault_handler,
                                    (uintptr_t)fault_handler,
                                    (uintptr_t)fault_handler,
                                    (uintptr_t)fault_handler,
                                    (uintptr_t)fault_handler,
                                    0,
                                    0,
                                    0,
                                    0,
                                    (uintptr_t)fault_handler,
                                    (uintptr_t)fault_handler,
                                    0,
                                    (uintptr_t)fault_handler,
                                    (uintptr_t)fault_handler};
