// conescan-sim: streams the roll/pitch error time series of conical Earth sensors as CSV
// (MODEL §9). A thin shell: read the command line (and scene file), let the scene layer build and
// validate every scene (scene_plan.hpp), then stream rows (or a summary, or the error budget).
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "campaign_run.hpp"
#include "cli/command_line.hpp"
#include "cli/output_sink.hpp"
#include "merge.hpp"
#include "scene/ephemeris_writer.hpp"
#include "scene/scene_file.hpp"
#include "scene/scene_plan.hpp"
#include "scene_calibration/fit_correction.hpp"

namespace {

using namespace conescan;

constexpr int exit_bad_usage = 2;
constexpr int exit_write_error = 1;
// What a shell reports for a process ended by SIGPIPE; used when SIGPIPE is ignored and the
// closed reader shows up as EPIPE instead.
constexpr int exit_closed_reader = 141;

// `what`: what was written ("the CSV", "the help").
int finish(const cli::output_sink& out, const char* what) {
  using outcome = cli::output_sink::outcome;
  switch (out.state()) {
    case outcome::ok:
      return 0;
    case outcome::closed_reader:
      return exit_closed_reader;
    case outcome::write_error:
      std::fprintf(stderr, "conescan-sim: error writing %s to standard output: %s\n", what,
                   std::strerror(out.error_number()));
      return exit_write_error;
  }
  return exit_write_error;
}

int refuse(const conescan::diagnostic& error) {
  std::fprintf(stderr, "conescan-sim: %s\n", error.text().c_str());
  return exit_bad_usage;
}

// --help, --print-config: all of the text or an error (a full disk is not a success).
int write_text(const std::string& text, const char* what) {
  cli::output_sink out(STDOUT_FILENO);
  out.append(text);
  out.flush();
  return finish(out, what);
}

// --write-oem, --write-aem (scene/ephemeris_writer.hpp): 0, or exit 1 with the error.
int write_ephemerides(const scene::scene_plan& plan) {
  const scene::scene_request& r = plan.request();
  for (const auto& [path, write] : {std::pair{&r.write_oem_file, &scene::write_oem},
                                    std::pair{&r.write_aem_file, &scene::write_aem}}) {
    if (path->empty()) continue;
    if (const conescan::checked<void> written = write(plan.scene(0), *path); !written.ok()) {
      std::fprintf(stderr, "conescan-sim: %s\n", written.error().text().c_str());
      return exit_write_error;
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  cli::command_line_parser parser;
  const conescan::checked<cli::command_line> line = parser.parse(argc, argv);
  if (!line.ok()) return refuse(line.error());
  if (line.value().help) return write_text(parser.help(), "the help");
  if (!line.value().merge.empty()) {  // the shards' summaries added up (merge.hpp)
    const auto merged = cli::merge_state_files(line.value().merge);
    if (!merged.ok()) return refuse(merged.error());
    cli::output_sink out(STDOUT_FILENO);
    cli::write_merged_summary(out, merged.value());
    out.flush();
    return finish(out, "the summary");
  }
  const auto entries = cli::scene_options(line.value());
  if (!entries.ok()) return refuse(entries.error());
  const conescan::checked<scene::scene_plan> plan = scene::build_scene_plan(entries.value());
  if (!plan.ok()) return refuse(plan.error());
  if (line.value().print_config)
    return write_text(scene::scene_file_text(plan.value().request()), "the scene file");
  // --write-oem, --write-aem: the scene's orbit and attitude, each whole or not at all, first.
  if (const int written = write_ephemerides(plan.value()); written != 0) return written;

  // --apply: the fit's correction, read before any output (fit_correction.hpp).
  std::unique_ptr<scene::fit_correction> correction;
  if (const auto& fit = plan.value().request().apply_fit) {
    auto made = scene::fit_correction::of(plan.value().scene(0), *fit);
    if (!made.ok()) return refuse({"", made.error().text(), {}});
    correction = std::move(made).value();
  }
  cli::output_sink out(STDOUT_FILENO);
  const bool state_written = cli::run_campaign(out, plan.value(), correction.get());
  out.flush();
  const int status = finish(out, "the CSV");
  return status == 0 && !state_written ? exit_write_error : status;
}
