# Toolchain of the flight target (tests/flight): Debian's gcc-arm-none-eabi for a Cortex-M7 with
# its double-precision FPU (FPv5-D16, hard-float calling convention), as QEMU's mps2-an500 board
# has. Bare metal: no operating system, so CMake's own checks build static libraries, not
# programs (which would need a start-up and a linker script).
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)
set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_CXX_COMPILER arm-none-eabi-g++)
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
set(cortex_m7 "-mcpu=cortex-m7 -mthumb -mfpu=fpv5-d16 -mfloat-abi=hard")
set(CMAKE_C_FLAGS_INIT "${cortex_m7}")
set(CMAKE_CXX_FLAGS_INIT "${cortex_m7}")
set(CMAKE_EXE_LINKER_FLAGS_INIT "${cortex_m7}")
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
