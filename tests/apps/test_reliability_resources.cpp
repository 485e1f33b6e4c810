// Resource exhaustion is a message and a smaller plan, or exit 1, never an abort: --threads
// beyond what the address-space limit leaves room for (the audit's bad_alloc in about half the
// runs of --threads 1024 --runs 3000 --summary under ulimit -v 4000000).
#include <catch2/catch.hpp>
#include <string>

#include "support/cli.hpp"

using conescan_test::run_sim;

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
