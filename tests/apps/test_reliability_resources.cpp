// Resource exhaustion is a message and a smaller plan, or exit 1, never an abort: --threads
// beyond what the address-space limit leaves room for (the audit's bad_alloc in about half the
// runs of --threads 1024 --runs 3000 --summary under ulimit -v 4000000).
#include <catch2/catch.hpp>
#include <string>

#include "support/cli.hpp"

using conescan_test::run_program;
using conescan_test::run_sim;
using conescan_test::temp_file;

TEST_CASE("resources: --threads beyond the address space runs a smaller plan, never aborts",
          "[reliability][resources][regression][address-space]") {
  // Tagged [address-space]: the sanitizer preset leaves it out, since AddressSanitizer cannot
  // start under an address-space limit (its shadow memory is reserved at start).
  const std::string campaign = "--runs 3000 --head noise=0.01 --summary --duration-s 600";
  const auto one = run_sim(campaign + " --threads 1");
  REQUIRE(one.exit_status == 0);
  for (int attempt = 0; attempt < 4; ++attempt) {
    const auto run = run_sim(campaign + " --threads 1024", "ulimit -v 4000000;");
    INFO(run.err);
    CHECK(run.exit_status == 0);
    CHECK(run.out == one.out);  // the output is that of one thread, whatever the plan
    CHECK(run.err.rfind("conescan-sim: --threads 1024: the address-space limit (ulimit -v) "
                        "leaves room for ",
                        0) == 0);
    CHECK(std::count(run.err.begin(), run.err.end(), '\n') == 1);
  }
  // A tighter limit: fewer workers still, or one thread; never status 134.
  for (const char* limit : {"ulimit -v 700000;", "ulimit -v 1500000;"}) {
    const auto run = run_sim(campaign + " --threads 1024", limit);
    INFO(limit << " " << run.err);
    CHECK(run.exit_status == 0);
    CHECK(run.out == one.out);
  }
  // More threads than chunks: as many workers as chunks, silently (nothing is lost).
  const auto few = run_sim("--duration-s 600 --threads 64");
  CHECK(few.exit_status == 0);
  CHECK(few.err.empty());
  CHECK(few.out == run_sim("--duration-s 600 --threads 1").out);
}

TEST_CASE("resources: the fit's workers that cannot start leave their parts to the others",
          "[reliability][resources][regression][address-space]") {
  // The fit's --threads defaults to every core: under an address-space limit that leaves no room
  // for a worker's stack the system refuses it, and the fit aborted (status 134, std::system_error
  // from std::thread). Its passes' parts now run on the threads that started (parallel_parts),
  // and a part's result does not depend on its thread: the same fit to the bit.
  const std::string scene = " --model scan --duration-s 3000 --step-s 10";
  const temp_file telemetry(run_sim(scene + " --head sigma=0.05,noise=0.01").out, ".csv");
  const std::string fit =
      "--telemetry " + telemetry.path + scene + " --head sigma=0 --free h1.sigma --threads ";
  const auto one = run_program(CONESCAN_FIT_PATH, fit + "1");
  REQUIRE(one.exit_status == 0);
  for (const char* limit : {"ulimit -v 600000;", "ulimit -v 800000;"}) {
    const auto run = run_program(CONESCAN_FIT_PATH, fit + "64", limit);
    INFO(limit << " " << run.err);
    CHECK(run.exit_status == 0);
    CHECK(run.out == one.out);
  }
}
