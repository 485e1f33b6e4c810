// The blinding calendar (conescan-sim --calendar; src/simulation/blinding_calendar.hpp,
// calendar_csv.hpp): against the rows at the calendar's resolution (every row a body blinds lies
// in one of its intervals, every row inside one is blinded, one interval per run of blinded
// rows) on a circular sun-synchronous orbit, an eccentric orbit with misaligned heads and fields,
// and a wobbling attitude table; the edges to the tolerance, both sides; the CSV tables by hand;
// the span, the orbit position and the command line.
#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "simulation/blinding_calendar.hpp"
#include "simulation/calendar_csv.hpp"
#include "simulation/simulation.hpp"
#include "support/cli.hpp"
#include "support/scene_of.hpp"
#include "text/number_text.hpp"

namespace sc = conescan::scene;
namespace src = conescan::sources;
using conescan::status;
using conescan::vec3;
using conescan_test::run_sim;
using conescan_test::scene_of;
using conescan_test::temp_file;

namespace {

using options = std::vector<std::pair<std::string, std::string>>;

// docs/SUN_MOON.md's example day: 800 km sun-synchronous, node at 09:00 on 2026-05-01 (its RAAN
// there), two pitch-axis heads: the +y head in its Sun season, the -y head meets the Moon.
options example_day() {
  return {{"model", "scan"},
          {"earth", "wgs84"},
          {"epoch", "2026-05-01T00:00:00"},
          {"a-km", "7178.137"},
          {"e", "0"},
          {"sun-sync", "true"},
          {"j2", "true"},
          {"raan-deg", "353.93852694944263"},
          {"head", "beta=90,sigma=0"},
          {"head", "beta=-90,sigma=0"}};
}

// The paper's orbit (e = 0.1) on the same day with its node at RAAN 90 deg: misaligned heads with
// 2 deg fields, the Sun on the -y head's cone, the Moon on the +y head's.
options eccentric_day() {
  return {{"model", "scan"},  {"earth", "wgs84"},        {"epoch", "2026-05-01T00:00:00"},
          {"raan-deg", "90"}, {"head", "beta=90,fov=2"}, {"head", "beta=-90,phase=90,fov=2"}};
}

options with(options o, const options& more) {
  o.insert(o.end(), more.begin(), more.end());
  return o;
}

sc::blinding_calendar calendar_of(const options& o) {
  const conescan::checked<sc::blinding_calendar> c =
      sc::blinding_calendar_of(scene_of(with(o, {{"calendar", "unused"}})));
  INFO((c.ok() ? std::string() : c.error().text()));
  REQUIRE(c.ok());
  return c.value();
}

// The interval of `head` and `body` in `list` that holds t, or nullptr; `edge_s`: the distance
// from t to the nearest edge of that head and body's intervals.
const sc::calendar_interval* holding(const std::vector<sc::calendar_interval>& list,
                                     std::size_t head, std::size_t body, double t, double& edge_s) {
  const sc::calendar_interval* found = nullptr;
  edge_s = INFINITY;
  for (const sc::calendar_interval& i : list) {
    if (i.head != head || i.body != body) continue;
    edge_s = std::min({edge_s, std::abs(t - i.start_s), std::abs(t - i.end_s)});
    if (t >= i.start_s && t <= i.end_s) found = &i;
  }
  return found;
}

// The calendar of `o` over duration_s against its rows at 1 s (--intrusions): each row's status
// against the intervals (rows within 2 ms of an edge left out: the edges hold to 0.5 ms), and one
// interval per run of blinded rows. With `every_row` false (heads with a field run the sensor
// physics, ~0.2 ms a row) the statuses come from the rule at the rows' times
// (simulation::sky_check_at), and the rows themselves are computed within 30 s of every edge and
// every 600th row, their statuses the rule's. Returns the intervals lost.
std::size_t check_against_rows(const options& o, const std::string& duration_s,
                               bool every_row = true) {
  const sc::blinding_calendar calendar = calendar_of(with(o, {{"duration-s", duration_s}}));
  const conescan::checked<sc::simulation> made = sc::simulation::of(
      scene_of(with(o, {{"intrusions", "true"}, {"step-s", "1"}, {"duration-s", duration_s}})));
  REQUIRE(made.ok());
  const sc::simulation& sim = made.value();
  REQUIRE(calendar.heads == sim.head_count());
  sc::row row = sim.make_row();
  sc::simulation::sky_check sky;
  std::vector<std::size_t> runs(sim.head_count() * sc::calendar_bodies, 0);
  std::vector<const sc::calendar_interval*> last(runs.size(), nullptr);
  std::size_t rows_checked = 0, rows_blinded = 0, rows_computed = 0;
  for (std::uint64_t k = 0; k < sim.rows(); ++k) {
    const double t = static_cast<double>(k);
    sim.sky_check_at(t, sky);
    REQUIRE(sky.ok);
    for (std::size_t h = 0; h < sim.head_count(); ++h)
      for (std::size_t b = 0; b < sc::calendar_bodies; ++b) {
        double edge_s = 0;
        const sc::calendar_interval* in = holding(calendar.lost, h, b, t, edge_s);
        const status blinding = b == 0 ? status::sun : status::moon;
        INFO("row t = " << t << " s, head " << h + 1 << ", " << sc::calendar_body_name(b));
        if (every_row || edge_s < 30 || k % 600 == 0) {
          sim.compute(k, row);
          ++rows_computed;
          REQUIRE((row.heads[h].state == blinding) == (sky.heads[h].state == blinding));
        }
        if (edge_s < 2e-3) continue;
        REQUIRE((sky.heads[h].state == blinding) == (in != nullptr));
        ++rows_checked;
        if (!in) continue;
        ++rows_blinded;
        if (in != last[h * sc::calendar_bodies + b]) ++runs[h * sc::calendar_bodies + b];
        last[h * sc::calendar_bodies + b] = in;
      }
  }
  // Every interval here lasts more than a row step, so each holds a run of rows of its own.
  std::size_t runs_total = 0;
  for (std::size_t n : runs) runs_total += n;
  for (const sc::calendar_interval& i : calendar.lost) CHECK(i.end_s - i.start_s > 1.0);
  CHECK(runs_total == calendar.lost.size());
  CHECK(rows_checked > sim.rows());
  CHECK(rows_blinded > 0);
  CHECK(rows_computed > sim.rows() / 600);
  return calendar.lost.size();
}

// Both sides of every edge, 1 ms out: the rule (sky_check_at) says so (edges to 0.5 ms).
void check_edges(const options& o, const std::string& duration_s) {
  const sc::blinding_calendar calendar = calendar_of(with(o, {{"duration-s", duration_s}}));
  const sc::simulation sim =
      sc::simulation::of(scene_of(with(o, {{"intrusions", "true"}, {"duration-s", duration_s}})))
          .value();
  sc::simulation::sky_check s;
  const auto lost = [&](const sc::calendar_interval& i, double t) {
    sim.sky_check_at(t, s);
    REQUIRE(s.ok);
    return s.heads[i.head].state == (i.body == 0 ? status::sun : status::moon);
  };
  const auto on_cone = [&](const sc::calendar_interval& i, double t) {
    sim.sky_check_at(t, s);
    REQUIRE(s.ok);
    const auto& view = i.body == 0 ? s.bodies.sun : s.bodies.moon;
    const double offset =
        i.body == 0 ? s.heads[i.head].sun_offset_rad : s.heads[i.head].moon_offset_rad;
    return std::abs(offset) <= s.heads[i.head].fov_rad / 2 + view.angular_radius_rad;
  };
  int edges = 0;
  for (const auto& [list, holds] :
       {std::pair{&calendar.lost, +0}, std::pair{&calendar.on_cone, +1}})
    for (const sc::calendar_interval& i : *list) {
      const auto state = [&](double t) { return holds == 0 ? lost(i, t) : on_cone(i, t); };
      INFO((holds == 0 ? "lost" : "on the cone")
           << ": head " << i.head + 1 << ", " << sc::calendar_body_name(i.body) << ", ["
           << i.start_s << ", " << i.end_s << "] s");
      CHECK(state((i.start_s + i.end_s) / 2));
      if (i.start_s > 0) {
        CHECK_FALSE(state(i.start_s - 1e-3));
        CHECK(state(i.start_s + 1e-3));
        ++edges;
      }
      if (i.end_s < calendar.span_s) {
        CHECK(state(i.end_s - 1e-3));
        CHECK_FALSE(state(i.end_s + 1e-3));
        ++edges;
      }
    }
  CHECK(edges > 10);
}

}  // namespace

TEST_CASE("calendar: the example day's events are the rows', one interval per run", "[calendar]") {
  const sc::blinding_calendar c = calendar_of(with(example_day(), {{"duration-s", "86400"}}));
  // The +y head loses its crossings to the Sun twice an orbit (docs/SUN_MOON.md: 113 rows at
  // 1 s), the -y head twice to the Moon (17 rows); the Sun on the +y head's cone all day.
  std::size_t sun = 0, moon = 0;
  for (const sc::calendar_interval& i : c.lost) (i.body == 0 ? sun : moon) += 1;
  CHECK(sun == 28);
  CHECK(moon == 2);
  REQUIRE_FALSE(c.on_cone.empty());
  CHECK(c.on_cone.front().head == 0);
  CHECK(c.on_cone.front().body == 0);
  CHECK(c.on_cone.front().start_s == 0);
  CHECK(c.on_cone.front().end_s == 86400);
  CHECK(c.resolution_s == 1);
  CHECK(check_against_rows(example_day(), "86400") == 30);
}

// [many-chain-rows]: a day of rows with fields runs the sensor physics' chain on every row near an
// event (minutes under the sanitizers, which leave it out; the chain has its own tests there).
TEST_CASE("calendar: an eccentric orbit, misaligned heads with fields: the rows'",
          "[calendar][many-chain-rows]") {
  CHECK(check_against_rows(eccentric_day(), "86400", false) >= 30);
}

TEST_CASE("calendar: a wobbling attitude (a table of angles): the rows'", "[calendar]") {
  // 1 deg of roll, pitch and yaw at periods of 10, 7 and 13 minutes, every 5 s over 6 h.
  std::ostringstream table;
  table << "t_s,roll_deg,pitch_deg,yaw_deg\n";
  for (int t = 0; t <= 6 * 3600 + 5; t += 5) {
    const double w = 2 * std::numbers::pi * t;
    table << t << "," << std::sin(w / 600) << "," << std::sin(w / 420) << "," << std::cos(w / 780)
          << "\n";
  }
  const temp_file file(table.str(), ".csv");
  options o = example_day();
  o.push_back({"attitude-csv", file.path});
  // Linear interpolation of a 1 deg wobble sampled every 5 s is 8e-4 deg off between samples:
  // accepted here (both the calendar and the rows see the same interpolated attitude).
  o.push_back({"interpolation-tolerance-deg", "0.001"});
  CHECK(check_against_rows(o, "21600") >= 3);
  // The wobble takes the Sun on and off the +y head's cone (1 deg against its 0.27 deg) many
  // times: the steps' bounds ride on the attitude's sampled rate.
  CHECK(calendar_of(with(o, {{"duration-s", "21600"}})).on_cone.size() >= 20);
  check_edges(o, "21600");
}

TEST_CASE("calendar: every edge within the tolerance, both sides", "[calendar]") {
  check_edges(example_day(), "86400");
  check_edges(eccentric_day(), "43200");
}

TEST_CASE("calendar: the CSV tables, by hand", "[calendar]") {
  sc::blinding_calendar c;
  c.epoch = src::parse_epoch("2026-01-01T00:00:00", src::time_scale::utc).value();
  c.span_s = 2.5 * 86400;
  c.resolution_s = 1;
  c.heads = 2;
  c.lost = {{0, 0, 86390, 86410, 12.5}, {1, 1, 100, 105.5, 300}, {0, 0, 90000, 90002, 13}};
  c.on_cone = {{0, 0, 0, 2.5 * 86400, 0}};
  const std::vector<sc::calendar_file> files = sc::calendar_csv_files(c);
  REQUIRE(files.size() == 4);
  CHECK(files[0].name == "lost.csv");
  CHECK(files[0].text ==
        "head,body,start_utc,end_utc,start_s,end_s,duration_s,day,start_orbit_deg\n"
        "h1,sun,2026-01-01T23:59:50.000,2026-01-02T00:00:10.000,86390.000,86410.000,20.000,1,"
        "12.50\n"
        "h2,moon,2026-01-01T00:01:40.000,2026-01-01T00:01:45.500,100.000,105.500,5.500,1,300.00\n"
        "h1,sun,2026-01-02T01:00:00.000,2026-01-02T01:00:02.000,90000.000,90002.000,2.000,2,"
        "13.00\n");
  CHECK(files[1].name == "on-cone.csv");
  CHECK(files[2].name == "days.csv");
  // The interval across midnight counts 10 s in each day, its event in the first; day 3 is half.
  CHECK(files[2].text ==
        "head,body,day,date,on_cone_s,lost_s,lost_events\n"
        "h1,sun,1,2026-01-01,86400.000,10.000,1\n"
        "h1,sun,2,2026-01-02,86400.000,12.000,1\n"
        "h1,sun,3,2026-01-03,43200.000,0.000,0\n"
        "h1,moon,1,2026-01-01,0.000,0.000,0\n"
        "h1,moon,2,2026-01-02,0.000,0.000,0\n"
        "h1,moon,3,2026-01-03,0.000,0.000,0\n"
        "h2,sun,1,2026-01-01,0.000,0.000,0\n"
        "h2,sun,2,2026-01-02,0.000,0.000,0\n"
        "h2,sun,3,2026-01-03,0.000,0.000,0\n"
        "h2,moon,1,2026-01-01,0.000,5.500,1\n"
        "h2,moon,2,2026-01-02,0.000,0.000,0\n"
        "h2,moon,3,2026-01-03,0.000,0.000,0\n");
  CHECK(files[3].name == "seasons.csv");
  CHECK(files[3].text ==
        "head,body,on_cone_days,first_on_cone_day,last_on_cone_day,lost_days,first_lost_day,"
        "last_lost_day,lost_events,lost_s,lost_hours,shortest_event_s,longest_event_s\n"
        "h1,sun,3,1,3,2,1,2,2,22.000,0.0061,2.000,20.000\n"
        "h1,moon,0,,,0,,,0,0.000,0.0000,,\n"
        "h2,sun,0,,,0,,,0,0.000,0.0000,,\n"
        "h2,moon,0,,,1,1,1,1,5.500,0.0015,5.500,5.500\n");
}

TEST_CASE("calendar: a year from the epoch, to the same date", "[calendar]") {
  const auto year_from = [](const char* epoch) {
    return sc::calendar_year_s(src::parse_epoch(epoch, src::time_scale::utc).value()) / 86400;
  };
  CHECK(year_from("2026-01-01T00:00:00") == 365);
  CHECK(year_from("2027-03-01T06:00:00") == 366);  // across 2028-02-29
  CHECK(year_from("2028-02-29T00:00:00") == 365);  // to 2029-02-28
  // 2016 ended with a leap second: the year from its July holds it.
  CHECK(year_from("2016-07-01T00:00:00") * 86400 == Approx(365 * 86400.0 + 1).margin(1e-6));
}

TEST_CASE("calendar: where in the orbit, the argument of latitude", "[calendar]") {
  const double i = 60 * std::numbers::pi / 180;
  const vec3<double> up(0, std::cos(i), std::sin(i));
  CHECK(sc::argument_of_latitude_deg({7e6, 0, 0}, up * 7500.0) == Approx(0).margin(1e-12));
  CHECK(sc::argument_of_latitude_deg(up * 7e6, {-7500, 0, 0}) == Approx(90).margin(1e-12));
  CHECK(sc::argument_of_latitude_deg({-7e6, 0, 0}, up * -7500.0) == Approx(180).margin(1e-12));
  CHECK(sc::argument_of_latitude_deg(up * -7e6, {7500, 0, 0}) == Approx(270).margin(1e-12));
  // Equatorial: the true longitude along the motion.
  CHECK(sc::argument_of_latitude_deg({0, 7e6, 0}, {-7500, 0, 0}) == Approx(90).margin(1e-12));
  CHECK(sc::argument_of_latitude_deg({0, 7e6, 0}, {7500, 0, 0}) == Approx(270).margin(1e-12));
}

TEST_CASE("calendar: the command line", "[calendar][cli]") {
  const std::string day =
      "--model scan --earth wgs84 --epoch 2026-05-01T00:00:00 --a-km 7178.137 --e 0 --sun-sync "
      "--j2 --raan-deg 353.93852694944263 --head beta=90,sigma=0 --head beta=-90,sigma=0 ";
  const std::string dir = "conescan_test_calendar_" + std::to_string(::getpid());
  SECTION("the files, and a scene file that writes them again") {
    auto run = run_sim(day + "--duration-s 86400 --calendar " + dir);
    INFO(run.err);
    REQUIRE(run.exit_status == 0);
    CHECK(run.out.empty());
    CHECK(run.err.find("calendar of 2 head(s) over 1 days at 1 s: 30 intervals lost") !=
          std::string::npos);
    const auto read = [&](const std::string& name) {
      std::ifstream in(dir + "/" + name);
      std::stringstream ss;
      ss << in.rdbuf();
      return ss.str();
    };
    const std::string lost = read("lost.csv");
    CHECK(lost.rfind("head,body,start_utc,end_utc,", 0) == 0);
    CHECK(std::count(lost.begin(), lost.end(), '\n') == 31);
    CHECK(read("seasons.csv").find("\nh1,sun,1,1,1,1,1,1,28,") != std::string::npos);
    const auto config = run_sim(day + "--duration-s 86400 --calendar " + dir + " --print-config");
    REQUIRE(config.exit_status == 0);
    for (const char* line : {"calendar = \"", "intrusions = true", "step-s = 1\n"})
      CHECK(config.out.find(line) != std::string::npos);
    const temp_file scene(config.out);
    std::remove((dir + "/lost.csv").c_str());
    REQUIRE(run_sim("--config " + scene.path).exit_status == 0);
    CHECK(read("lost.csv") == lost);
    for (const char* name : {"lost.csv", "on-cone.csv", "days.csv", "seasons.csv"})
      std::remove((dir + "/" + name).c_str());
    ::rmdir(dir.c_str());
  }
  SECTION("a year from the epoch unless the span is given") {
    const auto config = run_sim(day + "--calendar " + dir + " --print-config");
    REQUIRE(config.exit_status == 0);
    CHECK(config.out.find("duration-s = 31536000\n") != std::string::npos);
    CHECK(config.out.find("max-rows = 31536001\n") != std::string::npos);
  }
  SECTION("refused, naming the option") {
    struct refusal {
      std::string args, says;
    };
    for (const refusal& r :
         {refusal{"--calendar d", "--calendar: needs --model scan"},
          refusal{day + "--calendar d --sweep e=0:0.1:0.05",
                  "--calendar: writes one scene's calendar: drop --sweep"},
          refusal{day + "--calendar d --summary", "drop --summary"},
          refusal{day + "--calendar d --step-s 0.0001",
                  "--step-s: step-s = 1e-04 is below the calendar's least resolution"}}) {
      const auto run = run_sim(r.args);
      INFO(r.args << "\n" << run.err);
      CHECK(run.exit_status == 2);
      CHECK(run.out.empty());
      CHECK(run.err.find(r.says) != std::string::npos);
    }
  }
  SECTION("a file in the way of the directory: exit 1, nothing written") {
    const temp_file in_the_way("x");
    const auto run = run_sim(day + "--duration-s 600 --calendar " + in_the_way.path);
    CHECK(run.exit_status == 1);
    CHECK(run.err.find("cannot make the directory") != std::string::npos);
  }
}
