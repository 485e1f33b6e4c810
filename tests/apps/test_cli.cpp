// conescan-sim against the CLI contract (MODEL §9) and the reference vectors.
#include <catch2/catch.hpp>
#include <charconv>
#include <cmath>

#include "support/cli.hpp"

using conescan_test::csv_table;
using conescan_test::parse_csv;
using conescan_test::read_file;
using conescan_test::run_sim;

namespace {

const std::string contract_header =
    "t_s,nu_deg,r_km,alt_km,lat_deg,rho_deg,h1_chord_deg,h1_phase_deg,h1_eta_err_deg,"
    "h1_roll_err_deg,h1_pitch_err_deg,h1_status,roll_err_deg,pitch_err_deg,status";

// Tolerances of tests/data/reference/README.md: 1e-9 deg for angles, 1e-6 km for distances,
// nu and phases modulo 360.
double tolerance_for(const std::string& column) {
  if (column == "t_s") return 1e-9;
  if (column.size() > 3 && column.compare(column.size() - 3, 3, "_km") == 0) return 1e-6;
  return 1e-9;
}

void check_matches_reference(const csv_table& actual, const csv_table& expected) {
  REQUIRE(actual.header == expected.header);
  REQUIRE(actual.rows.size() == expected.rows.size());
  for (std::size_t r = 0; r < expected.rows.size(); ++r) {
    for (std::size_t c = 0; c < expected.header.size(); ++c) {
      const std::string& name = expected.header[c];
      const std::string& want = expected.rows[r][c];
      const std::string& got = actual.rows[r].at(c);
      INFO("row " << r << " column " << name << ": got " << got << ", expected " << want);
      if (name.find("status") != std::string::npos) {
        CHECK(got == want);
        continue;
      }
      const double x = std::stod(got), y = std::stod(want);
      if (std::isnan(y)) {
        CHECK(std::isnan(x));
        continue;
      }
      double d = std::abs(x - y);
      if (name == "nu_deg" || name.find("phase") != std::string::npos)
        d = std::min(d, std::abs(360 - d));
      CHECK(d <= tolerance_for(name));
    }
  }
}

}  // namespace

TEST_CASE("cli: no arguments stream the paper's scene with the contract's header", "[cli]") {
  const auto run = run_sim("");
  REQUIRE(run.exit_status == 0);
  const csv_table t = parse_csv(run.out);
  CHECK(t.rows.front().size() == t.header.size());
  std::string header;
  for (const auto& h : t.header) header += (header.empty() ? "" : ",") + h;
  CHECK(header == contract_header);
  // One two-body period of a = 7280 km (6180.6 s) at 10 s steps: t = 0 .. 6180.
  REQUIRE(t.rows.size() == 619);
  CHECK(t.number(618, "t_s") == 6180);
  double max_roll = 0;
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    max_roll = std::max(max_roll, std::abs(t.number(r, "roll_err_deg")));
    CHECK(t.text(r, "status") == "ok");
  }
  // The paper: "never exceed 0.02 degrees" at e = 0.1.
  CHECK(max_roll > 0.01);
  CHECK(max_roll < 0.02);
}

TEST_CASE("cli: reproduces reference scene paper-scene-60s", "[cli][reference]") {
  const auto run = run_sim("--step-s 60");
  REQUIRE(run.exit_status == 0);
  check_matches_reference(
      parse_csv(run.out),
      parse_csv(read_file(CONESCAN_TEST_DATA "/reference/paper-scene-60s.csv")));
}

TEST_CASE("cli: reproduces reference scene circular-alpha20", "[cli][reference]") {
  const auto run =
      run_sim("--e 0 --step-s 600 --head alpha=20,beta=90,gamma=45,sigma=0.02,phase=0");
  REQUIRE(run.exit_status == 0);
  check_matches_reference(
      parse_csv(run.out),
      parse_csv(read_file(CONESCAN_TEST_DATA "/reference/circular-alpha20.csv")));
}

TEST_CASE("cli: bad options exit 2, name the option, and print no CSV", "[cli][errors]") {
  struct bad {
    const char* args;
    const char* named;
  };
  const bad cases[] = {
      {"--e 1.5", "--e"},
      {"--e 1", "--e"},
      {"--e -0.1", "--e"},
      {"--head alpha=0,beta=90,gamma=120,sigma=0.02,phase=0", "gamma"},
      {"--head gamma=0", "gamma"},
      {"--head alpha=90", "alpha"},
      {"--head alpha=-90", "alpha"},
      {"--head sigma=-0.01", "sigma"},
      {"--head sigma=45", "sigma"},
      {"--head ''", "--head: head 1 '': empty head"},
      {"--head alpha=0,zeta=1", "zeta"},
      {"--head alpha=0,alpha=1", "twice"},
      {"--head alpha=x", "alpha"},
      {"--a-km 6000", "perigee"},
      {"--a-km nan", "--a-km"},
      {"--a-km inf", "--a-km"},
      {"--step-s 0", "--step-s"},
      {"--step-s -10", "--step-s"},
      {"--orbits -1", "--orbits"},
      {"--duration-s -1", "--duration-s"},
      {"--orbits 2 --duration-s 100", "--duration-s"},
      {"--earth mars", "--earth"},
      {"--model exact", "--model"},
      {"--earth wgs84", "--model"},
      {"--earth wgs84 --model scan --radius-km 6000", "--radius-km"},
      {"--processing-radius big", "--processing-radius"},
      {"--processing-radius 9000", "--processing-radius"},
      {"--pitch-deg 90.5", "--pitch-deg"},
      {"--step-s 0.0001 --orbits 1000", "--max-rows"},
      {"--a-km 60000 --sun-sync", "--sun-sync"},
      {"--no-such-option 1", "no-such-option"},
  };
  for (const bad& b : cases) {
    const auto run = run_sim(b.args);
    INFO("conescan-sim " << b.args << "\nstderr: " << run.err);
    CHECK(run.exit_status == 2);
    CHECK(run.out.empty());
    CHECK(run.err.find(b.named) != std::string::npos);
  }
}

TEST_CASE("cli: several heads are numbered in the order given", "[cli]") {
  const auto run = run_sim(
      "--step-s 3000 --head alpha=0,beta=90 --head alpha=0,beta=-90 --head alpha=-60,beta=0");
  REQUIRE(run.exit_status == 0);
  const csv_table t = parse_csv(run.out);
  CHECK(t.header.size() == 6 + 3 * 6 + 3);
  // Head 3 looks 60 deg above the roll-pitch plane: its 45 deg cone never reaches the Earth.
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    CHECK(t.text(r, "h1_status") == "ok");
    CHECK(t.text(r, "h3_status") == "miss");
    CHECK(t.text(r, "h3_chord_deg") == "nan");
    CHECK(t.text(r, "status") == "ok");
    // Heads 1 and 2 mirror each other across the orbit plane: their roll errors cancel.
    CHECK(t.number(r, "h1_roll_err_deg") == Approx(-t.number(r, "h2_roll_err_deg")).margin(1e-15));
    CHECK(std::abs(t.number(r, "roll_err_deg")) < 1e-12);
  }
}

TEST_CASE("cli: --help states units and defaults", "[cli]") {
  const auto run = run_sim("--help");
  CHECK(run.exit_status == 0);
  for (const char* text : {"--a-km", "km", "deg", "7280", "--step-s", "10", "--head", "alpha=0"})
    CHECK(run.out.find(text) != std::string::npos);
  // A text option's value is shown as what it is (the option table's value_name), never TEXT.
  for (const char* text :
       {"--tle FILE ", "--oem FILE ", "--aem FILE ", "--attitude-csv FILE ", "--write-oem FILE ",
        "--write-aem FILE ", "--apply FILE ", "--summary-state FILE ", "--epoch UTC ",
        "--date DATE ", "--sweep NAME=FROM:TO:STEP ", "--shard K/N ", "--config FILE "})
    CHECK(run.out.find(text) != std::string::npos);
  CHECK(run.out.find(" TEXT ") == std::string::npos);
}

TEST_CASE("cli: every number is the shortest round-trip text, as std::to_chars writes it",
          "[cli][format]") {
  // MODEL §9. The CLI formats with src/text/shortest_double.hpp; std::to_chars is the yardstick.
  // Scenes with one and two heads (the system's copied text), failed heads (nan) and a wide
  // range of magnitudes (a 10^6 km orbit, millisecond steps).
  for (const std::string args :
       {"--step-s 7", "--a-km 1e6 --step-s 1000",
        "--step-s 0.001 --duration-s 2 --head alpha=80,beta=90,gamma=45,sigma=0.02",
        "--step-s 13 --head alpha=0,beta=90,gamma=45,sigma=0.02 "
        "--head alpha=20,beta=-90,gamma=45,sigma=0.05,phase=30"}) {
    const auto run = run_sim(args);
    REQUIRE(run.exit_status == 0);
    const csv_table t = parse_csv(run.out);
    long numbers = 0, mismatches = 0;
    for (const auto& row : t.rows) {
      for (const std::string& field : row) {
        double value = 0;
        const auto parsed = std::from_chars(field.data(), field.data() + field.size(), value);
        if (parsed.ec != std::errc() || parsed.ptr != field.data() + field.size()) continue;
        ++numbers;
        char text[64];
        const std::string expected(text, std::to_chars(text, text + sizeof text, value).ptr);
        if (field != expected && ++mismatches <= 3)
          UNSCOPED_INFO(args << ": wrote " << field << ", std::to_chars " << expected);
      }
    }
    INFO(args << ": " << numbers << " numbers");
    CHECK(numbers > 1000);
    CHECK(mismatches == 0);
  }
}
