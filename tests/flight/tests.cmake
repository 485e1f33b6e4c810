# The core on a flight processor (tests/flight, docs/FLIGHT_SOFTWARE.md), included by
# tests/CMakeLists.txt. flight.build builds every probe for the Cortex-M7 and for the host (a
# fixture of its own: the main build does not wait for it); then per probe and scalar
# flight.<probe>.<scalar> runs it under QEMU (mps2-an500, -icount shift=0) against the host and
# asserts its budgets; flight.table checks docs/FLIGHT_SOFTWARE.md's table against what they
# measured. The tools come from scripts/setup.sh: a machine without them fails these tests.
find_program(FLIGHT_QEMU qemu-system-arm)
find_program(FLIGHT_SIZE arm-none-eabi-size)
find_program(FLIGHT_NM arm-none-eabi-nm)
find_path(FLIGHT_GLM_DIR glm/vec3.hpp)
set(flight_dir ${PROJECT_BINARY_DIR}/flight)
set(flight_source ${CMAKE_CURRENT_SOURCE_DIR}/flight)

add_test(NAME flight.build
         COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${PROJECT_SOURCE_DIR} -DWORK_DIR=${flight_dir}
                 -DGLM_INCLUDE_DIR=${FLIGHT_GLM_DIR} -DLAUNCHER=${CMAKE_CXX_COMPILER_LAUNCHER}
                 -P ${flight_source}/build.cmake)
set_tests_properties(flight.build PROPERTIES FIXTURES_SETUP flight_programs TIMEOUT 900)

file(GLOB flight_probes CONFIGURE_DEPENDS ${flight_source}/probes/*.cpp ${flight_source}/probes/*.c)
set(flight_probe_tests)
foreach(source IN LISTS flight_probes)
  get_filename_component(name ${source} NAME_WE)
  foreach(scalar float double)
    set(target ${flight_dir}/target/${name}_${scalar})
    add_test(NAME flight.${name}.${scalar}
             COMMAND ${Python3_EXECUTABLE} ${flight_source}/compare.py probe --name ${name}
                     --scalar ${scalar} --elf ${target}.elf --size-elf ${target}_size.elf
                     --baseline ${flight_dir}/target/baseline.elf
                     --host ${flight_dir}/host/${name}_${scalar} --qemu ${FLIGHT_QEMU}
                     --size-tool ${FLIGHT_SIZE} --nm-tool ${FLIGHT_NM}
                     --results ${flight_dir}/results)
    set_tests_properties(flight.${name}.${scalar} PROPERTIES FIXTURES_REQUIRED flight_programs
                         FIXTURES_SETUP flight_results TIMEOUT 300)
  endforeach()
endforeach()

# The flight example (examples/flight_software) on the target: it checks itself (exit 0).
add_test(NAME flight.example
         COMMAND ${Python3_EXECUTABLE} ${flight_source}/compare.py program
                 --elf ${flight_dir}/target/flight_example.elf --qemu ${FLIGHT_QEMU} --nm-tool ${FLIGHT_NM})
set_tests_properties(flight.example PROPERTIES FIXTURES_REQUIRED flight_programs TIMEOUT 300)

# A stack overflow on the target faults, reported (the stack sits first in RAM).
add_test(NAME flight.stack_overflow
         COMMAND ${Python3_EXECUTABLE} ${flight_source}/compare.py program --expect-fault
                 --elf ${flight_dir}/target/stack_overflow.elf --qemu ${FLIGHT_QEMU} --nm-tool ${FLIGHT_NM})
set_tests_properties(flight.stack_overflow PROPERTIES FIXTURES_REQUIRED flight_programs TIMEOUT 300)

# malloc must not link on the target (no system calls: no _sbrk).
add_test(NAME flight.no_heap
         COMMAND ${CMAKE_COMMAND} -DTARGET_DIR=${flight_dir}/target -P ${flight_source}/no_heap.cmake)
set_tests_properties(flight.no_heap PROPERTIES FIXTURES_REQUIRED flight_programs TIMEOUT 300)

# The example's calibration.h is scripts/fit-header.py's output for its fit.json.
add_test(NAME flight.calibration_header
         COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${PROJECT_SOURCE_DIR} -DPYTHON=${Python3_EXECUTABLE}
                 -DWORK_DIR=${flight_dir} -P ${flight_source}/calibration_header.cmake)

add_test(NAME flight.table
         COMMAND ${Python3_EXECUTABLE} ${flight_source}/compare.py table
                 --results ${flight_dir}/results --page ${PROJECT_SOURCE_DIR}/docs/FLIGHT_SOFTWARE.md)
set_tests_properties(flight.table PROPERTIES FIXTURES_REQUIRED "flight_programs;flight_results")
