// The attitude table (src/sources/attitude_csv.hpp): linear in the angles, the short way round,
// exact at its rows, its span checked, and every malformed file refused with file and line.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "conescan/attitude.hpp"
#include "sources/attitude_csv.hpp"
#include "sources/rotation.hpp"
#include "support/diagnostic_of.hpp"
#include "support/text_file.hpp"

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
  struct bad_case {
    std::string content;
    std::string expected;
  };
  const std::vector<bad_case> cases = {
      {"", "attitude.csv: empty: expected the header t_s,roll_deg,pitch_deg,yaw_deg"},
      {"t_s,roll_deg,pitch_deg,yaw_deg\n", "attitude.csv: no rows after the header"},
      {"0,0,0,0\n10,1,1,1\n",
       "attitude.csv:1: expected the header t_s,roll_deg,pitch_deg,yaw_deg, not '0,0,0,0'"},
      {replaced(good, "yaw_deg", "yaw_rad"),
       "attitude.csv:1: expected the header t_s,roll_deg,pitch_deg,yaw_deg, not "
       "'t_s,roll_deg,pitch_deg,yaw_rad'"},
      {replaced(good, "10,1,1,1", "10,1,1"),
       "attitude.csv:3: row with 3 fields (expected t_s,roll_deg,pitch_deg,yaw_deg)"},
      {replaced(good, "10,1,1,1", "10,1,1,1,1"),
       "attitude.csv:3: row with 5 fields (expected t_s,roll_deg,pitch_deg,yaw_deg)"},
      {replaced(good, "10,1,1,1", "10,1,x,1"), "attitude.csv:3: malformed number 'x' (pitch_deg)"},
      {replaced(good, "10,1,1,1", "10,inf,1,1"),
       "attitude.csv:3: malformed number 'inf' (roll_deg)"},
      {replaced(good, "10,1,1,1", "0,1,1,1"),
       "attitude.csv:3: t_s 0 is not after the previous row's 0 (times must increase)"},
      {good + "5,0,0,0\n",
       "attitude.csv:4: t_s 5 is not after the previous row's 10 (times must increase)"},
  };
  for (const bad_case& c : cases) {
    INFO(c.content);
    CHECK(refusal_of_text(c.content) == c.expected);
  }
  const text_file f("attitude.csv", good + "20,0,0,0\n");
  const checked<attitude_table> limited = read_attitude_csv(f.path(), 2);
  REQUIRE(error_of(limited));
  CHECK(error_of(limited)->where.line == 4);
  CHECK(error_of(limited)->message == "more than 2 rows (the limit that bounds memory)");
}
