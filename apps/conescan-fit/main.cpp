// conescan-fit: from a sensor's telemetry to its misalignment and horizon biases, with their
// uncertainty (MODEL §11; docs/CALIBRATION.md). A thin shell: the scene options are
// conescan-sim's (the option table, scene files), its own options are the fit option table's
// (src/scene_calibration/fit_request.hpp, which conescan.fit shares); the flow from the checked
// plan to the result is src/scene_calibration/fit_run.hpp's, conescan.fit's too. Exit 0: a
// converged fit (or a design); 1: a fit that did not converge (its last state, no estimate), or a
// write error; 2: bad input, nothing on standard output.
#include <cstdio>
#include <optional>
#include <string>
#include <variant>

#include "calibration/fit_json.hpp"
#include "calibration/report.hpp"
#include "cli/command_line.hpp"
#include "cli/fit_options.hpp"
#include "cli/guarded_main.hpp"
#include "cli/output_sink.hpp"
#include "cli/residual_csv.hpp"
#include "scene_calibration/fit_request.hpp"
#include "scene_calibration/fit_run.hpp"
#include "simulation/truth_source.hpp"

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

int write_error(const conescan::diagnostic& error) {
  std::fprintf(stderr, "conescan-fit: %s\n", error.text().c_str());
  return exit_write_error;
}

// The report, the JSON, the help: all of the text or none of it, with errno's text (a file-size
// limit is EFBIG, not a kill by SIGXFSZ), as conescan-sim writes (cli/output_sink.hpp).
int write_all(const std::string& text, int status, const char* what = "the report") {
  const int written = cli::write_whole_text(text, "conescan-fit", what);
  return written != 0 ? written : status;
}

}  // namespace

static int run(int argc, char** argv) {
  cli::command_line_parser parser(scene::scene_program::fit, description);
  const fit_cli::fit_options own(parser.app());
  const conescan::checked<cli::command_line> line = parser.parse(argc, argv);
  if (!line.ok()) return refuse(line.error().text());
  if (line.value().help) return write_all(parser.help(), 0, "the help");
  auto entries = cli::scene_options(line.value());
  if (!entries.ok()) return refuse(entries.error().text());
  for (scene::option_value& v : own.entries()) entries.value().push_back(std::move(v));
  const conescan::checked<calibration::fit_plan> plan =
      calibration::build_fit_plan(entries.value());
  if (!plan.ok()) return refuse(plan.error().text());
  const calibration::fit_request& r = plan.value().request;
  const scene::loaded_scene& scene = plan.value().scene;
  if (const auto note = scene::interpolation_tolerance_note(scene))
    std::fprintf(stderr, "conescan-fit: note: %s\n", note->c_str());

  if (r.predict) {
    const auto design = calibration::run_design(plan.value());
    if (!design.ok()) return refuse(design.error().text());
    return write_all(r.json ? calibration::design_json(design.value())
                            : calibration::design_table(design.value()),
                     0);
  }
  const auto data = calibration::read_fit_telemetry(plan.value());
  if (!data.ok()) return refuse(data.error().text());
  std::optional<cli::residual_csv> residuals;
  if (r.residuals) {
    auto opened = cli::residual_csv::open(*r.residuals);
    if (!opened.ok()) return write_error(opened.error());
    residuals.emplace(std::move(opened).value());
  }
  const auto outcome = calibration::run_fit(
      plan.value(), data.value(),
      residuals ? calibration::scene_residual_sink(
                      [&](const calibration::residual_row& row, double latitude_deg) {
                        residuals->write(row, latitude_deg);
                      })
                : calibration::scene_residual_sink());
  if (!outcome.ok()) return refuse(outcome.error().text());
  if (residuals)
    if (const conescan::checked<void> done = residuals->finish(); !done.ok())
      return write_error(done.error());
  const bool converged = std::holds_alternative<calibration::fit_result>(outcome.value());
  return write_all(
      r.json ? calibration::fit_json(outcome.value()) : calibration::fit_table(outcome.value()),
      converged ? 0 : exit_not_converged);
}

int main(int argc, char** argv) {
  return conescan::cli::guarded_main("conescan-fit", run, argc, argv);
}
