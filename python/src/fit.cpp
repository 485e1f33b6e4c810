// conescan._conescan's calibration: conescan-fit from Python (python/conescan/_fit.py turns
// keyword arguments into option texts and the result's JSON into a dict).
//
// The same path as conescan-fit (apps/conescan-fit/main.cpp): the scene options and the fit's
// own through build_fit_plan (src/scene_calibration/fit_request.hpp: the one table of fit options
// and their checks), the telemetry reader, fit_scene or predict_scene; the result is
// calibration::fit_json's or design_json's text, the one writer of `conescan-fit --json`, so the
// dict has its content and shape. Telemetry given as arrays is written as the CSV the reader reads
// (every double as its shortest round-trip text, so read back exactly) and read by the same reader,
// with its checks and messages, the file named "<array>".
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <charconv>
#include <cmath>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "calibration/fit_json.hpp"
#include "calibration/telemetry.hpp"
#include "scene/truth_source.hpp"
#include "scene_calibration/fit_request.hpp"
#include "scene_calibration/scene_fit.hpp"
#include "scenes.hpp"

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

// The columns as a telemetry CSV: the names as the header (the text columns first), a row per
// element; NaN as "nan" (a head that did not measure), other non-finite values as "inf"/"-inf"
// (which the reader refuses, naming the line).
std::string telemetry_text(const text_columns& texts, const column_arrays& columns) {
  std::string text;
  for (std::size_t c = 0; c < texts.size(); ++c) text += (c ? "," : "") + texts[c].first;
  for (std::size_t c = 0; c < columns.size(); ++c)
    text += (c || !texts.empty() ? "," : "") + columns[c].first;
  text += '\n';
  const py::ssize_t rows = !texts.empty()    ? static_cast<py::ssize_t>(texts.front().second.size())
                           : columns.empty() ? 0
                                             : columns.front().second.shape(0);
  char buffer[32];
  for (py::ssize_t k = 0; k < rows; ++k) {
    for (std::size_t c = 0; c < texts.size(); ++c)
      text += (c ? "," : "") + texts[c].second[static_cast<std::size_t>(k)];
    for (std::size_t c = 0; c < columns.size(); ++c) {
      if (c || !texts.empty()) text += ',';
      const double v = columns[c].second.data()[k];  // no Python call: GIL released
      if (std::isnan(v)) {
        text += "nan";
        continue;
      }
      const auto end = std::to_chars(buffer, buffer + sizeof buffer, v).ptr;
      text.append(buffer, end);
    }
    text += '\n';
  }
  return text;
}

// (converged, the fit's JSON): conescan-fit --telemetry ... --json. The telemetry is the file of
// the fit option `telemetry`, or the columns when it is not given.
std::pair<bool, std::string> fit(const option_texts& options,
                                 const std::optional<std::string>& config,
                                 const option_texts& fit_options, const text_columns& texts,
                                 const column_arrays& columns, bool columns_given) {
  const calibration::fit_plan plan =
      plan_of(options, config, fit_options,
              columns_given ? calibration::telemetry_input::in_memory
                            : calibration::telemetry_input::file_option,
              false);
  calibration::fit_options settings;
  settings.loss = plan.request.loss;
  settings.max_iterations = plan.request.max_iterations;
  settings.threads = plan.threads;
  std::optional<conescan::checked<calibration::fit_outcome>> outcome;
  {
    py::gil_scoped_release release;  // reading, and Ceres' iterations
    std::optional<conescan::checked<calibration::telemetry>> data;
    const std::size_t heads = plan.scene.heads.size();
    const calibration::telemetry_time_stamps stamps = calibration::scene_time_stamps(plan.scene);
    if (plan.request.telemetry) {
      data.emplace(calibration::read_telemetry_file(*plan.request.telemetry, heads, stamps));
    } else {
      std::istringstream in(telemetry_text(texts, columns));
      data.emplace(calibration::read_telemetry(in, "<array>", heads, stamps));
    }
    if (data->ok())
      outcome.emplace(calibration::fit_scene(plan.scene, data->value(), plan.free, settings));
    else
      outcome.emplace(data->error());
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
    design.emplace(calibration::predict_scene(plan.scene, plan.free, plan.threads));
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
