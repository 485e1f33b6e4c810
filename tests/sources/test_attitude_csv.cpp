// The attitude table (src/sources/attitude_csv.hpp): linear in the angles, the short way round,
// exact at its rows, its span checked, and every malformed file refused with file and line.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "conescan/attitude.hpp"
#include "sources/aem.hpp"
#include "sources/attitude_csv.hpp"
#include "sources/rotation.hpp"
#include "support/diagnostic_of.hpp"
#include "support/text_file.hpp"
#include "text/number_text.hpp"

using conescan::checked;
using conescan::diagnostic;

using namespace conescan::sources;
using conescan_test::replaced;
using conescan_test::text_file;

namespace {

constexpr double deg = std::numbers::pi / 180;

const attitude_table& must_read(const checked<attitude_table>& r) {
  if (const diagnostic* e = error_of(r)) FAIL(e->text());
  return r.value();
}

attitude_angles at(const attitude_table& t, double t_s) {
  const checked<attitude_angles> a = t.angles_at(t_s);
  if (const diagnostic* e = error_of(a)) FAIL(e->text());
  return a.value();
}

std::string refusal_of_text(std::string_view content) {
  const text_file f("attitude.csv", content);
  const checked<attitude_table> r = read_attitude_csv(f.path());
  const diagnostic* e = error_of(r);
  if (!e) FAIL("read, not refused");
  return replaced(e->text(), f.path(), "attitude.csv");
}

}  // namespace

TEST_CASE("attitude CSV: linear in the angles, the short way round", "[attitude_csv]") {
  const text_file f("attitude.csv",
                    "t_s, roll_deg ,pitch_deg,yaw_deg\r\n"
                    "0,0,2,179\r\n"
                    "10,1,-2,-179\r\n"
                    "\r\n"
                    "20,1.5,-2,-170\r\n");
  const checked<attitude_table> r = read_attitude_csv(f.path());
  const attitude_table& t = must_read(r);
  CHECK(t.rows() == 3);
  const attitude_angles mid = at(t, 5);
  CHECK(mid.roll_rad == Approx(0.5 * deg));
  CHECK(mid.pitch_rad == Approx(0.0).margin(1e-15));
  CHECK(std::remainder(mid.yaw_rad - 180 * deg, 2 * std::numbers::pi) == Approx(0).margin(1e-14));
  CHECK(at(t, 2.5).yaw_rad == Approx(179.5 * deg));
  // Exact at the rows.
  CHECK(at(t, 10).roll_rad == 1 * deg);
  CHECK(at(t, 20).yaw_rad == -170 * deg);
  CHECK(at(t, 15).roll_rad == Approx(1.25 * deg));
  CHECK(t.check_coverage(0, 20).ok());
  CHECK(t.check_coverage(3, 3).ok());
  const checked<void> e = t.check_coverage(0, 20.5);
  REQUIRE_FALSE(e.ok());
  CHECK(replaced(e.error().text(), f.path(), "attitude.csv") ==
        "attitude.csv: the attitude covers t_s 0 to 20 s, not the scene's 0 to 20.5 s");
  const checked<attitude_angles> before = t.angles_at(-0.1);
  REQUIRE(error_of(before));
  CHECK(error_of(before)->message == "t_s -0.1 is outside the attitude's 0 to 20 s");
}

TEST_CASE("attitude CSV: linear in angles against the geodesic, as documented", "[attitude_csv]") {
  // (0, 2, 2) -> (2, 0, 2) deg: their midpoints differ by 8.7e-3 deg (attitude_csv.hpp).
  const text_file f("attitude.csv", "t_s,roll_deg,pitch_deg,yaw_deg\n0,0,2,2\n1,2,0,2\n");
  const checked<attitude_table> r = read_attitude_csv(f.path());
  const attitude_angles m = at(must_read(r), 0.5);
  const conescan::mat3<double> linear =
      conescan::dcm_body_from_orbit(m.roll_rad, m.pitch_rad, m.yaw_rad);
  // The geodesic's midpoint, by the core's DCMs and rotation.hpp's rotation vectors.
  const conescan::mat3<double> a = conescan::dcm_body_from_orbit(0.0, 2 * deg, 2 * deg);
  const conescan::mat3<double> b = conescan::dcm_body_from_orbit(2 * deg, 0.0, 2 * deg);
  // Rotation B A^T as a quaternion from its matrix (trace form: the rotation is small).
  const conescan::mat3<double> rel = b * glm::transpose(a);
  const double w = 0.5 * std::sqrt(1 + rel[0][0] + rel[1][1] + rel[2][2]);
  const quaternion q{w, (rel[1][2] - rel[2][1]) / (4 * w), (rel[2][0] - rel[0][2]) / (4 * w),
                     (rel[0][1] - rel[1][0]) / (4 * w)};
  const quaternion half = quaternion_from_rotation_vector(rotation_vector(q) * 0.5);
  const conescan::mat3<double> slerp = rotation_matrix(half) * a;
  const conescan::mat3<double> diff = linear * glm::transpose(slerp);
  const double angle = std::acos(std::min(1.0, 0.5 * (diff[0][0] + diff[1][1] + diff[2][2] - 1)));
  CHECK(angle / deg == Approx(8.73e-3).epsilon(0.01));
}

TEST_CASE("malformed attitude CSVs are refused with line and column", "[attitude_csv]") {
  const std::string good = "t_s,roll_deg,pitch_deg,yaw_deg\n0,0,0,0\n10,1,1,1\n";
  const std::string expected_header =
      "a time (t_s, utc, or gps_week and gps_s) and an attitude (roll_deg, pitch_deg, yaw_deg, "
      "or q_w, q_x, q_y, q_z)";
  const std::string quaternions = "t_s,q_w,q_x,q_y,q_z\n0,1,0,0,0\n10,0.8,0.6,0,0\n";
  struct bad_case {
    std::string content;
    std::string expected;
  };
  const std::vector<bad_case> cases = {
      {"", "attitude.csv: empty: expected a header of " + expected_header},
      {"t_s,roll_deg,pitch_deg,yaw_deg\n", "attitude.csv: no rows after the header"},
      {"0,0,0,0\n10,1,1,1\n", "attitude.csv:1:1: unknown column '0': expected " + expected_header},
      {replaced(good, "yaw_deg", "yaw_rad"),
       "attitude.csv:1:24: unknown column 'yaw_rad': expected " + expected_header},
      {replaced(good, "pitch_deg", "roll_deg"),
       "attitude.csv:1:14: column 'roll_deg' appears twice"},
      {replaced(good, ",yaw_deg", ""),
       "attitude.csv:1: missing column 'yaw_deg' (expected " + expected_header + ")"},
      {replaced(good, "t_s,", "utc,t_s,"),
       "attitude.csv:1: mixed time columns: give one time (t_s, utc, or gps_week and gps_s)"},
      {replaced(good, "t_s,", "gps_week,"),
       "attitude.csv:1: gps_week without gps_s (the seconds "
       "of the week)"},
      {replaced(good, "t_s,", "utc,"),
       "attitude.csv:1: absolute times (utc, GPS) need the "
       "scene's epoch"},
      {"roll_deg,pitch_deg,yaw_deg\n0,0,0\n",
       "attitude.csv:1: no time column: expected " + expected_header},
      {"t_s,roll_deg,pitch_deg,yaw_deg,q_w\n0,0,0,0,1\n",
       "attitude.csv:1: mixed angle and quaternion columns: give one attitude"},
      {replaced(good, "10,1,1,1", "10,1,1"),
       "attitude.csv:3: row with 3 fields (the header has 4)"},
      {replaced(good, "10,1,1,1", "10,1,1,1,1"),
       "attitude.csv:3: row with more than 4 fields (the header has 4)"},
      {replaced(good, "10,1,1,1", "10,1,x,1"),
       "attitude.csv:3:6: malformed number 'x' (pitch_deg)"},
      {replaced(good, "10,1,1,1", "10,inf,1,1"),
       "attitude.csv:3:4: malformed number 'inf' (roll_deg)"},
      {replaced(good, "10,1,1,1", "0,1,1,1"),
       "attitude.csv:3: t_s 0 is not after the previous row's 0 (times must increase)"},
      {good + "5,0,0,0\n",
       "attitude.csv:4: t_s 5 is not after the previous row's 10 (times must increase)"},
      {replaced(quaternions, "0.8,0.6", "0.8,0.61"),
       "attitude.csv:3:4: quaternion (q_w, q_x, q_y, q_z) of norm 1.0060318086422517, not 1 "
       "within 0.001: not a rotation"},
      {replaced(quaternions, "1,0,0,0", "0,0,0,0"),
       "attitude.csv:2:3: quaternion (q_w, q_x, q_y, q_z) of norm 0, not 1 within 0.001: not a "
       "rotation"},
      // The true norm where the squares would overflow or underflow (it said inf, and 0).
      {replaced(quaternions, "1,0,0,0", "1e200,1e200,0,0"),
       "attitude.csv:2:3: quaternion (q_w, q_x, q_y, q_z) of norm 1.414213562373095e+200, not 1 "
       "within 0.001: not a rotation"},
      {replaced(quaternions, "1,0,0,0", "1e-200,0,0,0"),
       "attitude.csv:2:3: quaternion (q_w, q_x, q_y, q_z) of norm 1e-200, not 1 within 0.001: not "
       "a rotation"},
      {replaced(quaternions, "0.8,0.6", "0.8,nan"),
       "attitude.csv:3:8: malformed number 'nan' "
       "(q_x)"},
  };
  for (const bad_case& c : cases) {
    INFO(c.content);
    CHECK(refusal_of_text(c.content) == c.expected);
  }
  const text_file f("attitude.csv", good + "20,0,0,0\n");
  const checked<attitude_table> limited = read_attitude_csv(f.path(), {std::nullopt, 2});
  REQUIRE(error_of(limited));
  CHECK(error_of(limited)->where.line == 4);
  CHECK(error_of(limited)->message == "more than 2 rows (the limit that bounds memory)");
}

namespace {

quaternion body_from_inertial(const attitude_table& t, double t_s) {
  const checked<quaternion> q = t.body_from_inertial_at(t_s);
  if (const diagnostic* e = error_of(q)) FAIL(e->text());
  return q.value();
}

void check_vector(const conescan::vec3<double>& actual, const conescan::vec3<double>& expected) {
  INFO("(" << actual.x << ", " << actual.y << ", " << actual.z << ")");
  CHECK(conescan::norm(actual - expected) < 1e-15);
}

}  // namespace

TEST_CASE("attitude CSV: a star tracker's quaternions, inertial to body, scalar first or last",
          "[attitude_csv]") {
  // The body axes are the inertial ones turned +90 deg about z: inertial y is body x. Written
  // scalar first, scalar last, negated, and a row of 0.9999 norm (normalised): all the same.
  const double c = std::sqrt(0.5);
  const std::string s = conescan::text::shortest_text(c);
  for (const std::string& table :
       {"t_s,q_w,q_x,q_y,q_z\n0," + s + ",0,0," + s + "\n60," + s + ",0,0," + s + "\n",
        "t_s,q_x,q_y,q_z,q_w\n0,0,0," + s + "," + s + "\n60,0,0," + s + "," + s + "\n",
        "q_z , q_y,t_s,q_w, q_x\n-" + s + ",0,0,-" + s + ",0\n-" + s + ",0,60,-" + s + ",-0\n",
        "t_s,q_w,q_x,q_y,q_z\n0,0.70703,0,0,0.70703\n60," + s + ",0,0," + s + "\n"}) {
    INFO(table);
    const text_file f("tracker.csv", table);
    const checked<attitude_table> r = read_attitude_csv(f.path());
    const attitude_table& t = must_read(r);
    CHECK(t.kind() == attitude_table_kind::quaternions);
    const conescan::mat3<double> dcm = rotation_matrix(body_from_inertial(t, 30));
    check_vector(conescan::apply(dcm, conescan::vec3<double>(0, 1, 0)), {1, 0, 0});
    check_vector(conescan::apply(dcm, conescan::vec3<double>(0, 0, 1)), {0, 0, 1});
    const checked<attitude_angles> angles = t.angles_at(30);
    CHECK(error_of(angles)->message == "a quaternion table holds no angles");
  }
  const text_file first("first.csv", "t_s,q_w,q_x,q_y,q_z\n0,1,0,0,0\n");
  const text_file last("last.csv", "t_s,q_x,q_y,q_z,q_w\n0,0,0,0,1\n");
  CHECK(must_read(read_attitude_csv(first.path())).scalar_first());
  CHECK_FALSE(must_read(read_attitude_csv(last.path())).scalar_first());
}

TEST_CASE("attitude CSV: quaternions on the geodesic, exact at the rows, the shorter way",
          "[attitude_csv]") {
  // 0 -> 120 deg about z in 60 s, the second row written with the opposite sign: the midpoint
  // is 60 deg about z, the body x axis then at inertial azimuth 60 deg.
  const text_file f("spin.csv",
                    "t_s,q_w,q_x,q_y,q_z\n0,1,0,0,0\n60,-0.5,0,0,-0.8660254037844386\n"
                    "120,-0.5,0,0,0.8660254037844386\n");
  const checked<attitude_table> r = read_attitude_csv(f.path());
  const attitude_table& t = must_read(r);
  const quaternion mid = body_from_inertial(t, 30);
  // Inertial -> body by +60 deg: body <- inertial maps inertial (cos 60, sin 60, 0) to body x.
  check_vector(
      conescan::apply(rotation_matrix(mid), conescan::vec3<double>(0.5, std::sqrt(3.0) / 2, 0)),
      {1, 0, 0});
  CHECK(angle_between(body_from_inertial(t, 60), quaternion{0.5, 0, 0, -0.8660254037844386}) <
        1e-15);
  // 60 -> 120 s turns by another 120 deg about z (240 deg in all), not back.
  const quaternion later = body_from_inertial(t, 90);
  CHECK(angle_between(later, quaternion_from_rotation_vector({0, 0, -180 * deg})) < 1e-14);
  CHECK(t.check_coverage(0, 120).ok());
  CHECK_FALSE(t.check_coverage(0, 121).ok());
}

namespace {

instant utc_instant(const char* text) {
  const checked<instant> t = parse_epoch(text, time_scale::utc);
  if (const diagnostic* e = error_of(t)) FAIL(e->text());
  return t.value();
}

}  // namespace

TEST_CASE("attitude CSV: a star tracker's table equals an AEM of the same attitude",
          "[attitude_csv][aem]") {
  // A tumble sampled every 10 s, written once as an AEM (EME2000 -> SC_BODY_1, A2B, scalar
  // last, LINEAR: the geodesic) and once as a table with utc times (scalar first).
  std::string aem =
      "CCSDS_AEM_VERS = 2.0\nCREATION_DATE = 2026-01-01T00:00:00\nORIGINATOR = conescan tests\n"
      "META_START\nOBJECT_NAME = TEST\nOBJECT_ID = 2026-001A\nCENTER_NAME = EARTH\n"
      "REF_FRAME_A = EME2000\nREF_FRAME_B = SC_BODY_1\nATTITUDE_DIR = A2B\nTIME_SYSTEM = UTC\n"
      "START_TIME = 2026-06-21T11:59:00\nSTOP_TIME = 2026-06-21T12:01:00\n"
      "ATTITUDE_TYPE = QUATERNION\nQUATERNION_TYPE = LAST\nINTERPOLATION_METHOD = LINEAR\n"
      "META_STOP\nDATA_START\n";
  std::string table = "utc,q_w,q_x,q_y,q_z\n";
  for (int k = 0; k <= 12; ++k) {
    const double t = 10.0 * k, angle = 0.02 * t + 0.3 * std::sin(0.05 * t);
    const conescan::vec3<double> axis = conescan::vec3<double>(0.3, -0.5, 0.8) / std::sqrt(0.98);
    const quaternion q = quaternion_from_rotation_vector(axis * angle);
    const std::string utc =
        k < 6 ? "2026-06-21T11:59:" + std::string(k == 0 ? "00" : std::to_string(10 * k))
              : "2026-06-21T12:0" + std::to_string((k - 6) / 6) + ":" +
                    (k % 6 == 0 ? "00" : std::to_string(10 * (k % 6)));
    const auto text = [](double x) { return conescan::text::shortest_text(x); };
    aem += utc + " " + text(q.x) + " " + text(q.y) + " " + text(q.z) + " " + text(q.w) + "\n";
    table += utc + "," + text(q.w) + "," + text(q.x) + "," + text(q.y) + "," + text(q.z) + "\n";
  }
  aem += "DATA_STOP\n";
  const text_file aem_file("tumble.aem", aem), table_file("tumble.csv", table);
  const checked<aem_attitude> from_aem = read_aem(aem_file.path());
  const instant epoch = utc_instant("2026-06-21T12:00:00");
  const checked<attitude_table> from_table = read_attitude_csv(table_file.path(), {epoch});
  REQUIRE(from_aem.ok());
  const attitude_table& t = must_read(from_table);
  CHECK(t.time_column() == attitude_time_column::utc);
  CHECK(t.first_t_s() == -60);
  CHECK(t.last_t_s() == 60);
  double worst = 0;
  for (double t_s = -60; t_s <= 60; t_s += 0.7) {
    const quaternion a =
        from_aem.value().attitude_at(add_seconds(epoch, t_s)).value().body_from_inertial;
    worst = std::max(worst, angle_between(a, body_from_inertial(t, t_s)));
  }
  // Measured 1.0e-13 rad (6e-12 deg): the rounding of two ways of writing the geodesic (the AEM
  // interpolates rotation vectors relative to the interval's first sample).
  CHECK(worst < 1e-12);
}

TEST_CASE("attitude CSV: utc and GPS times, leap seconds through ERFA", "[attitude_csv][time]") {
  // GPS week 2000 began 2018-05-06T00:00:00 GPS = 2018-05-05T23:59:42 UTC (GPS - UTC = 18 s).
  const instant epoch = utc_instant("2018-05-05T23:59:40");
  const text_file utc("utc.csv",
                      "utc,roll_deg,pitch_deg,yaw_deg\n2018-05-05T23:59:42Z,1,2,3\n"
                      "2018-125T23:59:52.5,2,3,4\n");
  const text_file gps("gps.csv",
                      "gps_week,gps_s,roll_deg,pitch_deg,yaw_deg\n2000,0,1,2,3\n2000,10.5,2,3,4\n");
  for (const text_file* f : {&utc, &gps}) {
    const checked<attitude_table> r = read_attitude_csv(f->path(), {epoch});
    const attitude_table& t = must_read(r);
    CHECK(t.first_t_s() == Approx(2).margin(1e-9));
    CHECK(t.last_t_s() == Approx(12.5).margin(1e-9));
  }
  // Across the leap second at the end of 2016: 23:59:59 to 00:00:00 is 2 s.
  const text_file leap("leap.csv",
                       "utc,roll_deg,pitch_deg,yaw_deg\n2016-12-31T23:59:59,0,0,0\n"
                       "2016-12-31T23:59:60.5,0,0,0\n2017-01-01T00:00:00,1,0,0\n");
  const checked<attitude_table> r =
      read_attitude_csv(leap.path(), {utc_instant("2016-12-31T23:59:59")});
  const attitude_table& t = must_read(r);
  CHECK(t.last_t_s() == Approx(2).margin(1e-9));
  CHECK(at(t, 1.75).roll_rad == Approx(0.5 * deg));
  // Refused: a leap second that does not exist, a week that is not whole, seconds past a week.
  const auto refused = [&](const std::string& content) {
    const text_file f("bad.csv", content);
    const checked<attitude_table> bad = read_attitude_csv(f.path(), {epoch});
    const diagnostic* e = error_of(bad);
    if (!e) FAIL("read, not refused");
    return replaced(e->text(), f.path(), "bad.csv");
  };
  CHECK(refused("utc,roll_deg,pitch_deg,yaw_deg\n2018-06-30T23:59:60,0,0,0\n") ==
        "bad.csv:2:1: utc: epoch '2018-06-30T23:59:60' UTC: second 60 on a day without a leap "
        "second (UTC)");
  CHECK(refused("utc,roll_deg,pitch_deg,yaw_deg\n2018-06-30 12:00,0,0,0\n") ==
        "bad.csv:2:1: utc: malformed epoch '2018-06-30 12:00' (expected YYYY-MM-DDThh:mm:ss[.fff] "
        "or YYYY-DDDThh:mm:ss[.fff])");
  CHECK(refused("gps_week,gps_s,roll_deg,pitch_deg,yaw_deg\n2000.5,0,0,0,0\n") ==
        "bad.csv:2:1: GPS week 2000.5 is not a whole number of weeks in [0, 1e6)");
  CHECK(refused("gps_week,gps_s,roll_deg,pitch_deg,yaw_deg\n2000,604800,0,0,0\n") ==
        "bad.csv:2:1: GPS seconds of the week 604800 are outside [0, 604800)");
}
