// Campaigns over threads, shards and merges: --threads N writes byte for byte what
// --threads 1 writes; --shard K/N takes the single process's runs with their seeds; the shards'
// --summary-state files merge (--merge) into the single process's summary; Chan's merge of the
// running statistics; every bad input of the issue.
#include <sys/wait.h>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "simulation/summary.hpp"
#include "simulation/summary_state.hpp"
#include "support/cli.hpp"

using conescan_test::parse_csv;
using conescan_test::read_file;
using conescan_test::run_sim;
using conescan_test::temp_file;

namespace sc = conescan::scene;

namespace {

const std::string paper_fig2a = CONESCAN_TEST_DATA "/../../data/scenes/paper-fig2a.toml";
const std::string full_budget = CONESCAN_TEST_DATA "/../../data/scenes/full-budget.toml";

// Two heads either side of the orbit on WGS84 with noise: the campaign, shortened.
const std::string noisy_two_heads =
    "--earth wgs84 --model scan --horizon-km 40 --head beta=90,noise=0.01 "
    "--head beta=-90,noise=0.01";

// Scenes of several chunks (2048 rows each) and of every kind: runs, sweeps, budget, noise.
const std::vector<std::string> scenes{
    "--step-s 1",                                                           // 6 190 rows, 4 chunks
    "--config " + paper_fig2a + " --step-s 2",                              // a sweep of 5 scenes
    noisy_two_heads + " --step-s 30 --runs 7",                              // runs with noise
    noisy_two_heads + " --step-s 30 --runs 3 --sweep seed=1:3:1",           // a sweep of seeds
    "--config " + full_budget + " --budget --step-s 2",                     // the budget's sources
    noisy_two_heads + " --step-s 30 --processing horizon-vector --runs 2",  // the condition column
    "--sweep runs=1:4:1 --head noise=0.02 --step-s 5",  // a different count of runs
    // a physics table on WGS84, its build's rows on the threads (a pencil with lag, 600 rows)
    "--model scan --earth wgs84 --radiance-offset-km 40 --processing-horizon-km 40 "
    "--radiance-season 0.2 --head spin-hz=1,tau-ms=1 --step-s 1 --duration-s 599",
};

// The numbers of two summaries: counts equal, statistics within `relative` of each other (of
// the larger magnitude of the line's mean and RMS, the scale the mean is known to).
void check_same_summary(const std::string& expected, const std::string& actual, double relative) {
  const auto a = parse_csv(expected), b = parse_csv(actual);
  REQUIRE(a.header == b.header);
  REQUIRE(a.rows.size() == b.rows.size());
  for (std::size_t r = 0; r < a.rows.size(); ++r) {
    for (std::size_t c = 0; c < a.header.size(); ++c) {
      const std::string& name = a.header[c];
      INFO("line " << r + 1 << ", " << name << ": " << a.rows[r][c] << " against " << b.rows[r][c]);
      if (name.find("_deg") == std::string::npos) {  // counts, names, leading columns
        CHECK(a.rows[r][c] == b.rows[r][c]);
        continue;
      }
      const double x = std::stod(a.rows[r][c]), y = std::stod(b.rows[r][c]);
      if (std::isnan(x)) {
        CHECK(std::isnan(y));
        continue;
      }
      const std::string angle = name.substr(0, name.find('_'));
      const double scale = std::max(std::abs(a.number(r, angle + "_rms_deg")), std::abs(x));
      CHECK(std::abs(x - y) <= relative * scale);
    }
  }
}

std::string without_header(const std::string& csv) {
  return csv.substr(csv.find('\n') + 1);
}

}  // namespace

TEST_CASE("campaign: --threads 1, 2 and 3 write the same bytes", "[campaign][threads]") {
  for (const std::string& scene : scenes) {
    for (const char* output : {"", " --summary"}) {
      const std::string args = scene + output;
      const auto one = run_sim(args + " --threads 1");
      INFO(args << "\n" << one.err);
      REQUIRE(one.exit_status == 0);
      REQUIRE(std::count(one.out.begin(), one.out.end(), '\n') > 2);
      for (const char* threads : {" --threads 2", " --threads 3"}) {
        const auto many = run_sim(args + threads);
        INFO(threads);
        CHECK(many.exit_status == 0);
        CHECK(many.out == one.out);
        CHECK(many.err.empty());
      }
    }
  }
  // --trace's lines on standard error, in row order too.
  const std::string traced = "--model scan --earth wgs84 --step-s 5 --trace";
  const auto one = run_sim(traced + " --threads 1");
  CHECK(one.err.size() > 10000);
  CHECK(run_sim(traced + " --threads 3").err == one.err);
  // The default (every core) as well.
  CHECK(run_sim(scenes[2]).out == run_sim(scenes[2] + " --threads 1").out);
}

TEST_CASE("campaign: a failed write with threads ends at a row boundary with today's statuses",
          "[campaign][threads][output]") {
  const std::string big = "--step-s 0.05 --threads 3";  // 123 781 rows, ~10 MB
  const auto full = run_sim(big + " > /dev/full");
  CHECK(full.exit_status == 1);
  CHECK(full.err.find("No space left on device") != std::string::npos);
  // A file-size limit: the rows kept are those --threads 1 keeps, whole.
  const temp_file one(""), three("");
  const auto limited_one = run_sim("--step-s 0.05 --threads 1 > " + one.path, "ulimit -f 300;");
  const auto limited_three = run_sim(big + " > " + three.path, "ulimit -f 300;");
  CHECK(limited_one.exit_status == 1);
  CHECK(limited_three.exit_status == 1);
  const std::string kept = read_file(three.path);
  CHECK(kept.size() > 100000);
  CHECK(kept.back() == '\n');
  CHECK(kept == read_file(one.path));
  // A reader that closes early: conescan-sim's status 141 (SIGPIPE), nothing on standard error.
  const temp_file err("");
  const std::string script = std::string(CONESCAN_SIM_PATH) +
                             " --orbits 1000 --max-rows 100000000 --threads 3 2>" + err.path +
                             " | head -c 4096 >/dev/null; exit ${PIPESTATUS[0]}";
  const int status = std::system(("bash -c " + conescan_test::shell_word(script)).c_str());
  CHECK(WEXITSTATUS(status) == 141);
  CHECK(read_file(err.path).empty());
}

TEST_CASE("campaign: shards take the single process's runs and merge into its summary",
          "[campaign][shard][merge]") {
  for (const std::string& scene :
       {noisy_two_heads + " --step-s 30 --runs 10",  // runs split inside one scene
        noisy_two_heads + " --step-s 30 --runs 3 --sweep seed=1:4:1",  // 4 sweep values x 3 runs
        std::string("--config ") + paper_fig2a + " --step-s 20",       // 5 sweep values, one run
        std::string("--sweep runs=1:4:1 --head noise=0.02 --step-s 50")}) {  // 10 runs in all
    INFO(scene);
    const auto single = run_sim(scene + " --summary");
    REQUIRE(single.exit_status == 0);
    // The shards' CSVs, concatenated without their headers, are the single process's.
    std::string rows;
    std::vector<std::unique_ptr<temp_file>> states;
    std::string merge_args;
    for (int k = 1; k <= 4; ++k) {
      states.push_back(std::make_unique<temp_file>("", ".state"));
      const std::string shard = " --shard " + std::to_string(k) + "/4";
      const auto part = run_sim(scene + shard + " --summary-state " + states.back()->path);
      REQUIRE(part.exit_status == 0);
      rows += without_header(part.out);
      merge_args += " " + states.back()->path;
    }
    CHECK(rows == without_header(run_sim(scene).out));
    // Merged in any order of the files: the single summary, counts equal, statistics to 1e-12.
    const auto merged = run_sim("--merge" + merge_args);
    INFO(merged.err);
    REQUIRE(merged.exit_status == 0);
    CHECK(merged.err.empty());
    check_same_summary(single.out, merged.out, 1e-12);
    const auto reversed = run_sim("--merge " + states[3]->path + " " + states[1]->path + " " +
                                  states[2]->path + " " + states[0]->path);
    CHECK(reversed.out == merged.out);
    // One process's own state merges to its own summary, byte for byte.
    const temp_file whole("", ".state");
    REQUIRE(run_sim(scene + " --summary --summary-state " + whole.path).out == single.out);
    CHECK(run_sim("--merge " + whole.path).out == single.out);
  }
}

TEST_CASE("campaign: Chan's merge of running statistics equals adding the values one by one",
          "[campaign][merge][statistics]") {
  // A bias of 1e3 with a spread of 1e-3 (a misalignment plus noise): the naive sum of squares
  // would lose every digit of the variance; Welford and Chan keep them.
  std::mt19937_64 rng(17);
  std::normal_distribution<double> noise(1e3, 1e-3);
  std::vector<double> values(10007);
  for (double& v : values) v = noise(rng);
  sc::running_statistics sequential;
  for (const double v : values) sequential.add(v);
  for (const std::size_t parts : {2u, 3u, 7u, 100u}) {
    sc::running_statistics merged, empty;
    merged.merge(empty);  // an empty part changes nothing
    std::uniform_int_distribution<std::size_t> cut(0, values.size());
    std::vector<std::size_t> cuts{0, values.size()};
    for (std::size_t k = 1; k < parts; ++k) cuts.push_back(cut(rng));
    std::sort(cuts.begin(), cuts.end());
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
      sc::running_statistics part;
      for (std::size_t i = cuts[k]; i < cuts[k + 1]; ++i) part.add(values[i]);
      merged.merge(part);
    }
    merged.merge(empty);
    INFO(parts << " parts");
    CHECK(merged.count == sequential.count);
    CHECK(merged.min == sequential.min);
    CHECK(merged.max == sequential.max);
    // Both are within a few ulps of the true mean, not of each other's.
    CHECK(std::abs(merged.mean - sequential.mean) <= 1e-13 * std::abs(sequential.mean));
    CHECK(std::abs(merged.std() - sequential.std()) <= 1e-9 * sequential.std());
    CHECK(std::abs(sequential.std() - 1e-3) < 1e-4);  // the spread itself, to 10 %
  }
}

TEST_CASE("campaign: bad --threads, --shard and --summary-state are refused",
          "[campaign][hostile]") {
  const std::string runs = " --head noise=0.01 --runs 3 --duration-s 100";
  for (const std::string args :
       {"--threads 0", "--threads 1025", "--threads 99999999999999", "--threads two",
        "--threads -2", "--shard 0/4", "--shard 5/4", "--shard 1/0", "--shard 0/0", "--shard a/4",
        "--shard 1/b", "--shard 1", "--shard 1/4/2", "--shard ' 1/4'", "--shard 01/4",
        "--shard 4/4", "--summary-state ''", "--summary-state 'a\"b'"}) {
    const auto r = run_sim(args + runs);
    const std::string option = args.substr(0, args.find(' '));
    INFO(args << ": " << r.err);
    CHECK(r.exit_status == 2);
    CHECK(r.out.empty());
    CHECK(r.err.rfind("conescan-sim: " + option + ": ", 0) == 0);
  }
  // 3 runs share among at most 3 shards; the message says so.
  CHECK(run_sim("--shard 4/4" + runs).err.find("N must be at most 3") != std::string::npos);
  CHECK(run_sim("--shard 3/3" + runs).exit_status == 0);
  // The budget runs once: one shard of it.
  CHECK(run_sim("--config " + full_budget + " --budget --shard 1/2").exit_status == 2);
  // A state file that cannot be written: status 1, the CSV still whole.
  const auto unwritable = run_sim("--summary-state /nonexistent/dir/state" + runs);
  CHECK(unwritable.exit_status == 1);
  CHECK(unwritable.err.find("--summary-state: cannot write '/nonexistent/dir/state'") !=
        std::string::npos);
}

TEST_CASE("campaign: --merge refuses what is not every shard of one campaign, naming the file",
          "[campaign][merge][hostile]") {
  const std::string scene = noisy_two_heads + " --runs 4 --step-s 600";
  std::vector<std::unique_ptr<temp_file>> shards;
  for (int k = 1; k <= 2; ++k) {
    shards.push_back(std::make_unique<temp_file>("", ".state"));
    REQUIRE(run_sim(scene + " --shard " + std::to_string(k) + "/2 --summary-state " +
                    shards.back()->path)
                .exit_status == 0);
  }
  const std::string& one = shards[0]->path;
  const std::string& two = shards[1]->path;
  const std::string good = read_file(one);
  REQUIRE(run_sim("--merge " + one + " " + two).exit_status == 0);

  // Another scene's shard; a shard of another split; another conescan's (valid hash).
  const temp_file other_scene("", ".state"), other_split("", ".state");
  REQUIRE(run_sim(noisy_two_heads + " --runs 4 --step-s 700 --shard 2/2 --summary-state " +
                  other_scene.path)
              .exit_status == 0);
  REQUIRE(run_sim(scene + " --shard 2/4 --summary-state " + other_split.path).exit_status == 0);
  sc::summary_state older = sc::read_summary_state(read_file(two)).value();
  older.version = "0.0.9";
  const temp_file other_version(sc::summary_state_text(older), ".state");

  std::string flipped = good;
  flipped[flipped.find("stats ") + 7] ^= 1;  // a digit of a count
  const temp_file truncated(good.substr(0, good.size() / 2), ".state");
  const temp_file corrupt(flipped, ".state");
  const temp_file foreign(run_sim(scene).out, ".state");
  const temp_file empty("", ".state");
  const struct {
    std::string files, named, why;
  } cases[] = {
      {"/nonexistent.state " + two, "/nonexistent.state", "No such file"},
      {one + " " + truncated.path, truncated.path, "truncated"},
      {corrupt.path + " " + two, corrupt.path, "corrupt"},
      {foreign.path + " " + two, foreign.path, "not a conescan summary state"},
      {empty.path + " " + two, empty.path, "not a conescan summary state"},
      {one + " " + other_scene.path, other_scene.path, "another scene"},
      {one + " " + other_version.path, other_version.path, "conescan 0.0.9"},
      {one + " " + other_split.path, other_split.path, "a shard of 4"},
      {one + " " + one, one, "again"},
      {one, "shard 2/2", "missing"},
  };
  for (const auto& c : cases) {
    const auto r = run_sim("--merge " + c.files);
    INFO("--merge " << c.files << ": " << r.err);
    CHECK(r.exit_status == 2);
    CHECK(r.out.empty());
    CHECK(r.err.rfind("conescan-sim: --merge: ", 0) == 0);
    CHECK(r.err.find(c.named) != std::string::npos);
    CHECK(r.err.find(c.why) != std::string::npos);
  }
  // --merge takes files only, at least one.
  CHECK(run_sim("--merge").exit_status == 2);
  CHECK(run_sim("--merge " + one + " " + two + " --e 0.01").exit_status == 2);
}

TEST_CASE("campaign: a progress line on a terminal only, never in the CSV",
          "[campaign][progress]") {
  // script(1) gives conescan-sim a terminal for standard error; the campaign lasts over the
  // line's first second (2 million rows on one thread: 2.7 s on an idle machine).
  const temp_file csv("", ".csv");
  const std::string command = std::string(CONESCAN_SIM_PATH) + " --config " +
                              CONESCAN_TEST_DATA "/../../data/scenes/monte-carlo.toml" +
                              " --runs 24 --threads 1 > " + csv.path;
  const auto terminal =
      run_sim("", "script -qec " + conescan_test::shell_word(command) + " /dev/null; true ||");
  INFO(terminal.out);
  CHECK(terminal.out.find(" rows/s, ") != std::string::npos);
  CHECK(terminal.out.find(" left") != std::string::npos);
  const std::string summary = read_file(csv.path);
  CHECK(summary.find('\r') == std::string::npos);
  CHECK(summary.find("rows/s") == std::string::npos);
  // Standard error a file: nothing.
  const auto file = run_sim("--config " CONESCAN_TEST_DATA
                            "/../../data/scenes/monte-carlo.toml --runs 24 --threads 2");
  CHECK(file.exit_status == 0);
  CHECK(file.err.empty());
  CHECK(file.out == summary);
}
