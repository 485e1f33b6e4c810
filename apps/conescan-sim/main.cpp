// conescan-sim: streams the roll/pitch error time series of conical Earth sensors as CSV
// (SPEC §9). A thin shell: parse, validate, build the scene, stream rows.
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>

#include "csv_rows.hpp"
#include "options.hpp"
#include "output_sink.hpp"
#include "scene/simulation.hpp"

namespace {

constexpr int exit_bad_usage = 2;
constexpr int exit_write_error = 1;
// What a shell reports for a process ended by SIGPIPE; used when SIGPIPE is ignored and the
// closed reader shows up as EPIPE instead.
constexpr int exit_closed_reader = 141;

int finish(const conescan::cli::output_sink& out) {
  using outcome = conescan::cli::output_sink::outcome;
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

}  // namespace

int main(int argc, char** argv) {
  using namespace conescan;
  CLI::App app{
      "conescan-sim: attitude errors of conical scanning Earth horizon sensors with a "
      "misaligned optical axis, as CSV on standard output (angles in degrees, distances in km, "
      "time in s). With no options: the paper's scene (Ricci & Carrara, INPE).",
      "conescan-sim"};
  cli::options opts;
  cli::declare_options(app, opts);
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "conescan-sim: %s\n(run conescan-sim --help for the options)\n",
                 e.what());
    return exit_bad_usage;
  }
  auto scene = cli::to_scene(app, opts);
  if (auto* err = std::get_if<scene::config_error>(&scene)) {
    std::fprintf(stderr, "conescan-sim: --%s: %s\n", err->option.c_str(), err->message.c_str());
    return exit_bad_usage;
  }
  const scene::simulation sim(std::get<scene::scene_config>(scene));

  cli::output_sink out(STDOUT_FILENO);
  cli::write_header(out, sim.head_count(), "");
  scene::row row = sim.make_row();
  for (std::uint64_t k = 0; k < sim.rows() && out.state() == cli::output_sink::outcome::ok; ++k) {
    sim.compute(k, row);
    cli::write_row(out, row, "", 0);
    out.end_row();
    if (opts.trace)
      for (std::size_t h = 0; h < row.heads.size(); ++h)
        std::fprintf(stderr, "trace: t_s=%.17g head=%zu iterations=%d status=%s\n", row.t_s,
                     h + 1, row.heads[h].iterations, to_string(row.heads[h].state));
  }
  out.flush();
  return finish(out);
}
