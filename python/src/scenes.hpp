// conescan._conescan's scene runner (python/src/scenes.cpp): _simulate, _summary, _options.
#pragma once

#include <pybind11/pybind11.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "scene/scene_plan.hpp"

namespace conescan::python {

namespace py = pybind11;

/// Options as python/conescan/_scenes.py gives them: (option name, text) pairs.
using option_texts = std::vector<std::pair<std::string, std::string>>;

/// Raises the scene layer's error as ValueError, its text conescan-sim's message.
[[noreturn]] void raise(const conescan::diagnostic& error);

/// A note conescan-sim prints on standard error (interpolation_tolerance_note), as a Python
/// UserWarning (an exception where warnings are errors).
void warn(const std::string& note);

/// The options' entries as conescan-sim reads them: the scene file's (config), then the
/// keyword arguments' (which win, as the command line's do). A bad scene file raises.
std::vector<scene::option_value> scene_entries(const option_texts& options,
                                               const std::optional<std::string>& config);

/// Adds _simulate, _summary and _options (the option table) to the module.
void def_scenes(py::module_& m);

/// Adds _fit and _predict (conescan.fit, conescan.predict: python/src/fit.cpp).
void def_fit(py::module_& m);

}  // namespace conescan::python
