// conescan-sim's options as a new user types them: one parser for every number, the
// same hostile values on every option of the table, the command line over a scene file,
// messages that name what the user typed, and work bounded before it is spent. conescan-sim is
// run as a process: the CLI is the subject.
#include <catch2/catch.hpp>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "scene/head_spec.hpp"
#include "scene/option_table.hpp"
#include "support/cli.hpp"
#include "text/number_text.hpp"

using conescan_test::parse_csv;
using conescan_test::run_sim;
using conescan_test::shell_word;
using conescan_test::temp_file;

namespace sc = conescan::scene;

namespace {

// The line `key = value` of a --print-config output, or "" when absent.
std::string printed_value(const std::string& config, const std::string& key) {
  const std::string prefix = "\n" + key + " = ";
  const std::size_t at = ("\n" + config).find(prefix);
  if (at == std::string::npos) return {};
  const std::size_t start = at + prefix.size() - 1;
  return config.substr(start, config.find('\n', start) - start);
}

std::string shortest(double v) {
  return conescan::text::shortest_text(v);
}

// The double std::from_chars reads (the reference of correct rounding), if it reads all.
bool reference_value(const std::string& text, double& value) {
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return ec == std::errc() && end == text.data() + text.size() && std::isfinite(value);
}

// The same hostile values on every option: empty, a sign, a leading zero, hex, an
// overflow, NaN, infinity, a denormal, 2^64, unicode digits, blanks.
const std::vector<std::string> hostile_values{
    "",   "-1",          "010", "0x10", "1e400", "nan", "inf", "1e-320", "18446744073709551616",
    "１", "0.1\xC2\xB5", " 1",  "1 "};

}  // namespace

TEST_CASE("options: every option of the table refuses or reads exactly the same hostile values",
          "[cli][options][hostile]") {
  // Accepted values must read back through --print-config as std::from_chars reads them;
  // refused ones exit 2 with no output and a message naming the option. Counts, choices, texts
  // and specs accept none of them.
  int runs = 0, accepted = 0;
  for (const sc::option_spec& option : sc::option_table()) {
    const std::string name(option.name);
    for (const std::string& value : hostile_values) {
      const std::string word = option.kind == sc::value_kind::flag
                                   ? "--" + name + "=" + shell_word(value)
                                   : "--" + name + " " + shell_word(value);
      const auto run = run_sim(word + " --print-config");
      ++runs;
      INFO("conescan-sim " << word << "\nexit " << run.exit_status << "\nstderr: " << run.err);
      if (run.exit_status == 2) {
        CHECK(run.out.empty());
        CHECK(run.err.find("--" + name) != std::string::npos);
        CHECK(run.err.find('\r') == std::string::npos);
        continue;
      }
      REQUIRE(run.exit_status == 0);
      ++accepted;
      if (option.kind == sc::value_kind::flag) {  // CLI11 reads --flag= as --flag
        CHECK(value.empty());
        CHECK(printed_value(run.out, name) == "true");
        continue;
      }
      if (option.kind == sc::value_kind::text && name != "processing-radius") {
        // A file to write (--write-oem, --write-aem, --summary-state): any name, kept as typed.
        CHECK(printed_value(run.out, name) == "\"" + value + "\"");
        continue;
      }
      double expected = 0;
      REQUIRE((option.kind == sc::value_kind::real || name == "processing-radius"));
      REQUIRE(reference_value(value, expected));
      CHECK(printed_value(run.out, name) == shortest(expected));
    }
  }
  INFO(runs << " command lines, " << accepted << " accepted");
  CHECK(runs >= 400);
  CHECK(accepted > 20);
}

TEST_CASE("options: head keys and scene-file values read the hostile values alike",
          "[cli][options][hostile]") {
  int runs = 0;
  for (const char* key : {"alpha", "beta", "gamma", "sigma", "phase", "noise", "lsb", "dgamma",
                          "bias-in", "bias-out"}) {
    for (const std::string& value : hostile_values) {
      const std::string spec =
          std::string(key) + "=" + value + (std::string(key) == "gamma" ? ",sigma=0" : "");
      const auto run = run_sim("--head " + shell_word(spec) + " --print-config");
      ++runs;
      INFO("--head " << spec << "\nstderr: " << run.err);
      if (run.exit_status == 2) {
        CHECK(run.err.find("--head") != std::string::npos);
        continue;
      }
      REQUIRE(run.exit_status == 0);
      double expected = 0;
      // Blanks around a head key's value are part of the spec's syntax (like around ',').
      REQUIRE(reference_value(std::string(conescan::text::trim_blanks(value)), expected));
      CHECK(printed_value(run.out.substr(run.out.find("[[head]]")), key) == shortest(expected));
    }
  }
  // The sensor physics keys (MODEL §12, model scan), each with what it needs: numbers as above,
  // words (fov-shape, locator) refuse every hostile value.
  struct physics_key {
    const char* name;
    const char* with;  // the other keys it needs
  };
  for (const physics_key& k :
       {physics_key{"fov", ""}, physics_key{"spin-hz", ""}, physics_key{"tau-ms", ",spin-hz=1"},
        physics_key{"threshold", ",locator=fixed"}, physics_key{"fov-shape", ""},
        physics_key{"locator", ""}}) {
    for (const std::string& value : hostile_values) {
      const std::string spec = std::string(k.name) + "=" + value + k.with;
      const auto run = run_sim("--model scan --head " + shell_word(spec) + " --print-config");
      ++runs;
      INFO("--head " << spec << "\nstderr: " << run.err);
      if (run.exit_status == 2) {
        CHECK(run.err.find("--head") != std::string::npos);
        continue;
      }
      REQUIRE(run.exit_status == 0);
      const bool word = sc::is_head_word_key(k.name);
      CHECK_FALSE(word);
      double expected = 0;
      REQUIRE(reference_value(std::string(conescan::text::trim_blanks(value)), expected));
      CHECK(printed_value(run.out.substr(run.out.find("[[head]]")), k.name) == shortest(expected));
    }
  }
  // The same values in a scene file: bare (a blank value is "no value"), with FILE:LINE.
  for (const sc::option_spec& option : sc::option_table()) {
    const std::string name(option.name);
    for (const std::string& value : hostile_values) {
      const temp_file file("# hostile\n" + name + " = " + value + "\n");
      const auto run = run_sim("--config " + file.path + " --print-config");
      ++runs;
      INFO(name << " = " << value << "\nstderr: " << run.err);
      if (run.exit_status == 2) {
        CHECK(run.out.empty());
        CHECK(run.err.find(file.path + ":2:") != std::string::npos);
        CHECK(run.err.find(name) != std::string::npos);
        continue;
      }
      REQUIRE(run.exit_status == 0);
      if (option.kind == sc::value_kind::text && name != "processing-radius") {
        CHECK(printed_value(run.out, name) ==
              "\"" + std::string(conescan::text::trim_blanks(value)) + "\"");
        continue;
      }
      double expected = 0;
      REQUIRE(reference_value(std::string(conescan::text::trim_blanks(value)), expected));
      // An option --print-config leaves out at its default (the radiance's) is not written.
      const auto* real = std::get_if<sc::field_ref<double>>(&option.binding);
      const sc::scene_request defaults;
      const bool omitted_default =
          option.omitted && option.omitted(defaults) && real && expected == real->of(defaults);
      CHECK(printed_value(run.out, name) == (omitted_default ? "" : shortest(expected)));
    }
  }
  CHECK(runs > 500);
}

TEST_CASE("options: counts are decimal digits, range-checked to 2^64 - 1 exactly",
          "[cli][options][counts]") {
  // A regression: --max-rows -1 and 0x10, --seed -1 and 010 (read as 8), --runs 010 were
  // accepted; --runs -1 blamed --max-rows.
  for (const char* args :
       {"--max-rows -1", "--seed -1", "--seed 010", "--runs 010", "--max-rows 0x10", "--runs -1",
        "--seed 18446744073709551616", "--max-rows 1e9", "--runs +1", "--seed 1.0"}) {
    const auto run = run_sim(std::string(args) + " --duration-s 0");
    const std::string option = std::string(args).substr(0, std::string(args).find(' '));
    INFO(args << ": " << run.err);
    CHECK(run.exit_status == 2);
    CHECK(run.out.empty());
    CHECK(run.err.rfind("conescan-sim: " + option + ": ", 0) == 0);
  }
  // The right answer for 1e9: the digits.
  CHECK(run_sim("--max-rows 1e9").err.find("e.g. 1000000000") != std::string::npos);
  // The largest count, exactly.
  const auto largest = run_sim(
      "--max-rows 18446744073709551615 --seed 18446744073709551615 "
      "--print-config");
  REQUIRE(largest.exit_status == 0);
  // Beyond TOML's largest integer, 2^63 - 1, a scene file writes a count as a string.
  CHECK(printed_value(largest.out, "max-rows") == "\"18446744073709551615\"");
  CHECK(printed_value(largest.out, "seed") == "\"18446744073709551615\"");
  CHECK(printed_value(run_sim("--seed 9223372036854775807 --print-config").out, "seed") ==
        "9223372036854775807");
  // The same in a scene file, with its line and column (TOML itself refuses a bare 010).
  const temp_file file("seed = \"010\"\n");
  CHECK(run_sim("--config " + file.path)
            .err.find(file.path + ":1:8: --seed: '010' has a leading zero") != std::string::npos);
}

TEST_CASE("options: one correctly rounded parser for the command line, files, sweeps and heads",
          "[cli][options][numbers]") {
  // A regression: 7100.100000000000818545231595635414123535156250001 lies just above the
  // midpoint of two doubles: CLI11 read 7100.1, std::from_chars (and everything else)
  // 7100.100000000001.
  const std::string text = "7100.100000000000818545231595635414123535156250001";
  double reference = 0;
  REQUIRE(reference_value(text, reference));
  REQUIRE(shortest(reference) == "7100.100000000001");
  const auto cli = run_sim("--a-km " + text + " --print-config");
  CHECK(printed_value(cli.out, "a-km") == "7100.100000000001");
  const temp_file file("a-km = " + text + "\n");
  CHECK(printed_value(run_sim("--config " + file.path + " --print-config").out, "a-km") ==
        "7100.100000000001");
  const auto swept = run_sim("--sweep a-km=" + text + ":7100.2:1 --duration-s 0");
  REQUIRE(swept.exit_status == 0);
  CHECK(parse_csv(swept.out).text(0, "a-km") == "7100.100000000001");
  // A head key: 0.1 + 2^-56 + a little rounds up to the next double above 0.1.
  const std::string alpha = "0.100000000000000019428902930940239457413554191589355468750001";
  double alpha_reference = 0;
  REQUIRE(reference_value(alpha, alpha_reference));
  const auto head = run_sim("--head alpha=" + alpha + " --print-config");
  REQUIRE(head.exit_status == 0);
  CHECK(printed_value(head.out.substr(head.out.find("[[head]]")), "alpha") ==
        shortest(alpha_reference));
  // Hex floats are refused everywhere: they were written by --print-config and refused by the
  // file reader.
  CHECK(run_sim("--e 0x1p-4").err.find("--e: '0x1p-4' is not a decimal number") !=
        std::string::npos);
  CHECK(run_sim("--head alpha=0x1p-4").exit_status == 2);
  CHECK(run_sim("--sweep e=0x0:0.1:0.05").exit_status == 2);
  // A leading '+' is a decimal number.
  CHECK(printed_value(run_sim("--roll-deg +0.5 --print-config").out, "roll-deg") == "0.5");
}

TEST_CASE("options: the command line wins over the scene file", "[cli][options][precedence]") {
  // A regression: full-budget.toml sets orbits = 1; --duration-s on the command line was
  // refused ("--orbits excludes --duration-s") though the command line should win.
  const std::string full_budget = CONESCAN_TEST_DATA "/../../data/scenes/full-budget.toml";
  const auto run = run_sim("--config " + full_budget + " --duration-s 60");
  INFO(run.err);
  REQUIRE(run.exit_status == 0);
  std::string body = conescan_test::read_file(full_budget);
  body.replace(body.find("orbits = 1"), 10, "duration-s = 60");
  const temp_file edited(body);
  CHECK(run.out == run_sim("--config " + edited.path).out);
  // And the other way round, and for --date against --sun-declination-deg.
  const temp_file duration("duration-s = 60\nstep-s = 10\n");
  CHECK(run_sim("--config " + duration.path + " --orbits 0.05").out ==
        run_sim("--orbits 0.05 --step-s 10").out);
  const temp_file dated(
      "earth = \"wgs84\"\nmodel = \"scan\"\nhorizon-shift-km = 10\ndate = \"2026-06-21\"\n"
      "duration-s = 600\nstep-s = 100\n");
  CHECK(run_sim("--config " + dated.path + " --sun-declination-deg -5").out ==
        run_sim("--earth wgs84 --model scan --horizon-shift-km 10 --sun-declination-deg -5 "
                "--duration-s 600 --step-s 100")
            .out);
  // Within one place the two still exclude each other, named with where each was given.
  const auto both = run_sim("--orbits 1 --duration-s 5");
  CHECK(both.exit_status == 2);
  CHECK(both.err.find("--duration-s: excludes --orbits (given on the command line)") !=
        std::string::npos);
  const temp_file conflict("orbits = 2\nduration-s = 5\n");
  CHECK(run_sim("--config " + conflict.path)
            .err.find(conflict.path +
                      ":2:14: --duration-s: excludes "
                      "--orbits (given at " +
                      conflict.path + ":1:10)") != std::string::npos);
  // An option given twice on the command line.
  CHECK(run_sim("--e 0.1 --e 0.2").err.find("--e: given twice") != std::string::npos);
}

TEST_CASE("options: messages name what the user typed, and where", "[cli][options][messages]") {
  struct bad {
    std::string args;
    std::string expected;  // in stderr
  };
  const temp_file cr_only("e = 0.1\ra-km = 7000\rfoo = 1\r");
  const temp_file head_value("step-s = 10\n[[head]]\nalpha = 5\ngamma = 0x10\n");
  const temp_file heads_17([] {
    std::string body;
    for (int k = 0; k < 17; ++k) body += "[[head]]\nbeta = " + std::to_string(10 * k) + "\n";
    return body;
  }());
  const bad cases[] = {
      // A regression: the preset, not the option it fills in, without wgs84.
      {"--horizon-preset co2-15um",
       "conescan-sim: --horizon-preset: horizon-pole-km shapes the WGS84 horizon: add --earth "
       "wgs84"},
      // gamma, typed, not the default sigma.
      {"--head gamma=1e-300",
       "--head: head 1 'gamma=1e-300': gamma = 1e-300 is not above the "
       "default misalignment sigma = 0.02 deg"},
      // The perigee names --a-km when only it was typed.
      {"--a-km 3000", "conescan-sim: --a-km: perigee radius"},
      // A scene file's conversion error, at its line.
      {"--config " + head_value.path, head_value.path + ":4:9: --head: head key 'gamma': '0x10'"},
      // The head count, at the line of the 17th head.
      {"--config " + heads_17.path, heads_17.path + ":33:1: --head: more than 16 heads"},
      // A CR-only file: lines counted, no raw CR in the message.
      {"--config " + cr_only.path, cr_only.path + ":3:1: unknown key 'foo'"},
      // --head's keys as words of their own.
      {"--head alpha=3 gamma=30 sigma=0.05",
       "--head: 'gamma=30' is a word of its own: a head's keys go in one word joined by commas"},
      // --config ''.
      {"--config ''", "--config: empty file name"},
      {"--config /", "--config: /: cannot read: Is a directory"},
  };
  for (const bad& b : cases) {
    const auto run = run_sim(b.args);
    INFO("conescan-sim " << b.args << "\nstderr: " << run.err);
    CHECK(run.exit_status == 2);
    CHECK(run.out.empty());
    CHECK(run.err.find(b.expected) != std::string::npos);
    CHECK(run.err.find('\r') == std::string::npos);
  }
  // Not a word about sigma, which the user did not type.
  CHECK(run_sim("--head gamma=1e-300").err.find("sigma = 0.02 is outside") == std::string::npos);
}

TEST_CASE("options: bad scenes are refused before any output (MODEL §7)",
          "[cli][options][refuse]") {
  // A regression: each was accepted, then wrote rows of `invalid` (the satellite inside the
  // horizon surface, or a step whose quotient overflows).
  struct bad {
    const char* args;
    const char* named;
  };
  for (const bad& b : {
           bad{"--head lsb=1e-320", "--head: head 1: lsb = 1e-320 is outside 0 or [1e-9, 10]"},
           bad{"--earth wgs84 --model scan --horizon-pole-km 1000",
               "--horizon-pole-km: the apparent horizon reaches 7356.752314245179 km"},
           bad{"--earth wgs84 --model scan --horizon-shift-km 1000 --sun-declination-deg 90",
               "--horizon-shift-km: the apparent horizon reaches 7378.137 km"},
           bad{"--horizon-shift-km 1000 --sun-declination-deg 90", "--horizon-shift-km"},
       }) {
    const auto run = run_sim(std::string(b.args) + " --duration-s 0");
    INFO(b.args << ": " << run.err);
    CHECK(run.exit_status == 2);
    CHECK(run.out.empty());
    CHECK(run.err.find(b.named) != std::string::npos);
  }
  // Both sides of the boundaries: the smallest step, and a pole that stays below the perigee.
  CHECK(run_sim("--head lsb=1e-9 --duration-s 0 --model scan").exit_status == 0);
  CHECK(run_sim("--earth wgs84 --model scan --horizon-pole-km 190 --duration-s 0").exit_status ==
        0);
  CHECK(run_sim("--earth wgs84 --model scan --horizon-pole-km 200 --duration-s 0").exit_status ==
        2);
}

TEST_CASE("options: a sweep of an option that is overridden is refused", "[cli][options][sweep]") {
  // A regression: identical rows, no word.
  for (const char* args :
       {"--sweep orbits=0:1:0.5 --duration-s 600", "--sweep i-deg=0:90:90 --sun-sync",
        "--sweep seed=1:3:1", "--sweep sun-declination-deg=0:20:10"}) {
    const auto run = run_sim(args);
    INFO(args << ": " << run.err);
    CHECK(run.exit_status == 2);
    CHECK(run.err.find("--sweep: sweeping") != std::string::npos);
    CHECK(run.err.find("changes nothing") != std::string::npos);
  }
  // Where it takes effect it runs: seed with noise, the declination with the season term.
  CHECK(run_sim("--sweep seed=1:3:1 --head noise=0.01 --duration-s 0").exit_status == 0);
  const auto declination = run_sim(
      "--sweep sun-declination-deg=0:20:10 --earth wgs84 --model scan --horizon-shift-km "
      "10 --sun-declination-deg 0 --duration-s 0");
  CHECK(declination.exit_status == 0);
  CHECK(parse_csv(declination.out).rows.size() == 3);
}

TEST_CASE("options: every numeric option can be swept, counts in whole steps",
          "[cli][options][sweep]") {
  // A regression: the README said any numeric option; seed, runs, noise, lsb and
  // horizon-pole-km could not be swept.
  for (const char* args :
       {"--sweep seed=5:7:1 --head noise=0.01 --duration-s 0",
        "--sweep runs=1:3:1 --head noise=0.01 --duration-s 0",
        "--sweep h1.noise=0:0.02:0.01 --duration-s 0", "--sweep h1.lsb=0:0.01:0.005 --duration-s 0",
        "--sweep horizon-pole-km=-20:0:10 --earth wgs84 --model scan --duration-s 0",
        "--sweep processing-horizon-km=0:40:20 --duration-s 0"}) {
    const auto run = run_sim(args);
    INFO(args << ": " << run.err);
    CHECK(run.exit_status == 0);
    CHECK(!parse_csv(run.out).rows.empty());
  }
  const auto fractional = run_sim("--sweep seed=1:2:0.5 --head noise=0.01 --duration-s 0");
  CHECK(fractional.exit_status == 2);
  CHECK(fractional.err.find("seed = 1.5 is not a count") != std::string::npos);
  // A swept seed is the seed column, and equals the single run with it.
  const auto seeds = run_sim("--sweep seed=5:6:1 --head noise=0.01 --duration-s 0");
  const auto table = parse_csv(seeds.out);
  REQUIRE(table.rows.size() == 2);
  CHECK(table.text(1, "seed") == "6");
  const auto single = parse_csv(run_sim("--seed 6 --head noise=0.01 --duration-s 0").out);
  CHECK(table.text(1, "roll_err_deg") == single.text(0, "roll_err_deg"));
  // max-rows guards the others; it is not swept.
  CHECK(run_sim("--sweep max-rows=1:2:1").err.find("cannot sweep 'max-rows'") != std::string::npos);
}

TEST_CASE("options: counts are written as integers, exactly", "[cli][options][counts]") {
  // A regression: the seed column printed 9007199254740993 as 9007199254740992 (a double),
  // and a summary's 100000 rows as 1e+05.
  const auto seed = run_sim("--seed 9007199254740993 --head noise=0.01 --duration-s 0");
  REQUIRE(seed.exit_status == 0);
  CHECK(parse_csv(seed.out).text(0, "seed") == "9007199254740993");
  const auto other = run_sim("--seed 9007199254740992 --head noise=0.01 --duration-s 0");
  CHECK(parse_csv(other.out).text(0, "h1_chord_deg") !=
        parse_csv(seed.out).text(0, "h1_chord_deg"));
  const auto summary = run_sim("--step-s 1 --duration-s 99999 --summary");
  REQUIRE(summary.exit_status == 0);
  CHECK(parse_csv(summary.out).text(0, "rows") == "100000");
  CHECK(parse_csv(summary.out).text(0, "ok") == "100000");
}

TEST_CASE("options: angles are reduced in degrees before radians", "[cli][options][angles]") {
  // A regression: --roll-deg 1e20 gave roll_err -100.35 deg with status ok (1e20 deg turned
  // into radians, then reduced); 1e20 mod 360 = -80 exactly (in (-180, 180]).
  CHECK(run_sim("--roll-deg 1e20 --model scan --duration-s 0").out ==
        run_sim("--roll-deg -80 --model scan --duration-s 0").out);
  const double m0 = std::remainder(1e18, 360.0);
  const auto huge = run_sim("--m0-deg 1e18 --duration-s 0");
  const auto reduced = run_sim("--m0-deg " + shortest(m0) + " --duration-s 0");
  REQUIRE(huge.exit_status == 0);
  CHECK(huge.out == reduced.out);
  for (const char* option : {"--yaw-deg", "--raan-deg", "--argp-deg"})
    CHECK(run_sim(std::string(option) + " 1e20 --model scan --duration-s 0").out ==
          run_sim(std::string(option) + " -80 --model scan --duration-s 0").out);
  CHECK(run_sim("--head beta=1e20,phase=1e20 --model scan --duration-s 0").out ==
        run_sim("--head beta=-80,phase=-80 --model scan --duration-s 0").out);
}

TEST_CASE("options: the quantised phase lies on the step's grid", "[cli][options][lsb]") {
  // A regression: an LSB that does not divide 360 deg, rounded before wrapping.
  const auto run = run_sim(
      "--model scan --duration-s 0 --pitch-deg -8 --roll-deg -0.1 "
      "--head alpha=85,beta=0,gamma=75,sigma=1,phase=90,lsb=0.007");
  REQUIRE(run.exit_status == 0);
  const double phase = parse_csv(run.out).number(0, "h1_phase_deg");
  INFO("phase " << phase);
  CHECK(std::abs(phase) > 150);
  CHECK(std::abs(phase / 0.007 - std::round(phase / 0.007)) < 1e-6);
}

TEST_CASE("options: --trace works with --budget", "[cli][options][trace]") {
  // A regression: it was silently ignored.
  const auto run = run_sim("--budget --trace --duration-s 0");
  REQUIRE(run.exit_status == 0);
  CHECK(run.err.find("trace: source=misalignment t_s=0 head=1 iterations=") != std::string::npos);
  CHECK(run.err.find("trace: source=all t_s=0 head=1") != std::string::npos);
}

TEST_CASE("options: --budget of a scene whose sources cannot all be simulated",
          "[cli][options][budget]") {
  // A regression: a 1000 km sphere: the budget's single-source runs used WGS84 a for the
  // processing's sphere, above the orbit, and std::invalid_argument aborted conescan-sim.
  const auto small = run_sim("--radius-km 1000 --a-km 3000 --e 0 --duration-s 0 --budget");
  INFO(small.err);
  REQUIRE(small.exit_status == 0);
  CHECK(parse_csv(small.out).header.at(2) == "misalignment_roll_err_deg");
  // A source that truly cannot be simulated is refused, naming --budget and the source: the
  // horizon-pole source raises a sphere of radius a (not b) by the pole term, to 6553.137 km,
  // above the 6552 km perigee, where the full scene's polar radius b + 175 km stays below.
  const auto pole =
      run_sim("--earth wgs84 --model scan --horizon-pole-km 175 --duration-s 0 --budget");
  CHECK(pole.exit_status == 2);
  CHECK(pole.out.empty());
  CHECK(pole.err.find("--budget: the horizon-pole source's scene cannot be simulated") !=
        std::string::npos);
  CHECK(run_sim("--earth wgs84 --model scan --horizon-pole-km 175 --duration-s 0").exit_status ==
        0);
}

TEST_CASE("options: work and memory are bounded before they are spent", "[cli][options][bounds]") {
  // Under a CPU-time limit and, without sanitizers (which reserve terabytes of address space),
  // a 512 MB address-space limit: the findings of an earlier review exceed both.
  const std::string limits = "ulimit -t 60;" + conescan_test::address_space_limit(524288);
  const auto limited = [&](const std::string& command, const std::string& input = "") {
    return run_sim("--duration-s 0 " + command, limits + input);
  };
  // A sweep whose STEP cannot advance FROM: it ran forever, growing (3.6 GB in 10 min).
  const auto same = limited("--sweep roll-deg=1e63:1e63:1");
  CHECK(same.exit_status == 0);
  CHECK(parse_csv(same.out).rows.size() == 1);
  const auto stuck = limited("--sweep roll-deg=1e16:1.00000000000001e16:1");
  CHECK(stuck.exit_status == 2);
  CHECK(stuck.err.find("STEP does not advance the value past 1e+16") != std::string::npos);
  CHECK(limited("--sweep roll-deg=1e63:2e63:1").err.find("more than 2^53 values") !=
        std::string::npos);
  // A sweep of 10^7 values stored them all before --max-rows was checked (2.9 GB, bad_alloc).
  const auto many = limited("--sweep e=0:0.1:1e-8");
  CHECK(many.exit_status == 2);
  CHECK(many.err.find("has 10000001 values, each a scene of at least one row: more than "
                      "--max-rows = 10000000") != std::string::npos);
  // An endless stream of head lines: refused at the file's bound, before TOML reads it (which
  // would refuse the second line: a key given twice).
  const auto heads = limited("--config /dev/stdin", "yes 'head = \"alpha=1\"' |");
  CHECK(heads.exit_status == 2);
  CHECK(heads.err.find("longer than 1048576 bytes") != std::string::npos);
  const auto tables = limited("--config /dev/stdin", "yes '[[head]]' |");
  CHECK(tables.exit_status == 2);
  const auto full_tables =
      limited("--config /dev/stdin", "printf '[[head]]\\nalpha = 1\\n%.0s' $(seq 20) |");
  CHECK(full_tables.err.find("/dev/stdin:33:1: --head: more than 16 heads") != std::string::npos);
  const auto comments = limited("--config /dev/stdin", "yes '# a comment' |");
  CHECK(comments.exit_status == 2);
  CHECK(comments.err.find("longer than 1048576 bytes") != std::string::npos);
}
