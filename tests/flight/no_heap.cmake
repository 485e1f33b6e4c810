# ctest flight.no_heap: builds tests/flight/harness/heap_use.cpp (a malloc) for the target; the
# link must fail on the heap's system call (_sbrk), the proof that the harness links none.
#   cmake -DTARGET_DIR=<the target's build tree> -P no_heap.cmake
execute_process(COMMAND ${CMAKE_COMMAND} --build ${TARGET_DIR} --target heap_use.elf
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(rc EQUAL 0)
  message(FATAL_ERROR "a program calling malloc linked for the target:\n${out}")
endif()
if(NOT out MATCHES "undefined reference to `_sbrk'")
  message(FATAL_ERROR "the heap program failed, but not for want of _sbrk:\n${out}")
endif()
message(STATUS "malloc does not link on the target: undefined reference to `_sbrk'")
