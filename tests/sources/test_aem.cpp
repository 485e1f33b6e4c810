// The CCSDS AEM reader (src/sources/aem.hpp): its quaternion conventions on hand-made files with
// known answers and against Orekit's reading of AEMExample01, interpolation on the rotation
// group, and every malformed or unsupported input refused with file, line and keyword.
//
// Known answers: a body frame turned from the inertial one by +90 deg about z has x_B = y_I,
// y_B = -x_I, z_B = z_I, so C_BI maps inertial (0, 1, 0) to body (1, 0, 0); CCSDS writes it as
// the A2B quaternion (e sin 45 deg, cos 45 deg) = (0, 0, 0.7071, 0.7071) (aem.hpp). A turn of
// +120 deg about (1, 1, 1) permutes the axes: x_B = y_I, y_B = z_I, z_B = x_I; its quaternion is
// (0.5, 0.5, 0.5, 0.5).
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "sources/aem.hpp"
#include "support/diagnostic_of.hpp"
#include "support/text_file.hpp"

using conescan::checked;
using conescan::diagnostic;

using namespace conescan::sources;
using conescan::apply;
using conescan::mat3;
using conescan::vec3;
using conescan_test::read_text;
using conescan_test::replaced;
using conescan_test::text_file;

namespace {

constexpr double deg = std::numbers::pi / 180;
const std::string ccsds_dir = std::string(CONESCAN_TEST_DATA) + "/ccsds/";
const std::string s45 = "0.70710678118654752";

instant utc(const char* text) {
  return (parse_epoch(text, time_scale::utc)).value();
}

const aem_attitude& must_read(const checked<aem_attitude>& r) {
  if (const diagnostic* e = error_of(r)) FAIL(e->text());
  return r.value();
}

std::string refusal_of_text(std::string_view content, const char* name = "bad.aem") {
  const text_file f(name, content);
  const checked<aem_attitude> r = read_aem(f.path());
  const diagnostic* e = error_of(r);
  if (!e) FAIL("read, not refused");
  // The message names the file as given; without its directory for the comparisons.
  return replaced(e->text(), f.path(), name);
}

interpolated_attitude attitude(const aem_attitude& a, const instant& t) {
  const checked<interpolated_attitude> r = a.attitude_at(t);
  if (const diagnostic* e = error_of(r)) FAIL(e->text());
  return r.value();
}

/// An AEM of one segment whose META block holds `frames` (REF_FRAME_A/B, ATTITUDE_DIR,
/// QUATERNION_TYPE and any interpolation) and whose data lines are `data`.
std::string aem(const std::string& frames, const std::string& data,
                const std::string& version = "1.0") {
  return "CCSDS_AEM_VERS = " + version +
         "\nCREATION_DATE = 2020-01-01T00:00:00\nORIGINATOR = conescan tests\n\nMETA_START\n"
         "OBJECT_NAME = TEST\nOBJECT_ID = 2020-001A\n" +
         frames +
         "TIME_SYSTEM = UTC\nSTART_TIME = 2020-01-01T00:00:00\nSTOP_TIME = 2020-01-01T00:01:00\n"
         "ATTITUDE_TYPE = QUATERNION\nMETA_STOP\n\nDATA_START\n" +
         data + "DATA_STOP\n";
}

/// The same quaternion line at the segment's start and end (a constant attitude).
std::string constant(const std::string& components) {
  return "2020-01-01T00:00:00 " + components + "\n2020-01-01T00:01:00 " + components + "\n";
}

mat3<double> dcm_of(const std::string& content) {
  const text_file f("convention.aem", content);
  const checked<aem_attitude> r = read_aem(f.path());
  return attitude(must_read(r), utc("2020-01-01T00:00:30")).dcm();
}

void check_vector(const vec3<double>& actual, const vec3<double>& expected, double tolerance) {
  INFO("actual (" << actual.x << ", " << actual.y << ", " << actual.z << ")");
  CHECK(conescan::norm(actual - expected) < tolerance);
}

/// Shuster's attitude matrix A(Q) (aem.hpp), written out here independently of rotation.hpp:
/// v_B = A(Q) v_A for the quaternion (q1, q2, q3, qc) that transforms A to B.
vec3<double> shuster_apply(double q1, double q2, double q3, double qc, const vec3<double>& v) {
  const vec3<double> q(q1, q2, q3);
  return v * (qc * qc - conescan::dot(q, q)) + q * (2 * conescan::dot(q, v)) -
         conescan::cross(q, v) * (2 * qc);
}

}  // namespace

TEST_CASE("AEM quaternion conventions: A2B against B2A, scalar first against last", "[aem]") {
  const vec3<double> x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
  const std::string inertial_body = "REF_FRAME_A = EME2000\nREF_FRAME_B = SC_BODY_1\n";
  const std::string body_inertial = "REF_FRAME_A = SC_BODY_1\nREF_FRAME_B = EME2000\n";
  // +90 deg about z, written five ways that all mean it.
  const std::vector<std::string> files = {
      aem(inertial_body + "ATTITUDE_DIR = A2B\nQUATERNION_TYPE = LAST\n",
          constant("0 0 " + s45 + " " + s45)),
      aem(inertial_body + "ATTITUDE_DIR = A2B\nQUATERNION_TYPE = FIRST\n",
          constant(s45 + " 0 0 " + s45)),
      aem(inertial_body + "ATTITUDE_DIR = B2A\nQUATERNION_TYPE = LAST\n",
          constant("0 0 -" + s45 + " " + s45)),
      aem(body_inertial + "ATTITUDE_DIR = B2A\nQUATERNION_TYPE = LAST\n",
          constant("0 0 " + s45 + " " + s45)),
      aem(body_inertial + "ATTITUDE_DIR = A2B\nQUATERNION_TYPE = first\n",
          constant("-" + s45 + " 0 0 " + s45)),  // the negated quaternion: the same rotation
  };
  for (const std::string& f : files) {
    INFO(f);
    const mat3<double> c = dcm_of(f);
    check_vector(apply(c, y), x, 1e-15);
    check_vector(apply(c, x), -y, 1e-15);
    check_vector(apply(c, z), z, 1e-15);
  }
  // Each wrong reading gives the opposite turn or another rotation: the tests can fail.
  check_vector(apply(dcm_of(aem(inertial_body + "ATTITUDE_DIR = B2A\nQUATERNION_TYPE = LAST\n",
                                constant("0 0 " + s45 + " " + s45))),
                     y),
               -x, 1e-15);
  // +120 deg about (1, 1, 1): the axes permuted, for every direction and order.
  const mat3<double> c = dcm_of(aem(inertial_body + "ATTITUDE_DIR = A2B\nQUATERNION_TYPE = LAST\n",
                                    constant("0.5 0.5 0.5 0.5")));
  check_vector(apply(c, y), x, 1e-15);
  check_vector(apply(c, z), y, 1e-15);
  check_vector(apply(c, x), z, 1e-15);
  // Version 2 without ATTITUDE_DIR: A2B.
  check_vector(apply(dcm_of(aem(inertial_body + "QUATERNION_TYPE = LAST\n",
                                constant("0.5 0.5 0.5 0.5"), "2.0")),
                     x),
               z, 1e-15);
}

TEST_CASE("AEMExample01 and 02: read as Orekit reads them", "[aem]") {
  const checked<aem_attitude> r = read_aem(ccsds_dir + "AEMExample01.txt");
  const aem_attitude& a = must_read(r);
  REQUIRE(a.segments().size() == 2);
  const aem_segment& s = a.segments()[0];
  CHECK(s.inertial_frame == "EME2000");
  CHECK(s.body_frame == "SC_BODY_1");
  CHECK(s.method == interpolation_method::hermite);
  CHECK(s.degree == 7);
  CHECK(s.samples.size() == 4);
  CHECK(a.usable_start() == utc("1996-11-28T22:08:02.5555"));
  CHECK(a.usable_stop() == utc("1996-12-28T21:23:00.5555"));
  // Orekit (AEMParserTest.testParseAEM01): the second line is Rotation(0.74533, 0.42319,
  // -0.45697, 0.23784), whose applyTo turns an EME2000 vector into the body frame: A(Q) v.
  // At the sample's own epoch the interpolant is the sample (normalised: |Q| = 1 - 2e-6).
  const mat3<double> c = attitude(a, utc("1996-11-28T22:08:03.5555")).dcm();
  const double n =
      std::sqrt(0.42319 * 0.42319 + 0.45697 * 0.45697 + 0.23784 * 0.23784 + 0.74533 * 0.74533);
  for (const vec3<double>& v :
       {vec3<double>(1, 0, 0), vec3<double>(0, 1, 0), vec3<double>(0, 0, 1)}) {
    check_vector(apply(c, v), shuster_apply(0.42319 / n, -0.45697 / n, 0.23784 / n, 0.74533 / n, v),
                 1e-14);
  }
  // Before USEABLE_START_TIME (the first line, 21:29:07) it serves no time.
  const checked<interpolated_attitude> early = a.attitude_at(utc("1996-11-28T21:29:07.2555"));
  CHECK(error_of(early));
  must_read(read_aem(ccsds_dir + "AEMExample02.txt"));
  // Its samples turn by 100 deg and more in a second: far beyond any accuracy.
  const checked<void> e =
      a.check_coverage(a.usable_start(), utc("1996-11-29T00:00:00"), 1e-6 * deg);
  REQUIRE_FALSE(e.ok());
  CHECK(e.error().message.find("attitude interpolation error estimate") == 0);
  CHECK(a.check_coverage(a.usable_start(), utc("1996-11-29T00:00:00"), std::nullopt).ok());
  // Between the segments (1996-11-30T01:18:02.5555 to 1996-12-18T12:10:00.5555): no data.
  const checked<void> gap =
      a.check_coverage(utc("1996-11-29T00:00:00"), utc("1996-12-20T00:00:00"), std::nullopt);
  REQUIRE_FALSE(gap.ok());
  CHECK(gap.error().message.find("no usable data just after 1996-11-30T01:18:02.556 UTC") == 0);
}

TEST_CASE("AEM interpolation on the rotation group", "[aem]") {
  const std::string frames =
      "REF_FRAME_A = EME2000\nREF_FRAME_B = SC_BODY_1\nATTITUDE_DIR = "
      "B2A\nQUATERNION_TYPE = FIRST\n";
  // B2A with scalar first: the line is q_BI itself, (cos(a/2), 0, 0, sin(a/2)) for a turn by a
  // about z of the vectors (the body axes turned by -a).
  const auto line = [](double t, double angle) {
    std::ostringstream s;
    s.precision(17);
    s << format_utc(add_seconds(utc("2020-01-01T00:00:00"), t), 6) << " " << std::cos(angle / 2)
      << " 0 0 " << std::sin(angle / 2) << "\n";
    return s.str();
  };
  SECTION("LINEAR (the default) is the geodesic: slerp") {
    const text_file f("slerp.aem", aem(frames, line(0, 0) + line(60, 90 * deg)));
    const checked<aem_attitude> r = read_aem(f.path());
    const mat3<double> c = attitude(must_read(r), utc("2020-01-01T00:00:20")).dcm();
    check_vector(apply(c, vec3<double>(1, 0, 0)), {std::cos(30 * deg), std::sin(30 * deg), 0},
                 1e-15);
  }
  SECTION("LAGRANGE of degree d is exact for an angle polynomial of degree d, past pi") {
    // angle(t) = 0.3 t + 0.004 t^2 - 2e-5 t^3 rad: 2.6 rad per 2-s step at most, many turns.
    const auto angle = [](double t) { return 0.3 * t + 0.004 * t * t - 2e-5 * t * t * t; };
    std::string data;
    for (int k = 0; k <= 30; ++k) data += line(2.0 * k, angle(2.0 * k));
    for (const int d : {3, 5}) {
      const text_file f("spin.aem", aem(frames +
                                            "INTERPOLATION_METHOD = LAGRANGE\n"
                                            "INTERPOLATION_DEGREE = " +
                                            std::to_string(d) + "\n",
                                        data));
      const checked<aem_attitude> r = read_aem(f.path());
      const aem_attitude& a = must_read(r);
      double worst = 0, worst_estimate = 0;
      for (double t = 0.1; t < 60; t += 0.77) {
        const interpolated_attitude q = attitude(a, add_seconds(utc("2020-01-01T00:00:00"), t));
        const vec3<double> x = apply(q.dcm(), vec3<double>(1, 0, 0));
        worst = std::max(
            worst, std::abs(std::remainder(std::atan2(x.y, x.x) - angle(t), 2 * std::numbers::pi)));
        worst_estimate = std::max(worst_estimate, static_cast<double>(q.estimate.angle_rad));
      }
      CHECK(worst < 1e-12);
      CHECK(worst_estimate < 1e-6);  // float storage of an estimate that is ~1e-13
    }
    // HERMITE on quaternions alone is LAGRANGE of the same degree.
    const text_file h("spin.aem", aem(frames + "INTERPOLATION_METHOD = HERMITE\n"
                                               "INTERPOLATION_DEGREE = 3\n",
                                      data));
    const checked<aem_attitude> r = read_aem(h.path());
    CHECK(must_read(r).segments()[0].points() == 4);
  }
  SECTION("quaternion signs flipping between lines change nothing") {
    std::string data, flipped;
    for (int k = 0; k <= 6; ++k) {
      const double a = 0.4 * k;
      data += line(10.0 * k, a);
      std::string l = line(10.0 * k, a);
      if (k % 2 == 1) l = line(10.0 * k, a + 2 * std::numbers::pi);  // -q
      flipped += l;
    }
    const std::string lagrange = "INTERPOLATION_METHOD = LAGRANGE\nINTERPOLATION_DEGREE = 3\n";
    const text_file f1("a.aem", aem(frames + lagrange, data));
    const text_file f2("b.aem", aem(frames + lagrange, flipped));
    const checked<aem_attitude> r1 = read_aem(f1.path());
    const checked<aem_attitude> r2 = read_aem(f2.path());
    for (double t = 0; t <= 60; t += 3.3) {
      const instant at = add_seconds(utc("2020-01-01T00:00:00"), t);
      CHECK(angle_between(attitude(must_read(r1), at).body_from_inertial,
                          attitude(must_read(r2), at).body_from_inertial) < 1e-15);
    }
  }
}

TEST_CASE("the CCSDS examples and malformed AEMs are refused with line and keyword", "[aem]") {
  CHECK(refusal_of_text(read_text(ccsds_dir + "AEM-wrong-keyword.txt"), "AEM-wrong-keyword.txt") ==
        "AEM-wrong-keyword.txt:24: unknown keyword 'WRONG_KEYWORD' in the META block");
  CHECK(refusal_of_text(read_text(ccsds_dir + "OEMExample5ITRF.txt"), "OEMExample5ITRF.txt") ==
        "OEMExample5ITRF.txt:1: this is an OEM (CCSDS_OEM_VERS), not an AEM");
  const std::string frames =
      "REF_FRAME_A = EME2000\nREF_FRAME_B = SC_BODY_1\nATTITUDE_DIR = "
      "A2B\nQUATERNION_TYPE = LAST\n";
  const std::string good = aem(frames, constant("0 0 0 1"));
  const text_file ok("ok.aem", good);
  must_read(read_aem(ok.path()));
  struct bad_case {
    std::string content;
    std::string expected;
  };
  const std::vector<bad_case> cases = {
      {replaced(good, "ATTITUDE_TYPE = QUATERNION", "ATTITUDE_TYPE = EULER_ANGLE"),
       "bad.aem:15: unsupported ATTITUDE_TYPE 'EULER_ANGLE' (conescan takes QUATERNION only)"},
      {replaced(good, "ATTITUDE_TYPE = QUATERNION", "ATTITUDE_TYPE = QUATERNION/RATE"),
       "bad.aem:15: unsupported ATTITUDE_TYPE 'QUATERNION/RATE' (conescan takes QUATERNION "
       "only)"},
      {replaced(good, "QUATERNION_TYPE = LAST\n", ""),
       "bad.aem:15: missing mandatory keyword QUATERNION_TYPE in the META block starting at line "
       "5 (ATTITUDE_TYPE QUATERNION)"},
      {replaced(good, "QUATERNION_TYPE = LAST", "QUATERNION_TYPE = MIDDLE"),
       "bad.aem:11: unsupported QUATERNION_TYPE 'MIDDLE' (conescan takes FIRST or LAST)"},
      {replaced(good, "ATTITUDE_DIR = A2B\n", ""),
       "bad.aem:15: missing mandatory keyword ATTITUDE_DIR in the META block starting at line 5 "
       "(AEM version 1)"},
      {replaced(good, "ATTITUDE_DIR = A2B", "ATTITUDE_DIR = C2D"),
       "bad.aem:10: unsupported ATTITUDE_DIR 'C2D' (conescan takes A2B or B2A)"},
      {replaced(good, "REF_FRAME_A = EME2000", "REF_FRAME_A = LVLH"),
       "bad.aem:8: unsupported REF_FRAME_A 'LVLH' (conescan takes one inertial frame, EME2000, "
       "GCRF, ICRF, TEME or TOD, and one spacecraft body frame, SC_BODY_n)"},
      {replaced(good, "REF_FRAME_B = SC_BODY_1", "REF_FRAME_B = ICRF"),
       "bad.aem:9: unsupported REF_FRAME_B 'ICRF' (conescan takes one inertial frame, EME2000, "
       "GCRF, ICRF, TEME or TOD, and one spacecraft body frame, SC_BODY_n)"},
      {replaced(good, "TIME_SYSTEM = UTC", "TIME_SYSTEM = MET"),
       "bad.aem:12: unsupported TIME_SYSTEM 'MET' (conescan takes UTC, TAI, TT or GPS)"},
      {replaced(good, "0 0 0 1\n2020", "0 0 0 0.9\n2020"),
       "bad.aem:19: quaternion of norm 0.9 (expected 1 within 0.001)"},
      {replaced(good, "0 0 0 1\n2020", "0 0 1\n2020"),
       "bad.aem:19: data line with 4 fields (expected an epoch and the 4 quaternion components)"},
      {replaced(good, "0 0 0 1\n2020", "0 0 0 one\n2020"),
       "bad.aem:19: malformed number 'one' (QC)"},
      {replaced(good, "DATA_START\n", ""), "bad.aem:18: data line before DATA_START"},
      {replaced(good, "DATA_STOP\n", ""), "bad.aem:20: the DATA_START at line 18 has no DATA_STOP"},
      {good + "2020-01-01T00:02:00 0 0 0 1\n", "bad.aem:22: data line after DATA_STOP"},
      {replaced(good, "2020-01-01T00:01:00 0", "2020-01-01T00:00:00 0"),
       "bad.aem:20: epoch 2020-01-01T00:00:00 repeats the previous line's (epochs must increase "
       "within a segment)"},
      {replaced(good, "DATA_START\n", "DATA_START\nMETA_START\n"),
       "bad.aem:19: unexpected META_START between DATA_START and DATA_STOP"},
      {replaced(good, "CCSDS_AEM_VERS = 1.0", "CCSDS_AEM_VERS = 3.0"),
       "bad.aem:1: unsupported CCSDS_AEM_VERS '3.0' (conescan reads versions 1 to 2)"},
  };
  for (const bad_case& c : cases) {
    INFO(c.content);
    CHECK(refusal_of_text(c.content) == c.expected);
  }
  // A requested time outside the usable span, and a span the file does not cover.
  const checked<aem_attitude> r = read_aem(ok.path());
  const aem_attitude& a = must_read(r);
  const checked<interpolated_attitude> late = a.attitude_at(utc("2020-01-01T00:01:01"));
  REQUIRE(error_of(late));
  CHECK(error_of(late)->message.find("no usable data at 2020-01-01T00:01:01.000 UTC") == 0);
  const checked<void> e =
      a.check_coverage(utc("2020-01-01T00:00:10"), utc("2020-01-01T00:02:00"), std::nullopt);
  REQUIRE_FALSE(e.ok());
  CHECK(e.error().text().ends_with(
      "ok.aem: no usable data just after 2020-01-01T00:01:00.000 UTC; usable: "
      "2020-01-01T00:00:00.000 to 2020-01-01T00:01:00.000 (segment at line 5) UTC"));
}
