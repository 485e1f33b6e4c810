// Every reader checks its format before reading on and holds a bounded amount of memory; one
// wording per cause; the regressions of docs/RELIABILITY.md's audit: CR-only line ends, a
// directory given as a file, --merge of /dev/zero, a re-hashed summary state with impossible
// statistics, two OEM segments that disagree, an OEM of SGP4 states with HERMITE interpolation
// (and --interpolation-tolerance-deg, its stated escape), an all-zero OEM state, an epoch a hair
// before second 60, a fit's iteration count.
#include <sys/stat.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "fuzz/reader_harness.hpp"
#include "simulation/summary_state.hpp"
#include "support/cli.hpp"
#include "text/text_lines.hpp"

namespace fs = std::filesystem;
using conescan_test::read_file;
using conescan_test::run_program;
using conescan_test::run_sim;
using conescan_test::temp_file;

namespace {

const std::string data = CONESCAN_TEST_DATA;
const std::string paper_oem = data + "/ccsds/paper-orbit.oem";
const std::string wobble_aem = data + "/ccsds/paper-orbit-wobble.aem";
const std::string wobble_csv = data + "/attitude/wobble.csv";
const std::string tle_file = data + "/tle/delta-1-deb.tle";

std::string replaced_all(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = 0; (at = text.find(from, at)) != std::string::npos; at += to.size())
    text.replace(at, from.size(), to);
  return text;
}

std::vector<std::string> lines_of(const std::string& body) {
  const temp_file f(body, ".txt");
  std::vector<std::string> lines;
  const auto read = conescan::text::for_each_line(f.path, [&](std::string_view line) {
    lines.emplace_back(line);
    return conescan::success();
  });
  REQUIRE(read.ok());
  return lines;
}

// True when `text` holds only printable ASCII, '\n' and whole UTF-8 sequences: nothing a
// terminal would act on or show as garbage (the fuzz harness's rule, line by line).
bool printable(std::string text) {
  std::erase(text, '\n');
  return conescan_fuzz::reader_detail::printable(text);
}

const std::string fit_args = " --model scan --free h1.sigma";

}  // namespace

// --- Line ends --------------------------------------------------------------------------------

TEST_CASE("readers: a line ends at LF, CRLF or a lone CR", "[reliability][readers]") {
  CHECK(lines_of("a\nb\r\nc\rd") == std::vector<std::string>{"a", "b", "c", "d"});
  CHECK(lines_of("a\r\r\nb\r") == std::vector<std::string>{"a", "", "b"});
  CHECK(lines_of("\r\n\r\n") == std::vector<std::string>{"", ""});
  CHECK(lines_of("") == std::vector<std::string>{});
  // A CR-only file of more lines than one block of 64 KiB, its CRLF split across blocks too.
  std::string many;
  for (int k = 0; k < 20000; ++k) many += "line " + std::to_string(k) + (k % 2 ? "\r" : "\r\n");
  const std::vector<std::string> read = lines_of(many);
  REQUIRE(read.size() == 20000);
  CHECK(read[19999] == "line 19999");
  // The longest line still read; one more character refused.
  const std::string longest(conescan::text::max_line_chars, 'x');
  CHECK(lines_of(longest + "\r" + longest).size() == 2);
  const temp_file too_long(longest + "y\r", ".txt");
  const auto refused = conescan::text::for_each_line(
      too_long.path, [](std::string_view) { return conescan::success(); });
  REQUIRE_FALSE(refused.ok());
  CHECK(refused.error().message == "line longer than 4096 characters");
}

TEST_CASE("readers: OEM, AEM and attitude CSV with CR-only line ends read as with LF",
          "[reliability][readers][regression]") {
  // (the wobble every 60 s is coarser than 1e-6 deg: accepted with the escape)
  const std::string scene = " --step-s 60 --duration-s 1200 --interpolation-tolerance-deg 0.05";
  for (const auto& [option, path] : {std::pair{"--oem", paper_oem}, std::pair{"--aem", wobble_aem},
                                     std::pair{"--attitude-csv", wobble_csv}}) {
    INFO(option);
    const std::string original = read_file(path);
    const temp_file cr(replaced_all(original, "\n", "\r"), ".txt");
    const temp_file crlf(replaced_all(original, "\n", "\r\n"), ".txt");
    const auto lf_run = run_sim(std::string(option) + " " + path + scene);
    REQUIRE(lf_run.exit_status == 0);
    for (const temp_file* f : {&cr, &crlf}) {
      const auto run = run_sim(std::string(option) + " " + f->path + scene);
      INFO(run.err);
      CHECK(run.exit_status == 0);
      CHECK(run.out == lf_run.out);
    }
  }
}

// --- One wording per cause ---------------------------------------------------------------------

TEST_CASE("readers: a missing file and a directory are said alike by every reader",
          "[reliability][readers][regression]") {
  const std::string dir = fs::temp_directory_path().string();
  const struct {
    std::string program, args;
  } readers[] = {
      {CONESCAN_SIM_PATH, "--tle FILE"},
      {CONESCAN_SIM_PATH, "--oem FILE"},
      {CONESCAN_SIM_PATH, "--aem FILE"},
      {CONESCAN_SIM_PATH, "--attitude-csv FILE"},
      {CONESCAN_SIM_PATH, "--model scan --apply FILE"},
      {CONESCAN_SIM_PATH, "--merge FILE"},
      {CONESCAN_FIT_PATH, "--telemetry FILE" + fit_args},
  };
  for (const auto& r : readers) {
    for (const auto& [path, reason] :
         {std::pair{std::string("/nonexistent/file"),
                    std::string(": cannot open: No such file or directory")},
          std::pair{dir, std::string(": cannot read: Is a directory")}}) {
      const std::string args = replaced_all(r.args, "FILE", path);
      const auto run = run_program(r.program, args);
      INFO(args << "\n" << run.err);
      CHECK(run.exit_status == 2);
      CHECK(run.out.empty());
      CHECK(run.err.find(reason) != std::string::npos);
      CHECK(run.err.find(path) != std::string::npos);
    }
  }
}

TEST_CASE("readers: garbage is refused with printable messages", "[reliability][readers]") {
  std::mt19937 draw(28);
  std::string garbage;
  for (int k = 0; k < 300; ++k) garbage += static_cast<char>(draw() % 256);
  for (const std::string start : {"", "CCSDS_OEM_VERS = 2.0\n", "t_s,roll_deg,pitch_deg,yaw_deg\n",
                                  "ISS\n1 ", "t_s,h1_chord_deg,h1_phase_deg\n0,"}) {
    const temp_file f(start + garbage + "\r\x1b[2J", ".txt");
    for (const std::string& args :
         {"--tle " + f.path, "--oem " + f.path, "--aem " + f.path, "--attitude-csv " + f.path,
          "--merge " + f.path, "--model scan --apply " + f.path}) {
      const auto run = run_sim(args);
      INFO(args << "\n" << run.err);
      CHECK(run.exit_status == 2);
      CHECK(printable(run.err));
    }
    const auto fit = run_program(CONESCAN_FIT_PATH, "--telemetry " + f.path + fit_args);
    CHECK(fit.exit_status == 2);
    CHECK(printable(fit.err));
  }
}

TEST_CASE("readers: an OEM state of zeros is no orbit, said without NaN",
          "[reliability][readers][regression]") {
  std::string oem = read_file(paper_oem);
  const std::size_t first = oem.find("2000-01-01T12:00:00.000000000 ");
  REQUIRE(first != std::string::npos);
  const std::size_t end = oem.find('\n', first);
  oem.replace(first, end - first, "2000-01-01T12:00:00.000000000 0 0 0 0 0 0");
  const temp_file zero(oem, ".oem");
  const auto run = run_sim("--oem " + zero.path + " --duration-s 0");
  CHECK(run.exit_status == 2);
  CHECK(run.err.find("nan") == std::string::npos);
  CHECK(run.err.find("(|r| = 0 km, |v| = 0 km/s) is no orbit") != std::string::npos);
}

TEST_CASE("readers: an epoch a hair before second 60 is in its second", "[reliability][readers]") {
  const auto run = run_sim("--epoch 2020-01-01T00:00:59.9999999999999999 --duration-s 0");
  CHECK(run.exit_status == 0);
  CHECK(run.err.empty());
  // A real second 60 is refused, as before.
  CHECK(run_sim("--epoch 2020-01-01T00:00:60 --duration-s 0").exit_status == 2);
  // On a day with a leap second, 23:59:60.999... is that second's.
  CHECK(run_sim("--epoch 2016-12-31T23:59:60.9999999999999999 --duration-s 0").exit_status == 0);
}

TEST_CASE("readers: NOT CONVERGED counts the iterations as the solver's message does",
          "[reliability][readers][regression]") {
  const temp_file telemetry(
      run_sim("--model scan --head sigma=0.05,phase=30,noise=0.01 --step-s 60").out, ".csv");
  const auto run = run_program(CONESCAN_FIT_PATH, "--telemetry " + telemetry.path +
                                                      " --model scan --head sigma=0 --free "
                                                      "h1.sigma,h1.phase --max-iterations 1");
  CHECK(run.exit_status == 1);
  // One count, said once: the solver's own message names the same limit.
  CHECK(run.out.rfind("NOT CONVERGED after 1 iteration: the iteration limit (1) was reached\n",
                      0) == 0);
}

// --- Bounded reading, format first ------------------------------------------------------------

TEST_CASE("readers: a whole-file reader checks the start first and bounds what it holds",
          "[reliability][readers][property]") {
  using conescan::text::read_bounded_file;
  const auto magic = [](std::string_view start) -> conescan::checked<void> {
    if (start.rfind("MAGIC", 0) == 0) return conescan::success();
    return conescan::diagnostic{{}, "not magic"};
  };
  // An endless device: refused at its start, and without a check past the bound.
  const auto zero = read_bounded_file("/dev/zero", std::size_t{1} << 40, "a test", magic);
  REQUIRE_FALSE(zero.ok());
  CHECK(zero.error().text() == "/dev/zero: not magic");
  const auto endless = read_bounded_file("/dev/zero", 1 << 20, "a test");
  REQUIRE_FALSE(endless.ok());
  CHECK(endless.error().message == "larger than 1048576 bytes: not a test");
  // A short file is checked whole; an empty one too.
  const temp_file good("MAGIC and more", ".txt"), empty("", ".txt");
  CHECK(read_bounded_file(good.path, 100, "a test", magic).value() == "MAGIC and more");
  CHECK_FALSE(read_bounded_file(empty.path, 100, "a test", magic).ok());
  CHECK(read_bounded_file(good.path, 14, "a test").ok());
  CHECK_FALSE(read_bounded_file(good.path, 13, "a test").ok());
}

TEST_CASE("readers: --merge refuses /dev/zero at once, within a small address space",
          "[reliability][readers][regression]") {
  const auto run = run_sim("--merge /dev/zero", conescan_test::address_space_limit(1000000));
  CHECK(run.exit_status == 2);
  CHECK(run.err ==
        "conescan-sim: --merge: /dev/zero: not a conescan summary state (it does not start with "
        "'conescan-summary-state 2')\n");
}

namespace sc = conescan::scene;

TEST_CASE("readers: a re-hashed summary state with impossible statistics is refused",
          "[reliability][readers][regression]") {
  const temp_file state("", ".state");
  REQUIRE(run_sim("--summary --duration-s 600 --summary-state " + state.path).exit_status == 0);
  const sc::summary_state good = sc::read_summary_state(read_file(state.path)).value();
  const auto refused = [&](auto edit) {
    sc::summary_state s = good;
    edit(s.scenes.at(0).sources.at(0).roll);
    // Written again by the writer: the hash matches, only the numbers are impossible.
    const auto read = sc::read_summary_state(sc::summary_state_text(s));
    return !read.ok() && read.error().message.rfind("corrupt summary state (line", 0) == 0;
  };
  CHECK(refused([](sc::running_statistics& q) { q.mean = 1e308; }));
  CHECK(refused([](sc::running_statistics& q) { std::swap(q.min, q.max), q.min += 1e-3; }));
  CHECK(refused([](sc::running_statistics& q) { q.max = 10; }));
  CHECK(refused([](sc::running_statistics& q) { q.m2 = 1e6; }));
  CHECK(refused([](sc::running_statistics& q) { q.m2 = -1; }));
  CHECK_FALSE(refused([](sc::running_statistics&) {}));
  // End to end: the merge refuses it, nothing on standard output.
  sc::summary_state s = good;
  s.scenes.at(0).sources.at(0).roll.mean = 1e308;
  const temp_file edited(sc::summary_state_text(s), ".state");
  const auto run = run_sim("--merge " + edited.path);
  CHECK(run.exit_status == 2);
  CHECK(run.out.empty());
  // A shard count of 10^18 is a missing shard, found without a slot per shard.
  s = good;
  s.shard = {1, 1000000000000000000};
  s.total_units = 1000000000000000000;
  const temp_file many(sc::summary_state_text(s), ".state");
  const auto shards = run_sim("--merge " + many.path, conescan_test::address_space_limit(1000000));
  CHECK(shards.exit_status == 2);
  CHECK(shards.err.find("shard 2/1000000000000000000 is missing (1 file(s) given)") !=
        std::string::npos);
}

// --- OEM: overlapping segments, HERMITE on SGP4's states, the tolerance ------------------------

namespace {

// The paper orbit's OEM as two segments over the same times, the second moved `shift_km` in x.
std::string two_segments(double shift_km) {
  const std::string oem = read_file(paper_oem);
  const std::size_t meta = oem.find("META_START");
  const std::string header = oem.substr(0, meta), body = oem.substr(meta);
  std::string shifted;
  std::istringstream in(body);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string epoch;
    double x = 0;
    if (line.rfind("20", 0) == 0 && fields >> epoch >> x) {
      std::string rest;
      std::getline(fields, rest);
      char text[64];
      std::snprintf(text, sizeof text, "%.17g", x + shift_km);
      line = epoch + " " + text + rest;
    }
    shifted += line + "\n";
  }
  return header + body + "\n" + shifted;
}

}  // namespace

TEST_CASE("readers: two OEM segments that overlap and disagree are refused",
          "[reliability][readers][regression]") {
  const temp_file disagree(two_segments(100), ".oem"), agree(two_segments(0), ".oem");
  const std::string scene = " --step-s 60 --duration-s 600";
  const auto run = run_sim("--oem " + disagree.path + scene);
  INFO(run.err);
  CHECK(run.exit_status == 2);
  CHECK(run.err.find("overlap and disagree by 1e+05 m") != std::string::npos);
  CHECK(run.err.find("the later would win there") != std::string::npos);
  // Identical segments agree; so does a shift within a raised tolerance (1e-3 km ~ 8e-6 deg).
  CHECK(run_sim("--oem " + agree.path + scene).exit_status == 0);
  const temp_file close(two_segments(1e-3), ".oem");
  CHECK(run_sim("--oem " + close.path + scene).exit_status == 2);
  CHECK(
      run_sim("--oem " + close.path + scene + " --interpolation-tolerance-deg 1e-4").exit_status ==
      0);
}

TEST_CASE("readers: an OEM of SGP4 states with HERMITE says why and gives an escape",
          "[reliability][readers][regression]") {
  const temp_file written("", ".oem");
  REQUIRE(
      run_sim("--tle " + tle_file + " --step-s 60 --duration-s 1200 --write-oem " + written.path)
          .exit_status == 0);
  const std::string lagrange = read_file(written.path);
  const temp_file hermite(
      replaced_all(lagrange, "INTERPOLATION = LAGRANGE", "INTERPOLATION = HERMITE"), ".oem");
  const std::string scene = " --step-s 10 --duration-s 600";
  const auto refused = run_sim("--oem " + hermite.path + scene);
  INFO(refused.err);
  CHECK(refused.exit_status == 2);
  CHECK(refused.err.find("the velocities are inconsistent with the positions") !=
        std::string::npos);
  CHECK(refused.err.find("INTERPOLATION = LAGRANGE") != std::string::npos);
  CHECK(refused.err.find("--interpolation-tolerance-deg") != std::string::npos);
  // Named at a data line (a line that starts with the year), not the META block's.
  const std::size_t colon = refused.err.find(".oem:") + 5;
  const std::size_t line = std::stoul(refused.err.substr(colon));
  std::istringstream text(read_file(hermite.path));
  std::string at;
  for (std::size_t k = 0; k < line; ++k) std::getline(text, at);
  CHECK(at.rfind("2006-", 0) == 0);
  // LAGRANGE, as the message says: accepted.
  CHECK(run_sim("--oem " + written.path + scene).exit_status == 0);
  // The escape: accepted, with the bound printed once on standard error, also over a sweep.
  for (const std::string extra : {"", " --sweep step-s=10:30:10"}) {
    const auto accepted =
        run_sim("--oem " + hermite.path + scene + extra + " --interpolation-tolerance-deg 0.001");
    INFO(accepted.err);
    CHECK(accepted.exit_status == 0);
    CHECK(accepted.err.rfind("conescan-sim: note: --interpolation-tolerance-deg 0.001: the OEM's "
                             "interpolation error estimate reaches 0.000",
                             0) == 0);
    CHECK(std::count(accepted.err.begin(), accepted.err.end(), '\n') == 1);
    CHECK(accepted.err.find("may be off by up to") != std::string::npos);
  }
  // Within the default the option changes nothing and prints nothing.
  const auto quiet =
      run_sim("--oem " + written.path + scene + " --interpolation-tolerance-deg 0.001");
  CHECK(quiet.err.empty());
  CHECK(quiet.out == run_sim("--oem " + written.path + scene).out);
  // Its domain, both sides.
  for (const std::string bad : {"0", "-1e-6", "1.0000001", "nan", "inf"})
    CHECK(run_sim("--interpolation-tolerance-deg " + bad).exit_status == 2);
  for (const std::string good : {"1e-300", "1"})
    CHECK(run_sim("--duration-s 0 --interpolation-tolerance-deg " + good).exit_status == 0);
}
