# CONESCAN_BUILD_PYTHON: the module `conescan` (python/) for NumPy. On by default when the project
# is top-level and Python 3 (interpreter, development files, NumPy) and pybind11 are found.
#
# Which interpreter. Debian's numpy, pytest and pybind11 are installed for /usr/bin/python3; a
# python3 earlier on PATH (a version manager's or conda's interpreter, which need not have numpy) is the one
# FindPython3 would take (its default strategy, LOCATION, takes the first interpreter on PATH
# that satisfies the version), and the module would be built for, and tested with, an
# interpreter that cannot import numpy. Hints (Python3_ROOT_DIR) do not help: such an
# interpreter also satisfies them. So, unless Python3_EXECUTABLE is given (FindPython3 then takes
# exactly that interpreter, with its own headers), /usr/bin/python3 is chosen when it imports
# numpy; otherwise FindPython3 searches as usual. The tests run with the same interpreter.
if(NOT DEFINED Python3_EXECUTABLE AND EXISTS /usr/bin/python3)
  execute_process(COMMAND /usr/bin/python3 -c "import numpy" RESULT_VARIABLE numpy_missing
                  OUTPUT_QUIET ERROR_QUIET)
  if(numpy_missing EQUAL 0)
    set(Python3_EXECUTABLE /usr/bin/python3 CACHE FILEPATH
        "Python 3 interpreter the module conescan is built and tested for")
  endif()
endif()

set(python_components Interpreter Development.Module NumPy)
set(python_found OFF)
if(PROJECT_IS_TOP_LEVEL AND NOT DEFINED CONESCAN_BUILD_PYTHON)
  find_package(Python3 3.8 COMPONENTS ${python_components} QUIET)
  find_package(pybind11 2.6 CONFIG QUIET)
  if(Python3_FOUND AND pybind11_FOUND)
    set(python_found ON)
  endif()
endif()
option(CONESCAN_BUILD_PYTHON
       "Build the Python module conescan (needs Python 3 development files, NumPy, pybind11)"
       ${python_found})

if(CONESCAN_BUILD_PYTHON)
  find_package(Python3 3.8 REQUIRED COMPONENTS ${python_components})
  find_package(pybind11 2.6 REQUIRED CONFIG)
  # Where cmake --install puts the package, relative to the install prefix: the interpreter's
  # platlib relative to its scheme's data directory, which is the scheme's own prefix
  # (lib/python3.11/dist-packages for Debian's posix_local scheme, whose prefix is /usr/local;
  # lib/python3.X/site-packages elsewhere), so that the default prefix lands on sys.path.
  execute_process(
    COMMAND ${Python3_EXECUTABLE} -c
            "import os, sysconfig; print(os.path.relpath(sysconfig.get_path('platlib'), sysconfig.get_path('data')))"
    OUTPUT_VARIABLE python_platlib OUTPUT_STRIP_TRAILING_WHITESPACE COMMAND_ERROR_IS_FATAL ANY)
  set(CONESCAN_PYTHON_INSTALL_DIR ${python_platlib} CACHE PATH
      "Install directory of the Python package, relative to CMAKE_INSTALL_PREFIX")
endif()
