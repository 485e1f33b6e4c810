# ctest flight.build: configures and builds tests/flight twice, for the Cortex-M7
# (cmake/arm-none-eabi-cortex-m7.cmake) into WORK_DIR/target and for the host into WORK_DIR/host.
#   cmake -DSOURCE_DIR=<conescan> -DWORK_DIR=<dir> -DGLM_INCLUDE_DIR=<dir holding glm/>
#         [-DLAUNCHER=ccache] [-DHOST_C=cc] [-DHOST_CXX=c++] -P build.cmake
set(launcher)
if(LAUNCHER)
  list(APPEND launcher -DCMAKE_C_COMPILER_LAUNCHER=${LAUNCHER} -DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER})
endif()
set(host_compilers)
if(HOST_C)
  list(APPEND host_compilers -DCMAKE_C_COMPILER=${HOST_C})
endif()
if(HOST_CXX)
  list(APPEND host_compilers -DCMAKE_CXX_COMPILER=${HOST_CXX})
endif()

function(run_cmake)
  execute_process(COMMAND ${CMAKE_COMMAND} ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                  ERROR_VARIABLE out)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "cmake ${ARGN} failed:\n${out}")
  endif()
endfunction()

foreach(side target host)
  set(options -DGLM_INCLUDE_DIR=${GLM_INCLUDE_DIR} -DCMAKE_BUILD_TYPE=Release ${launcher})
  if(side STREQUAL "target")
    list(APPEND options -DCMAKE_TOOLCHAIN_FILE=${SOURCE_DIR}/cmake/arm-none-eabi-cortex-m7.cmake)
  else()
    list(APPEND options -DFLIGHT_HOST=ON ${host_compilers})
  endif()
  run_cmake(-S ${SOURCE_DIR}/tests/flight -B ${WORK_DIR}/${side} ${options})
  run_cmake(--build ${WORK_DIR}/${side} -j2)
  message(STATUS "flight: the ${side}'s programs built in ${WORK_DIR}/${side}")
endforeach()
