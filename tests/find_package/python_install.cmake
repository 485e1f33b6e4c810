# cmake --install of a build tree into a fresh prefix, then the module conescan imported from the
# prefix alone (PYTHONPATH=<prefix>/<PYTHON_DIR>) by the interpreter it was built for: it must
# come from there and compute.
#   cmake -DBUILD_DIR=<conescan build> -DWORK_DIR=<scratch> -DPYTHON=<interpreter>
#         -DPYTHON_DIR=<CONESCAN_PYTHON_INSTALL_DIR> -P python_install.cmake
file(REMOVE_RECURSE ${WORK_DIR})
set(prefix ${WORK_DIR}/prefix)
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix}
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install ${BUILD_DIR} failed:\n${out}")
endif()
set(check [[
import sys, numpy as np, conescan
where = conescan.__file__, conescan._conescan.__file__
assert all(f.startswith(sys.argv[1]) for f in where), f"imported from {where}, not the prefix"
r = conescan.half_chord(np.radians(45.02), np.radians(90.0), np.arcsin(6378137 / 6552000))
assert r.status == conescan.Status.ok and abs(np.degrees(r.value) - 71.124355929) < 1e-8, r
if hasattr(conescan._conescan, "_simulate"):  # the scene layer, linked into the module
    rows = conescan.simulate(duration_s=0)  # the paper's scene at perigee: a (1 - e)
    assert len(rows) == 1 and abs(rows["r_km"][0] - 6552) < 1e-9, rows
print("conescan", conescan.__version__, "from", where[1])
]])
execute_process(
  COMMAND ${CMAKE_COMMAND} -E env PYTHONPATH=${prefix}/${PYTHON_DIR} PYTHONDONTWRITEBYTECODE=1
          ${PYTHON} -c "${check}" ${prefix}/${PYTHON_DIR}/conescan
  WORKING_DIRECTORY ${WORK_DIR} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "importing the installed conescan failed:\n${out}")
endif()
message(STATUS "${out}")
