// conescan-sim: streams the roll/pitch error time series of conical Earth sensors as CSV
// (SPEC §9). A thin shell: read the command line (and scene file), let the scene layer build and
// validate every scene (scene_plan.hpp), then stream rows (or a summary, or the error budget).
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "command_line.hpp"
#include "csv_rows.hpp"
#include "output_sink.hpp"
#include "scene/budget.hpp"
#include "scene/ephemeris_writer.hpp"
#include "scene/scene_file.hpp"
#include "scene/scene_plan.hpp"
#include "scene/simulation.hpp"
#include "scene/summary.hpp"

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

int refuse(const scene::config_error& error) {
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

// A progress line on standard error when it is a terminal, for runs longer than about 1 s.
class progress {
 public:
  explicit progress(std::uint64_t total)
      : total_(total), enabled_(isatty(STDERR_FILENO) == 1), start_(clock::now()) {}
  ~progress() {
    if (shown_) std::fputs("\r\033[K", stderr);
  }
  void update(std::uint64_t done) {
    if (!enabled_ || (done & 0x3fff) != 0) return;
    const double seconds = std::chrono::duration<double>(clock::now() - start_).count();
    if (seconds < 1) return;
    shown_ = true;
    std::fprintf(stderr, "\rconescan-sim: %llu/%llu rows (%.0f%%), %.3g rows/s ",
                 static_cast<unsigned long long>(done), static_cast<unsigned long long>(total_),
                 100.0 * static_cast<double>(done) / static_cast<double>(total_),
                 static_cast<double>(done) / seconds);
  }

 private:
  using clock = std::chrono::steady_clock;
  std::uint64_t total_;
  bool enabled_;
  bool shown_ = false;
  clock::time_point start_;
};

void trace(const scene::row& row, const char* source) {
  for (std::size_t h = 0; h < row.heads.size(); ++h)
    std::fprintf(stderr, "trace: %s%s%st_s=%.17g head=%zu iterations=%d status=%s\n",
                 source ? "source=" : "", source ? source : "", source ? " " : "", row.t_s, h + 1,
                 row.heads[h].iterations, to_string(row.heads[h].state));
}

// The summary's columns: a count per status, in the order of all_statuses (status.hpp).
std::string statistics_header() {
  std::string header = "source,rows";
  for (status s : all_statuses) header += std::string(",") + to_string(s);
  return header +
         ",roll_min_deg,roll_max_deg,roll_mean_deg,roll_rms_deg,roll_std_deg,roll_3sigma_deg,"
         "pitch_min_deg,pitch_max_deg,pitch_mean_deg,pitch_rms_deg,pitch_std_deg,"
         "pitch_3sigma_deg\n";
}

// One summary line: counts, then min, max, mean, RMS, 1 sigma and 3 sigma of roll and pitch
// over the ok rows (NaN when there are none).
void write_statistics(cli::output_sink& out, const cli::leading_columns& leading,
                      const std::string& source, const scene::error_statistics& s) {
  leading.write_values(out);
  out.append(source);
  out.append(',');
  out.append_count(s.rows);
  for (std::uint64_t count : s.status_counts) {
    out.append(',');
    out.append_count(count);
  }
  const double nan = not_a_number<double>();
  for (const scene::running_statistics* q : {&s.roll, &s.pitch}) {
    const bool any = q->count > 0;
    for (double v : {any ? q->min : nan, any ? q->max : nan, any ? q->mean : nan, q->rms(),
                     q->std(), 3 * q->std()}) {
      out.append(',');
      out.append_number(rad_to_deg(v));
    }
  }
  out.append('\n');
  out.end_row();
}

void write_budget_header(cli::output_sink& out, const std::vector<scene::budget_source>& sources) {
  out.append("t_s,nu_deg");
  for (const scene::budget_source& s : sources)
    out.append("," + s.name + "_roll_err_deg," + s.name + "_pitch_err_deg," + s.name + "_status");
  out.append(",sum_roll_err_deg,sum_pitch_err_deg,sum_status\n");
}

void write_error_pair(cli::output_sink& out, double roll, double pitch, status state) {
  out.append(',');
  out.append_number(cli::degrees_pm180(roll));
  out.append(',');
  out.append_number(cli::degrees_pm180(pitch));
  out.append(',');
  out.append(to_string(state));
}

// --budget: every source's scene in lock step, one row per time step (or one summary line per
// source), plus the sum of the single sources to judge linearity.
void run_budget(cli::output_sink& out, const scene::scene_plan& plan) {
  const std::vector<scene::budget_source>& sources = plan.budget();
  const scene::scene_request& request = plan.request();
  std::vector<scene::simulation> sims;
  std::vector<scene::row> rows;
  for (const scene::budget_source& s : sources) {
    sims.emplace_back(s.scene);
    rows.push_back(sims.back().make_row());
  }
  std::vector<scene::error_statistics> stats(sources.size() + 1);  // + the sum of singles
  if (request.summary)
    out.append(statistics_header());
  else
    write_budget_header(out, sources);
  out.end_row();
  progress bar(plan.total_rows());
  const std::uint64_t n = sims.front().rows();
  for (std::uint64_t k = 0; k < n && out.state() == cli::output_sink::outcome::ok; ++k) {
    bar.update(k + 1);
    double roll_sum = 0, pitch_sum = 0;
    status sum_state = status::ok;
    for (std::size_t i = 0; i < sims.size(); ++i) {
      sims[i].compute(k, rows[i]);
      if (request.trace) trace(rows[i], sources[i].name.c_str());
      stats[i].add(rows[i].roll_err_rad, rows[i].pitch_err_rad, rows[i].state);
      if (sources[i].name == "all") continue;
      roll_sum += rows[i].roll_err_rad;
      pitch_sum += rows[i].pitch_err_rad;
      if (rows[i].state != status::ok) sum_state = status::none;
    }
    stats.back().add(roll_sum, pitch_sum, sum_state);
    if (request.summary) continue;
    out.append_number(rows[0].t_s);
    out.append(',');
    out.append_number(rad_to_deg(wrap_two_pi(rows[0].true_anomaly_rad)));
    for (const scene::row& r : rows)
      write_error_pair(out, r.roll_err_rad, r.pitch_err_rad, r.state);
    write_error_pair(out, roll_sum, pitch_sum, sum_state);
    out.append('\n');
    out.end_row();
  }
  if (!request.summary) return;
  const cli::leading_columns none;
  for (std::size_t i = 0; i < sources.size(); ++i)
    write_statistics(out, none, sources[i].name, stats[i]);
  write_statistics(out, none, "sum", stats.back());
}

// Leading columns: the swept option, the run (with --runs > 1), the seed (with noise), each when
// some scene of the plan has it.
cli::leading_columns leading_columns_of(const scene::scene_plan& plan) {
  cli::leading_columns leading;
  if (plan.request().sweep) leading.names.push_back(plan.request().sweep->name);
  if (plan.any_runs()) leading.names.push_back("run");
  if (plan.any_noise()) leading.names.push_back("seed");
  leading.values.resize(leading.names.size());
  leading.condition = plan.request().scene.processing == scene::processing_method::horizon_vector;
  return leading;
}

// The leading values of scene j: its swept value, `run` (the run, or in a summary the number of
// runs), its seed.
void set_leading_values(cli::leading_columns& leading, const scene::scene_plan& plan,
                        std::uint64_t j, const scene::scene_config& scene, std::uint64_t run) {
  std::size_t column = 0;
  if (plan.request().sweep) leading.values[column++] = {plan.sweep_value(j), 0, false};
  if (plan.any_runs()) leading.values[column++] = {0, run, true};
  if (plan.any_noise()) leading.values[column++] = {0, scene.seed, true};
}

// The rows (or the summary) of scene j, every run.
void run_scene(cli::output_sink& out, const scene::scene_plan& plan, std::uint64_t j,
               cli::leading_columns& leading, progress& bar, std::uint64_t& done) {
  const scene::scene_config scene = plan.scene(j);
  const scene::scene_request& request = plan.request();
  const scene::simulation sim(scene);
  // Rows are computed a block at a time (compute_rows: faster per row), written one by one.
  std::vector<scene::row> block(scene::simulation::rows_per_block, sim.make_row());
  // One summary over all runs of a scene: the statistics of the noise, not of one draw.
  scene::run_summary summary(sim.head_count());
  for (std::uint64_t run = 0; run < scene.runs; ++run) {
    set_leading_values(leading, plan, j, scene, run + 1);
    for (std::uint64_t k = 0; k < sim.rows() && out.state() == cli::output_sink::outcome::ok;
         k += block.size()) {
      const auto count =
          static_cast<std::size_t>(std::min<std::uint64_t>(block.size(), sim.rows() - k));
      sim.compute_rows(k, count, block.data(), run);
      for (std::size_t i = 0; i < count && out.state() == cli::output_sink::outcome::ok; ++i) {
        bar.update(++done);
        if (request.trace) trace(block[i], nullptr);
        if (request.summary) {
          summary.add(block[i]);
          continue;
        }
        cli::write_row(out, block[i], leading);
        out.end_row();
      }
    }
  }
  if (!request.summary) return;
  set_leading_values(leading, plan, j, scene, scene.runs);
  for (std::size_t h = 0; h < summary.heads.size(); ++h)
    write_statistics(out, leading, "h" + std::to_string(h + 1), summary.heads[h]);
  write_statistics(out, leading, "system", summary.system);
}

void run_scenes(cli::output_sink& out, const scene::scene_plan& plan) {
  cli::leading_columns leading = leading_columns_of(plan);
  if (plan.request().summary) {
    leading.write_names(out);
    out.append(statistics_header());
  } else {
    cli::write_header(out, plan.request().scene.heads.size(), leading);
  }
  out.end_row();
  progress bar(plan.total_rows());
  std::uint64_t done = 0;
  for (std::uint64_t j = 0; j < plan.scene_count() && out.state() == cli::output_sink::outcome::ok;
       ++j)
    run_scene(out, plan, j, leading, bar, done);
}

// The scene options: the scene file's, then the command line's (which win over them).
scene::checked<std::vector<scene::option_value>> scene_options(const cli::command_line& line) {
  std::vector<scene::option_value> entries;
  if (line.config) {
    auto file = scene::read_scene_file(*line.config);
    if (!file.ok()) return std::move(file).error();
    entries = std::move(file).value();
  }
  entries.insert(entries.end(), line.options.begin(), line.options.end());
  return entries;
}

// --write-oem, --write-aem (scene/ephemeris_writer.hpp): 0, or exit 1 with the error.
int write_ephemerides(const scene::scene_plan& plan) {
  const scene::scene_request& r = plan.request();
  for (const auto& [path, write] : {std::pair{&r.write_oem_file, &scene::write_oem},
                                    std::pair{&r.write_aem_file, &scene::write_aem}}) {
    if (path->empty()) continue;
    if (const scene::checked<void> written = write(plan.scene(0), *path); !written.ok()) {
      std::fprintf(stderr, "conescan-sim: %s\n", written.error().text().c_str());
      return exit_write_error;
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  cli::command_line_parser parser;
  const scene::checked<cli::command_line> line = parser.parse(argc, argv);
  if (!line.ok()) return refuse(line.error());
  if (line.value().help) return write_text(parser.help(), "the help");
  const auto entries = scene_options(line.value());
  if (!entries.ok()) return refuse(entries.error());
  const scene::checked<scene::scene_plan> plan = scene::build_scene_plan(entries.value());
  if (!plan.ok()) return refuse(plan.error());
  if (line.value().print_config)
    return write_text(scene::scene_file_text(plan.value().request()), "the scene file");
  // --write-oem, --write-aem: the scene's orbit and attitude, each whole or not at all, first.
  if (const int written = write_ephemerides(plan.value()); written != 0) return written;

  cli::output_sink out(STDOUT_FILENO);
  if (plan.value().request().budget)
    run_budget(out, plan.value());
  else
    run_scenes(out, plan.value());
  out.flush();
  return finish(out, "the CSV");
}
