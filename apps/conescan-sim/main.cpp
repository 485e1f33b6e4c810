// conescan-sim: streams the roll/pitch error time series of conical Earth sensors as CSV
// (SPEC §9). A thin shell: parse, validate every scene, then stream rows (or a summary).
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>

#include "csv_rows.hpp"
#include "options.hpp"
#include "output_sink.hpp"
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
    case outcome::ok: return 0;
    case outcome::closed_reader: return exit_closed_reader;
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

void write_statistics(cli::output_sink& out, const std::string& sweep_name, double sweep_value,
                      const std::string& source, const scene::error_statistics& s) {
  const double deg = 180 / pi<double>();
  const bool any = s.ok_rows() > 0;
  const double nan = not_a_number<double>();
  if (!sweep_name.empty()) {
    out.append_number(sweep_value);
    out.append(',');
  }
  out.append(source);
  out.append(',');
  out.append_number(static_cast<double>(s.rows));
  for (std::uint64_t count : s.status_counts) {
    out.append(',');
    out.append_number(static_cast<double>(count));
  }
  for (double v : {any ? s.roll_min * deg : nan, any ? s.roll_max * deg : nan,
                   s.roll_mean() * deg, s.roll_rms() * deg, any ? s.pitch_min * deg : nan,
                   any ? s.pitch_max * deg : nan, s.pitch_mean() * deg, s.pitch_rms() * deg}) {
    out.append(',');
    out.append_number(v);
  }
  out.append('\n');
  out.end_row();
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
  app.add_flag("--print-config", print_config,
               "print the effective scene as a scene file and exit")
      ->group("Scenes and output");
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "conescan-sim: %s\n(run conescan-sim --help for the options)\n",
                 e.what());
    return exit_bad_usage;
  }
  auto runs = cli::to_scene_runs(app, opts);
  if (auto* err = std::get_if<scene::config_error>(&runs)) {
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

  const auto& scenes = std::get<std::vector<cli::scene_run>>(runs);
  std::vector<scene::simulation> simulations;
  std::uint64_t total_rows = 0;
  for (const cli::scene_run& run : scenes) {
    simulations.emplace_back(run.scene);
    total_rows += simulations.back().rows();
  }
  const std::string sweep_name =
      opts.sweep.empty() ? std::string() : opts.sweep.substr(0, opts.sweep.find('='));
  const std::size_t heads = simulations.front().head_count();

  cli::output_sink out(STDOUT_FILENO);
  if (opts.summary) {
    out.append(sweep_name.empty() ? "" : sweep_name + ",");
    out.append(
        "source,rows,ok,miss,engulfed,grazing,fold,invalid,none,roll_min_deg,roll_max_deg,"
        "roll_mean_deg,roll_rms_deg,pitch_min_deg,pitch_max_deg,pitch_mean_deg,pitch_rms_deg\n");
  } else {
    cli::write_header(out, heads, sweep_name);
  }
  out.end_row();

  progress bar(total_rows);
  std::uint64_t done = 0;
  for (std::size_t s = 0; s < simulations.size(); ++s) {
    const scene::simulation& sim = simulations[s];
    scene::row row = sim.make_row();
    scene::run_summary summary(sim.head_count());
    for (std::uint64_t k = 0; k < sim.rows() && out.state() == cli::output_sink::outcome::ok;
         ++k) {
      sim.compute(k, row);
      bar.update(++done);
      if (opts.trace)
        for (std::size_t h = 0; h < row.heads.size(); ++h)
          std::fprintf(stderr, "trace: t_s=%.17g head=%zu iterations=%d status=%s\n", row.t_s,
                       h + 1, row.heads[h].iterations, to_string(row.heads[h].state));
      if (opts.summary) {
        summary.add(row);
        continue;
      }
      cli::write_row(out, row, sweep_name, scenes[s].sweep_value);
      out.end_row();
    }
    if (opts.summary) {
      for (std::size_t h = 0; h < summary.heads.size(); ++h)
        write_statistics(out, sweep_name, scenes[s].sweep_value, "h" + std::to_string(h + 1),
                         summary.heads[h]);
      write_statistics(out, sweep_name, scenes[s].sweep_value, "system", summary.system);
    }
  }
  out.flush();
  return finish(out);
}
