// MODEL §7's gimbal status: where the true pitch is within 1.91 deg of +-90 deg (1/cos pitch >
// 30), roll is undefined, and the row's roll and pitch errors (per head and system) are nan with
// status gimbal, while eta_err still reports the nadir error. Both sides of the boundary, in the
// core and through conescan-sim (constant angles, an attitude table reaching 90 deg exactly).
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <string>

#include "conescan/attitude.hpp"
#include "support/cli.hpp"

using conescan::classify_true_pitch;
using conescan::status;
using conescan_test::parse_csv;
using conescan_test::run_sim;
using conescan_test::temp_file;

TEMPLATE_TEST_CASE("gimbal: 1/cos pitch > 30 is gimbal, on both sides of the boundary",
                   "[gimbal][physics]", float, double, long double) {
  using T = TestType;
  using std::acos;
  const T boundary = acos(T(1) / T(30));  // 88.0898 deg
  const T eps = std::numeric_limits<T>::epsilon();
  for (const T sign : {T(1), T(-1)}) {
    CHECK(classify_true_pitch(T(sign * boundary * (1 - 64 * eps))) == status::ok);
    CHECK(classify_true_pitch(T(sign * boundary * (1 + 64 * eps))) == status::gimbal);
    CHECK(classify_true_pitch(T(sign * conescan::pi<T>() / 2)) == status::gimbal);
    CHECK(classify_true_pitch(T(sign * conescan::pi<T>() / 3)) == status::ok);
    // Past the pole (an unwrapped angle): the same |cos|.
    CHECK(classify_true_pitch(T(sign * (conescan::pi<T>() - boundary * (1 + 64 * eps)))) ==
          status::gimbal);
  }
  CHECK(classify_true_pitch(T(0)) == status::ok);
  CHECK(classify_true_pitch(std::numeric_limits<T>::quiet_NaN()) == status::invalid);
  CHECK(classify_true_pitch(std::numeric_limits<T>::infinity()) == status::invalid);
  CHECK(conescan::gimbal_secant_max<T>() == T(30));
}

namespace {

// A head that sees the Earth with the nadir near the body's -x axis (pitch near 90 deg).
const std::string near_pole = " --duration-s 0 --model scan --head alpha=20,beta=180,gamma=70";

}  // namespace

TEST_CASE("gimbal: conescan-sim's rows on both sides of 88.0898 deg of pitch",
          "[gimbal][cli][regression]") {
  for (const std::string sign : {"", "-"}) {
    const auto ok = parse_csv(run_sim("--pitch-deg " + sign + "88.0897" + near_pole).out);
    const auto gimbal = parse_csv(run_sim("--pitch-deg " + sign + "88.0899" + near_pole).out);
    REQUIRE(ok.rows.size() == 1);
    REQUIRE(gimbal.rows.size() == 1);
    if (sign.empty()) {  // the head sees the Earth at +88 deg; at -88 deg it misses it
      CHECK(ok.text(0, "h1_status") == "ok");
      CHECK(ok.text(0, "status") == "ok");
      CHECK(gimbal.text(0, "h1_status") == "gimbal");
      CHECK(gimbal.text(0, "status") == "gimbal");
      for (const std::string column :
           {"h1_roll_err_deg", "h1_pitch_err_deg", "roll_err_deg", "pitch_err_deg"})
        CHECK(gimbal.text(0, column) == "nan");
      // The nadir error stands: eta_err, chord and phase are still reported.
      CHECK(std::abs(gimbal.number(0, "h1_eta_err_deg") - ok.number(0, "h1_eta_err_deg")) < 1e-6);
      CHECK(std::isfinite(gimbal.number(0, "h1_chord_deg")));
    }
  }
  // +-90 deg itself is an attitude (the nadir along -+x): accepted, every row gimbal.
  CHECK(parse_csv(run_sim("--pitch-deg 90" + near_pole).out).text(0, "status") == "gimbal");
  for (const std::string bad : {"90.0000001", "-90.5", "nan"})
    CHECK(run_sim("--pitch-deg " + bad + near_pole).exit_status == 2);
  // The summary counts them, and keeps their roll out of the statistics.
  const auto summary = parse_csv(run_sim("--pitch-deg 89.999 --summary" + near_pole).out);
  CHECK(summary.text(1, "source") == "system");
  CHECK(summary.text(1, "gimbal") == "1");
  CHECK(summary.text(1, "roll_max_deg") == "nan");
}

TEST_CASE("gimbal: an attitude table reaching 90 deg of pitch prints no roll errors as ok",
          "[gimbal][cli][regression]") {
  // Pitch from 80 to 90 deg in 60 s: the audit's case printed roll errors of 81-90 deg, ok.
  const temp_file table("t_s,roll_deg,pitch_deg,yaw_deg\n0,0,80,0\n60,0,90,0\n", ".csv");
  const auto csv = parse_csv(run_sim("--attitude-csv " + table.path +
                                     " --duration-s 60 --step-s 1 --model scan --head "
                                     "alpha=20,beta=180,gamma=70")
                                 .out);
  REQUIRE(csv.rows.size() == 61);
  int gimbal = 0;
  for (std::size_t k = 0; k < csv.rows.size(); ++k) {
    const double pitch_deg = 80 + 10 * csv.number(k, "t_s") / 60;
    const bool beyond = std::abs(std::cos(pitch_deg * M_PI / 180)) * 30 < 1;
    if (csv.text(k, "status") == "gimbal") ++gimbal;
    if (csv.text(k, "status") == "ok") {
      CHECK_FALSE(beyond);
      CHECK(std::abs(csv.number(k, "roll_err_deg")) < 1);
    }
    if (beyond) CHECK(csv.text(k, "status") == "gimbal");
  }
  CHECK(gimbal >= 11);  // 88.09 .. 90 deg: the last 11 rows at 1 s
}
