// The Sun and the Moon in a scene (MODEL §13, --intrusions; src/scene/scene_sky.hpp and the
// simulation's intrusion step): the columns and statuses end to end, both sides of each boundary
// against an independent reconstruction, the orbit geometry that decides a season (a head on the
// orbit normal; 09:00 against 10:30 sun-synchronous orbits over a year), summaries, campaigns,
// the fit, hostile input, and --date's one Sun.
//
// The example orbit (docs/SUN_MOON.md "Sun and Moon"): 800 km circular, sun-synchronous with J2,
// the ascending node at a mean local time LTAN on the epoch: RAAN = GAST + 15 deg/h (LTAN - UT1),
// the right ascension of the mean Sun (GAST - 15 deg/h (UT1 - 12 h), in the true equinox) plus
// the node's hour angle from it. The pitch-axis heads alpha = 0, beta = +-90, gamma = 45.
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "conescan/intrusion.hpp"
#include "conescan/orbital_frame.hpp"
#include "conescan/sensor_head.hpp"
#include "scene/option_table.hpp"
#include "scene/scene_plan.hpp"
#include "simulation/simulation.hpp"
#include "sources/scene_frame.hpp"
#include "sources/sun_declination.hpp"
#include "sources/sun_moon.hpp"
#include "support/cli.hpp"
#include "support/scene_of.hpp"

namespace sc = conescan::scene;
namespace src = conescan::sources;
using conescan::apply;
using conescan::apply_transpose;
using conescan::dot;
using conescan::norm;
using conescan::status;
using conescan::vec3;
using conescan_test::parse_csv;
using conescan_test::plan_of;
using conescan_test::run_program;
using conescan_test::run_sim;
using conescan_test::temp_file;

namespace {

constexpr double deg = std::numbers::pi / 180;
using options = std::vector<std::pair<std::string, std::string>>;

// The RAAN (deg, TOD) of a node at mean local time ltan_h on the epoch (top of file).
double raan_deg(const std::string& epoch, double ltan_h) {
  const src::instant t = src::parse_epoch(epoch, src::time_scale::utc).value();
  const double gast_deg = src::scene_rotations_at(t).gast_rad / deg;
  const double ut_h = std::fmod(t.tai_seconds - src::tai_minus_utc_s(t), 86400.0) / 3600;
  return std::fmod(gast_deg + 15 * (ltan_h - ut_h) + 720, 360);
}

// The example orbit at `epoch` with its node at ltan_h, --intrusions, and (with_heads) the two
// pitch-axis heads without misalignment.
options sun_sync(const std::string& epoch, double ltan_h, const std::string& earth = "wgs84",
                 bool with_heads = true) {
  options o{{"model", "scan"},
            {"earth", earth},
            {"intrusions", "true"},
            {"epoch", epoch},
            {"a-km", "7178.137"},
            {"e", "0"},
            {"sun-sync", "true"},
            {"j2", "true"},
            {"raan-deg", conescan::text::shortest_text(raan_deg(epoch, ltan_h))}};
  if (with_heads) {
    o.push_back({"head", "beta=90,sigma=0"});
    o.push_back({"head", "beta=-90,sigma=0"});
  }
  return o;
}

std::string args_of(const options& given) {
  std::string args;
  for (const auto& [name, text] : given)
    args += " --" + name + (text == "true" ? std::string() : " " + text);  // a flag: no value
  return args;
}

}  // namespace

TEST_CASE("intrusions: without the flag every output is today's; with it, columns are added",
          "[intrusions][cli]") {
  const std::string scene =
      " --model scan --earth wgs84 --head beta=90 --head beta=-90 "
      "--step-s 60 --orbits 0.5 --epoch 2026-05-01T00:00:00";
  const auto off = run_sim(scene);
  REQUIRE(off.exit_status == 0);
  // A scene file saying false is the scene without it; --print-config does not write it.
  const temp_file file("intrusions = false\n");
  CHECK(run_sim("--config " + file.path + scene).out == off.out);
  CHECK(run_sim(scene + " --print-config").out.find("intrusions") == std::string::npos);
  const auto on = run_sim(scene + " --intrusions");
  REQUIRE(on.exit_status == 0);
  CHECK(run_sim(scene + " --intrusions --print-config").out.find("intrusions = true") !=
        std::string::npos);
  // The added columns follow each head's status; without them the rows are the same text (no
  // body meets the Earth pulse in this half orbit).
  const auto a = parse_csv(off.out), b = parse_csv(on.out);
  REQUIRE(b.header.size() == a.header.size() + 4);
  CHECK(b.column("h1_sun_deg") == b.column("h1_status") + 1);
  CHECK(b.column("h1_moon_deg") == b.column("h1_status") + 2);
  CHECK(b.column("h2_sun_deg") == b.column("h2_status") + 1);
  for (std::size_t k = 0; k < b.rows.size(); ++k) {
    std::vector<std::string> without = b.rows[k];
    for (const char* name : {"h2_moon_deg", "h2_sun_deg", "h1_moon_deg", "h1_sun_deg"})
      without.erase(without.begin() + static_cast<std::ptrdiff_t>(b.column(name)));
    CHECK(without == a.rows[k]);
  }
  // The summary's two fractions only with the flag.
  CHECK(parse_csv(run_sim(scene + " --summary").out).header.back() == "pitch_3sigma_deg");
  CHECK(parse_csv(run_sim(scene + " --intrusions --summary").out).header.back() ==
        "moon_lost_fraction");
}

TEST_CASE("intrusions: a 09:00 sun-synchronous day, statuses against offsets and the summary",
          "[intrusions]") {
  // 2026-05-01 lies in the +y head's Sun season (docs/SUN_MOON.md); the Moon, near full, meets
  // the other head's Earth pulse for a few seconds late that day (t_s 84 329 and 86 026).
  const sc::scene_plan plan = plan_of([] {
    options o = sun_sync("2026-05-01T00:00:00", 9);
    o.push_back({"step-s", "1"});
    o.push_back({"duration-s", "86400"});
    return o;
  }());
  const sc::simulation sim = sc::simulation::of(plan.scene(0)).value();
  sc::row row = sim.make_row();
  std::array<std::uint64_t, 2> sun{}, moon{};
  double largest_sun_offset = 0;
  for (std::uint64_t k = 0; k < sim.rows(); ++k) {
    sim.compute(k, row);
    for (std::size_t h = 0; h < 2; ++h) {
      const sc::head_row& hr = row.heads[h];
      if (hr.state == status::sun) {
        ++sun[h];
        // Lost only on the cone: within fov/2 + r_Sun (0.2713 deg at most, at perihelion).
        largest_sun_offset = std::max(largest_sun_offset, std::abs(hr.sun_offset_rad) / deg);
        CHECK(std::isnan(hr.chord_rad));
        CHECK(std::isnan(hr.roll_err_rad));
      }
      if (hr.state == status::moon) {
        ++moon[h];
        CHECK(std::abs(hr.moon_offset_rad) / deg < 0.28);  // r_Moon from 800 km: <= 0.28 deg
      }
    }
    // The system keeps solving from the head that was not blinded.
    CHECK(row.state == status::ok);
  }
  INFO("sun rows h1 " << sun[0] << ", h2 " << sun[1] << "; moon rows h1 " << moon[0] << ", h2 "
                      << moon[1] << "; largest |offset| of a sun row " << largest_sun_offset);
  CHECK(sun[0] > 20);
  CHECK(sun[1] == 0);
  CHECK(largest_sun_offset < 0.2713);
  CHECK(moon[0] + moon[1] > 0);
}

namespace {

// An independent look at the Sun of one row: the direct ERFA Sun (no track), the truth's state
// and attitude turned into head 1's scan frame; the gap between its pulse and the Earth pulse
// whose crossings `earth` are (rad, < 0 when they meet), and its elevation above the limb of the
// sphere `radius_m` (rad, < 0 when hidden).
struct sun_margins {
  double pulse_gap;
  double above_limb;
};

sun_margins margins_at(const sc::simulation& sim, const sc::head_config& h, double t,
                       double radius_m, const conescan::crossings<double>& earth) {
  const sc::truth_state truth = sim.truth().truth_at(t);
  const src::instant at = src::add_seconds(sim.truth().epoch(), t);
  const src::body_view sun =
      src::view_from(src::sun_moon_at(at).value().sun_tod_m, src::sun_radius_m, truth.r_eci_m);
  const conescan::mat3<double> eci_from_orbit =
      conescan::dcm_eci_from_orbit(truth.r_eci_m, truth.v_eci_m_s);
  const vec3<double> in_body =
      apply(truth.body_from_orbit, apply_transpose(eci_from_orbit, sun.direction_tod));
  const auto head = conescan::sensor_head<double>::from_mounting(
      h.alpha_deg * deg, h.beta_deg * deg, {h.gamma_deg * deg, h.sigma_deg * deg, 0}, {0, 0},
      10 * deg);
  const conescan::body_pulse<double> pulse = conescan::body_pulse_of(
      head.circle(), head.in_scan_frame(in_body), sun.angular_radius_rad, 0.0);
  const double gap = std::abs(conescan::wrap_pi(pulse.azimuth - earth.phase())) -
                     (pulse.half_width + earth.half_chord());
  const double r = norm(truth.r_eci_m);
  const double from_nadir = std::acos(-dot(sun.direction_tod, truth.r_eci_m) / r);
  return {gap, from_nadir - std::asin(radius_m / r)};
}

}  // namespace

TEST_CASE("intrusions: both sides of each boundary, against an independent Sun", "[intrusions]") {
  // A sphere scene (its limb is a cone about nadir), one head on the pitch axis with no
  // misalignment, two orbits of the 09:00 season at 1 s; each change of status is bisected to
  // 1e-4 s with rows at any time (simulation::compute_at). Just before and just after it the
  // statuses differ; at it the Sun's pulse just meets the Earth pulse (gap 0) or its centre just
  // clears the limb (0): each transition is one of the two, to the motion of 1e-4 s (1e-7 rad).
  options o = sun_sync("2026-05-01T00:00:00", 9, "sphere");
  o.pop_back();  // one head: beta=90
  o.push_back({"step-s", "1"});
  o.push_back({"duration-s", "12200"});
  const sc::loaded_scene scene = plan_of(o).scene(0);
  const sc::simulation sim = sc::simulation::of(scene).value();
  const double radius_m =
      scene.config.radius_km.value_or(6378.137) * 1000 + scene.config.horizon_km * 1000;
  sc::row before = sim.make_row(), after = sim.make_row(), probe = sim.make_row();
  int meets = 0, clears = 0;
  for (std::uint64_t k = 0; k + 1 < sim.rows(); ++k) {
    sim.compute(k, before);
    sim.compute(k + 1, after);
    if (before.heads[0].state == after.heads[0].state) continue;
    double lo = static_cast<double>(k), hi = lo + 1;
    const status lo_state = before.heads[0].state;
    while (hi - lo > 1e-4) {
      const double mid = (lo + hi) / 2;
      sim.compute_at(mid, probe);
      (probe.heads[0].state == lo_state ? lo : hi) = mid;
    }
    sim.compute_at(lo, before);
    sim.compute_at(hi, after);
    INFO("transition at t_s " << lo << ": " << to_string(before.heads[0].state) << " -> "
                              << to_string(after.heads[0].state));
    CHECK(before.heads[0].state != after.heads[0].state);
    // The Earth pulse of the side that measured (noise 0: measured = true crossings).
    const sc::row& measured = before.heads[0].state == status::ok ? before : after;
    const double t = measured.t_s;
    const double half = measured.heads[0].chord_rad / 2, mid = measured.heads[0].phase_rad;
    const conescan::crossings<double> earth{mid - half, mid + half, status::ok, 0};
    const sun_margins m = margins_at(sim, scene.config.heads[0], t, radius_m, earth);
    INFO("pulse gap " << m.pulse_gap << " rad, above the limb " << m.above_limb << " rad");
    const bool at_pulse = std::abs(m.pulse_gap) < 1e-6;
    const bool at_limb = std::abs(m.above_limb) < 1e-6;
    CHECK((at_pulse || at_limb));
    meets += at_pulse;
    clears += at_limb;
  }
  INFO(meets << " transitions where the pulses just meet, " << clears
             << " where the Sun just clears the limb");
  CHECK(meets >= 2);
  CHECK(clears >= 2);
}

TEST_CASE("intrusions: a head on the orbit normal sees the Sun on its cone all orbit or never",
          "[intrusions]") {
  // The +y head of an orbit-pointing satellite spins about the negative orbit normal: over an
  // orbit the Sun's angle from it moves by its own motion and parallax only (0.057 deg on the
  // paper's orbit, docs/SUN_MOON.md), so on a day whose offset lies farther than that from the
  // edge r_Sun, every row of the orbit is on the cone or none is.
  for (const auto& [epoch, in_season] :
       {std::pair{"2026-05-01T00:00:00", true}, std::pair{"2026-01-15T00:00:00", false},
        std::pair{"2026-06-19T00:00:00", true}, std::pair{"2026-08-01T00:00:00", false}}) {
    options o = sun_sync(epoch, 9);
    o.push_back({"step-s", "20"});
    o.push_back({"orbits", "1"});
    const sc::simulation sim = sc::simulation::of(plan_of(o).scene(0)).value();
    sc::row row = sim.make_row();
    double lowest = 1e9, highest = -1e9;
    int on_cone = 0;
    for (std::uint64_t k = 0; k < sim.rows(); ++k) {
      sim.compute(k, row);
      const double offset = row.heads[0].sun_offset_rad / deg;
      lowest = std::min(lowest, offset);
      highest = std::max(highest, offset);
      on_cone += std::abs(offset) <= 0.262;  // r_Sun at aphelion: inside, whatever the day
    }
    INFO(epoch << ": offset " << lowest << " to " << highest << " deg, " << on_cone << " of "
               << sim.rows() << " rows within r_Sun");
    CHECK(highest - lowest < 0.06);
    CHECK(on_cone == (in_season ? static_cast<int>(sim.rows()) : 0));
  }
}

TEST_CASE("intrusions: the Sun season of a 09:00 and a 10:30 sun-synchronous orbit",
          "[intrusions]") {
  // Days of 2026 with the Sun on the +y head's cone (|offset| <= r_Sun, pencil beam), the offset
  // sampled 7 times a day (it moves 0.06 deg an orbit: coarse steps suffice; the full calendar
  // is conescan-sim --calendar, tests/apps/test_blinding_calendar.cpp). The 09:00 orbit's Sun stays
  // 34 to 47 deg below the orbit plane, crossing the cone's 45 deg: a season of 37 days in four
  // spells; the 10:30 orbit's stays within 14.5 to 25.5 deg: none, on either head.
  for (const auto& [ltan, low, high] : {std::tuple{9.0, 33, 41}, std::tuple{10.5, 0, 0}}) {
    options o = sun_sync("2026-01-01T00:00:00", ltan);
    o.push_back({"step-s", "12342.857142857143"});  // 86400 / 7
    o.push_back({"duration-s", "31536000"});
    const sc::simulation sim = sc::simulation::of(plan_of(o).scene(0)).value();
    sc::row row = sim.make_row();
    std::set<int> days[2];
    double nearest = 1e9;
    for (std::uint64_t k = 0; k < sim.rows(); ++k) {
      sim.compute(k, row);
      for (std::size_t h = 0; h < 2; ++h) {
        const double offset = std::abs(row.heads[h].sun_offset_rad) / deg;
        if (h == 0) nearest = std::min(nearest, offset);
        if (offset <= 0.2666) days[h].insert(static_cast<int>(row.t_s / 86400));
      }
    }
    INFO("node at " << ltan << " h: " << days[0].size() << " days on the +y head's cone, "
                    << days[1].size() << " on the -y head's; nearest " << nearest << " deg");
    CHECK(static_cast<int>(days[0].size()) >= low);
    CHECK(static_cast<int>(days[0].size()) <= high);
    CHECK(days[1].empty());
    if (ltan > 10) CHECK(nearest > 15);
  }
}

TEST_CASE("intrusions: summaries merge, threads and shards give the same bytes",
          "[intrusions][cli][campaign]") {
  const std::string scene =
      args_of(sun_sync("2026-05-01T00:00:00", 9)) + " --step-s 2 --duration-s 20000";
  const auto one = run_sim(scene + " --summary --threads 1");
  REQUIRE(one.exit_status == 0);
  CHECK(run_sim(scene + " --summary --threads 2").out == one.out);
  const auto t = parse_csv(one.out);
  const double rows = t.number(0, "rows");
  CHECK(t.number(0, "sun") > 0);
  CHECK(t.number(0, "sun_lost_fraction") == t.number(0, "sun") / rows);
  CHECK(t.number(1, "moon_lost_fraction") == t.number(1, "moon") / rows);
  CHECK(t.number(2, "sun_lost_fraction") == 0);  // the system is never blinded itself
  // Two shards of runs (a noisy head: --runs 2), merged: the single process's summary.
  const std::string runs = args_of(sun_sync("2026-05-01T00:00:00", 9, "wgs84", false)) +
                           " --step-s 2 --duration-s 20000 --head beta=90,sigma=0 "
                           "--head beta=-90,sigma=0,noise=0.001 --runs 2 --summary";
  const auto whole = run_sim(runs);
  REQUIRE(whole.exit_status == 0);
  const std::string a = "conescan_test_intrusions_1.state", b = "conescan_test_intrusions_2.state";
  REQUIRE(run_sim(runs + " --shard 1/2 --summary-state " + a).exit_status == 0);
  REQUIRE(run_sim(runs + " --shard 2/2 --summary-state " + b).exit_status == 0);
  const auto merged = run_sim("--merge " + a + " " + b);
  std::remove(a.c_str());
  std::remove(b.c_str());
  INFO(merged.err);
  // The counts and fractions exactly; the statistics to Chan's merge
  // (tests/apps/test_campaign.cpp).
  const auto w = parse_csv(whole.out), m = parse_csv(merged.out);
  REQUIRE(m.rows.size() == w.rows.size());
  for (std::size_t k = 0; k < w.rows.size(); ++k)
    for (const char* name :
         {"rows", "ok", "sun", "moon", "sun_lost_fraction", "moon_lost_fraction"})
      CHECK(m.text(k, name) == w.text(k, name));
  CHECK(w.number(0, "sun") > 0);
  // A sweep carries the columns too.
  const auto swept = run_sim(scene + " --sweep h1.gamma=44:46:1 --summary");
  REQUIRE(swept.exit_status == 0);
  CHECK(parse_csv(swept.out).header.back() == "moon_lost_fraction");
  // And the error budget's summary (its lines had no fractions, in the CLI and Python alike).
  const auto budget = run_sim(scene + " --budget --summary");
  REQUIRE(budget.exit_status == 0);
  const auto b_lines = parse_csv(budget.out);
  CHECK(b_lines.header.back() == "moon_lost_fraction");
  const std::size_t all = b_lines.rows.size() - 3;  // then the sum and the interaction
  CHECK(b_lines.text(all, "source") == "all");
  CHECK(b_lines.number(all, "sun_lost_fraction") == b_lines.number(all, "sun") / rows);
}

TEST_CASE("intrusions: hostile input is refused, naming the option", "[intrusions][cli]") {
  const std::string scan = " --model scan --orbits 0.1";
  struct refused {
    std::string args;
    std::string named;
  };
  for (const refused& r : std::vector<refused>{
           {" --intrusions --orbits 0.1", "--intrusions"},  // the default model is bias
           {" --intrusions --model bias --orbits 0.1", "--intrusions"},
           {scan + " --intrusions --date 2026-01-01", "--date"},
           {scan + " --intrusions --earth wgs84 --horizon-shift-km 5 --sun-declination-deg 3",
            "--sun-declination-deg"},
           // The track of a span ending at 2099-12-31T23:59:59 UTC needs the ephemerides to
           // 2100-01-01T12:00:08 TT, past their end.
           {" --model scan --intrusions --epoch 2099-12-31T17:58:59 --step-s 21660 "
            "--duration-s 21660",
            "--epoch"},
           {scan + " --intrusions --epoch 1959-12-31T23:00:00", "--epoch"},
           {scan + " --intrusions=maybe", "--intrusions"}}) {
    const auto run = run_sim(r.args);
    INFO(r.args << ": " << run.err);
    CHECK(run.exit_status == 2);
    CHECK(run.out.empty());
    CHECK(run.err.find(r.named) != std::string::npos);
  }
  const temp_file file("intrusions = \"yes\"\n");
  const auto from_file = run_sim("--config " + file.path + scan);
  CHECK(from_file.exit_status == 2);
  CHECK(from_file.err.find("intrusions") != std::string::npos);
  // Just inside the ephemerides' end: accepted.
  CHECK(run_sim(" --model scan --intrusions --epoch 2099-12-31T17:58:59 --step-s 21500 "
                "--duration-s 21500")
            .exit_status == 0);
  // A budget runs with the bodies in every source's scene (its sources are scan scenes).
  CHECK(run_sim(" --intrusions --budget --summary --orbits 0.1").exit_status == 0);
}

TEST_CASE("intrusions: conescan-fit leaves out the rows a body blinds and says how many",
          "[intrusions][cli][fit]") {
  // Telemetry of the 09:00 season with the heads' true values as the fit's start: the fit's
  // scene finds the same blinded rows as the telemetry's statuses.
  const std::string scene = args_of(sun_sync("2026-05-01T00:00:00", 9, "wgs84", false)) +
                            " --step-s 5 --duration-s 20000";
  const std::string heads =
      " --head beta=90,sigma=0.03,phase=40,noise=0.01 "
      "--head beta=-90,sigma=0,noise=0.01";
  const auto tm = run_sim(scene + heads);
  REQUIRE(tm.exit_status == 0);
  const auto t = parse_csv(tm.out);
  int sun_rows = 0;
  for (std::size_t k = 0; k < t.rows.size(); ++k) sun_rows += t.text(k, "h1_status") == "sun";
  REQUIRE(sun_rows > 0);
  const temp_file file(tm.out, ".csv");
  const std::string fit = "--telemetry " + file.path + scene + heads + " --free h1.sigma,h1.phase";
  const auto table = run_program(CONESCAN_FIT_PATH, fit);
  INFO(table.err << table.out);
  REQUIRE(table.exit_status == 0);
  CHECK(table.out.find("rows left out because a body blinded the head (MODEL 13): h1 " +
                       std::to_string(sun_rows) + " by the Sun") != std::string::npos);
  const auto json = run_program(CONESCAN_FIT_PATH, fit + " --json");
  REQUIRE(json.exit_status == 0);
  CHECK(json.out.find("\"blinded\": {\"sun\": [" + std::to_string(sun_rows) + ", 0]") !=
        std::string::npos);
  // The design leaves them out as well; without --intrusions nothing is said.
  const auto design =
      run_program(CONESCAN_FIT_PATH, "--predict" + scene + heads + " --free h1.sigma,h1.phase");
  CHECK(design.out.find("by the Sun") != std::string::npos);
  std::string plain = fit;
  plain.replace(plain.find(" --intrusions"), 13, "");
  const auto without = run_program(CONESCAN_FIT_PATH, plain);
  CHECK(without.exit_status == 0);
  CHECK(without.out.find("blinded") == std::string::npos);
}

TEST_CASE("one Sun: --date takes ERFA's declination at noon UTC, --print-config writes it",
          "[intrusions][sun_erfa]") {
  // Provenance of the new reference: sun_declination.hpp (eraEpv00, eraAb, IAU 2006/2000A) at
  // 2026-06-21T12:00:00 UTC; the Astronomical Almanac's low-precision formula (--date before
  // the one Sun), written here, agrees to its 0.01 deg: measured 0.0028 deg at this date.
  sc::scene_request r;
  REQUIRE(sc::apply_option(*sc::find_option("date"), r,
                           {"date", "2026-06-21", conescan::origin::command_line()})
              .ok());
  const src::instant noon = src::parse_epoch("2026-06-21T12:00:00", src::time_scale::utc).value();
  CHECK(*r.scene.sun_declination_deg == src::sun_declination_rad(noon) / deg);
  const double n = 2461213.0 - 2451545.0;  // JD of the date's noon from J2000
  const double g = (357.528 + 0.9856003 * n) * deg;
  const double lambda = (280.460 + 0.9856474 * n + 1.915 * std::sin(g) + 0.020 * std::sin(2 * g));
  const double almanac =
      std::asin(std::sin((23.439 - 0.0000004 * n) * deg) * std::sin(lambda * deg)) / deg;
  INFO("ERFA " << *r.scene.sun_declination_deg << " deg, the Almanac " << almanac << " deg");
  CHECK(std::abs(*r.scene.sun_declination_deg - almanac) < 0.006);
  // --print-config writes the declination, which reads back to the same scene.
  const std::string scene = " --earth wgs84 --model scan --horizon-preset co2-15um --orbits 0.05";
  const auto printed = run_sim(scene + " --date 2026-06-21 --print-config");
  CHECK(printed.out.find("sun-declination-deg = " +
                         conescan::text::shortest_text(*r.scene.sun_declination_deg)) !=
        std::string::npos);
  // The dates of ERFA's UTC table, and no others.
  for (const char* good : {"1960-01-01", "2099-12-31", "2024-02-29"})
    CHECK(run_sim(scene + " --date " + good).exit_status == 0);
  for (const char* bad : {"1959-12-31", "2100-01-01", "2025-02-29", "2025-1-01", "2025-01-01x"}) {
    const auto run = run_sim(scene + " --date " + std::string(bad));
    INFO(bad << ": " << run.err);
    CHECK(run.exit_status == 2);
    CHECK(run.err.find("--date") != std::string::npos);
  }
}
