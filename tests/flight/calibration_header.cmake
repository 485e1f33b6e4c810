# ctest flight.calibration_header: examples/flight_software/calibration.h must be what
# scripts/fit-header.py makes of examples/flight_software/fit.json, and the tool must refuse a
# file that is not a fit (exit 2).
#   cmake -DSOURCE_DIR=<conescan> -DPYTHON=<python3> -DWORK_DIR=<dir> -P calibration_header.cmake
set(example ${SOURCE_DIR}/examples/flight_software)
file(MAKE_DIRECTORY ${WORK_DIR})
execute_process(COMMAND ${PYTHON} ${SOURCE_DIR}/scripts/fit-header.py fit.json
                WORKING_DIRECTORY ${example} RESULT_VARIABLE rc OUTPUT_VARIABLE made
                ERROR_VARIABLE error)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "fit-header.py failed (exit ${rc}): ${error}")
endif()
file(READ ${example}/calibration.h committed)
if(NOT made STREQUAL committed)
  message(FATAL_ERROR "examples/flight_software/calibration.h is not fit-header.py's output for "
                      "fit.json: regenerate it (scripts/fit-header.py fit.json > calibration.h)")
endif()
file(WRITE ${WORK_DIR}/not-a-fit.json "{\"kind\": \"budget\"}\n")
execute_process(COMMAND ${PYTHON} ${SOURCE_DIR}/scripts/fit-header.py ${WORK_DIR}/not-a-fit.json
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE error)
if(NOT rc EQUAL 2 OR NOT error MATCHES "not-a-fit.json: not a fit" OR NOT out STREQUAL "")
  message(FATAL_ERROR "fit-header.py on a file that is not a fit: exit ${rc}, '${error}', '${out}'")
endif()
message(STATUS "calibration.h is fit-header.py's output for fit.json; a non-fit is refused")
