// conescan._conescan's calibration: conescan-fit from Python (python/conescan/_fit.py turns
// keyword arguments into option texts and the result's JSON into a dict).
//
// The same flow as conescan-fit (apps/conescan-fit/main.cpp): the scene options and the fit's
// own through build_fit_plan (src/scene_calibration/fit_request.hpp: the one table of fit options
// and their checks), then src/scene_calibration/fit_run.hpp's read_fit_telemetry, run_fit or
// run_design, which return the result's structs. Telemetry given as arrays goes in as columns
// (calibration::telemetry_columns, the arrays borrowed, not copied), read by the file's reader with
// its checks and messages, the file named "<array>". The dict is made from calibration::fit_json's
// or design_json's text, the one writer of `conescan-fit --json`, so it has that object's content
// and shape, written once (a second writer from the structs to a dict would be a second copy).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>
#include <span>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "calibration/fit_json.hpp"
#include "calibration/telemetry.hpp"
#include "scene_calibration/fit_request.hpp"
#include "scene_calibration/fit_run.hpp"
#include "scenes.hpp"
#include "simulation/truth_source.hpp"

namespace conescan::python {
namespace {

// Telemetry columns from python/conescan/_fit.py: 1-d, float64, the same length.
using column_arrays = std::vector<
    std::pair<std::string, py::array_t<double, py::array::c_style | py::array::forcecast>>>;

// A refusal as conescan.fit's caller reads it: the function's own arguments (telemetry, free,
// loss, max_iterations) named as Python spells them ("max_iterations: '2.5' is not a count"),
// the scene's keywords as the command line does (conescan.simulate's rule).
[[noreturn]] void raise_named(conescan::diagnostic error) {
  const calibration::fit_option_spec* spec = calibration::find_fit_option(error.option);
  if (spec && spec->python) {
    std::string keyword(spec->name);
    for (char& c : keyword)
      if (c == '-') c = '_';
    error.message = keyword + ": " + error.message;
    error.option.clear();
  }
  raise(error);
}

// The scene's and the fit's options as conescan-fit reads them (fit_request.hpp): the scene
// file's entries, the scene keywords, then the fit keywords (free, loss, max-iterations,
// telemetry), checked by the one table of fit options.
calibration::fit_plan plan_of(const option_texts& options, const std::optional<std::string>& config,
                              const option_texts& fit_options, calibration::telemetry_input input,
                              bool predict) {
  std::vector<scene::option_value> entries = scene_entries(options, config);
  for (const auto& [name, text] : fit_options) {
    const calibration::fit_option_spec* spec = calibration::find_fit_option(name);
    if (!spec || !spec->python)
      throw py::value_error("unknown fit option " + conescan::quote(name));
    entries.push_back({name, text, conescan::origin::command_line()});
  }
  if (predict) entries.push_back({"predict", "true", conescan::origin::command_line()});
  conescan::checked<calibration::fit_plan> plan = calibration::build_fit_plan(entries, input);
  if (!plan.ok()) raise_named(plan.error());
  if (const auto note = scene::interpolation_tolerance_note(plan.value().scene)) warn(*note);
  return std::move(plan).value();
}

// Text columns from python/conescan/_fit.py (utc): as long as the numeric ones, no comma or line
// end in a value (the module checks).
using text_columns = std::vector<std::pair<std::string, std::vector<std::string>>>;

// (converged, the fit's JSON): conescan-fit --telemetry ... --json. The telemetry is the file of
// the fit option `telemetry`, or the columns when it is not given, read by the one reader as
// "<array>" (calibration::read_telemetry_columns: the file's checks and messages).
std::pair<bool, std::string> fit(const option_texts& options,
                                 const std::optional<std::string>& config,
                                 const option_texts& fit_options, const text_columns& texts,
                                 const column_arrays& columns, bool columns_given) {
  const calibration::fit_plan plan =
      plan_of(options, config, fit_options,
              columns_given ? calibration::telemetry_input::in_memory
                            : calibration::telemetry_input::file_option,
              false);
  calibration::telemetry_columns in_memory{texts, {}};
  for (const auto& [name, values] : columns)
    in_memory.numbers.emplace_back(
        name, std::span<const double>(values.data(), static_cast<std::size_t>(values.shape(0))));
  std::optional<conescan::checked<calibration::fit_outcome>> outcome;
  {
    py::gil_scoped_release release;  // reading, and Ceres' iterations
    const conescan::checked<calibration::telemetry> data =
        plan.request.telemetry ? calibration::read_fit_telemetry(plan)
                               : calibration::read_fit_telemetry(plan, in_memory, "<array>");
    if (data.ok())
      outcome.emplace(calibration::run_fit(plan, data.value()));
    else
      outcome.emplace(data.error());
  }
  if (!outcome->ok()) raise_named(outcome->error());
  const bool converged = std::holds_alternative<calibration::fit_result>(outcome->value());
  return {converged, calibration::fit_json(outcome->value())};
}

// The design's JSON: conescan-fit --predict --json.
std::string predict(const option_texts& options, const std::optional<std::string>& config,
                    const option_texts& fit_options) {
  const calibration::fit_plan plan =
      plan_of(options, config, fit_options, calibration::telemetry_input::file_option, true);
  std::optional<conescan::checked<calibration::design_result>> design;
  {
    py::gil_scoped_release release;
    design.emplace(calibration::run_design(plan));
  }
  if (!design->ok()) raise_named(design->error());
  return calibration::design_json(design->value());
}

}  // namespace

void def_fit(py::module_& m) {
  m.def("_fit", &fit, py::arg("options"), py::arg("config"), py::arg("fit_options"),
        py::arg("text_columns"), py::arg("columns"), py::arg("columns_given"),
        "(converged, conescan-fit --json's text) (conescan.fit).");
  m.def("_predict", &predict, py::arg("options"), py::arg("config"), py::arg("fit_options"),
        "conescan-fit --predict --json's text (conescan.predict).");
  m.def(
      "_fit_options",
      [] {
        py::list out;
        for (const calibration::fit_option_spec& o : calibration::fit_option_table())
          if (o.python) out.append(py::make_tuple(std::string(o.name), std::string(o.help)));
        return out;
      },
      "conescan.fit's own keywords from the fit option table: (name, help) per option.");
}

}  // namespace conescan::python
