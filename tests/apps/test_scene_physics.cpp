// The sensor physics in a scene (MODEL §12; src/scene/scene_physics.hpp and the simulation's
// physics step), end to end through conescan-sim: off means off (the keys at their defaults
// change no byte), the reductions to MODEL §5 on the sphere and on the apparent horizon, the step
// edge's lag, the statuses a row gets (miss, grazing, invalid), the options refused with their
// names, sweeps, the error budget's sources, summaries, campaigns over threads and shards, scene
// files, --apply, and conescan-fit's refusal. The chain costs ~0.5 ms per head and row: every
// scene here has a few rows.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "scene/head_spec.hpp"
#include "scene/scene_physics.hpp"
#include "scene/scene_plan.hpp"
#include "simulation/simulation.hpp"
#include "support/cli.hpp"
#include "support/scene_of.hpp"

namespace sc = conescan::scene;
using conescan::status;
using conescan_test::csv_table;
using conescan_test::parse_csv;
using conescan_test::run_program;
using conescan_test::run_sim;
using conescan_test::scene_of;
using conescan_test::temp_file;

namespace {

// A short scan scene: the paper's orbit, a 40 km horizon, seven rows.
const std::string scan = "--model scan --horizon-km 40";
const std::string short_scan = scan + " --step-s 600 --duration-s 3600";
const std::string instant_scan = scan + " --duration-s 0";

csv_table rows_of(const std::string& args) {
  const auto run = run_sim(args);
  INFO("conescan-sim " << args << "\n" << run.err);
  REQUIRE(run.exit_status == 0);
  return parse_csv(run.out);
}

// The largest |a - b| of a column over the rows (both tables ok everywhere).
double largest_difference(const csv_table& a, const csv_table& b, const std::string& column) {
  REQUIRE(a.rows.size() == b.rows.size());
  double largest = 0;
  for (std::size_t r = 0; r < a.rows.size(); ++r)
    largest = std::max(largest, std::abs(a.number(r, column) - b.number(r, column)));
  return largest;
}

}  // namespace

TEST_CASE("scene physics: off means off, the keys at their defaults change no byte",
          "[scene-physics]") {
  // Given explicitly at their defaults, the physics keys and options leave the scene as it was:
  // the chain does not run, the rows and --print-config are byte for byte the plain scene's.
  const std::string plain = short_scan + " --head sigma=0.05,phase=30";
  const std::string defaults =
      short_scan +
      " --head sigma=0.05,phase=30,fov=0,fov-shape=square,spin-hz=0,tau-ms=0,locator=normalised,"
      "threshold=0.5 --radiance-scale-km 7 --radiance-offset-km 0 --radiance-disk 1 "
      "--radiance-season 0";
  CHECK(run_sim(defaults).out == run_sim(plain).out);
  CHECK(run_sim(defaults + " --print-config").out == run_sim(plain + " --print-config").out);
  // The printed head has the paper's ten keys and none of the physics'.
  const std::string head = sc::format_head_spec(sc::head_config{});
  CHECK(head ==
        "alpha=0,beta=90,gamma=45,sigma=0.02,phase=0,noise=0,lsb=0,dgamma=0,bias-in=0,"
        "bias-out=0");
  sc::head_config h;
  CHECK_FALSE(sc::physics_on(sc::scene_config{}, h));
  h.spin_hz = 1;  // alone it changes nothing, but switches the chain on (the reduction test's)
  CHECK(sc::physics_on(sc::scene_config{}, h));
  h = {};
  h.fov_deg = 2;
  CHECK(h.field_of_view_deg() == 2);  // MODEL §13's intrusion rule widens the pulses by it
}

TEST_CASE("scene physics: in its reduction settings the chain gives MODEL §5's crossings",
          "[scene-physics]") {
  // Pencil beam, no lag, normalised 1/2, delta50 = 0, L_disk >= 1: MODEL §12's exact reduction,
  // for any H and L_disk, on the sphere and on the apparent horizon (1e-9 deg; measured ~1e-12).
  // spin-hz= alone switches the chain on without leaving the reduction.
  struct reduction {
    const char* scene;
    const char* physics;
  };
  for (const reduction& r : {
           reduction{"--head sigma=0.05,phase=60 --roll-deg 0.3",
                     " --head sigma=0.05,phase=60,"
                     "spin-hz=1 --roll-deg 0.3"},
           reduction{"--head sigma=0.05,phase=60",
                     " --head sigma=0.05,phase=60 "
                     "--radiance-scale-km 3 --radiance-disk 2"},
           reduction{"--earth wgs84 --horizon-preset co2-15um --date 2026-06-21 --head "
                     "sigma=0.03,phase=200 --head beta=-90",
                     " --earth wgs84 --horizon-preset co2-15um --date 2026-06-21 --head "
                     "sigma=0.03,phase=200,spin-hz=2 --head beta=-90 --radiance-scale-km 12"},
       }) {
    const csv_table geometric = rows_of(short_scan + " " + r.scene);
    const csv_table physics = rows_of(short_scan + r.physics);
    INFO(r.physics);
    for (const std::string head : {"h1", "h2"}) {
      if (std::find(geometric.header.begin(), geometric.header.end(), head + "_chord_deg") ==
          geometric.header.end())
        continue;
      CHECK(largest_difference(geometric, physics, head + "_chord_deg") < 1e-9);
      CHECK(largest_difference(geometric, physics, head + "_phase_deg") < 1e-9);
    }
    CHECK(largest_difference(geometric, physics, "roll_err_deg") < 1e-8);
  }
}

TEST_CASE("scene physics: the slope locator on a pencil without lag is the surface's jump",
          "[scene-physics]") {
  // With delta50 = 0 the pencil's output jumps from L0 / 2 to L0 where the line meets the
  // surface: y' is infinite there, so the slope locator's crossing is the geometric one on every
  // row (a sampled search once landed on either side of the jump from row to row, 0.05 deg off).
  const std::string rows = scan + " --step-s 100 --duration-s 6100 --head sigma=0.05,phase=60";
  const csv_table geometric = rows_of(rows);
  const csv_table slope = rows_of(rows + ",locator=slope");
  CHECK(largest_difference(geometric, slope, "h1_chord_deg") < 1e-9);
  CHECK(largest_difference(geometric, slope, "h1_phase_deg") < 1e-9);
}

TEST_CASE("scene physics: a step edge with lag delays both crossings by omega tau ln 2",
          "[scene-physics]") {
  // MODEL §12: H -> 0, k = 1/2, 1 rev/s and 1 ms: the phase later by 0.249533 deg, the chord
  // unchanged; with k = 0.3 the chord changes by omega tau ln((1 - k)/k).
  const std::string sigma0 = " --head sigma=0";
  const csv_table geometric = rows_of(short_scan + sigma0);
  const csv_table lagged =
      rows_of(short_scan + " --radiance-scale-km 0 --head sigma=0,spin-hz=1,tau-ms=1");
  const double omega_tau_deg = 360 * 1e-3;
  for (std::size_t r = 0; r < geometric.rows.size(); ++r) {
    CHECK(lagged.number(r, "h1_phase_deg") - geometric.number(r, "h1_phase_deg") ==
          Approx(omega_tau_deg * std::log(2.0)).margin(1e-9));
    CHECK(lagged.number(r, "h1_chord_deg") ==
          Approx(geometric.number(r, "h1_chord_deg")).margin(1e-9));
  }
  const csv_table k03 = rows_of(
      short_scan + " --radiance-scale-km 0 --head sigma=0,spin-hz=1,tau-ms=1,threshold=0.3");
  for (std::size_t r = 0; r < geometric.rows.size(); ++r)
    CHECK(k03.number(r, "h1_chord_deg") - geometric.number(r, "h1_chord_deg") ==
          Approx(omega_tau_deg * std::log(0.7 / 0.3)).margin(1e-9));
}

TEST_CASE("scene physics: statuses per row, never a number", "[scene-physics]") {
  // Three rows near perigee, where the chord is 147 deg (the sky's arc 213 deg).
  const std::string perigee = scan + " --step-s 60 --duration-s 120";
  struct expected {
    const char* head;
    const char* more;
    const char* state;
  };
  for (const expected& e : {
           // A fixed threshold above the disk's radiance: the output never reaches it.
           expected{"locator=fixed,threshold=1.5", "", "miss"},
           // A field wider along the scan (20 deg / sin 45 deg) than the chord (10 to 18 deg,
           // rolled).
           expected{"fov=20", " --roll-deg -33", "grazing"},
           // 1 rev/s and 30 ms: the lag's memory (20 omega tau = 216 deg) outlasts the sky (213).
           expected{"spin-hz=1,tau-ms=30", "", "invalid"},
       }) {
    const csv_table t = rows_of(perigee + " --head " + e.head + e.more);
    INFO(e.head << e.more);
    for (std::size_t r = 0; r < t.rows.size(); ++r) {
      CHECK(t.text(r, "h1_status") == e.state);
      CHECK(t.text(r, "h1_chord_deg") == "nan");
      CHECK(t.text(r, "roll_err_deg") == "nan");
    }
  }
  // Both sides: 29 ms settles, a 0.5 threshold is reached, a narrower field is ok.
  for (const char* head : {"spin-hz=1,tau-ms=29", "locator=fixed,threshold=0.999", "fov=2"}) {
    const csv_table t = rows_of(perigee + " --head " + std::string(head));
    for (std::size_t r = 0; r < t.rows.size(); ++r) CHECK(t.text(r, "h1_status") == "ok");
  }
}

TEST_CASE("scene physics: bad keys and options are refused with their names (MODEL §7)",
          "[scene-physics]") {
  struct bad {
    const char* args;
    const char* named;
  };
  for (const bad& b : {
           bad{"--head fov=-1", "--head: head 1: fov = -1 is outside 0 or [0.001, 90) deg"},
           bad{"--head fov=0.0001", "fov = 1e-04 is outside"},
           bad{"--head fov=90", "fov = 90 is outside"},
           bad{"--head fov=60,gamma=30,sigma=0", "fov = 60 reaches the spin axis"},
           bad{"--head fov=inf", "--head: head 1 'fov=inf'"},
           bad{"--head fov-shape=oval", "'oval' is not one of: square, circle"},
           bad{"--head spin-hz=2000", "spin-hz = 2000 is outside 0 or [0.001, 1000] rev/s"},
           bad{"--head tau-ms=1", "tau-ms = 1 needs spin-hz="},
           bad{"--head spin-hz=1,tau-ms=-1", "tau-ms = -1 is outside"},
           bad{"--head spin-hz=1,tau-ms=1e-9", "tau-ms = 1e-09 is outside"},
           bad{"--head spin-hz=1,tau-ms=1e-5,locator=slope",
               "tau-ms = 1e-05 at spin-hz = 1 is a lag shorter than locator=slope resolves (2 "
               "pi spin-hz tau below 1e-06 rad of scan azimuth): give tau-ms=0 or at least "
               "0.00016"},
           bad{"--head threshold=1", "threshold = 1 is outside [1e-05, 1)"},
           bad{"--head threshold=0", "threshold = 0 is outside [1e-05, 1)"},
           bad{"--head threshold=9.9e-6", "threshold = 9.9e-06 is outside [1e-05, 1)"},
           bad{"--head locator=fixed,threshold=-0.5", "threshold = -0.5 is outside [1e-08, inf)"},
           bad{"--head locator=fixed,threshold=9.9e-9", "threshold = 9.9e-09 is outside [1e-08"},
           bad{"--head locator=slope,threshold=0.3", "not used by locator=slope"},
           bad{"--head locator=steepest", "'steepest' is not one of: normalised, fixed, slope"},
           bad{"--radiance-scale-km -1", "--radiance-scale-km: radiance-scale-km = -1 is outside"},
           bad{"--radiance-scale-km nan", "--radiance-scale-km: 'nan' is not a finite number"},
           bad{"--radiance-scale-km 1e-310", "radiance-scale-km = 1e-310 is outside 0 or [1e-06"},
           bad{"--radiance-scale-km 9e-7", "radiance-scale-km = 9e-07 is outside 0 or [1e-06"},
           bad{"--radiance-offset-km 2000", "--radiance-offset-km: radiance-offset-km = 2000"},
           bad{"--radiance-disk -0.1", "--radiance-disk: radiance-disk = -0.1 is outside [0, 100]"},
           bad{"--radiance-season 1", "--radiance-season: radiance-season = 1 is outside (-1, 1)"},
           bad{"--radiance-season -1", "radiance-season = -1 is outside (-1, 1)"},
       }) {
    const auto run = run_sim(short_scan + " " + b.args);
    INFO(b.args << ": " << run.err);
    CHECK(run.exit_status == 2);
    CHECK(run.out.empty());
    CHECK(run.err.find(b.named) != std::string::npos);
  }
  // The chain traces the true scan cone: not with the bias model; the option the user gave named.
  const auto bias = run_sim("--model bias --radiance-offset-km 3 --duration-s 0");
  CHECK(bias.exit_status == 2);
  CHECK(bias.err.find("--radiance-offset-km: radiance-offset-km needs --model scan") !=
        std::string::npos);
  const auto bias_head = run_sim("--head beta=90 --head beta=-90,fov=1 --duration-s 0");
  CHECK(bias_head.exit_status == 2);
  CHECK(bias_head.err.find("--head: head 2: the sensor physics") != std::string::npos);
  // Both sides of the boundaries.
  for (const char* ok :
       {"--head fov=0.001", "--head fov=89,gamma=60,sigma=0", "--head spin-hz=1000",
        "--head spin-hz=1,tau-ms=1e-6", "--radiance-season 0.999", "--radiance-scale-km 0",
        "--radiance-scale-km 1e-6", "--radiance-disk 0", "--head threshold=1e-5",
        "--head locator=fixed,threshold=1e-8"})
    CHECK(run_sim(instant_scan + " " + ok + " --print-config").exit_status == 0);
}

TEST_CASE("scene physics: every physics key turns the chain on and is named when refused",
          "[scene-physics]") {
  // The head key table (head_spec.hpp) is the one list: each physics key given alone, at a
  // value other than its default, makes head_physics_given true and is named in the refusal
  // under the bias model; the other keys leave the physics off.
  std::string named;
  for (const sc::head_key& k : sc::head_keys()) {
    sc::head_config head;
    const std::string words = k.field ? "" : k.words.list(",");
    if (k.field)
      head.*k.field += 0.25;
    else  // the last word: the default is the first
      REQUIRE(k.words.set(head, words.substr(words.rfind(',') + 1)));
    INFO(k.name);
    CHECK_FALSE(k.same(head, sc::head_config{}));
    CHECK(sc::head_physics_given(head) == (k.group == sc::head_key_group::physics));
    if (k.group == sc::head_key_group::physics) named += std::string(k.name) + "=, ";
  }
  CHECK(named == sc::physics_keys_text() + ", ");
  const auto bias_shape = run_sim("--head fov-shape=circle --duration-s 0");
  CHECK(bias_shape.exit_status == 2);
  CHECK(bias_shape.err.find("the sensor physics (" + sc::physics_keys_text() + ") needs") !=
        std::string::npos);
  CHECK(bias_shape.err.find("fov-shape=") != std::string::npos);
  // --head's help names every key, the word keys with their words, and the default locator and
  // threshold as head_config has them.
  const sc::head_config defaults;
  const std::string help(sc::head_help(false));
  for (const sc::head_key& k : sc::head_keys())
    CHECK(help.find(std::string(k.name) + "=" + (k.field ? ".." : k.words.list("|"))) !=
          std::string::npos);
  CHECK(help.find("(default " + sc::find_head_key("locator")->text(defaults) + " " +
                  sc::find_head_key("threshold")->text(defaults) + ")") != std::string::npos);
  // Each key's value round-trips through format_head_spec and parse_head_spec; the word keys
  // through their enum's names.
  sc::head_config h;
  h.fov_deg = 1.5;
  h.shape = conescan::field_shape::circle;
  h.spin_hz = 2;
  h.tau_ms = 0.5;
  h.locator = conescan::locator_kind::fixed;
  h.threshold = 0.25;
  const std::string spec = sc::format_head_spec(h);
  CHECK(spec.find("fov-shape=circle") != std::string::npos);
  CHECK(spec.find("locator=fixed") != std::string::npos);
  const auto back = sc::parse_head_spec(spec);
  REQUIRE(back.ok());
  for (const sc::head_key& k : sc::head_keys()) CHECK(k.same(back.value(), h));
}

TEST_CASE("scene physics: sweeps of the keys and options", "[scene-physics]") {
  const csv_table lag = rows_of(instant_scan + " --sweep h1.tau-ms=0:2:0.5 --head spin-hz=1");
  REQUIRE(lag.rows.size() == 5);
  CHECK(lag.header.front() == "h1.tau-ms");
  // The phase grows with the lag, about omega tau ln 2 per ms (more on the profile's knee).
  for (std::size_t r = 1; r < lag.rows.size(); ++r)
    CHECK(lag.number(r, "h1_phase_deg") > lag.number(r - 1, "h1_phase_deg") + 0.1);
  const csv_table scale = rows_of(instant_scan +
                                  " --sweep radiance-scale-km=3:9:3 "
                                  "--head locator=fixed,threshold=0.3");
  REQUIRE(scale.rows.size() == 3);
  // A fixed threshold at 0.3 cuts the profile H ln(ln 2 / -ln 0.7) = 0.664 H above the horizon:
  // the chord grows with H.
  CHECK(scale.number(1, "h1_chord_deg") > scale.number(0, "h1_chord_deg"));
  CHECK(scale.number(2, "h1_chord_deg") > scale.number(1, "h1_chord_deg"));
  const auto word = run_sim(short_scan + " --sweep h1.locator=0:1:1");
  CHECK(word.exit_status == 2);
  CHECK(word.err.find("cannot sweep 'h1.locator': its value is a word") != std::string::npos);
  // The Sun's declination matters to the radiance's season term: its sweep is not refused.
  CHECK(run_sim(instant_scan + " --sweep sun-declination-deg=-20:20:20 "
                               "--radiance-season 0.2 --sun-declination-deg 0 --head locator=fixed")
            .exit_status == 0);
}

TEST_CASE("scene physics: the budget's horizon-height, field-of-view and detector-lag sources",
          "[scene-physics][budget]") {
  // Two heads with a field, a lag and a fixed threshold on a limb with a season term: the limb
  // (the radiance and the locator) is the horizon-height source, the field and the lag run on
  // it and are measured from it.
  const std::string limb = " --radiance-season 0.2 --sun-declination-deg 23.44";
  const std::string physics = short_scan +
                              " --head spin-hz=1,tau-ms=1,fov=1.5,locator=fixed,sigma=0.02 "
                              "--head beta=-90,fov=1.5,spin-hz=1,tau-ms=1,locator=fixed" +
                              limb;
  const auto budget = run_sim(physics + " --budget --summary");
  REQUIRE(budget.exit_status == 0);
  std::vector<std::string> sources;
  for (const auto& row : parse_csv(budget.out).rows) sources.push_back(row.front());
  CHECK(sources == std::vector<std::string>{"misalignment", "horizon-height", "field-of-view",
                                            "detector-lag", "all", "sum", "interaction"});
  const csv_table rows = parse_csv(run_sim(physics + " --budget").out);
  // The horizon-height source is the scene with only the limb (a pencil without lag).
  const std::string heads_on_limb =
      " --head locator=fixed,sigma=0 --head beta=-90,locator=fixed,"
      "sigma=0";
  const csv_table limb_alone = rows_of(short_scan + heads_on_limb + limb);
  // The lag on that limb: its scene less the limb's, row by row (differences of printed
  // shortest round trips: 1e-15 of the errors, 1e-12 deg at most).
  const csv_table lag_on_limb =
      rows_of(short_scan +
              " --head spin-hz=1,tau-ms=1,locator=fixed,sigma=0 --head beta=-90,spin-hz=1,"
              "tau-ms=1,locator=fixed,sigma=0" +
              limb);
  const csv_table all = rows_of(physics);  // "all" is the scene itself
  REQUIRE(rows.rows.size() == all.rows.size());
  for (std::size_t r = 0; r < rows.rows.size(); ++r) {
    CHECK(rows.text(r, "horizon-height_roll_err_deg") == limb_alone.text(r, "roll_err_deg"));
    CHECK(rows.number(r, "detector-lag_roll_err_deg") ==
          Approx(lag_on_limb.number(r, "roll_err_deg") - limb_alone.number(r, "roll_err_deg"))
              .margin(1e-12));
    CHECK(rows.number(r, "detector-lag_pitch_err_deg") ==
          Approx(lag_on_limb.number(r, "pitch_err_deg") - limb_alone.number(r, "pitch_err_deg"))
              .margin(1e-12));
    CHECK(rows.text(r, "all_roll_err_deg") == all.text(r, "roll_err_deg"));
    // The sum of the single sources, and the interaction: all - sum.
    double roll_sum = 0;
    for (const char* source : {"misalignment", "horizon-height", "field-of-view", "detector-lag"})
      roll_sum += rows.number(r, std::string(source) + "_roll_err_deg");
    CHECK(rows.number(r, "sum_roll_err_deg") == Approx(roll_sum).margin(1e-12));
    CHECK(rows.number(r, "interaction_roll_err_deg") ==
          Approx(rows.number(r, "all_roll_err_deg") - rows.number(r, "sum_roll_err_deg"))
              .margin(1e-12));
    CHECK(rows.text(r, "interaction_status") == "ok");
  }
  // A scene without physics has none of these sources; the limb alone (a radiance option) is
  // the horizon-height source.
  const auto plain = run_sim(short_scan + " --budget --summary");
  CHECK(plain.out.find("field-of-view") == std::string::npos);
  CHECK(plain.out.find("horizon-height") == std::string::npos);
  const csv_table offset =
      parse_csv(run_sim(short_scan + " --radiance-offset-km 5 --head sigma=0 --budget").out);
  CHECK(offset.header ==
        std::vector<std::string>{
            "t_s", "nu_deg", "horizon-height_roll_err_deg", "horizon-height_pitch_err_deg",
            "horizon-height_status", "all_roll_err_deg", "all_pitch_err_deg", "all_status",
            "sum_roll_err_deg", "sum_pitch_err_deg", "sum_status", "interaction_roll_err_deg",
            "interaction_pitch_err_deg", "interaction_status"});
}

TEST_CASE("scene physics: summaries, threads and shards", "[scene-physics][campaign]") {
  // Several scenes at once on the campaign's workers, each thread with its own workspace: the
  // same bytes as one thread.
  const std::string scene =
      short_scan +
      " --sweep h1.fov=0.5:2:0.5 --head spin-hz=1,tau-ms=0.5,fov-shape=circle "
      "--head beta=-90,locator=slope --runs 2 --head noise=0.001,beta=0";
  const auto one = run_sim(scene + " --threads 1");
  REQUIRE(one.exit_status == 0);
  CHECK(run_sim(scene + " --threads 3").out == one.out);
  const auto summary = run_sim(scene + " --summary --threads 1");
  REQUIRE(summary.exit_status == 0);
  CHECK(run_sim(scene + " --summary --threads 3").out == summary.out);
  // Shards: their rows, concatenated, are the single process's.
  std::string rows;
  for (int k = 1; k <= 2; ++k) {
    const auto part = run_sim(scene + " --threads 2 --shard " + std::to_string(k) + "/2");
    REQUIRE(part.exit_status == 0);
    rows += part.out.substr(part.out.find('\n') + 1);
  }
  CHECK(rows == one.out.substr(one.out.find('\n') + 1));
}

TEST_CASE("scene physics: compute_rows from several threads at once", "[scene-physics]") {
  // The campaign runner calls compute_rows on every worker at once (campaign_run.cpp): the
  // chain's workspace is per thread, so the rows are those of one thread, bit for bit.
  const sc::loaded_scene scene = scene_of({{"model", "scan"},
                                           {"horizon-km", "40"},
                                           {"step-s", "300"},
                                           {"duration-s", "2400"},
                                           {"head", "fov=1.5,spin-hz=1,tau-ms=1"},
                                           {"head", "beta=-90,fov=1,fov-shape=circle"},
                                           {"radiance-season", "0.2"}});
  const sc::simulation sim = sc::simulation::of(scene).value();
  std::vector<sc::row> serial(sim.rows(), sim.make_row());
  sim.compute_rows(0, serial.size(), serial.data());
  std::vector<std::vector<sc::row>> parallel(4, serial);
  std::vector<std::thread> threads;
  for (auto& rows : parallel)
    threads.emplace_back([&sim, &rows] { sim.compute_rows(0, rows.size(), rows.data()); });
  for (std::thread& t : threads) t.join();
  for (const auto& rows : parallel)
    for (std::size_t k = 0; k < rows.size(); ++k) {
      CHECK(rows[k].heads[0].state == status::ok);
      CHECK(rows[k].heads[0].phase_rad == serial[k].heads[0].phase_rad);
      CHECK(rows[k].heads[1].chord_rad == serial[k].heads[1].chord_rad);
    }
}

TEST_CASE("scene physics: scene files, --print-config and the fit", "[scene-physics][config]") {
  const temp_file file(
      "model = \"scan\"\nhorizon-km = 40\nstep-s = 600\nduration-s = 1800\n"
      "radiance-offset-km = 2.5\nradiance-season = 0.1\n\n[[head]]\nfov = 1.5\n"
      "fov-shape = \"circle\"\nspin-hz = 1\ntau-ms = 0.8\nlocator = \"fixed\"\n"
      "threshold = 0.4\n");
  const auto direct = run_sim("--config " + file.path);
  INFO(direct.err);
  REQUIRE(direct.exit_status == 0);
  const auto printed = run_sim("--config " + file.path + " --print-config");
  CHECK(printed.out.find("radiance-offset-km = 2.5\nradiance-season = 0.1\n") != std::string::npos);
  CHECK(printed.out.find("fov = 1.5\nfov-shape = \"circle\"\nspin-hz = 1\ntau-ms = 0.8\n"
                         "locator = \"fixed\"\nthreshold = 0.4\n") != std::string::npos);
  const temp_file again(printed.out);
  CHECK(run_sim("--config " + again.path).out == direct.out);
  // A word where a number goes and a number where a word goes, at their line.
  const temp_file wrong("[[head]]\nlocator = 3\n");
  const auto refused = run_sim("--config " + wrong.path);
  CHECK(refused.exit_status == 2);
  CHECK(refused.err.find(wrong.path + ":2:") != std::string::npos);
  CHECK(refused.err.find("'3' is not one of: normalised, fixed, slope") != std::string::npos);
  // conescan-fit models the physics (MODEL §12 in its forward model): the keys and options are
  // the scene's; a physics parameter is free only where it exists and has a derivative.
  const temp_file telemetry(run_sim(short_scan + " --head spin-hz=1,tau-ms=1").out, ".csv");
  const auto fit = [&](const std::string& extra) {
    return run_program(CONESCAN_FIT_PATH,
                       "--telemetry " + telemetry.path + " " + short_scan + extra);
  };
  const auto accepted = fit(" --head spin-hz=1,tau-ms=0.5 --free h1.tau-ms --json");
  INFO(accepted.err);
  CHECK(accepted.exit_status == 0);
  const std::string tau_key = "\"h1.tau-ms\": {\"estimate\": ";
  const std::size_t tau_at = accepted.out.find(tau_key);
  REQUIRE(tau_at != std::string::npos);
  CHECK(std::stod(accepted.out.substr(tau_at + tau_key.size())) == Approx(1).epsilon(1e-8));
  for (const auto& [extra, named] :
       {std::pair<std::string, std::string>{" --free h1.tau-ms",
                                            "h1.tau-ms is free but head 1 runs no sensor physics"},
        {" --head spin-hz=1 --free h1.tau-ms", "head 1 starts without lag (tau-ms=0"},
        {" --head spin-hz=1,tau-ms=1 --free h1.threshold", "head 1 has no fixed locator"},
        {" --free radiance-offset-km", "radiance-offset-km is free but no head runs"},
        {" --radiance-scale-km 0 --free radiance-scale-km", "the limb is a step edge"}}) {
    const auto free_refused = fit(extra);
    INFO(extra << ": " << free_refused.err);
    CHECK(free_refused.exit_status == 2);
    CHECK(free_refused.err.find("--free: ") != std::string::npos);
    CHECK(free_refused.err.find(named) != std::string::npos);
  }
}
