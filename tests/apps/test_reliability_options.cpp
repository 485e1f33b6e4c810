// Options a program does not honour are not offered by it: the option table's honoured_by
// (scene_program) against each program's --help and command line, scene files shared between
// programs, and conescan-fit's own options as one table of checks (fit_request.hpp) that the
// command line and the Python module both read.
#include <catch2/catch.hpp>
#include <set>
#include <string>
#include <vector>

#include "scene/option_table.hpp"
#include "scene_calibration/fit_request.hpp"
#include "support/cli.hpp"

using conescan_test::run_program;
using conescan_test::run_sim;
using conescan_test::temp_file;
namespace sc = conescan::scene;
namespace cal = conescan::calibration;

namespace {

std::set<std::string> offered(const std::string& program) {
  const auto help = run_program(program, "--help");
  REQUIRE(help.exit_status == 0);
  std::set<std::string> names;
  // A line "  --name ..." (std::regex is avoided: GCC 12's libstdc++ regex trips
  // -Wmaybe-uninitialized under the sanitizer build's -O1).
  std::istringstream lines(help.out);
  std::string line;
  while (std::getline(lines, line)) {
    const std::size_t start = line.find_first_not_of(" \t");
    if (start == 0 || start == std::string::npos || line.compare(start, 2, "--") != 0) continue;
    const std::size_t name_start = start + 2;
    const std::size_t name_end =
        line.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789-", name_start);
    if (name_end != name_start) names.insert(line.substr(name_start, name_end - name_start));
  }
  return names;
}

// A value the option accepts in the default scene (refused or not, it must reach the rule).
std::string value_for(const sc::option_spec& o) {
  switch (o.kind) {
    case sc::value_kind::flag:
      return "";
    case sc::value_kind::head:
      return " sigma=0.01";
    case sc::value_kind::choice:
      return " " + std::string(std::get<sc::choice_binding>(o.binding).words[0]);
    default:
      break;
  }
  if (o.name == "sweep") return " e=0:0.1:0.05";
  if (o.name == "shard") return " 1/1";
  if (o.name == "processing-radius") return " local";
  return " 2";
}

cal::fit_request request_of(std::vector<sc::option_value> entries,
                            cal::telemetry_input input = cal::telemetry_input::file_option) {
  const auto r = cal::read_fit_request(entries, input);
  INFO((r.ok() ? "" : r.error().text()));
  REQUIRE(r.ok());
  return r.value();
}

std::string refusal_of(std::vector<sc::option_value> entries,
                       cal::telemetry_input input = cal::telemetry_input::file_option) {
  const auto r = cal::read_fit_request(entries, input);
  REQUIRE_FALSE(r.ok());
  return r.error().text();
}

sc::option_value typed(const std::string& name, const std::string& text) {
  return {name, text, conescan::origin::command_line()};
}

}  // namespace

TEST_CASE("options: each program offers exactly the options it honours",
          "[reliability][options][property]") {
  const std::set<std::string> sim = offered(CONESCAN_SIM_PATH), fit = offered(CONESCAN_FIT_PATH);
  for (const sc::option_spec& o : sc::option_table()) {
    const std::string name(o.name);
    INFO("--" << name);
    CHECK(sim.count(name) == 1);  // conescan-sim honours every scene option
    CHECK(fit.count(name) == (sc::honours(sc::scene_program::fit, o) ? 1u : 0u));
    if (sc::honours(sc::scene_program::fit, o)) continue;
    // Not offered, and refused by name, saying whose it is.
    CHECK_FALSE(o.not_honoured.empty());
    const auto run = run_program(
        CONESCAN_FIT_PATH, "--" + name + value_for(o) + " --model scan --free h1.sigma --predict");
    CHECK(run.exit_status == 2);
    CHECK(run.out.empty());
    CHECK(run.err.find("--" + name + ": not an option of conescan-fit: ") != std::string::npos);
  }
  // What a fit does not do, by name (the audit's list and the single-scene options).
  for (const char* name : {"write-oem", "write-aem", "summary-state", "shard", "trace", "sweep",
                           "budget", "summary", "runs", "apply"})
    CHECK(fit.count(name) == 0);
  // --threads is conescan-fit's too: the worker threads of its passes (the third audit).
  CHECK(fit.count("threads") == 1);
  // Python's functions: the campaign's, the trace and the files are conescan-sim's.
  for (const char* name : {"write-oem", "write-aem", "summary-state", "shard", "threads", "trace"})
    for (const auto program : {sc::scene_program::python_rows, sc::scene_program::python_summary})
      CHECK_FALSE(sc::honours(program, *sc::find_option(name)));
  CHECK_FALSE(sc::honours(sc::scene_program::python_rows, *sc::find_option("summary")));
  // conescan-sim's own modes are not conescan-fit's either; the fit options are not the sim's.
  for (const std::string own : {"print-config", "merge"}) {
    CHECK(sim.count(own) == 1);
    CHECK(fit.count(own) == 0);
  }
  for (const cal::fit_option_spec& f : cal::fit_option_table()) {
    CHECK(fit.count(std::string(f.name)) == 1);
    CHECK(sim.count(std::string(f.name)) == 0);
  }
}

TEST_CASE("options: conescan-fit's help says what an option means to a fit",
          "[reliability][options][fit]") {
  // The shared help spoke of sweeps and summaries, and named every physics key's default.
  const std::string help = run_program(CONESCAN_FIT_PATH, "--help").out;
  for (const sc::option_spec& o : sc::option_table()) {
    if (o.fit_help.empty()) continue;
    INFO("--" << o.name);
    CHECK(help.find(std::string(o.fit_help)) != std::string::npos);
    CHECK(run_sim("--help").out.find(std::string(o.fit_help)) == std::string::npos);
  }
  for (const char* said_nowhere : {"with --summary", "sweep values", "fov-shape=square"})
    CHECK(help.find(said_nowhere) == std::string::npos);
}

TEST_CASE("options: a scene file serves every program: its inert lines are read, the rest refused",
          "[reliability][options]") {
  // conescan-sim's --print-config writes runs = 1, seed = 1, trace = false, summary = false...:
  // asking for nothing, they are read by conescan-fit.
  const auto printed = run_sim("--model scan --head noise=0.01 --print-config");
  REQUIRE(printed.exit_status == 0);
  const temp_file scene(printed.out);
  CHECK(run_program(CONESCAN_FIT_PATH, "--config " + scene.path + " --free h1.sigma --predict")
            .exit_status == 0);
  // A line that asks for what conescan-fit does not do: refused at its line.
  const temp_file runs(printed.out + "runs = 3\n");
  std::string asking = printed.out;
  const std::size_t runs_line = asking.find("runs = 1");
  REQUIRE(runs_line != std::string::npos);
  asking.replace(runs_line, 8, "runs = 3");
  const temp_file asks(asking);
  const auto refused =
      run_program(CONESCAN_FIT_PATH, "--config " + asks.path + " --free h1.sigma --predict");
  CHECK(refused.exit_status == 2);
  CHECK(refused.err.find(asks.path + ":") != std::string::npos);
  CHECK(refused.err.find("--runs: not an option of conescan-fit") != std::string::npos);
  // conescan-sim reads it.
  CHECK(run_sim("--config " + asks.path + " --duration-s 0").exit_status == 0);
}

TEST_CASE("options: conescan-fit's own options, one table of checks",
          "[reliability][options][fit]") {
  const auto free = typed("free", "h1.sigma");
  const auto tm = typed("telemetry", "tm.csv");
  CHECK(request_of({free, tm}).telemetry == std::optional<std::string>("tm.csv"));
  CHECK(request_of({free, tm}).max_iterations == cal::fit_options{}.max_iterations);
  CHECK(request_of({free, tm, typed("max-iterations", "1")}).max_iterations == 1);
  CHECK(request_of({free, tm, typed("max-iterations", "10000")}).max_iterations == 10000);
  CHECK(request_of({free, tm, typed("loss", "none")}).loss == cal::robust_loss::none);
  CHECK(request_of({free, typed("predict", "true")}).predict);
  CHECK(request_of({free, tm, typed("json", "true")}).json);
  CHECK(request_of({free}, cal::telemetry_input::in_memory).telemetry == std::nullopt);
  // Scene options among the entries are not the table's: skipped here.
  CHECK(request_of({typed("e", "0.5"), free, tm}).free == "h1.sigma");
  // Both sides of each boundary, and every refusal naming its option.
  for (const std::string bad :
       {"0", "10001", "1.5", "true", "-1", "1e3", "", "1000000000000000000000000000000"})
    CHECK(refusal_of({free, tm, typed("max-iterations", bad)}) ==
          "--max-iterations: " + conescan::quote(bad) + " is not a count in [1, 10000]");
  CHECK(refusal_of({free, tm, typed("loss", "cauchy")}) ==
        "--loss: 'cauchy' is not one of: huber, none");
  CHECK(refusal_of({free, free, tm}) == "--free: given twice: list every parameter in one");
  CHECK(refusal_of({free, tm, tm}) == "--telemetry: given twice");
  CHECK(refusal_of({tm}) ==
        "--free: missing: name the parameters to estimate (conescan-fit --help)");
  CHECK(refusal_of({free}) == "--telemetry: missing: give the telemetry CSV to fit (or --predict)");
  CHECK(refusal_of({free, tm, typed("predict", "true")}) ==
        "--telemetry: --predict plans a scene without data: drop --telemetry");
  CHECK(refusal_of({free, tm}, cal::telemetry_input::in_memory) ==
        "--telemetry: given twice: as arrays and as a file");
  CHECK(refusal_of({free, tm, typed("json", "maybe")}).rfind("--json: ", 0) == 0);
  // The plan: the scene's checks first, then the fit's, then the free list against the heads.
  const std::vector<sc::option_value> scene{typed("model", "scan")};
  auto plan_error = [&](std::vector<sc::option_value> extra) {
    std::vector<sc::option_value> entries = scene;
    entries.insert(entries.end(), extra.begin(), extra.end());
    const auto plan = cal::build_fit_plan(entries);
    return plan.ok() ? std::string() : plan.error().text();
  };
  CHECK(plan_error({typed("e", "2"), typed("loss", "x")}).rfind("--e: ", 0) == 0);
  CHECK(plan_error({free, tm, typed("loss", "x")}).rfind("--loss: ", 0) == 0);
  CHECK(plan_error({typed("free", "h2.sigma"), tm}).rfind("--free: ", 0) == 0);
  CHECK(plan_error({typed("runs", "2"), free, tm}) ==
        "--runs: not an option of conescan-fit: repeats the scene with new noise; a fit is of "
        "one telemetry");
  CHECK(plan_error({free, tm}).empty());
}

TEST_CASE("options: single_scene_problem is a checked<void>", "[reliability][options][fit]") {
  sc::scene_request r;
  CHECK(cal::single_scene_problem(r).ok());
  r.scene.runs = 2;
  CHECK(cal::single_scene_problem(r).error().text() == "--runs: conescan-fit fits one telemetry");
  r.scene.runs = 1;
  r.budget = true;
  CHECK(cal::single_scene_problem(r).error().option == "budget");
}
