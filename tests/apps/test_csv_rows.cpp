// conescan-sim's summary lines and budget rows written from the scene layer's column home
// (csv_rows.hpp: leading_columns::of, write_summary_header, write_summary_line,
// write_budget_csv_header, write_budget_csv_row; scene::budget_run) are byte for byte what
// conescan-sim prints, for plans with each kind of leading column.
#include <catch2/catch.hpp>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "cli/csv_rows.hpp"
#include "cli/output_sink.hpp"
#include "scene/scene_file.hpp"
#include "scene/scene_plan.hpp"
#include "simulation/budget_run.hpp"
#include "support/cli.hpp"

using namespace conescan;

namespace {

// What `write` writes into an output sink.
template <class Write>
std::string written(Write&& write) {
  std::FILE* file = std::tmpfile();
  REQUIRE(file != nullptr);
  {
    cli::output_sink out(fileno(file));
    write(out);
    out.flush();
  }
  std::rewind(file);
  std::string text;
  char buffer[4096];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, file)) > 0;) text.append(buffer, n);
  std::fclose(file);
  return text;
}

scene::scene_plan plan_of(const std::vector<scene::option_value>& entries) {
  conescan::checked<scene::scene_plan> plan = scene::build_scene_plan(entries);
  REQUIRE(plan.ok());
  return std::move(plan).value();
}

// The summary of `entries` as csv_rows writes it.
std::string summary_text(const std::vector<scene::option_value>& entries) {
  const scene::scene_plan plan = plan_of(entries);
  return written([&](cli::output_sink& out) {
    cli::leading_columns leading = cli::leading_columns::of(plan);
    cli::write_summary_header(out, leading);
    for (std::uint64_t j = 0; j < plan.scene_count(); ++j) {
      const scene::loaded_scene scene = plan.scene(j);
      const scene::simulation sim = scene::simulation::of(scene).value();
      scene::chunked_summary<scene::run_summary> chunked(scene::run_summary(sim.head_count()));
      scene::row row = sim.make_row();
      for (std::uint64_t run = 0; run < scene.config.runs; ++run) {
        for (std::uint64_t k = 0; k < sim.rows(); ++k) {
          sim.compute(k, row, run);
          chunked.add(row);
        }
        chunked.end_run();
      }
      const scene::run_summary& summary = chunked.total();
      leading.set(plan, j, scene.config, scene.config.runs);
      for (std::size_t h = 0; h < summary.heads.size(); ++h)
        cli::write_summary_line(out, leading, scene::summary_source_name(h), summary.heads[h]);
      cli::write_summary_line(out, leading, scene::summary_system_name, summary.system);
    }
  });
}

std::string fig2a_path() {
  return std::string(CONESCAN_TEST_DATA) + "/../../data/scenes/paper-fig2a.toml";
}

std::vector<scene::option_value> file_entries(const std::string& path) {
  auto file = scene::read_scene_file(path);
  REQUIRE(file.ok());
  return std::move(file).value();
}

}  // namespace

TEST_CASE("summary lines from the column home are conescan-sim --summary's", "[csv_rows]") {
  const conescan::origin cli = conescan::origin::command_line();
  const std::string fig2a = fig2a_path();
  struct example {
    std::string args;
    std::vector<scene::option_value> entries;
  };
  const std::vector<example> examples{
      {"", {}},
      {"--config " + fig2a, file_entries(fig2a)},
      {"--head beta=90,noise=0.02 --head beta=-90 --runs 3 --seed 4 --duration-s 1200",
       {{"head", "beta=90,noise=0.02", cli},
        {"head", "beta=-90", cli},
        {"runs", "3", cli},
        {"seed", "4", cli},
        {"duration-s", "1200", cli}}},
      // Runs of more than one summary chunk (scene::summary_chunk_rows): 6001 rows.
      {"--head noise=0.01 --duration-s 30000 --step-s 5",
       {{"head", "noise=0.01", cli}, {"duration-s", "30000", cli}, {"step-s", "5", cli}}},
      {"--sweep h1.alpha=-80:80:80 --model scan --e 0 --orbits 0.1",
       {{"sweep", "h1.alpha=-80:80:80", cli},
        {"model", "scan", cli},
        {"e", "0", cli},
        {"orbits", "0.1", cli}}},
  };
  for (const example& e : examples) {
    INFO(e.args);
    const conescan_test::run_result cli_run = conescan_test::run_sim(e.args + " --summary");
    REQUIRE(cli_run.exit_status == 0);
    CHECK(summary_text(e.entries) == cli_run.out);
  }
}

TEST_CASE("the budget's rows and summary from the column home are conescan-sim --budget's",
          "[csv_rows]") {
  const std::string path = std::string(CONESCAN_TEST_DATA) + "/../../data/scenes/full-budget.toml";
  std::vector<scene::option_value> entries = file_entries(path);
  entries.push_back({"budget", "true", conescan::origin::command_line()});
  const scene::scene_plan plan = plan_of(entries);
  const scene::budget_run run(plan.budget());
  scene::budget_row row = run.make_row();
  scene::chunked_summary<scene::budget_summary> chunked(
      scene::budget_summary(plan.budget().size()));
  const std::string rows = written([&](cli::output_sink& out) {
    cli::write_budget_csv_header(out, plan.budget());
    for (std::uint64_t k = 0; k < run.rows(); ++k) {
      run.compute(k, row);
      chunked.add(row);
      cli::write_budget_csv_row(out, row);
      out.end_row();
    }
  });
  chunked.end_run();
  const scene::budget_summary& summary = chunked.total();
  CHECK(rows == conescan_test::run_sim("--config " + path + " --budget").out);
  const std::string lines = written([&](cli::output_sink& out) {
    const cli::leading_columns none;
    cli::write_summary_header(out, none);
    for (std::size_t i = 0; i < summary.sources.size(); ++i)
      cli::write_summary_line(out, none, plan.budget()[i].name, summary.sources[i]);
    cli::write_summary_line(out, none, scene::budget_sum_name, summary.sum);
    cli::write_summary_line(out, none, scene::budget_interaction_name, summary.interaction);
  });
  CHECK(lines == conescan_test::run_sim("--config " + path + " --budget --summary").out);
  CHECK(rows.size() > 10000);
}
