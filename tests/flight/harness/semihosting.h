/* ARM semihosting (Arm's "Semihosting for AArch32 and AArch64", v2.0): the debugger, here
 * QEMU with -semihosting-config enable=on, performs the call the program makes with BKPT 0xAB.
 * Only two calls: a string to the console and the exit with a status. */
#ifndef CONESCAN_FLIGHT_SEMIHOSTING_H
#define CONESCAN_FLIGHT_SEMIHOSTING_H

#ifdef __cplusplus
extern "C" {
#endif

/* SYS_WRITE0: a NUL-terminated string to the console. */
void semihosting_write(const char* text);

/* SYS_EXIT_EXTENDED: ends the run, QEMU exiting with `status` (0 success). Plain SYS_EXIT on
 * AArch32 carries no status (QEMU exits 0 or 1); the extended call carries it. */
_Noreturn void semihosting_exit(int status);

#ifdef __cplusplus
}
#endif

#endif
