// conescan-sim: streams the roll/pitch error time series of conical Earth sensors as CSV
// (MODEL §9). A thin shell: read the command line (and scene file), let the scene layer build and
// validate every scene (scene_plan.hpp), then stream rows (or a summary, or the error budget).
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <memory>
#include <new>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "calendar_run.hpp"
#include "campaign_run.hpp"
#include "cli/command_line.hpp"
#include "cli/guarded_main.hpp"
#include "cli/output_sink.hpp"
#include "merge.hpp"
#include "scene/scene_file.hpp"
#include "scene/scene_plan.hpp"
#include "scene_calibration/fit_correction.hpp"
#include "simulation/ephemeris_writer.hpp"
#include "simulation/summary_state.hpp"
#include "simulation/truth_source.hpp"
#include "text/output_file.hpp"

namespace {

using namespace conescan;

constexpr int exit_bad_usage = 2;
constexpr int exit_write_error = 1;

// `what`: what was written ("the CSV", "the help").
int finish(const cli::output_sink& out, const char* what) {
  return cli::finish_output(out, "conescan-sim", what);
}

int refuse(const conescan::diagnostic& error) {
  std::fprintf(stderr, "conescan-sim: %s\n", error.text().c_str());
  return exit_bad_usage;
}

// --help, --print-config: all of the text or an error (a full disk is not a success).
int write_text(const std::string& text, const char* what) {
  return cli::write_whole_text(text, "conescan-sim", what);
}

int write_error(const conescan::diagnostic& error) {
  std::fprintf(stderr, "conescan-sim: %s\n", error.text().c_str());
  return exit_write_error;
}

// The files written besides standard output (--write-oem, --write-aem, --summary-state), each
// opened, so its path checked, before the first byte of any output (text/output_file.hpp).
struct run_outputs {
  std::optional<text::output_file> oem, aem, state;
};

conescan::checked<run_outputs> open_outputs(const scene::scene_request& r) {
  run_outputs outputs;
  for (const auto& [option, path, file] :
       {std::tuple{"write-oem", &r.write_oem_file, &outputs.oem},
        std::tuple{"write-aem", &r.write_aem_file, &outputs.aem},
        std::tuple{"summary-state", &r.summary_state, &outputs.state}}) {
    if (path->empty()) continue;
    conescan::checked<text::output_file> opened = text::output_file::open(*path, option);
    if (!opened.ok()) return std::move(opened).error();
    file->emplace(std::move(opened).value());
  }
  return outputs;
}

// --write-oem, --write-aem (simulation/ephemeris_writer.hpp): both written, then both committed; 0,
// or exit 1 with the error (each file left as it was, no temporary file).
int write_ephemerides(const scene::scene_plan& plan, run_outputs& outputs) {
  for (const auto& [file, write] :
       {std::pair{&outputs.oem, &scene::write_oem}, std::pair{&outputs.aem, &scene::write_aem}})
    if (*file)
      if (const conescan::checked<void> written = write(plan.scene(0), **file); !written.ok())
        return write_error(written.error());
  for (std::optional<text::output_file>* file : {&outputs.oem, &outputs.aem})
    if (*file)
      if (const conescan::checked<void> done = (*file)->commit(); !done.ok())
        return write_error(done.error());
  return 0;
}

}  // namespace

static int run(int argc, char** argv) {
  cli::command_line_parser parser;
  const conescan::checked<cli::command_line> line = parser.parse(argc, argv);
  if (!line.ok()) return refuse(line.error());
  if (line.value().help) return write_text(parser.help(), "the help");
  if (line.value().version)
    return write_text("conescan-sim " + std::string(scene::conescan_version()) + "\n",
                      "the version");
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
  if (const auto note = scene::interpolation_tolerance_note(plan.value()))
    std::fprintf(stderr, "conescan-sim: note: %s\n", note->c_str());
  if (!plan.value().request().calendar_dir.empty()) return cli::run_calendar(plan.value());
  // Every input is read and checked before the first byte of any output: --apply's fit (read
  // whole: fit_correction.hpp), then the output files' paths; then the ephemerides, then the CSV.
  std::unique_ptr<scene::fit_correction> correction;
  if (const auto& fit = plan.value().request().apply_fit) {
    auto made = scene::fit_correction::of(plan.value().scene(0), *fit);
    if (!made.ok()) return refuse(made.error());
    correction = std::move(made).value();
  }
  conescan::checked<run_outputs> outputs = open_outputs(plan.value().request());
  if (!outputs.ok()) return write_error(outputs.error());
  if (const int written = write_ephemerides(plan.value(), outputs.value()); written != 0)
    return written;
  cli::output_sink out(STDOUT_FILENO);
  text::output_file* state = outputs.value().state ? &*outputs.value().state : nullptr;
  const bool state_written = cli::run_campaign(out, plan.value(), correction.get(), state);
  out.flush();
  const int status = finish(out, "the CSV");
  return status == 0 && !state_written ? exit_write_error : status;
}

int main(int argc, char** argv) {
  return conescan::cli::guarded_main("conescan-sim", run, argc, argv);
}
