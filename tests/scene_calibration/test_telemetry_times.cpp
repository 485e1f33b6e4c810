// Telemetry with absolute time stamps (calibration/telemetry.hpp): utc, or gps_week and gps_s,
// turned into seconds from the scene's epoch by scene_calibration's scene_time_stamps (ERFA's
// leap seconds); the same rows as t_s; mixed and unknown time columns refused.
#include <catch2/catch.hpp>
#include <sstream>
#include <string>

#include "calibration/telemetry.hpp"
#include "scene/loaded_scene.hpp"
#include "scene/scene_config.hpp"
#include "scene_calibration/scene_fit.hpp"

namespace cal = conescan::calibration;

namespace {

conescan::scene::loaded_scene scene_at(const char* epoch_utc) {
  conescan::scene::scene_config s;
  s.epoch_utc = epoch_utc;
  conescan::checked<conescan::scene::loaded_scene> loaded = conescan::scene::load_scene(s);
  REQUIRE(loaded.ok());
  return std::move(loaded).value();
}

conescan::checked<cal::telemetry> read(const std::string& text,
                                       const cal::telemetry_time_stamps& stamps) {
  std::istringstream in(text);
  return cal::read_telemetry(in, "tm.csv", 1, stamps);
}

std::vector<double> times_of(const cal::telemetry& t) {
  std::vector<double> out;
  for (const cal::observation& o : t.observations) out.push_back(o.sample.t_s);
  return out;
}

}  // namespace

TEST_CASE("telemetry: utc and GPS time stamps read as seconds from the scene's epoch",
          "[calibration][time]") {
  // 2016-12-31T23:59:58 UTC; the leap second 23:59:60 lies between the second and third rows.
  const cal::telemetry_time_stamps stamps = cal::scene_time_stamps(scene_at("2016-12-31T23:59:58"));
  const auto by_t = read("t_s,h1_chord_deg,h1_phase_deg\n0,100,1\n1.5,101,2\n3.5,102,3\n", stamps);
  const auto by_utc = read(
      "utc,h1_chord_deg,h1_phase_deg\n2016-12-31T23:59:58Z,100,1\n2016-12-31T23:59:59.5,101,2\n"
      "2017-01-01T00:00:00.5,102,3\n",
      stamps);
  // GPS = UTC + 17 s in 2016, + 18 s from 2017 (GPS week 1930 began 2017-01-01T00:00 GPS):
  // 23:59:58 UTC is week 1930, second 15; 2017-01-01T00:00:00.5 UTC is second 18.5.
  const auto by_gps = read(
      "gps_week,gps_s,h1_chord_deg,h1_phase_deg\n1930,15,100,1\n1930,16.5,101,2\n"
      "1930,18.5,102,3\n",
      stamps);
  REQUIRE(by_t.ok());
  REQUIRE(by_utc.ok());
  REQUIRE(by_gps.ok());
  const std::vector<double> expected = times_of(by_t.value());
  for (const auto* other : {&by_utc, &by_gps}) {
    const std::vector<double> got = times_of(other->value());
    REQUIRE(got.size() == expected.size());
    for (std::size_t i = 0; i < got.size(); ++i) CHECK(got[i] == Approx(expected[i]).margin(1e-9));
  }
}

TEST_CASE("telemetry: absolute time columns refused when mixed, partial, bad or without epoch",
          "[calibration][time]") {
  const cal::telemetry_time_stamps stamps = cal::scene_time_stamps(scene_at("2026-01-01T00:00:00"));
  const auto error = [&](const std::string& text, const cal::telemetry_time_stamps& s) {
    const auto r = read(text, s);
    REQUIRE_FALSE(r.ok());
    return r.error().text();
  };
  CHECK(error("t_s,utc,h1_chord_deg,h1_phase_deg\n0,2026-01-01T00:00:00,100,1\n", stamps) ==
        "tm.csv:1: --telemetry: mixed time columns: give one time (t_s, utc, or gps_week and "
        "gps_s)");
  CHECK(error("gps_s,h1_chord_deg,h1_phase_deg\n0,100,1\n", stamps) ==
        "tm.csv:1: --telemetry: gps_s without gps_week");
  CHECK(error("utc,h1_chord_deg,h1_phase_deg\n2026-01-01T00:00:00,100,1\n", {}) ==
        "tm.csv:1: --telemetry: absolute times (utc, GPS) need the scene's epoch");
  CHECK(error("utc,h1_chord_deg,h1_phase_deg\n2026-01-01 00:00,100,1\n", stamps) ==
        "tm.csv:2:1: --telemetry: column utc: malformed epoch '2026-01-01 00:00' (expected "
        "YYYY-MM-DDThh:mm:ss[.fff] or YYYY-DDDThh:mm:ss[.fff])");
  CHECK(error("utc,h1_chord_deg,h1_phase_deg\n2026-06-30T23:59:60,100,1\n", stamps) ==
        "tm.csv:2:1: --telemetry: column utc: epoch '2026-06-30T23:59:60' UTC: second 60 on a day "
        "without a leap second (UTC)");
  CHECK(error("gps_week,gps_s,h1_chord_deg,h1_phase_deg\n2400,-1,100,1\n", stamps) ==
        "tm.csv:2:1: --telemetry: column gps_week: GPS seconds of the week -1 are outside [0, "
        "604800)");
  CHECK(error("gps_week,gps_s,h1_chord_deg,h1_phase_deg\nx,0,100,1\n", stamps) ==
        "tm.csv:2:1: --telemetry: column gps_week: 'x' is not a finite number");
  CHECK(error("utc,h1_chord_deg,h1_phase_deg\n2026-01-01T00:00:01,100,1\n"
              "2026-01-01T00:00:00,100,1\n",
              stamps) ==
        "tm.csv:3:1: --telemetry: t_s = 0 does not follow the previous row's 1: rows must be in "
        "increasing time");
}
