# Installs conescan's core into a fresh prefix, builds examples/flight_software against it as a
# find_package consumer (float, -fno-exceptions -fno-rtti, warnings as errors) and runs it: the
# example checks its own statuses and values and exits 1 on a mismatch.
#   cmake -DSOURCE_DIR=<conescan source> -DWORK_DIR=<scratch dir> -P run_example.cmake
# Modelled on run.cmake.
file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
foreach(step
    "-S;${SOURCE_DIR};-B;${WORK_DIR}/core;-DCONESCAN_BUILD_APPS=OFF;-DCONESCAN_BUILD_TESTS=OFF;-DCMAKE_INSTALL_PREFIX=${prefix}"
    "--build;${WORK_DIR}/core"
    "--install;${WORK_DIR}/core"
    "-S;${SOURCE_DIR}/examples/flight_software;-B;${WORK_DIR}/flight_software;-DCMAKE_PREFIX_PATH=${prefix};-DCMAKE_BUILD_TYPE=Release;-DCMAKE_COMPILE_WARNING_AS_ERROR=ON"
    "--build;${WORK_DIR}/flight_software")
  execute_process(COMMAND ${CMAKE_COMMAND} ${step} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "cmake ${step} failed:\n${out}")
  endif()
endforeach()
execute_process(COMMAND ${WORK_DIR}/flight_software/flight_software RESULT_VARIABLE rc
                OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the flight_software example failed (exit ${rc}):\n${out}")
endif()
message(STATUS "flight_software:\n${out}")
