// conescan-sim's scene files, sweeps and summaries.

#include <catch2/catch.hpp>
#include <cmath>

#include "support/cli.hpp"

using conescan_test::csv_table;
using conescan_test::parse_csv;
using conescan_test::run_sim;

// A scene file in the working directory, removed at the end of the test.
using scene_file = conescan_test::temp_file;

TEST_CASE("scene file: the same scene as the command line", "[cli][config]") {
  const scene_file file(
      "# a test scene\n"
      "e = 0.05   # eccentricity\n"
      "step-s = 600\n"
      "model = \"scan\"\n"
      "[[head]]\n"
      "alpha = 0\n"
      "beta = 90\n"
      "[[head]]\n"
      "beta = -90\n"
      "phase = 45\n");
  const auto from_file = run_sim("--config " + file.path);
  const auto from_options =
      run_sim("--e 0.05 --step-s 600 --model scan --head alpha=0,beta=90 --head beta=-90,phase=45");
  REQUIRE(from_file.exit_status == 0);
  CHECK(from_file.out == from_options.out);
  // Heads as an array of spec strings, or of inline tables, are the same as [[head]] tables
  // (TOML allows a key once: no repeated head lines).
  const scene_file specs(
      "e = 0.05\nstep-s = 600\nmodel = \"scan\"\nhead = [\"alpha=0,beta=90\",\n"
      "        'beta=-90,phase=45']  # a literal string\n");
  CHECK(run_sim("--config " + specs.path).out == from_options.out);
  const scene_file tables(
      "e = 5e-2\nstep-s = 6_00\nmodel = \"\\u0073can\"\nhead = [\n  {alpha = 0, beta = 90},\n"
      "  {beta = -90, phase = 45},  # trailing comma\n]\n");
  CHECK(run_sim("--config " + tables.path).out == from_options.out);
}

TEST_CASE("scene file: the command line overrides the file", "[cli][config]") {
  const scene_file file("e = 0.05\nstep-s = 600\nhead = \"alpha=10\"\n");
  CHECK(run_sim("--config " + file.path + " --e 0 --head alpha=20").out ==
        run_sim("--e 0 --step-s 600 --head alpha=20").out);
}

TEST_CASE("scene file: --print-config writes a scene file that reads back", "[cli][config]") {
  const auto printed =
      run_sim("--e 0.02 --earth wgs84 --model scan --head alpha=5,phase=30 --print-config");
  REQUIRE(printed.exit_status == 0);
  const scene_file file(printed.out);
  const auto again = run_sim("--config " + file.path + " --step-s 1000");
  REQUIRE(again.exit_status == 0);
  CHECK(again.out ==
        run_sim("--e 0.02 --earth wgs84 --model scan --head alpha=5,phase=30 --step-s 1000").out);
}

TEST_CASE("scene file: errors name the file, the line and what is allowed", "[cli][config]") {
  struct bad {
    const char* body;
    const char* expected;  // in the message after "FILE:"
  };
  const bad cases[] = {
      {"e = 0.1\nfoo = 1\n", ":2:1: unknown key 'foo'; keys: a-km, e,"},
      {"e 0.1\n", ":1:3: Error while parsing key-value pair: expected '=', saw '0'"},
      {"[orbit]\n", ":1:1: unknown table '[orbit]'"},
      {"e = \"x\"\n", ":1:5: --e: 'x' is not a decimal number"},
      {"j2 = yes\n", ":1:6: --j2: Error while parsing value: could not determine value type"},
      {"j2 = \"yes\"\n", ":1:6: --j2: 'yes' is not true or false"},
      {"\n\n[[head]]\nzeta = 1\n", ":4:1: unknown key 'zeta' in a [[head]] table; keys: alpha"},
      {"[[head]]\n[[head]]\nalpha = 1\n", ":1:1: empty [[head]] table"},
      {"head = [{}]\n", ":1:9: empty inline head table"},
      {"e = 0.1\ne = 0.2\n",
       ":2:5: --e: Error while parsing key-value pair: cannot redefine existing floating-point "
       "'e'"},
      {"head = \"beta=90\"\nhead = \"beta=-90\"\n",
       ":2:8: --head: Error while parsing key-value pair: cannot redefine existing string 'head' "
       "(TOML allows a key once: write several heads as head = [\"...\", \"...\"] or [[head]] "
       "tables)"},
      {"# ok\ne = 2\n", ":2:5: --e: e = 2 is outside [0, 1)"},
      {"step-s = 10\n[[head]]\ngamma = 100\n", ":2:1: --head: head 1: gamma = 100 is outside"},
      {"e = 0.1\nheads = 2\n", ":2:1: unknown key 'heads'"},
      {"sweep = \"e=0:1:0.5\"\n", ":1:9: --sweep: at e = 0.5: --e: perigee"},
      {"a-km = [7000, 8000]\n", ":1:8: --a-km: the key takes one value, not an array"},
      {"orbit.a-km = 7000\n", ":1:1: unknown table '[orbit]'"},
      {"[[head]]\nbeta = {x = 1}\n", ":2:8: --head: head key 'beta' takes one value, not a table"},
      {"head = 5\n", ":1:8: --head: a head is a spec string"},
      {"seed = 18446744073709551615\n",
       ":1:28: --seed: Error while parsing decimal integer: '18446744073709551615' is not "
       "representable in 64 bits (TOML integers are 64-bit signed: write a larger count in "
       "quotes"},
      {"seed = 0x10\n", ":1:8: --seed: '0x10' is not a count"},
      {"a-km = inf\n", ":1:8: --a-km: 'inf' is not a finite number"},
      {"tle = \"a\\qb\"\n", ":1:10: --tle: Error while parsing string: unknown escape sequence"},
      {"[[head]]\nbeta = 90\n[other]\n", ":3:1: unknown table '[other]'"},
  };
  for (const bad& b : cases) {
    const scene_file file(b.body);
    const auto run = run_sim("--config " + file.path);
    INFO("file:\n" << b.body << "stderr: " << run.err);
    CHECK(run.exit_status == 2);
    CHECK(run.out.empty());
    CHECK(run.err.find(file.path + b.expected) != std::string::npos);
  }
  // Not a text file: refused at the first NUL byte, without reading the endless /dev/zero.
  const auto zeros = run_sim("--config /dev/zero");
  CHECK(zeros.exit_status == 2);
  CHECK(zeros.err.find("/dev/zero:1: a NUL byte") != std::string::npos);
  const auto missing = run_sim("--config /nonexistent/scene.toml");
  CHECK(missing.exit_status == 2);
  CHECK(missing.err.find("/nonexistent/scene.toml") != std::string::npos);
}

TEST_CASE("sweep: long format with the swept option first", "[cli][sweep]") {
  const auto run = run_sim("--sweep e=0:0.1:0.025 --step-s 1000");
  REQUIRE(run.exit_status == 0);
  const csv_table t = parse_csv(run.out);
  REQUIRE(t.header.at(0) == "e");
  CHECK(t.header.at(1) == "t_s");
  // 5 values x 7 rows (t = 0 .. 6000 s of a 6181.7 s period).
  REQUIRE(t.rows.size() == 35);
  const char* values[] = {"0", "0.025", "0.05", "0.075", "0.1"};
  for (std::size_t r = 0; r < t.rows.size(); ++r) CHECK(t.rows[r][0] == values[r / 7]);
  // Each block equals the single run with that value.
  const csv_table single = parse_csv(run_sim("--e 0.075 --step-s 1000").out);
  for (std::size_t r = 0; r < 7; ++r) {
    const std::vector<std::string>& swept = t.rows[21 + r];
    CHECK(std::vector<std::string>(swept.begin() + 1, swept.end()) == single.rows[r]);
  }
}

TEST_CASE("sweep: a head parameter", "[cli][sweep]") {
  const auto run = run_sim("--e 0 --step-s 6000 --sweep h1.alpha=0:20:10");
  REQUIRE(run.exit_status == 0);
  const csv_table t = parse_csv(run.out);
  REQUIRE(t.header.at(0) == "h1.alpha");
  REQUIRE(t.rows.size() == 6);
  // The paper: 1e-2 deg at alpha = 0, 1e-4 deg at alpha = 20, of opposite signs.
  CHECK(std::abs(t.number(0, "roll_err_deg")) > 5e-3);
  CHECK(std::abs(t.number(4, "roll_err_deg")) < 5e-4);
  CHECK(t.number(0, "roll_err_deg") * t.number(4, "roll_err_deg") < 0);
}

TEST_CASE("sweep: bad sweeps exit 2 with no CSV", "[cli][sweep]") {
  for (const char* bad : {"--sweep e", "--sweep e=0:1", "--sweep e=0:0.1:0", "--sweep e=1:0:0.1",
                          "--sweep zeta=0:1:1", "--sweep h2.alpha=0:10:5", "--sweep h1.zeta=0:1:1",
                          "--sweep e=0:0.1:x", "--sweep e=0:0.1:0.0000001"}) {
    const auto run = run_sim(bad);
    INFO(bad << ": " << run.err);
    CHECK(run.exit_status == 2);
    CHECK(run.out.empty());
    CHECK(run.err.find("--") != std::string::npos);
  }
}

TEST_CASE("summary: statistics per head and system", "[cli][summary]") {
  const auto rows = run_sim("--step-s 60 --head alpha=0 --head alpha=-60");
  const auto summary = run_sim("--step-s 60 --head alpha=0 --head alpha=-60 --summary");
  REQUIRE(summary.exit_status == 0);
  const csv_table s = parse_csv(summary.out);
  REQUIRE(s.rows.size() == 3);
  CHECK(s.text(0, "source") == "h1");
  CHECK(s.text(1, "source") == "h2");
  CHECK(s.text(2, "source") == "system");
  const csv_table r = parse_csv(rows.out);
  const double n = static_cast<double>(r.rows.size());
  CHECK(s.number(0, "rows") == n);
  CHECK(s.number(0, "ok") == n);
  CHECK(s.number(1, "miss") == n);  // head 2 looks away from the Earth
  CHECK(s.text(1, "roll_max_deg") == "nan");
  // Independent recomputation from the rows.
  double max_roll = -1, sum = 0, sum2 = 0;
  for (std::size_t k = 0; k < r.rows.size(); ++k) {
    const double v = r.number(k, "roll_err_deg");
    max_roll = std::max(max_roll, v);
    sum += v;
    sum2 += v * v;
  }
  CHECK(s.number(2, "roll_max_deg") == Approx(max_roll).epsilon(1e-15));
  CHECK(s.number(2, "roll_mean_deg") == Approx(sum / n).epsilon(1e-12));
  CHECK(s.number(2, "roll_rms_deg") == Approx(std::sqrt(sum2 / n)).epsilon(1e-12));
}
