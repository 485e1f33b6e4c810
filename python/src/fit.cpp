// conescan._conescan's calibration: conescan-fit from Python (python/conescan/_fit.py turns
// keyword arguments into option texts and the result's JSON into a dict).
//
// The same path as conescan-fit (apps/conescan-fit/main.cpp): the scene options through the
// option table (build_scene_plan), calibration::single_scene_problem, parse_free_list, the
// telemetry reader, fit_scene or predict_scene; the result is calibration::fit_json's or
// design_json's text, the one writer of `conescan-fit --json`, so the dict has its content and
// shape. Telemetry given as arrays is written as the CSV the reader reads (every double as its
// shortest round-trip text, so read back exactly) and read by the same reader, with its checks
// and messages, the file named "<array>".
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
#include "calibration/parameters.hpp"
#include "calibration/telemetry.hpp"
#include "scene_calibration/scene_fit.hpp"
#include "scenes.hpp"

namespace conescan::python {
namespace {

// Telemetry columns from python/conescan/_fit.py: 1-d, float64, the same length.
using column_arrays = std::vector<
    std::pair<std::string, py::array_t<double, py::array::c_style | py::array::forcecast>>>;

[[noreturn]] void raise(const conescan::diagnostic& error) {
  throw py::value_error(error.text());
}

// The plan's one scene, checked as conescan-fit checks it.
scene::scene_config one_scene(const option_texts& options,
                              const std::optional<std::string>& config) {
  const std::vector<scene::option_value> entries = scene_entries(options, config);
  conescan::checked<scene::scene_plan> plan = scene::build_scene_plan(entries);
  if (!plan.ok()) python::raise(plan.error());
  if (const std::string p = calibration::single_scene_problem(plan.value().request()); !p.empty())
    throw py::value_error(p);
  return plan.value().scene(0);
}

// fit_options::read's message for a --free never given (conescan-fit's order: after the scene).
void require_free(const std::string& free_list) {
  if (free_list.empty())
    raise({"free", "missing: name the parameters to estimate (conescan-fit --help)"});
}

// The free parameters' indices (parse_free_list), last as in conescan-fit.
std::vector<std::size_t> free_of(const scene::scene_config& scene, const std::string& free_list) {
  auto free = calibration::parse_free_list(free_list, scene.heads.size());
  if (!free.ok()) raise(free.error());
  return std::move(free).value();
}

// --loss and --max-iterations as fit_options::read checks them, in its order.
calibration::fit_options fit_settings(const std::string& free_list, const std::string& loss,
                                      int max_iterations) {
  calibration::fit_options settings;
  if (max_iterations < 1 || max_iterations > 10000)
    raise({"max-iterations",
           conescan::quote(std::to_string(max_iterations)) + " is not a count in [1, 10000]"});
  settings.max_iterations = max_iterations;
  require_free(free_list);
  if (loss == "none")
    settings.loss = calibration::robust_loss::none;
  else if (loss != "huber")
    raise({"loss", conescan::quote(loss) + " is not one of: huber, none"});
  return settings;
}

// The columns as a telemetry CSV: the names as the header, a row per element; NaN as "nan"
// (a head that did not measure), other non-finite values as "inf"/"-inf" (which the reader
// refuses, naming the line).
std::string telemetry_text(const column_arrays& columns) {
  std::string text;
  for (std::size_t c = 0; c < columns.size(); ++c) text += (c ? "," : "") + columns[c].first;
  text += '\n';
  const py::ssize_t rows = columns.empty() ? 0 : columns.front().second.shape(0);
  char buffer[32];
  for (py::ssize_t k = 0; k < rows; ++k) {
    for (std::size_t c = 0; c < columns.size(); ++c) {
      if (c) text += ',';
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

// (converged, the fit's JSON): conescan-fit --telemetry ... --json.
std::pair<bool, std::string> fit(const option_texts& options,
                                 const std::optional<std::string>& config,
                                 const std::string& free_list,
                                 const std::optional<std::string>& telemetry_path,
                                 const column_arrays& columns, const std::string& loss,
                                 int max_iterations) {
  const scene::scene_config scene = one_scene(options, config);
  const calibration::fit_options settings = fit_settings(free_list, loss, max_iterations);
  const std::vector<std::size_t> free = free_of(scene, free_list);
  std::optional<conescan::checked<calibration::fit_outcome>> outcome;
  {
    py::gil_scoped_release release;  // reading, and Ceres' iterations
    std::optional<conescan::checked<calibration::telemetry>> data;
    if (telemetry_path) {
      data.emplace(calibration::read_telemetry_file(*telemetry_path, scene.heads.size(),
                                                    calibration::scene_time_stamps(scene)));
    } else {
      std::istringstream in(telemetry_text(columns));
      data.emplace(calibration::read_telemetry(in, "<array>", scene.heads.size(),
                                               calibration::scene_time_stamps(scene)));
    }
    if (data->ok())
      outcome.emplace(calibration::fit_scene(scene, data->value(), free, settings));
    else
      outcome.emplace(data->error());
  }
  if (!outcome->ok()) raise(outcome->error());
  const bool converged = std::holds_alternative<calibration::fit_result>(outcome->value());
  return {converged, calibration::fit_json(outcome->value())};
}

// The design's JSON: conescan-fit --predict --json.
std::string predict(const option_texts& options, const std::optional<std::string>& config,
                    const std::string& free_list) {
  const scene::scene_config scene = one_scene(options, config);
  require_free(free_list);
  const std::vector<std::size_t> free = free_of(scene, free_list);
  std::optional<conescan::checked<calibration::design_result>> design;
  {
    py::gil_scoped_release release;
    design.emplace(calibration::predict_scene(scene, free));
  }
  if (!design->ok()) raise(design->error());
  return calibration::design_json(design->value());
}

}  // namespace

void def_fit(py::module_& m) {
  m.def("_fit", &fit, py::arg("options"), py::arg("config"), py::arg("free"),
        py::arg("telemetry_path"), py::arg("columns"), py::arg("loss"), py::arg("max_iterations"),
        "(converged, conescan-fit --json's text) (conescan.fit).");
  m.def("_predict", &predict, py::arg("options"), py::arg("config"), py::arg("free"),
        "conescan-fit --predict --json's text (conescan.predict).");
}

}  // namespace conescan::python
