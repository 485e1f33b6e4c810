// conescan-fit: from a sensor's telemetry to its misalignment and horizon biases, with their
// uncertainty (MODEL §11; docs/CALIBRATION.md). A thin shell: the scene options are
// conescan-sim's (the option table, scene files), its own options are fit_options.hpp's; the
// fit is src/scene_calibration/scene_fit.hpp's. Exit 0: a converged fit (or a design); 1: a fit
// that did not converge (its last state, no estimate), or a write error; 2: bad input, nothing on
// standard output.
#include <cstdio>
#include <optional>
#include <string>
#include <variant>

#include "calibration/fit_json.hpp"
#include "calibration/report.hpp"
#include "cli/command_line.hpp"
#include "cli/fit_options.hpp"
#include "cli/residual_csv.hpp"
#include "scene/scene_plan.hpp"
#include "scene_calibration/scene_fit.hpp"

namespace {

using namespace conescan;

constexpr int exit_bad_usage = 2;
constexpr int exit_not_converged = 1;
constexpr int exit_write_error = 1;

constexpr const char* description =
    "conescan-fit: estimates a conical Earth sensor's misalignment, cone-angle and crossing "
    "biases and the horizon height from its telemetry, with their uncertainty and an "
    "observability verdict (MODEL §11). The scene options are conescan-sim's: the orbit, the "
    "reference attitude, the heads' nominal mounting (their sigma, phase, ... the start of the "
    "free parameters and the values of the held ones), the Earth and the crossing noise.";

int refuse(const std::string& text) {
  std::fprintf(stderr, "conescan-fit: %s\n", text.c_str());
  return exit_bad_usage;
}

int write_all(const std::string& text, int status) {
  if (std::fwrite(text.data(), 1, text.size(), stdout) != text.size() || std::fflush(stdout) != 0) {
    std::fprintf(stderr, "conescan-fit: error writing to standard output\n");
    return exit_write_error;
  }
  return status;
}

}  // namespace

int main(int argc, char** argv) {
  cli::command_line_parser parser("conescan-fit", description);
  const fit_cli::fit_options own(parser.app());
  const conescan::checked<cli::command_line> line = parser.parse(argc, argv);
  if (!line.ok()) return refuse(line.error().text());
  if (line.value().help) return write_all(parser.help(), 0);
  const auto entries = cli::scene_options(line.value());
  if (!entries.ok()) return refuse(entries.error().text());
  const conescan::checked<scene::scene_plan> plan = scene::build_scene_plan(entries.value());
  if (!plan.ok()) return refuse(plan.error().text());
  if (const std::string p = calibration::single_scene_problem(plan.value().request()); !p.empty())
    return refuse(p);
  const conescan::checked<fit_cli::fit_request> request = own.read();
  if (!request.ok()) return refuse(request.error().text());
  const fit_cli::fit_request& r = request.value();
  const scene::scene_config scene = plan.value().scene(0);
  const auto free = calibration::parse_free_selection(r.free, scene.heads.size());
  if (!free.ok()) return refuse(free.error().text());

  if (r.predict) {
    const auto design = calibration::predict_scene(scene, free.value());
    if (!design.ok()) return refuse(design.error().text());
    return write_all(r.json ? calibration::design_json(design.value())
                            : calibration::design_table(design.value()),
                     0);
  }
  const auto data = calibration::read_telemetry_file(*r.telemetry, scene.heads.size(),
                                                     calibration::scene_time_stamps(scene));
  if (!data.ok()) return refuse(data.error().text());
  calibration::fit_options options;
  options.loss = r.loss;
  options.max_iterations = r.max_iterations;
  std::optional<cli::residual_csv> residuals;
  if (r.residuals) {
    auto opened = cli::residual_csv::open(*r.residuals);
    if (!opened.ok()) return refuse(opened.error().text());
    residuals.emplace(std::move(opened).value());
  }
  const auto outcome = calibration::fit_scene(
      scene, data.value(), free.value(), options,
      residuals ? calibration::scene_residual_sink(
                      [&](const calibration::residual_row& row, double latitude_deg) {
                        residuals->write(row, latitude_deg);
                      })
                : calibration::scene_residual_sink());
  if (!outcome.ok()) return refuse(outcome.error().text());
  if (residuals)
    if (const conescan::checked<void> done = residuals->finish(); !done.ok()) {
      std::fprintf(stderr, "conescan-fit: %s\n", done.error().text().c_str());
      return exit_write_error;
    }
  const bool converged = std::holds_alternative<calibration::fit_result>(outcome.value());
  return write_all(
      r.json ? calibration::fit_json(outcome.value()) : calibration::fit_table(outcome.value()),
      converged ? 0 : exit_not_converged);
}
