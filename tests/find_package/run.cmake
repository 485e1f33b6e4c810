# Builds conescan in a scratch directory as a user or a consumer would, and runs a program that
# checks its own results (exit 0, or a message and non-zero). Three ways (FROM):
#   install     (default) the core installed into a fresh prefix; the consumer CONSUMER (a
#               directory under SOURCE_DIR) finds it with CMAKE_PREFIX_PATH, builds (Release,
#               warnings as errors) and its program EXECUTABLE runs;
#   build_tree  the same consumer against the core's build tree (conescan_DIR: its export());
#   project     conescan itself configured with OPTIONS (one string, as on a command line), its
#               TARGET built and EXECUTABLE (a path in its build directory) run.
#   cmake -DSOURCE_DIR=<conescan source> -DWORK_DIR=<scratch dir> [-DFROM=install|build_tree|project]
#         [-DCONSUMER=<dir>] -DEXECUTABLE=<program> [-DOPTIONS=...] [-DTARGET=<target>]
#         [-DCOMPILER=<c++>] [-DLAUNCHER=<ccache>] -P run.cmake
file(REMOVE_RECURSE ${WORK_DIR})
if(NOT FROM)
  set(FROM install)
endif()
set(prefix ${WORK_DIR}/prefix)
set(project_dir ${WORK_DIR}/conescan)
set(compiler)
if(COMPILER)
  list(APPEND compiler -DCMAKE_CXX_COMPILER=${COMPILER})
endif()
if(LAUNCHER)
  list(APPEND compiler -DCMAKE_CXX_COMPILER_LAUNCHER=${LAUNCHER})
endif()

function(run_cmake)
  execute_process(COMMAND ${CMAKE_COMMAND} ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out
                  ERROR_VARIABLE out)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "cmake ${ARGN} failed:\n${out}")
  endif()
endfunction()

if(FROM STREQUAL "project")
  separate_arguments(options UNIX_COMMAND "${OPTIONS}")
  run_cmake(-S ${SOURCE_DIR} -B ${project_dir} -DCMAKE_BUILD_TYPE=Release ${compiler} ${options})
  run_cmake(--build ${project_dir} --target ${TARGET})
  set(program ${project_dir}/${EXECUTABLE})
else()
  run_cmake(-S ${SOURCE_DIR} -B ${project_dir} ${compiler} -DCONESCAN_BUILD_APPS=OFF
            -DCONESCAN_BUILD_TESTS=OFF -DCONESCAN_BUILD_BENCH=OFF -DCONESCAN_BUILD_PYTHON=OFF
            -DCMAKE_INSTALL_PREFIX=${prefix})
  run_cmake(--build ${project_dir})
  if(FROM STREQUAL "install")
    run_cmake(--install ${project_dir})
    set(find -DCMAKE_PREFIX_PATH=${prefix})
  elseif(FROM STREQUAL "build_tree")
    set(find -Dconescan_DIR=${project_dir})
  else()
    message(FATAL_ERROR "FROM=${FROM}: expected install, build_tree or project")
  endif()
  run_cmake(-S ${SOURCE_DIR}/${CONSUMER} -B ${WORK_DIR}/consumer ${compiler} ${find}
            -DCMAKE_BUILD_TYPE=Release -DCMAKE_COMPILE_WARNING_AS_ERROR=ON)
  run_cmake(--build ${WORK_DIR}/consumer)
  set(program ${WORK_DIR}/consumer/${EXECUTABLE})
endif()

execute_process(COMMAND ${program} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${EXECUTABLE} failed (exit ${rc}):\n${out}")
endif()
string(SUBSTRING "${out}" 0 2000 shown)
message(STATUS "${EXECUTABLE}:\n${shown}")
