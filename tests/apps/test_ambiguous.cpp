// MODEL §7's `ambiguous` through the CLI: two perfect heads at gamma 80 deg
// whose chords have both inversion roots within the attitude envelope. Before, one head's
// nearer root was the wrong one and the row said roll_err -6.02 deg with status ok.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "support/cli.hpp"

using conescan_test::csv_table;
using conescan_test::parse_csv;
using conescan_test::run_sim;

namespace {

const std::string two_heads =
    "--head alpha=20,gamma=80,sigma=0 --head alpha=20,beta=-90,gamma=80,sigma=0 --roll-deg 3 "
    "--pitch-deg 2 --model scan --step-s 1 --duration-s 1700";

/// The row at t_s.
std::size_t row_at(const csv_table& t, double t_s) {
  for (std::size_t k = 0; k < t.rows.size(); ++k)
    if (t.number(k, "t_s") == t_s) return k;
  FAIL("no row at t_s = " << t_s);
  return 0;
}

}  // namespace

TEST_CASE("ambiguous: the two heads no longer report a wrong roll as ok", "[cli][ambiguous]") {
  const auto run = run_sim(two_heads);
  REQUIRE(run.exit_status == 0);
  const csv_table t = parse_csv(run.out);
  const std::size_t k = row_at(t, 1611);
  CHECK(t.text(k, "h2_status") == "ambiguous");
  CHECK(t.text(k, "h2_roll_err_deg") == "nan");
  CHECK(t.text(k, "status") == "none");
  // A perfect sensor: wherever the system is ok its error is rounding, on every row.
  int ok_rows = 0, ambiguous_rows = 0;
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    for (const char* head : {"h1_status", "h2_status"})
      if (t.text(r, head) == "ambiguous") ++ambiguous_rows;
    if (t.text(r, "status") != "ok") continue;
    ++ok_rows;
    CHECK(std::abs(t.number(r, "roll_err_deg")) < 1e-9);
    CHECK(std::abs(t.number(r, "pitch_err_deg")) < 1e-9);
  }
  CHECK(ok_rows > 500);
  CHECK(ambiguous_rows > 100);
}

TEST_CASE("ambiguous: the envelope decides, on both sides", "[cli][ambiguous]") {
  // At t = 1611 s head 2's farther root lies between 0 and 10 deg of eta0: with an envelope of
  // 0 the nearer root is taken (the wrong one, 6.02 deg of roll), with 10 it is ambiguous.
  const auto narrow = run_sim(two_heads + " --attitude-envelope-deg 0");
  const auto wide = run_sim(two_heads + " --attitude-envelope-deg 10");
  REQUIRE(narrow.exit_status == 0);
  REQUIRE(wide.exit_status == 0);
  const csv_table n = parse_csv(narrow.out), w = parse_csv(wide.out);
  CHECK(n.text(row_at(n, 1611), "h2_status") == "ok");
  CHECK(n.number(row_at(n, 1611), "h2_roll_err_deg") == Approx(-6.024).margin(1e-3));
  CHECK(w.text(row_at(w, 1611), "h2_status") == "ambiguous");
  CHECK(wide.out == run_sim(two_heads).out);  // 10 deg is the default
}

TEST_CASE("ambiguous: the summary counts it, the option is validated", "[cli][ambiguous]") {
  const auto summary = run_sim(two_heads + " --summary");
  REQUIRE(summary.exit_status == 0);
  const csv_table s = parse_csv(summary.out);
  CHECK(s.number(1, "ambiguous") > 100);  // head 2
  CHECK(s.number(0, "ambiguous") + s.number(0, "ok") + s.number(0, "fold") == 1701);
  for (const char* bad : {"--attitude-envelope-deg -1", "--attitude-envelope-deg 90.5",
                          "--attitude-envelope-deg nan", "--attitude-envelope-deg inf"}) {
    const auto run = run_sim(bad);
    INFO(bad << ": " << run.err);
    CHECK(run.exit_status == 2);
    CHECK(run.out.empty());
    CHECK(run.err.find("attitude-envelope-deg") != std::string::npos);
  }
  const auto help = run_sim("--help");
  CHECK(help.out.find("--attitude-envelope-deg") != std::string::npos);
  CHECK(help.out.find("(default 10)") != std::string::npos);
}
