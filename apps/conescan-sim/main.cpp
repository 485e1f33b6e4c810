// conescan-sim: streams the roll/pitch error time series of conical Earth sensors as CSV
// (SPEC §9). A thin shell: parse, validate every scene, then stream rows (or a summary).
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "csv_rows.hpp"
#include "options.hpp"
#include "output_sink.hpp"
#include "scene/budget.hpp"
#include "scene/simulation.hpp"
#include "scene/summary.hpp"
#include "scene_file.hpp"

namespace {

using namespace conescan;

constexpr int exit_bad_usage = 2;
constexpr int exit_write_error = 1;
// What a shell reports for a process ended by SIGPIPE; used when SIGPIPE is ignored and the
// closed reader shows up as EPIPE instead.
constexpr int exit_closed_reader = 141;

int finish(const cli::output_sink& out) {
  using outcome = cli::output_sink::outcome;
  switch (out.state()) {
    case outcome::ok:
      return 0;
    case outcome::closed_reader:
      return exit_closed_reader;
    case outcome::write_error:
      std::fprintf(stderr, "conescan-sim: error writing the CSV to standard output: %s\n",
                   std::strerror(out.error_number()));
      return exit_write_error;
  }
  return exit_write_error;
}

// True when `option` (long name without dashes) was typed on the command line.
bool on_command_line(int argc, char** argv, const std::string& option) {
  const std::string flag = "--" + option;
  for (int i = 1; i < argc; ++i)
    if (argv[i] == flag || std::strncmp(argv[i], (flag + "=").c_str(), flag.size() + 1) == 0)
      return true;
  return false;
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
  out.append_number(static_cast<double>(s.rows));
  for (std::uint64_t count : s.status_counts) {
    out.append(',');
    out.append_number(static_cast<double>(count));
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

// --budget: every source's scene in lock step, one row per time step (or one summary line per
// source), plus the sum of the single sources to judge linearity.
void run_budget(cli::output_sink& out, const scene::scene_config& scene, bool summary_only,
                progress& bar) {
  const std::vector<scene::budget_source> sources = scene::budget_sources(scene);
  std::vector<scene::simulation> sims;
  std::vector<scene::row> rows;
  for (const scene::budget_source& s : sources) {
    sims.emplace_back(s.scene);
    rows.push_back(sims.back().make_row());
  }
  std::vector<scene::error_statistics> stats(sources.size() + 1);  // + the sum of singles
  const cli::leading_columns none;
  if (summary_only) {
    out.append(statistics_header());
  } else {
    out.append("t_s,nu_deg");
    for (const scene::budget_source& s : sources) {
      out.append("," + s.name + "_roll_err_deg," + s.name + "_pitch_err_deg," + s.name + "_status");
    }
    out.append(",sum_roll_err_deg,sum_pitch_err_deg,sum_status\n");
  }
  out.end_row();
  const std::uint64_t n = sims.front().rows();
  for (std::uint64_t k = 0; k < n && out.state() == cli::output_sink::outcome::ok; ++k) {
    bar.update(k + 1);
    double roll_sum = 0, pitch_sum = 0;
    status sum_state = status::ok;
    for (std::size_t i = 0; i < sims.size(); ++i) {
      sims[i].compute(k, rows[i]);
      stats[i].add(rows[i].roll_err_rad, rows[i].pitch_err_rad, rows[i].state);
      if (sources[i].name == "all") continue;
      roll_sum += rows[i].roll_err_rad;
      pitch_sum += rows[i].pitch_err_rad;
      if (rows[i].state != status::ok) sum_state = status::none;
    }
    stats.back().add(roll_sum, pitch_sum, sum_state);
    if (summary_only) continue;
    out.append_number(rows[0].t_s);
    out.append(',');
    out.append_number(rad_to_deg(wrap_two_pi(rows[0].true_anomaly_rad)));
    auto pair = [&](double roll, double pitch, status state) {
      out.append(',');
      out.append_number(cli::degrees_pm180(roll));
      out.append(',');
      out.append_number(cli::degrees_pm180(pitch));
      out.append(',');
      out.append(to_string(state));
    };
    for (const scene::row& r : rows) pair(r.roll_err_rad, r.pitch_err_rad, r.state);
    pair(roll_sum, pitch_sum, sum_state);
    out.append('\n');
    out.end_row();
  }
  if (!summary_only) return;
  for (std::size_t i = 0; i < sources.size(); ++i)
    write_statistics(out, none, sources[i].name, stats[i]);
  write_statistics(out, none, "sum", stats.back());
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "conescan-sim: attitude errors of conical scanning Earth horizon sensors with a "
      "misaligned optical axis, as CSV on standard output (angles in degrees, distances in km, "
      "time in s). With no options: the paper's scene (Ricci & Carrara, INPE).",
      "conescan-sim"};
  cli::options opts;
  cli::declare_options(app, opts);
  bool print_config = false;
  app.add_flag("--print-config", print_config, "print the effective scene as a scene file and exit")
      ->group("Scenes and output");
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "conescan-sim: %s\n(run conescan-sim --help for the options)\n", e.what());
    return exit_bad_usage;
  }
  auto parsed = cli::to_scene_runs(app, opts);
  if (auto* err = std::get_if<scene::config_error>(&parsed)) {
    // Name the scene file's line when the value came from it.
    const auto& file = static_cast<const cli::scene_file_format&>(*app.get_config_formatter());
    std::string where;
    if (!on_command_line(argc, argv, err->option))
      where = file.where(err->head ? "head#" + std::to_string(err->head) : err->option);
    std::fprintf(stderr, "conescan-sim: %s%s--%s: %s\n", where.c_str(), where.empty() ? "" : ": ",
                 err->option.c_str(), err->message.c_str());
    return exit_bad_usage;
  }
  if (print_config) {
    std::fputs(app.config_to_str(true, false).c_str(), stdout);
    return 0;
  }

  const auto& scenes = std::get<std::vector<cli::scene_run>>(parsed);
  cli::output_sink out(STDOUT_FILENO);
  if (opts.budget) {
    if (scenes.size() != 1 || scenes.front().scene.runs != 1) {
      std::fprintf(stderr,
                   "conescan-sim: --budget: runs one scene once: drop --sweep and --runs\n");
      return exit_bad_usage;
    }
    progress bar(scene::row_count(scenes.front().scene));
    run_budget(out, scenes.front().scene, opts.summary, bar);
    out.flush();
    return finish(out);
  }

  std::vector<scene::simulation> simulations;
  std::uint64_t total_rows = 0;
  for (const cli::scene_run& run : scenes) {
    simulations.emplace_back(run.scene);
    total_rows += simulations.back().rows() * run.scene.runs;
  }
  const scene::scene_config& first = scenes.front().scene;
  // Leading columns: the swept option, the run (with --runs > 1), the seed (with noise).
  cli::leading_columns leading;
  const bool sweep = !opts.sweep.empty(), runs = first.runs > 1, noisy = scene::has_noise(first);
  if (sweep) leading.names.push_back(opts.sweep.substr(0, opts.sweep.find('=')));
  if (runs) leading.names.push_back("run");
  if (noisy) leading.names.push_back("seed");
  leading.values.resize(leading.names.size());
  leading.condition = first.processing == scene::processing_method::horizon_vector;

  if (opts.summary) {
    leading.write_names(out);
    out.append(statistics_header());
  } else {
    cli::write_header(out, simulations.front().head_count(), leading);
  }
  out.end_row();

  progress bar(total_rows);
  std::uint64_t done = 0;
  for (std::size_t s = 0; s < simulations.size(); ++s) {
    const scene::simulation& sim = simulations[s];
    // Rows are computed a block at a time (compute_rows: faster per row), written one by one.
    std::vector<scene::row> block(scene::simulation::rows_per_block, sim.make_row());
    // One summary over all runs of a scene: the statistics of the noise, not of one draw.
    scene::run_summary summary(sim.head_count());
    for (std::uint64_t run = 0; run < scenes[s].scene.runs; ++run) {
      std::size_t column = 0;
      if (sweep) leading.values[column++] = scenes[s].sweep_value;
      if (runs) leading.values[column++] = static_cast<double>(run + 1);
      if (noisy) leading.values[column++] = static_cast<double>(scenes[s].scene.seed);
      for (std::uint64_t k = 0; k < sim.rows() && out.state() == cli::output_sink::outcome::ok;
           k += block.size()) {
        const auto count =
            static_cast<std::size_t>(std::min<std::uint64_t>(block.size(), sim.rows() - k));
        sim.compute_rows(k, count, block.data(), run);
        for (std::size_t i = 0; i < count && out.state() == cli::output_sink::outcome::ok; ++i) {
          const scene::row& row = block[i];
          bar.update(++done);
          if (opts.trace)
            for (std::size_t h = 0; h < row.heads.size(); ++h)
              std::fprintf(stderr, "trace: t_s=%.17g head=%zu iterations=%d status=%s\n", row.t_s,
                           h + 1, row.heads[h].iterations, to_string(row.heads[h].state));
          if (opts.summary) {
            summary.add(row);
            continue;
          }
          cli::write_row(out, row, leading);
          out.end_row();
        }
      }
    }
    if (opts.summary) {
      cli::leading_columns per_scene;
      if (sweep) per_scene.values.push_back(scenes[s].sweep_value);
      if (runs) per_scene.values.push_back(static_cast<double>(scenes[s].scene.runs));
      if (noisy) per_scene.values.push_back(static_cast<double>(scenes[s].scene.seed));
      for (std::size_t h = 0; h < summary.heads.size(); ++h)
        write_statistics(out, per_scene, "h" + std::to_string(h + 1), summary.heads[h]);
      write_statistics(out, per_scene, "system", summary.system);
    }
  }
  out.flush();
  return finish(out);
}
