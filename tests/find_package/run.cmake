# Installs conescan's core into a fresh prefix, builds a find_package consumer against it
# (Release, warnings as errors) and runs it; the consumer checks its own results and exits
# non-zero on a mismatch.
#   cmake -DSOURCE_DIR=<conescan source> -DWORK_DIR=<scratch dir>
#         -DCONSUMER=<consumer's directory under SOURCE_DIR> -DEXECUTABLE=<its program>
#         -P run.cmake
file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
foreach(step
    "-S;${SOURCE_DIR};-B;${WORK_DIR}/core;-DCONESCAN_BUILD_APPS=OFF;-DCONESCAN_BUILD_TESTS=OFF;-DCONESCAN_BUILD_BENCH=OFF;-DCMAKE_INSTALL_PREFIX=${prefix}"
    "--build;${WORK_DIR}/core"
    "--install;${WORK_DIR}/core"
    "-S;${SOURCE_DIR}/${CONSUMER};-B;${WORK_DIR}/consumer;-DCMAKE_PREFIX_PATH=${prefix};-DCMAKE_BUILD_TYPE=Release;-DCMAKE_COMPILE_WARNING_AS_ERROR=ON"
    "--build;${WORK_DIR}/consumer")
  execute_process(COMMAND ${CMAKE_COMMAND} ${step} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                  ERROR_VARIABLE out)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "cmake ${step} failed:\n${out}")
  endif()
endforeach()
execute_process(COMMAND ${WORK_DIR}/consumer/${EXECUTABLE} RESULT_VARIABLE rc
                OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${EXECUTABLE} failed (exit ${rc}):\n${out}")
endif()
message(STATUS "${EXECUTABLE}:\n${out}")
