// The CCSDS OEM reader (src/sources/oem.hpp): the files of tests/data/ccsds read or refused as a
// user would expect, interpolation exact on polynomials of its degree, the error estimate against
// the true error on a Kepler orbit, segments and usable spans, the bound on memory, and every
// malformed or unsupported input refused with file, line and keyword or value.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "orbit/kepler.hpp"
#include "sources/earth_rotation.hpp"
#include "sources/oem.hpp"
#include "support/diagnostic_of.hpp"
#include "support/text_file.hpp"

using conescan::checked;
using conescan::diagnostic;

using namespace conescan::sources;
using conescan::norm;
using conescan::vec3;
using conescan_test::read_text;
using conescan_test::replaced;
using conescan_test::text_file;

namespace {

constexpr double deg = std::numbers::pi / 180;
const std::string ccsds_dir = std::string(CONESCAN_TEST_DATA) + "/ccsds/";

instant utc(const char* text) {
  return (parse_epoch(text, time_scale::utc)).value();
}

const oem_ephemeris& must_read(const checked<oem_ephemeris>& r) {
  if (const diagnostic* e = error_of(r)) FAIL(e->text());
  return r.value();
}

/// The refusal's whole text ("FILE:LINE: message").
std::string refusal(const checked<oem_ephemeris>& r) {
  const diagnostic* e = error_of(r);
  if (!e) FAIL("read, not refused");
  return e->text();
}

std::string refusal_of_text(std::string_view content, const char* name = "bad.oem") {
  const text_file f(name, content);
  // The message names the file as given; without its directory for the comparisons.
  return replaced(refusal(read_oem(f.path())), f.path(), name);
}

interpolated_state state(const oem_ephemeris& o, const instant& t) {
  checked<interpolated_state> s = o.state_at(t);
  if (const diagnostic* e = error_of(s)) FAIL(e->text());
  return s.value();
}

const char* const header =
    "CCSDS_OEM_VERS = 2.0\nCREATION_DATE = 2020-01-01T00:00:00\nORIGINATOR = conescan tests\n";

std::string meta(const std::string& extra = "", const std::string& start = "2020-01-01T00:00:00",
                 const std::string& stop = "2020-01-01T06:00:00") {
  return "META_START\nOBJECT_NAME = TEST\nOBJECT_ID = 2020-001A\nCENTER_NAME = EARTH\n"
         "REF_FRAME = GCRF\nTIME_SYSTEM = UTC\nSTART_TIME = " +
         start + "\nSTOP_TIME = " + stop + "\n" + extra + "META_STOP\n";
}

std::string number(double x) {
  std::ostringstream s;
  s.precision(17);
  s << x;
  return s.str();
}

/// An OEM data line at t seconds after 2020-01-01T00:00:00 UTC, position (km), velocity (km/s).
std::string data_line(double t, const vec3<double>& r_km, const vec3<double>& v_km_s) {
  return format_utc(conescan::sources::add_seconds(utc("2020-01-01T00:00:00"), t), 9) + " " +
         number(r_km.x) + " " + number(r_km.y) + " " + number(r_km.z) + " " + number(v_km_s.x) +
         " " + number(v_km_s.y) + " " + number(v_km_s.z) + "\n";
}

/// A polynomial per component in u = (t - 50) / 5, u in [-10, 10] over the samples' [0, 100] s
/// (km), and its derivative (km/s).
struct polynomial {
  std::vector<vec3<double>> a;  // a[j]: coefficient of u^j
  vec3<double> value(double t) const {
    vec3<double> v(0.0);
    for (std::size_t j = a.size(); j-- > 0;) v = v * ((t - 50) / 5) + a[j];
    return v;
  }
  vec3<double> derivative(double t) const {
    vec3<double> v(0.0);
    for (std::size_t j = a.size(); j-- > 1;) {
      v = v * ((t - 50) / 5) + a[j] * static_cast<double>(j);
    }
    return v / 5.0;
  }
};

/// Random coefficients, each term within 100 km over the samples, about (7000, 0, 0) km.
polynomial random_polynomial(int degree, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> coefficient(-100, 100);
  polynomial p;
  for (int j = 0; j <= degree; ++j) {
    const double scale = std::pow(10.0, -j);
    p.a.push_back(vec3<double>(coefficient(rng), coefficient(rng), coefficient(rng)) * scale);
  }
  p.a[0] += vec3<double>(7000, 0, 0);  // keeps |r| away from 0 for the angle estimate
  return p;
}

/// (7000, 0, 0) km plus a pure u^degree term reaching 1000 km at the ends: what an interpolant
/// of lower degree must miss.
polynomial top_term(int degree) {
  polynomial p;
  p.a.assign(static_cast<std::size_t>(degree) + 1, vec3<double>(0.0));
  p.a[0] = vec3<double>(7000, 0, 0);
  p.a.back() = vec3<double>(1, 1, 1) * (1000 * std::pow(10.0, -degree));
  return p;
}

/// The largest interpolation error (m) over many times of an OEM of samples of p at irregular
/// times in [0, 100] s, and the largest error estimate there.
struct polynomial_errors {
  double position_m = 0, velocity_m_s = 0, estimate_m = 0;
};

polynomial_errors interpolate_polynomial(const polynomial& p, const std::string& interpolation,
                                         std::mt19937_64& rng) {
  std::string text =
      std::string(header) + meta(interpolation, "2020-01-01T00:00:00", "2020-01-01T00:01:40");
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  for (int k = 0; k <= 20; ++k) {
    // On the nanosecond, as the data line writes it.
    const double t = k == 0    ? 0.0
                     : k == 20 ? 100.0
                               : std::round((5.0 * k + jitter(rng)) * 1e9) / 1e9;
    text += data_line(t, p.value(t), p.derivative(t));
  }
  const text_file f("polynomial.oem", text);
  const checked<oem_ephemeris> r = read_oem(f.path());
  const oem_ephemeris& o = must_read(r);
  polynomial_errors worst;
  std::uniform_real_distribution<double> when(0, 100);
  for (int k = 0; k < 400; ++k) {
    const double t = when(rng);
    const interpolated_state s = state(o, add_seconds(utc("2020-01-01T00:00:00"), t));
    worst.position_m = std::max(worst.position_m, norm(s.state.r_m - p.value(t) * 1000.0));
    worst.velocity_m_s =
        std::max(worst.velocity_m_s, norm(s.state.v_m_s - p.derivative(t) * 1000.0));
    worst.estimate_m = std::max(worst.estimate_m, static_cast<double>(s.estimate.position_m));
  }
  return worst;
}

}  // namespace

TEST_CASE("the CCSDS examples: read or refused as a user would expect", "[oem]") {
  SECTION("ISS, EME2000, hourly: read, then refused for the scene as far too sparse") {
    const checked<oem_ephemeris> r = read_oem(ccsds_dir + "ISS.resampled.truncated.txt");
    const oem_ephemeris& o = must_read(r);
    REQUIRE(o.segments().size() == 1);
    const oem_segment& s = o.segments()[0];
    CHECK(s.samples.size() == 25);
    CHECK(s.method == oem_default_method);  // no INTERPOLATION in the file
    CHECK(s.degree == oem_default_degree);
    CHECK(o.usable_start() == utc("2022-01-17T12:00:00"));
    CHECK(o.usable_stop() == utc("2022-01-18T12:00:00"));
    // At a data line's epoch the interpolant is the line itself.
    const interpolated_state at_line = state(o, utc("2022-01-17T13:00:00"));
    CHECK(norm(at_line.state.r_m -
               vec3<double>(5021218.457183220, -2714921.344536780, -3693631.863364480)) < 1e-6);
    CHECK(norm(at_line.state.v_m_s -
               vec3<double>(5150.02544728106, 3647.80592200467, 4333.67398742523)) < 1e-9);
    const checked<void> e = o.check_coverage(o.usable_start(), o.usable_stop());
    REQUIRE_FALSE(e.ok());
    CHECK(e.error().where.line == 63);  // the data line that starts the worst interval
    CHECK(e.error().message.find(
              "interpolation error estimate 5.84e+06 m, 3.74e+03 m/s (31.9 deg)") == 0);
    CHECK(e.error().message.find("states 3.6e+03 s apart are too sparse for HERMITE of degree 7") !=
          std::string::npos);
    CHECK(o.check_coverage(o.usable_start(), o.usable_stop(), std::nullopt).ok());
  }
  SECTION("OEMExample1 (Mars Global Surveyor): refused at its centre, then at each other fault") {
    const std::string text = read_text(ccsds_dir + "OEMExample1.txt");
    CHECK(refusal_of_text(text, "OEMExample1.txt") ==
          "OEMExample1.txt:10: unsupported CENTER_NAME 'MARS BARYCENTER' (conescan takes EARTH "
          "only)");
    const std::string earth = replaced(text, "MARS BARYCENTER", "EARTH");
    CHECK(refusal_of_text(earth, "OEMExample1.txt") ==
          "OEMExample1.txt:11: unsupported REF_FRAME 'J2000' (conescan takes EME2000, GCRF, "
          "ICRF, TEME, TOD or ITRF*; the J2000 mean equator is EME2000)");
    CHECK(refusal_of_text(replaced(earth, "J2000", "EME2000"), "OEMExample1.txt") ==
          "OEMExample1.txt:81: epoch 1996-12-30T01:28:02.267 repeats the previous line's "
          "(epochs must increase within a segment)");
  }
  SECTION("OEM-wrong-keyword: the unknown keyword, at its line") {
    CHECK(refusal(read_oem(ccsds_dir + "OEM-wrong-keyword.txt"))
              .ends_with("OEM-wrong-keyword.txt:19: unknown keyword 'WRONG_KEYWORD' in the META "
                         "block"));
  }
  SECTION("OEM-ephemeris-number-format-error: its centre, then the malformed number") {
    const std::string text = read_text(ccsds_dir + "OEM-ephemeris-number-format-error.txt");
    CHECK(refusal_of_text(text).ends_with(
        ":9: unsupported CENTER_NAME 'MARS BARYCENTER' (conescan takes EARTH only)"));
    CHECK(refusal_of_text(replaced(text, "MARS BARYCENTER", "EARTH")) ==
          "bad.oem:44: malformed number 'this-is-not-a-number' (Z)");
  }
  SECTION("oemLowerCaseValue: lower-case values read; its 6 states too few to check degree 5") {
    const checked<oem_ephemeris> r = read_oem(ccsds_dir + "oemLowerCaseValue.oem");
    const oem_ephemeris& o = must_read(r);
    const oem_segment& s = o.segments().at(0);
    CHECK(s.method == interpolation_method::lagrange);
    CHECK(s.degree == 5);
    CHECK(s.ref_frame == "EME2000");
    const interpolated_state at_line = state(o, utc("2015-08-27T00:03:00"));
    CHECK(norm(at_line.state.r_m - vec3<double>(-2.218658483609717e5, -6.526135805276629e6,
                                                1.492717519166993e6)) < 1e-6);
    const checked<void> e = o.check_coverage(o.usable_start(), o.usable_stop());
    REQUIRE_FALSE(e.ok());
    CHECK(e.error().message.find(
              "the segment's 6 states are too few to check LAGRANGE of degree 5") !=
          std::string::npos);
  }
  SECTION("AEM files handed to the OEM reader") {
    CHECK(refusal(read_oem(ccsds_dir + "AEMExample01.txt"))
              .ends_with("AEMExample01.txt:1: this is an AEM (CCSDS_AEM_VERS), not an OEM"));
  }
}

TEST_CASE("OEMExample5ITRF: the ISS turned inertial, and refused as 30-minute sampling", "[oem]") {
  const checked<oem_ephemeris> r = read_oem(ccsds_dir + "OEMExample5ITRF.txt");
  const oem_ephemeris& o = must_read(r);
  const oem_segment& s = o.segments().at(0);
  REQUIRE(s.samples.size() == 49);
  CHECK(s.ref_frame == "ITRF2014");
  // The turn keeps |r|: the first line's radius.
  CHECK(norm(s.samples[0].r_m) ==
        Approx(norm(vec3<double>(-2757.3016318893897, -4173.479601381253, 4566.01849801963)) * 1000)
            .epsilon(1e-15));
  // Independent physics: the ISS's osculating orbit in the inertial frame. Its inclination is
  // 51.64 deg; its semi-major axis (vis-viva) ~6780 km, varying by J2 only (~10 km), which
  // would be off by hundreds of km had v + w x r been left out; its node regresses at the J2
  // rate -(3/2) n J2 (R/p)^2 cos i = -5.0 deg/day, where a wrong sign of the Earth rotation
  // angle would turn it by +722 deg/day.
  const double gm = 3.986004418e14;
  std::vector<double> node_deg;
  for (const conescan::sources::cartesian_state& c : s.samples) {
    const vec3<double> h = conescan::cross(c.r_m, c.v_m_s);
    CHECK(std::acos(h.z / norm(h)) / deg == Approx(51.64).margin(0.05));
    const double a = 1 / (2 / norm(c.r_m) - conescan::dot(c.v_m_s, c.v_m_s) / gm);
    CHECK(a / 1000 == Approx(6780).margin(25));
    node_deg.push_back(std::atan2(h.x, -h.y) / deg);
  }
  const double days = (s.t_s.back() - s.t_s.front()) / 86400;
  CHECK((node_deg.back() - node_deg.front()) / days == Approx(-5.0).margin(0.2));
  // A user asking for this orbit gets the refusal with the figure.
  const checked<void> e = o.check_coverage(o.usable_start(), o.usable_stop());
  REQUIRE_FALSE(e.ok());
  CHECK(e.error().text().ends_with(
      "OEMExample5ITRF.txt:63: interpolation error estimate 5e+04 m, 62.7 m/s (0.467 deg) at "
      "2017-04-12T22:16:43.122 UTC, after this line, exceeds the 1e-06 deg the angles need: "
      "states 1.8e+03 s apart are too sparse for HERMITE of degree 7 (or accept a coarser orbit "
      "with --interpolation-tolerance-deg)"));
}

TEST_CASE("interpolation is exact on polynomials of its degree, not beyond", "[oem]") {
  std::mt19937_64 rng(14);
  for (int d = 1; d <= 9; ++d) {
    INFO("degree " << d);
    const std::string lagrange =
        "INTERPOLATION = LAGRANGE\nINTERPOLATION_DEGREE = " + std::to_string(d) + "\n";
    const std::string hermite =
        "INTERPOLATION = Hermite\nINTERPOLATION_DEGREE = " + std::to_string(d) + "\n";
    // Values ~7e6 m, speeds up to 9 km/s: the file's 17 digits and the sums round to ~1e-8 m.
    const polynomial_errors l = interpolate_polynomial(random_polynomial(d, rng), lagrange, rng);
    CHECK(l.position_m < 1e-6);
    CHECK(l.velocity_m_s < 1e-7);
    CHECK(l.estimate_m < 1e-6);
    const polynomial_errors h = interpolate_polynomial(random_polynomial(d, rng), hermite, rng);
    CHECK(h.position_m < 1e-6);
    CHECK(h.velocity_m_s < 1e-7);
    // One degree more: Lagrange is no longer exact (1e-4 m and more: 1e4 times the rounding
    // above), and its estimate sees it. Hermite of degree d takes ceil((d + 1) / 2) samples:
    // exact to degree 2 ceil((d + 1) / 2) - 1, not beyond.
    const polynomial_errors l1 = interpolate_polynomial(top_term(d + 1), lagrange, rng);
    CHECK(l1.position_m > 1e-4);
    CHECK(l1.estimate_m > 0.5 * l1.position_m);
    const int hermite_exact = 2 * ((d + 2) / 2) - 1;
    const polynomial_errors h1 = interpolate_polynomial(top_term(hermite_exact + 1), hermite, rng);
    CHECK(h1.position_m > 1e-4);
  }
  const polynomial_errors linear =
      interpolate_polynomial(random_polynomial(1, rng), "INTERPOLATION = LINEAR\n", rng);
  CHECK(linear.position_m < 1e-6);
  CHECK(linear.velocity_m_s < 1e-7);
}

TEST_CASE("the error estimate follows the true error on a Kepler orbit", "[oem]") {
  // A 400 km circular-ish orbit sampled every h seconds, read back and compared with the orbit
  // itself at 7 times per interval. The estimate (oem.hpp) is the next Newton term: measured
  // within 2 % of the true error wherever that is above the data's rounding (1e-8 m).
  const double gm = 3.986004418e14;
  const conescan::orbit::elements el{6778137.0, 0.001, 51.6 * deg, 0.3, 0.5, 0.0};
  const conescan::orbit::kepler_orbit orbit(el, conescan::orbit::two_body_rates(el, gm), gm);
  for (const double h : {120.0, 300.0}) {
    for (const char* method : {"LAGRANGE", "HERMITE"}) {
      for (int d : {5, 7, 9}) {
        INFO(method << " degree " << d << ", states " << h << " s apart");
        std::string text =
            std::string(header) + meta(std::string("INTERPOLATION = ") + method +
                                       "\nINTERPOLATION_DEGREE = " + std::to_string(d) + "\n");
        for (double t = 0; t <= 6 * 3600; t += h) {
          const conescan::orbit::orbit_state x = orbit.state_at(t);
          text += data_line(t, x.r_eci_m / 1000.0, x.v_eci_m_s / 1000.0);
        }
        const text_file f("kepler.oem", text);
        const checked<oem_ephemeris> r = read_oem(f.path());
        const oem_ephemeris& o = must_read(r);
        double true_m = 0, estimate_m = 0;
        for (double t = 0.37; t < 6 * 3600; t += h / 7.3) {
          const interpolated_state s = state(o, add_seconds(utc("2020-01-01T00:00:00"), t));
          true_m = std::max(true_m, norm(s.state.r_m - orbit.state_at(t).r_eci_m));
          estimate_m = std::max(estimate_m, static_cast<double>(s.estimate.position_m));
        }
        if (true_m > 1e-6) CHECK(estimate_m / true_m == Approx(1).margin(0.15));
        // The span's worst estimate is the one the coverage check compares.
        const worst_interval_error w = o.worst_error(o.usable_start(), o.usable_stop());
        CHECK(w.error.position_m == Approx(estimate_m).epsilon(0.3));
      }
    }
  }
}

TEST_CASE("segments, usable spans, covariance, comments and accelerations", "[oem]") {
  // Two segments that touch at 01:00, a third after a gap; usable spans inside the data.
  std::string text = std::string(header) + "COMMENT header comment\n" +
                     meta("USEABLE_START_TIME = 2020-01-01T00:00:30\nINTERPOLATION = LINEAR\n",
                          "2020-01-01T00:00:00", "2020-01-01T01:00:00") +
                     "COMMENT data comment\n";
  for (int k = 0; k <= 60; ++k) {
    text += data_line(60.0 * k, {7000.0 + k, 0, 0}, {1, 0, 0});
  }
  text +=
      "COVARIANCE_START\nEPOCH = 2020-01-01T00:00:00\nCOV_REF_FRAME = RTN\n1.0\n2.0 3.0\n"
      "META_START\nCOVARIANCE_STOP\n";
  text += meta("COMMENT meta comment\nINTERPOLATION = LINEAR\n", "2020-01-01T01:00:00",
               "2020-01-01T02:00:00");
  for (int k = 60; k <= 120; ++k) {
    // With accelerations, which are read and not used.
    std::string line = data_line(60.0 * k, {9000.0 + k, 0, 0}, {2, 0, 0});
    line.insert(line.size() - 1, " 0.001 0.002 0.003");
    text += line;
  }
  text += meta("INTERPOLATION = LINEAR\n", "2020-01-01T03:00:00", "2020-01-01T04:00:00");
  text += data_line(3 * 3600.0, {1e4, 0, 0}, {0, 1, 0}) +
          data_line(4 * 3600.0, {1e4, 10, 0}, {0, 1, 0});
  const text_file f("segments.oem", text);
  // The covariance block swallowed a META_START line: no, it is refused.
  CHECK(refusal(read_oem(f.path())).find("META_START inside the covariance block") !=
        std::string::npos);
  const text_file good("segments.oem",
                       replaced(text, "META_START\nCOVARIANCE_STOP", "COVARIANCE_STOP"));
  const checked<oem_ephemeris> r = read_oem(good.path());
  const oem_ephemeris& o = must_read(r);
  REQUIRE(o.segments().size() == 3);
  CHECK(o.usable_start() == utc("2020-01-01T00:00:30"));
  // Linear between the samples of the first segment; at 01:00 the second serves.
  CHECK(state(o, utc("2020-01-01T00:30:30")).state.r_m.x == Approx(7030.5e3));
  CHECK(state(o, utc("2020-01-01T01:00:00")).state.r_m.x == Approx(9060e3));
  CHECK(state(o, utc("2020-01-01T00:59:59")).state.r_m.x == Approx(7060e3 - 1e3 / 60));
  // Before the usable start, in the gap, after the end: refused.
  for (const char* t : {"2020-01-01T00:00:10", "2020-01-01T02:30:00", "2020-01-01T04:00:01"}) {
    INFO(t);
    const checked<interpolated_state> s = o.state_at(utc(t));
    REQUIRE(error_of(s));
    CHECK(error_of(s)->message.find(std::string("no usable data at ") + t) == 0);
  }
  CHECK(
      o.check_coverage(utc("2020-01-01T00:00:30"), utc("2020-01-01T02:00:00"), std::nullopt).ok());
  const checked<void> gap =
      o.check_coverage(utc("2020-01-01T00:30:00"), utc("2020-01-01T03:30:00"), std::nullopt);
  REQUIRE_FALSE(gap.ok());
  CHECK(gap.error().message.find("no usable data just after 2020-01-01T02:00:00.000 UTC") == 0);
  const checked<void> early =
      o.check_coverage(utc("2020-01-01T00:00:00"), utc("2020-01-01T00:30:00"), std::nullopt);
  REQUIRE_FALSE(early.ok());
  CHECK(early.error().message.find("no usable data at 2020-01-01T00:00:00.000 UTC") == 0);
  const checked<void> reversed =
      o.check_coverage(utc("2020-01-01T00:30:00"), utc("2020-01-01T00:20:00"), std::nullopt);
  REQUIRE_FALSE(reversed.ok());
  CHECK(reversed.error().message.find("ends") != std::string::npos);
}

TEST_CASE("memory is bounded: a state limit, and a span that limits what is kept", "[oem]") {
  std::string text = std::string(header) + meta(
                                               "INTERPOLATION = LAGRANGE\n"
                                               "INTERPOLATION_DEGREE = 3\n",
                                               "2020-01-01T00:00:00", "2020-01-01T02:00:00");
  for (int k = 0; k <= 7200; ++k) {
    const double t = k;
    text += data_line(t, {7000 + 1e-3 * t, 1e-6 * t * t, 0}, {1e-3, 2e-6 * t, 0});
  }
  const text_file f("long.oem", text);
  oem_read_options small;
  small.max_states = 1000;
  const std::string limit = refusal(read_oem(f.path(), small));
  CHECK(limit.substr(limit.rfind('/') + 1) ==
        "long.oem:1015: more than 1000 data lines to keep (the limit that bounds memory): give a "
        "shorter span, or resample the file");
  small.span = time_span{utc("2020-01-01T01:00:00"), utc("2020-01-01T01:10:00")};
  const checked<oem_ephemeris> r = read_oem(f.path(), small);
  const oem_ephemeris& o = must_read(r);
  // 601 in the span, and either side the window's 4 samples, the estimate's one and one to spare
  // (6), trimmed in batches before the span (up to 11 then).
  CHECK(o.segments()[0].samples.size() <= 601 + 11 + 6);
  const checked<oem_ephemeris> all_r = read_oem(f.path());
  const oem_ephemeris& all = must_read(all_r);
  for (const char* t : {"2020-01-01T01:00:00", "2020-01-01T01:03:20.5", "2020-01-01T01:10:00"}) {
    INFO(t);
    CHECK(state(o, utc(t)).state.r_m == state(all, utc(t)).state.r_m);
  }
  CHECK(o.check_coverage(small.span->start, small.span->stop).ok());
  const checked<void> beyond = o.check_coverage(utc("2020-01-01T00:30:00"), small.span->stop);
  REQUIRE_FALSE(beyond.ok());
  CHECK(beyond.error().message.find("the file was read for a shorter span") != std::string::npos);
  const checked<interpolated_state> outside = o.state_at(utc("2020-01-01T00:30:00"));
  REQUIRE(error_of(outside));
  CHECK(error_of(outside)->message.find("shorter span") != std::string::npos);
}

TEST_CASE("malformed and unsupported OEMs are refused with line and keyword", "[oem]") {
  const std::string good_meta = meta();
  const std::string one_line = data_line(0, {7000, 0, 0}, {0, 7.5, 0});
  const std::string two_lines = one_line + data_line(60, {7000, 450, 0}, {0, 7.5, 0});
  const std::string good = std::string(header) + good_meta + two_lines;
  const text_file ok("ok.oem", good);
  must_read(read_oem(ok.path()));
  struct bad_case {
    std::string content;
    std::string expected;
  };
  const std::vector<bad_case> cases = {
      {replaced(good, "TIME_SYSTEM", "TIME_SYTEM"),
       "bad.oem:9: unknown keyword 'TIME_SYTEM' in the META block"},
      {replaced(good, "TIME_SYSTEM = UTC\n", ""),
       "bad.oem:11: missing mandatory keyword TIME_SYSTEM in the META block starting at line 4"},
      {replaced(good, "ORIGINATOR = conescan tests\n", ""),
       "bad.oem:3: missing mandatory keyword ORIGINATOR in the header starting at line 1"},
      {replaced(good, "CENTER_NAME = EARTH", "CENTER_NAME = MOON"),
       "bad.oem:7: unsupported CENTER_NAME 'MOON' (conescan takes EARTH only)"},
      {replaced(good, "REF_FRAME = GCRF", "REF_FRAME = MOD"),
       "bad.oem:8: unsupported REF_FRAME 'MOD' (conescan takes EME2000, GCRF, ICRF, TEME, TOD or "
       "ITRF*)"},
      {replaced(good, "TIME_SYSTEM = UTC", "TIME_SYSTEM = TDB"),
       "bad.oem:9: unsupported TIME_SYSTEM 'TDB' (conescan takes UTC, TAI, TT or GPS)"},
      {std::string(header) + good_meta + data_line(60, {7000, 0, 0}, {0, 7.5, 0}) + one_line,
       "bad.oem:14: epoch 2020-01-01T00:00:00.000000000 is before the previous line's (epochs "
       "must increase within a segment)"},
      {std::string(header) + good_meta + one_line + one_line,
       "bad.oem:14: epoch 2020-01-01T00:00:00.000000000 repeats the previous line's (epochs "
       "must increase within a segment)"},
      {replaced(good, " 7.5 ", " 7,5 "), "bad.oem:13: malformed number '7,5' (Y_DOT)"},
      {replaced(good, " 7000 ", " nan "), "bad.oem:13: malformed number 'nan' (X)"},
      {replaced(good, "2020-01-01T00:01:00", "2020-01-01T00:01:00Q"),
       "bad.oem:14: malformed epoch '2020-01-01T00:01:00Q.000000000' (expected "
       "YYYY-MM-DDThh:mm:ss[.fff] or YYYY-DDDThh:mm:ss[.fff])"},
      {replaced(good, " 0 7.5 0\n2020", " 0 7.5\n2020"),
       "bad.oem:13: data line with 6 fields (expected an epoch and 6 numbers, or 9 with "
       "accelerations)"},
      {std::string(header) + good_meta, "bad.oem:4: the segment has no data lines"},
      {std::string(header) + replaced(good_meta, "META_STOP\n", "") + two_lines,
       "bad.oem:12: data line inside the META block starting at line 4"},
      {replaced(good, "META_STOP\n", "META_STOP\nCOVARIANCE_START\n"),
       "bad.oem:15: the covariance block starting at line 13 has no COVARIANCE_STOP"},
      {"", "bad.oem: no META_START: the file holds no ephemeris"},
      {replaced(good, "CCSDS_OEM_VERS = 2.0", "CCSDS_OEM_VERS = 4.0"),
       "bad.oem:1: unsupported CCSDS_OEM_VERS '4.0' (conescan reads versions 1 to 3)"},
      {replaced(good, "CCSDS_OEM_VERS = 2.0\n", "COMMENT first\nCCSDS_OEM_VERS = 2.0\n"),
       "bad.oem:1: expected CCSDS_OEM_VERS = version first: not an OEM in KVN"},
      {replaced(good, "OBJECT_ID = 2020-001A\n", "OBJECT_ID = 2020-001A\nOBJECT_ID = B\n"),
       "bad.oem:7: keyword OBJECT_ID given twice in the META block (first at line 6)"},
      {replaced(good, "META_STOP", "INTERPOLATION_DEGREE = 0\nMETA_STOP"),
       "bad.oem:12: INTERPOLATION_DEGREE '0' is not an integer in 1..31"},
      {replaced(good, "META_STOP", "INTERPOLATION_DEGREE = seven\nMETA_STOP"),
       "bad.oem:12: INTERPOLATION_DEGREE 'seven' is not an integer in 1..31"},
      {replaced(good, "META_STOP", "INTERPOLATION = SPLINE\nMETA_STOP"),
       "bad.oem:12: unsupported INTERPOLATION 'SPLINE' (conescan takes LAGRANGE, HERMITE or "
       "LINEAR)"},
      {replaced(good, "STOP_TIME = 2020-01-01T06:00:00", "STOP_TIME = 2020-01-01T06:00"),
       "bad.oem:11: STOP_TIME: malformed epoch '2020-01-01T06:00' (expected "
       "YYYY-MM-DDThh:mm:ss[.fff] or YYYY-DDDThh:mm:ss[.fff])"},
      {replaced(good, "START_TIME = 2020-01-01T00:00:00", "START_TIME = 2020-01-01T07:00:00"),
       "bad.oem:11: the segment's stop time is before its start time"},
      {replaced(good, "START_TIME = 2020-01-01T00:00:00\nSTOP_TIME = 2020-01-01T06:00:00",
                "START_TIME = 2020-01-02T00:00:00\nSTOP_TIME = 2020-01-02T06:00:00"),
       "bad.oem:4: the segment's usable span (2020-01-02T00:00:00.000 to 2020-01-02T06:00:00.000 "
       "UTC) misses its data (2020-01-01T00:00:00.000 to 2020-01-01T00:01:00.000)"},
      {good + "OBJECT_NAME = LATE\n",
       "bad.oem:15: keyword OBJECT_NAME among the data lines (it belongs in a META block)"},
      {good + "DATA_STOP\n", "bad.oem:15: unexpected DATA_STOP among the data lines"},
      {good + "what is this\n", "bad.oem:15: malformed line among the data lines"},
      {replaced(good, "2020-01-01T00:00:00.000000000", "2100-01-01T00:00:00"),
       "bad.oem:13: epoch '2100-01-01T00:00:00' UTC: outside the leap-second table: conescan "
       "takes UTC 1960-01-01 to 2099-12-31 (ERFA 2.0.0's leap-second table to 2026-12-31, then "
       "no further leap second)"},
      {std::string(header) + good_meta + std::string(5000, '1') + "\n",
       "bad.oem:13: line longer than 4096 characters"},
      {replaced(good, "ORIGINATOR", std::string("ORIGIN\0ATOR", 11)),
       "bad.oem:3: NUL byte: not a text file"},
  };
  for (const bad_case& c : cases) {
    INFO(c.content.substr(0, 400));
    CHECK(refusal_of_text(c.content) == c.expected);
  }
  CHECK(refusal(read_oem("/nonexistent/file.oem")) ==
        "/nonexistent/file.oem: cannot open: No such file or directory");
  // A requested time outside the usable span.
  const checked<oem_ephemeris> r = read_oem(ok.path());
  const checked<interpolated_state> late = r.value().state_at(utc("2020-01-01T00:01:00.001"));
  REQUIRE(error_of(late));
  CHECK(error_of(late)->text().ends_with(
      "ok.oem: no usable data at 2020-01-01T00:01:00.001 UTC; usable: 2020-01-01T00:00:00.000 to "
      "2020-01-01T00:01:00.000 (segment at line 4) UTC"));
}

TEST_CASE("ITRF states: a point fixed on the Earth turns with it", "[oem]") {
  // A point on the equator at longitude 0 with zero ITRF velocity: inertially, it sits at the
  // Earth rotation angle and moves at w x r.
  const std::string text =
      std::string(header) + replaced(meta(), "REF_FRAME = GCRF", "REF_FRAME = ITRF2014") +
      data_line(0, {6378.137, 0, 0}, {0, 0, 0}) + data_line(60, {6378.137, 0, 0}, {0, 0, 0});
  const text_file f("itrf.oem", text);
  const checked<oem_ephemeris> r = read_oem(f.path());
  const oem_ephemeris& o = must_read(r);
  const instant t = utc("2020-01-01T00:00:30");
  const double era = earth_rotation_angle_rad(t);
  const interpolated_state s = state(o, t);
  // HERMITE (the default) of the two turned states: the circle to 1e-3 m over 30 s.
  CHECK(s.state.r_m.x == Approx(6378137.0 * std::cos(era)).margin(1e-3));
  CHECK(s.state.r_m.y == Approx(6378137.0 * std::sin(era)).margin(1e-3));
  CHECK(s.state.v_m_s.y ==
        Approx(earth_rotation_rate_rad_s * 6378137.0 * std::cos(era)).margin(1e-6));
}
