# Installs conescan's core into a fresh prefix and builds tests/find_package/consumer against it.
file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
foreach(step
    "-S;${SOURCE_DIR};-B;${WORK_DIR}/core;-DCONESCAN_BUILD_APPS=OFF;-DCONESCAN_BUILD_TESTS=OFF;-DCMAKE_INSTALL_PREFIX=${prefix}"
    "--build;${WORK_DIR}/core"
    "--install;${WORK_DIR}/core"
    "-S;${SOURCE_DIR}/tests/find_package/consumer;-B;${WORK_DIR}/consumer;-DCMAKE_PREFIX_PATH=${prefix}"
    "--build;${WORK_DIR}/consumer")
  execute_process(COMMAND ${CMAKE_COMMAND} ${step} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "cmake ${step} failed:\n${out}")
  endif()
endforeach()
execute_process(COMMAND ${WORK_DIR}/consumer/consumer RESULT_VARIABLE rc OUTPUT_VARIABLE out)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the consumer failed: ${out}")
endif()
message(STATUS "consumer: ${out}")
