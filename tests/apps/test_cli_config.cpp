// --print-config then --config reproduces the CSV byte for byte (the round-trip
// property), over randomly drawn valid scenes: every option of the table and every head key,
// presets, dates, sweeps, the error budget, summaries, several heads, options split between a
// scene file and the command line (which wins), numbers typed at full precision, with exponents,
// and as angles of many turns. Fixed seed; the count of scenes is checked and printed.
#include <algorithm>
#include <catch2/catch.hpp>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "scene/head_spec.hpp"
#include "scene/option_table.hpp"
#include "support/cli.hpp"
#include "text/number_text.hpp"

using conescan_test::run_sim;
using conescan_test::shell_word;
using conescan_test::temp_file;

namespace {

// One option as the scene draws it.
// What --write-oem and --write-aem write in the drawn scenes.
const std::string written_oem = "conescan_test_drawn_" + std::to_string(::getpid()) + ".oem";
// The directory --calendar writes in the drawn scenes.
const std::string drawn_calendar = "conescan_test_drawn_calendar_" + std::to_string(::getpid());
const std::string written_aem = "conescan_test_drawn_" + std::to_string(::getpid()) + ".aem";

struct drawn_option {
  std::string name;
  std::string value;  // "" for a flag
  int place = -1;     // 0: the command line, 1: the scene file, -1: split() draws it
};

class scene_drawer {
 public:
  explicit scene_drawer(std::uint64_t seed) : rng_(seed), campaign_rng_(seed + 17) {}

  std::vector<drawn_option> draw() {
    options_.clear();
    const bool wgs84 = chance(0.4);
    const bool budget = chance(0.15);
    // MODEL §10's sources: one orbit source (classical elements mostly) and one attitude source.
    orbit_source_ = chance(0.85) ? "" : chance(0.5) ? (chance(0.5) ? "tle" : "omm") : "oem";
    attitude_source_ = chance(0.85) ? "" : chance(0.5) ? "attitude-csv" : "aem";
    draw_orbit();
    draw_time();
    draw_earth(wgs84);
    draw_model(wgs84, budget);
    draw_attitude();
    draw_output(budget);
    draw_physics(budget);
    draw_study(budget);
    return options_;
  }

 private:
  double uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng_);
  }
  bool chance(double p) { return uniform(0, 1) < p; }
  std::size_t pick(std::size_t n) {
    return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng_);
  }

  // A number as a user might type it: short, at full precision, or with an exponent.
  std::string number(double lo, double hi) {
    const double v = uniform(lo, hi);
    char text[64];
    switch (pick(3)) {
      case 0:
        std::snprintf(text, sizeof text, "%.4g", v);
        return text;
      case 1:
        return conescan::text::shortest_text(v);
      default:
        std::snprintf(text, sizeof text, "%.9e", v);
        return text;
    }
  }
  void add(const std::string& name, const std::string& value = {}) {
    options_.push_back({name, value});
  }
  void maybe(const std::string& name, double lo, double hi, double p = 0.5) {
    if (chance(p)) add(name, number(lo, hi));
  }

  void draw_orbit() {
    const std::string data = CONESCAN_TEST_DATA;
    if (orbit_source_ == "tle" || orbit_source_ == "omm") {
      // Epoch 2006-06-25T19:46:43.98 UTC; the OMM in one of its formats.
      const char* formats[] = {"kvn", "xml", "csv", "json"};
      if (orbit_source_ == "tle")
        add("tle", data + "/tle/delta-1-deb.tle");
      else
        add("omm", data + "/omm/delta-1-deb." + formats[pick(4)]);
      // --object naming the file's one set by each of its keys, from a stream of its own (the
      // other draws stay as they were), placed by it too.
      const char* keys[] = {"6251", "1962-025E", "62025e", "Delta 1 Deb"};
      if (std::uniform_int_distribution<int>(0, 99)(catalogue_rng_) < 50) {
        add("object", keys[std::uniform_int_distribution<std::size_t>(0, 3)(catalogue_rng_)]);
        options_.back().place = static_cast<int>(catalogue_rng_() % 2);
      }
      if (attitude_source_ != "aem" && chance(0.5))
        add("epoch", "2006-06-2" + std::to_string(5 + pick(5)) + "T0" + std::to_string(pick(10)) +
                         ":3" + std::to_string(pick(10)) + ":00");
      return;
    }
    if (orbit_source_ == "oem") {  // the paper orbit 2000-01-01T12:00 .. 18:00 UTC
      add("oem", data + "/ccsds/paper-orbit.oem");
      return;
    }
    if (attitude_source_ != "aem" && chance(0.2))  // the AEM holds 2000-01-01T12:00 .. 18:00
      add("epoch", "20" + std::to_string(10 + pick(80)) + "-0" + std::to_string(1 + pick(9)) +
                       "-1" + std::to_string(pick(10)) + "T12:00:00Z");
    a_km_ = uniform(7200, 9000);  // perigee above 6480 km with the default e = 0.1
    add("a-km", conescan::text::shortest_text(a_km_));
    maybe("e", 0, 0.05);
    maybe("i-deg", 0, 180);
    // Angles of many turns too: reduced in degrees (exactly) before radians.
    maybe("raan-deg", -720, 720);
    maybe("argp-deg", -1e6, 1e6);
    maybe("m0-deg", -720, 720);
    if (chance(0.2)) add("sun-sync");
    if (chance(0.3)) add("j2");
  }

  void draw_time() {
    add("step-s", number(300, 2000));
    if (chance(0.5))
      add("duration-s", number(0, 3000));
    else
      add("orbits", number(0, 0.4));
    if (chance(0.3)) add("max-rows", std::to_string(10000 + pick(1000000)));
  }

  void draw_earth(bool wgs84) {
    if (wgs84) {
      add("earth", "wgs84");
    } else if (chance(0.5)) {
      add("earth", "sphere");
      if (chance(0.5)) add("radius-km", number(6000, 6400));
    }
    maybe("horizon-km", 0, 40);
    maybe("processing-horizon-km", 0, 50, 0.3);
    switch (pick(4)) {
      case 0:
        add("processing-radius", "equatorial");
        break;
      case 1:
        add("processing-radius", "local");
        break;
      case 2:
        add("processing-radius", number(6000, 6400));
        break;
      default:
        break;
    }
    if (!wgs84) return;
    const bool preset = chance(0.4);
    if (preset) add("horizon-preset", "co2-15um");
    maybe("horizon-pole-km", -20, 20, 0.3);
    const bool shift = chance(0.3);
    if (shift) add("horizon-shift-km", number(-15, 15));
    if (preset || shift || chance(0.3)) {
      if (chance(0.5))
        add("date", "20" + std::to_string(10 + pick(80)) + "-0" + std::to_string(1 + pick(9)) +
                        "-1" + std::to_string(pick(10)));
      else
        add("sun-declination-deg", number(-23.44, 23.44));
    }
  }

  void draw_model(bool wgs84, bool budget) {
    scan_ = wgs84 || chance(0.5);
    if (scan_) add("model", "scan");
    if (chance(0.3)) add("processing", chance(0.5) ? "horizon-vector" : "chord-phase");
    heads_ = 1 + pick(3);
    noisy_ = false;
    for (std::size_t k = 0; k < heads_; ++k) {
      std::string spec;
      auto key = [&](const char* name, double lo, double hi) {
        spec += (spec.empty() ? "" : ",") + std::string(name) + "=" + number(lo, hi);
      };
      if (chance(0.6)) key("alpha", -30, 30);
      key("beta", -180, 360);
      if (chance(0.5)) key("gamma", 30, 60);
      if (chance(0.5)) key("sigma", 0, 0.1);
      if (chance(0.5)) key("phase", -400, 400);
      if (chance(0.3)) {
        key("noise", 0, 0.02);
        noisy_ = true;
      }
      if (chance(0.3)) key("lsb", 0.001, 0.01);
      add("head", spec);
    }
    if (chance(0.4)) add("seed", std::to_string(rng_()));
    if (!budget && chance(0.2)) add("runs", std::to_string(1 + pick(3)));
    if (chance(0.1)) add("trace");
  }

  void draw_attitude() {
    const std::string data = CONESCAN_TEST_DATA;
    if (attitude_source_ == "aem") add("aem", data + "/ccsds/paper-orbit-wobble.aem");
    if (attitude_source_ == "attitude-csv") {
      // Angles (orbital -> body), or a star tracker's quaternions in one of the inertial frames.
      const char* frames[] = {"EME2000", "GCRF", "ICRF", "TEME", "TOD"};
      const bool angles = chance(0.5);
      add("attitude-csv", data + "/attitude/" + (angles ? "wobble.csv" : "spin.csv"));
      // A frame only for the quaternions (a table of angles has none: refused); drawn alike
      // either way, so that the draws after it stay as they were.
      if (chance(0.5)) {
        const char* frame = frames[pick(5)];
        if (!angles) add("attitude-frame", frame);
      }
    }
    if (!attitude_source_.empty()) {
      maybe("attitude-envelope-deg", 0, 90);
      return;
    }
    maybe("roll-deg", -5, 5);
    maybe("pitch-deg", -5, 5);
    maybe("yaw-deg", -400, 400);
    maybe("attitude-envelope-deg", 0, 90);
  }

  void draw_output(bool budget) {
    if (budget) {
      add("budget");
    } else if (chance(0.4)) {
      const char* sweeps[] = {"e=0:0.02:0.01",      "h1.alpha=0:10:5",     "roll-deg=-1:1:1",
                              "horizon-km=0:20:10", "step-s=500:1000:250", "h1.lsb=0:0.01:0.005",
                              "yaw-deg=0:90:45"};
      std::string sweep = sweeps[pick(std::size(sweeps))];
      // A file source replaces the elements and the angles: sweeping them changes nothing.
      if ((!orbit_source_.empty() && sweep[0] == 'e') ||
          (!attitude_source_.empty() && (sweep[0] == 'r' || sweep[0] == 'y')))
        sweep = "horizon-km=0:20:10";
      if (noisy_ && chance(0.3)) sweep = "seed=7:9:1";
      add("sweep", sweep);
    } else {
      // Written by each run of the scene (the test removes them).
      if (chance(0.1)) add("write-oem", written_oem);
      if (chance(0.1)) add("write-aem", written_aem);
    }
    if (chance(0.3)) add("summary");
    // --apply corrects one scene of the scan model with a fit of as many heads.
    const bool one_scene = !budget && std::none_of(options_.begin(), options_.end(),
                                                   [](const auto& o) { return o.name == "sweep"; });
    if (one_scene && scan_ && chance(0.15))
      add("apply", CONESCAN_TEST_DATA "/calibration/fit-h" + std::to_string(heads_) + ".json");
    // How the campaign runs: never what it writes. From a stream of its own, which
    // leaves the other options' draws as they were.
    std::uniform_int_distribution<int> percent(0, 99);
    const auto placed = [&](const char* name, const std::string& value) {
      add(name, value);
      options_.back().place = percent(campaign_rng_) % 2;
    };
    if (percent(campaign_rng_) < 20)
      placed("threads", std::to_string(1 + percent(campaign_rng_) % 3));
    if (percent(campaign_rng_) < 10) placed("shard", "1/1");
    if (percent(campaign_rng_) < 10)
      placed("summary-state", "conescan_test_config_round_trip.state");
    // The wobble's files are coarser than 1e-6 deg (tests/data/attitude/README.md): accepted with
    // the escape, as a user accepts a coarse attitude.
    const bool coarse = std::any_of(options_.begin(), options_.end(), [](const auto& o) {
      return o.value.find("wobble") != std::string::npos;
    });
    if (percent(campaign_rng_) < 10 || coarse)
      placed("interpolation-tolerance-deg", coarse ? "0.05" : "1e-05");
    // The Sun and the Moon (MODEL §13): a scan scene whose Sun is the rows' own (no fixed
    // declination). From a stream of its own too.
    const bool fixed_sun = std::any_of(options_.begin(), options_.end(), [](const auto& o) {
      return o.name == "date" || o.name == "sun-declination-deg";
    });
    if ((scan_ || budget) && !fixed_sun && percent(intrusions_rng_) < 30) add("intrusions");
  }

  // A mission study's options, from a stream of their own (the other draws stay as they were):
  // --eop with an ITRF OEM the IERS sample covers (in place of the paper orbit's OEM), the sensor
  // preset on a scan scene, and --calendar on a scan scene of one run and no other output mode.
  bool has(const char* name) const {
    return std::any_of(options_.begin(), options_.end(),
                       [&](const drawn_option& o) { return o.name == name; });
  }
  void draw_study(bool budget) {
    std::uniform_int_distribution<int> percent(0, 99);
    const std::string data = CONESCAN_TEST_DATA;
    if (orbit_source_ == "oem" && attitude_source_ != "aem" && percent(study_rng_) < 50) {
      for (drawn_option& o : options_)
        if (o.name == "oem") o.value = data + "/eop/itrf-2016-03-01.oem";
      add("eop", data + "/eop/finals2000A-2016-sample.txt");
    }
    if (!scan_ || budget) return;
    if (percent(study_rng_) < 8) add("sensor-preset", "conical-15um");
    const bool one_scene = !has("sweep") && !has("summary") && !has("apply") && !has("shard") &&
                           !has("summary-state") && !has("write-oem") && !has("write-aem") &&
                           !has("runs") && !has("date") && !has("sun-declination-deg");
    if (one_scene && percent(study_rng_) < 25) add("calendar", drawn_calendar);
  }

  // The sensor physics (MODEL §12) of a scan scene: head keys appended to the drawn heads and
  // the radiance options, all from a stream of their own, which leaves the other draws as they
  // were. Its scenes stay short (the chain costs ~0.5 ms per head and row).
  double physics_uniform(double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(physics_rng_);
  }
  bool physics_chance(double p) { return physics_uniform(0, 1) < p; }
  std::string physics_number(double lo, double hi) {
    return conescan::text::shortest_text(physics_uniform(lo, hi));
  }
  void draw_physics(bool budget) {
    if (!(scan_ || budget) || !physics_chance(0.25)) return;
    for (drawn_option& o : options_) {
      if (o.name != "head" || !physics_chance(0.7)) continue;
      std::string keys;
      auto key = [&](const std::string& name, const std::string& value) {
        keys += "," + name + "=" + value;
      };
      if (physics_chance(0.5)) key("fov", physics_number(0, 2));
      if (physics_chance(0.2)) key("fov-shape", "circle");
      if (physics_chance(0.5)) {
        key("spin-hz", physics_number(0.5, 5));
        if (physics_chance(0.7)) key("tau-ms", physics_number(0, 2));
      }
      switch (static_cast<int>(physics_uniform(0, 4))) {
        case 0:
          key("locator", "fixed");
          key("threshold", physics_number(0.2, 0.8));
          break;
        case 1:
          key("locator", "slope");
          break;
        case 2:
          key("threshold", physics_number(0.3, 0.7));
          break;
        default:
          break;
      }
      o.value += keys;
    }
    const auto placed = [&](const char* name, double lo, double hi) {
      if (!physics_chance(0.4)) return;
      add(name, physics_number(lo, hi));
      options_.back().place = physics_chance(0.5) ? 0 : 1;
    };
    placed("radiance-scale-km", 3, 10);
    placed("radiance-offset-km", -5, 5);
    placed("radiance-disk", 0.8, 2);
    placed("radiance-season", -0.3, 0.3);
  }

  std::mt19937_64 rng_;
  std::mt19937_64 campaign_rng_;
  std::mt19937_64 intrusions_rng_{20260101};
  std::mt19937_64 study_rng_{20261201};
  std::mt19937_64 catalogue_rng_{20261202};
  std::mt19937_64 physics_rng_{20261123};
  std::vector<drawn_option> options_;
  double a_km_ = 7000;
  std::string orbit_source_, attitude_source_;
  std::size_t heads_ = 1;
  bool noisy_ = false;
  bool scan_ = false;
};

// The options split between a scene file and the command line; some of the file's options are
// given again on the command line with another value, which wins.
struct split_scene {
  std::string file_body;
  std::string command_line;
};

// "alpha=1,beta=2" as TOML's inline table "{alpha = 1, beta = 2}", or its [[head]] table body.
std::string head_table(const std::string& spec, const std::string& separator) {
  std::string out;
  std::size_t start = 0;
  while (start <= spec.size()) {
    const std::size_t comma = std::min(spec.find(',', start), spec.size());
    const std::string item = spec.substr(start, comma - start);
    const std::string key = item.substr(0, item.find('='));
    const std::string value = item.substr(item.find('=') + 1);
    // A word (fov-shape, locator) is a TOML string.
    out += (out.empty() ? "" : separator) + key + " = " +
           (conescan::scene::is_head_word_key(key) ? "\"" + value + "\"" : value);
    start = comma + 1;
  }
  return out;
}

std::string heads_in_toml(const std::vector<std::string>& heads, std::uint64_t form) {
  std::string out = form == 2 ? "" : "head = [\n";
  for (const std::string& head : heads) {
    if (form == 0) out += "  \"" + head + "\",\n";
    if (form == 1) out += "  {" + head_table(head, ", ") + "},\n";
    if (form == 2) out += "\n[[head]]\n" + head_table(head, "\n") + "\n";
  }
  return form == 2 ? out : out + "]\n";
}

split_scene split(const std::vector<drawn_option>& options, std::mt19937_64& rng) {
  split_scene s;
  std::vector<std::string> file_heads;
  bool heads_on_command_line = rng() % 2 == 0;
  for (const drawn_option& o : options) {
    const bool flag = o.value.empty();
    if (o.name == "head") {
      if (heads_on_command_line)
        s.command_line += " --head " + shell_word(o.value);
      else
        file_heads.push_back(o.value);
      continue;
    }
    if (o.place >= 0 ? o.place == 0 : rng() % 2 == 0) {
      s.command_line += " --" + o.name + (flag ? "" : " " + shell_word(o.value));
      // Overridden: the file says otherwise, the command line wins.
      if (!flag && o.name == "roll-deg") s.file_body += "roll-deg = 42\n";
    } else {
      // TOML's integers stop at 2^63 - 1: a larger count (a seed) is written in quotes.
      const bool beyond_int64 =
          o.value.find_first_not_of("0123456789") == std::string::npos &&
          (o.value.size() > 19 || (o.value.size() == 19 && o.value > "9223372036854775807"));
      // A designator (1962-025E, 62025e) looks like a number to the test above: a key is text
      // unless it is a catalogue number's digits (object = 6251, as a user writes it).
      const bool key =
          o.name == "object" && o.value.find_first_not_of("0123456789") != std::string::npos;
      const bool text =
          !flag && (beyond_int64 || key ||
                    o.value.find_first_not_of("0123456789.eE+-") != std::string::npos);
      s.file_body += o.name + " = " +
                     (flag   ? "true"
                      : text ? "\"" + o.value + "\""
                             : o.value) +
                     "\n";
    }
  }
  // Heads in each TOML form: an array of spec strings (one a line), an array of inline tables,
  // [[head]] tables.
  if (!file_heads.empty()) s.file_body += heads_in_toml(file_heads, rng() % 3);
  return s;
}

}  // namespace

TEST_CASE("print-config: the printed scene reads back to the same CSV, byte for byte",
          "[cli][config][property]") {
  constexpr int scenes = 300;
  // Under AddressSanitizer each run of conescan-sim costs several times more (the round trip took
  // 330 s there): every scene is drawn, so the drawer's coverage of the option table is checked
  // alike, but only every fourth is run, and the counts below are scaled to the scenes run.
#if defined(__SANITIZE_ADDRESS__)
  constexpr int run_every = 4;
#else
  constexpr int run_every = 1;
#endif
  constexpr int scenes_run = (scenes + run_every - 1) / run_every;
  scene_drawer drawer(20250216);
  std::mt19937_64 rng(16);
  int valid = 0, refused = 0, budgets = 0, sweeps = 0, presets = 0, physics = 0;
  std::string refusals;
  std::set<std::string> drawn;
  for (int n = 0; n < scenes; ++n) {
    const std::vector<drawn_option> options = drawer.draw();
    for (const drawn_option& o : options) drawn.insert(o.name);
    const split_scene scene = split(options, rng);
    if (n % run_every != 0) continue;
    const temp_file original(scene.file_body);
    const std::string args = "--config " + original.path + scene.command_line;
    const auto direct = run_sim(args);
    INFO("scene " << n << ": conescan-sim " << args << "\nfile:\n"
                  << scene.file_body << "stderr: " << direct.err);
    if (direct.exit_status == 2) {
      ++refused;  // a drawn combination outside the domain (checked below to be rare)
      refusals += "scene " + std::to_string(n) + ": " + args + "\n" + direct.err;
      continue;
    }
    REQUIRE(direct.exit_status == 0);
    ++valid;
    // Counted wherever they were given, the command line or the file.
    const std::string given = args + "\n" + scene.file_body;
    budgets += given.find("budget") != std::string::npos;
    sweeps += given.find("sweep") != std::string::npos;
    presets += given.find("co2-15um") != std::string::npos;
    physics += std::any_of(options.begin(), options.end(), [](const drawn_option& o) {
      return o.name.rfind("radiance-", 0) == 0 || o.value.find("fov=") != std::string::npos ||
             o.value.find("spin-hz=") != std::string::npos ||
             o.value.find("locator=") != std::string::npos ||
             o.value.find("threshold=") != std::string::npos;
    });
    const auto printed = run_sim(args + " --print-config");
    REQUIRE(printed.exit_status == 0);
    const temp_file printed_file(printed.out);
    const auto again = run_sim("--config " + printed_file.path);
    INFO("printed:\n" << printed.out << "stderr: " << again.err);
    REQUIRE(again.exit_status == 0);
    CHECK(again.out == direct.out);
    // A fixed point: the printed scene prints itself.
    CHECK(run_sim("--config " + printed_file.path + " --print-config").out == printed.out);
  }
  INFO(valid << " valid scenes of " << scenes_run << " (" << refused << " refused); " << budgets
             << " budgets, " << sweeps << " sweeps, " << presets << " presets; refused:\n"
             << refusals);
  WARN("print-config round trip: " << valid << " scenes reproduced byte for byte (" << budgets
                                   << " budgets, " << sweeps << " sweeps, " << presets
                                   << " presets, " << physics << " with sensor physics), "
                                   << refused << " drawn scenes refused");
  std::remove("conescan_test_config_round_trip.state");
  CHECK(valid >= scenes_run - 5);
  CHECK(budgets >= 20 / run_every);
  CHECK(sweeps >= 40 / run_every);
  CHECK(presets >= 15 / run_every);
  CHECK(physics >= 30 / run_every);
  std::remove(written_oem.c_str());
  std::remove(written_aem.c_str());
  for (const char* name : {"lost.csv", "on-cone.csv", "days.csv", "seasons.csv"})
    std::remove((drawn_calendar + "/" + name).c_str());
  ::rmdir(drawn_calendar.c_str());
  // Every option of the table was drawn: a new option must be taught to the drawer.
  for (const conescan::scene::option_spec& option : conescan::scene::option_table()) {
    INFO("never drawn: --" << option.name);
    CHECK(drawn.count(std::string(option.name)) == 1);
  }
}

TEST_CASE("print-config: the issue's scenes read back", "[cli][config]") {
  // A regression: with --duration-s it wrote both orbits and duration-s (refused on reading);
  // with a preset it wrote horizon-km = 0 etc., which overrode the preset on reading.
  for (const char* args :
       {"--duration-s 100 --step-s 20",
        "--earth wgs84 --model scan --horizon-preset co2-15um --date 2026-06-21 --orbits 0.1 "
        "--step-s 60",
        "--config " CONESCAN_TEST_DATA "/../../data/scenes/full-budget.toml --budget --summary",
        "--config " CONESCAN_TEST_DATA "/../../data/scenes/mounting-study.toml --step-s 3000"}) {
    const auto direct = run_sim(args);
    REQUIRE(direct.exit_status == 0);
    const temp_file printed(run_sim(std::string(args) + " --print-config").out);
    const auto again = run_sim("--config " + printed.path);
    INFO(args << "\n" << conescan_test::read_file(printed.path) << again.err);
    REQUIRE(again.exit_status == 0);
    CHECK(again.out == direct.out);
  }
}
