// conescan._conescan's scene runner (python/src/scenes.cpp): _simulate, _summary, _options.
#pragma once

#include <pybind11/pybind11.h>

namespace conescan::python {

namespace py = pybind11;

/// Adds _simulate, _summary and _options (the option table) to the module.
void def_scenes(py::module_& m);

}  // namespace conescan::python
