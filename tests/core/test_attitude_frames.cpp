// Frames of MODEL §2 and §4: the 3-2-1 attitude (attitude.hpp), the orbital frame
// (orbital_frame.hpp) and a head's scan frame (scan_frame.hpp), in double.
//
// Expected values: the DCM is rebuilt here as the product of the three textbook elementary
// rotations; the scan frame's e1 is rebuilt as the normalised projection of body +z on the
// plane normal to S (MODEL §4's definition, not the header's closed form); the orbital frame is
// checked on a hand-worked circular orbit and by its defining properties.
#include <catch2/catch.hpp>
#include <cmath>
#include <initializer_list>
#include <limits>

#include "conescan/attitude.hpp"
#include "conescan/orbital_frame.hpp"
#include "conescan/processing.hpp"
#include "conescan/scan_frame.hpp"
#include "support/approx.hpp"

using conescan::deg_to_rad;
using conescan::mat3;
using conescan::status;
using conescan::vec3;

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();

double deg(double d) {
  return deg_to_rad(d);
}

/// Row-major 3x3 for the textbook products (independent of GLM's column-major storage).
struct matrix {
  double m[3][3];
};

matrix product(const matrix& a, const matrix& b) {
  matrix c{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) c.m[i][j] += a.m[i][k] * b.m[k][j];
  return c;
}

// Elementary frame rotations (passive, body <- reference) about axes 1, 2, 3.
matrix r1(double a) {
  return {{{1, 0, 0}, {0, std::cos(a), std::sin(a)}, {0, -std::sin(a), std::cos(a)}}};
}
matrix r2(double a) {
  return {{{std::cos(a), 0, -std::sin(a)}, {0, 1, 0}, {std::sin(a), 0, std::cos(a)}}};
}
matrix r3(double a) {
  return {{{std::cos(a), std::sin(a), 0}, {-std::sin(a), std::cos(a), 0}, {0, 0, 1}}};
}

void check_vec(const vec3<double>& actual, const vec3<double>& expected, double tol) {
  CHECK_WITHIN(actual.x, expected.x, tol);
  CHECK_WITHIN(actual.y, expected.y, tol);
  CHECK_WITHIN(actual.z, expected.z, tol);
}

/// Columns orthonormal and right-handed (det = +1 through e1 x e2 = e3).
void check_right_handed_orthonormal(const vec3<double>& e1, const vec3<double>& e2,
                                    const vec3<double>& e3, double tol) {
  CHECK_WITHIN(conescan::dot(e1, e1), 1.0, tol);
  CHECK_WITHIN(conescan::dot(e2, e2), 1.0, tol);
  CHECK_WITHIN(conescan::dot(e3, e3), 1.0, tol);
  CHECK_WITHIN(conescan::dot(e1, e2), 0.0, tol);
  CHECK_WITHIN(conescan::dot(e1, e3), 0.0, tol);
  CHECK_WITHIN(conescan::dot(e2, e3), 0.0, tol);
  check_vec(conescan::cross(e1, e2), e3, tol);
}

const double angles_deg[] = {-179.0, -120.0, -45.0, -3.0, 0.0, 0.02, 10.0, 89.0, 135.0, 180.0};

}  // namespace

TEST_CASE("dcm_body_from_orbit is R1(roll) R2(pitch) R3(yaw)", "[attitude]") {
  // Tolerance: each entry is a sum of at most two products of three roundings: 4 eps.
  for (double roll : angles_deg) {
    for (double pitch : {-89.0, -30.0, 0.0, 5.0, 60.0}) {
      for (double yaw : angles_deg) {
        INFO("roll " << roll << " pitch " << pitch << " yaw " << yaw);
        const mat3<double> c = conescan::dcm_body_from_orbit(deg(roll), deg(pitch), deg(yaw));
        const matrix expected = product(r1(deg(roll)), product(r2(deg(pitch)), r3(deg(yaw))));
        for (int row = 0; row < 3; ++row)
          for (int col = 0; col < 3; ++col)
            CHECK_WITHIN(c[col][row], expected.m[row][col], 4 * eps);
        check_right_handed_orthonormal(c[0], c[1], c[2], 8 * eps);
      }
    }
  }
}

TEST_CASE("nadir_in_body is the orbital +z in body axes, independent of yaw", "[attitude]") {
  // MODEL §2: n = C (0, 0, 1) = third column of C = (-sin pitch, sin roll cos pitch,
  // cos roll cos pitch). apply/apply_transpose are C v and C^T v.
  for (double roll : angles_deg) {
    for (double pitch : {-89.0, -30.0, 0.0, 5.0, 60.0}) {
      const vec3<double> n = conescan::nadir_in_body(deg(roll), deg(pitch));
      for (double yaw : {-100.0, 0.0, 33.0}) {
        INFO("roll " << roll << " pitch " << pitch << " yaw " << yaw);
        const mat3<double> c = conescan::dcm_body_from_orbit(deg(roll), deg(pitch), deg(yaw));
        check_vec(n, c[2], 0.0);  // same expressions: exactly equal
        check_vec(conescan::apply(c, vec3<double>(0, 0, 1)), n, 0.0);
        check_vec(conescan::apply_transpose(c, n), vec3<double>(0, 0, 1), 4 * eps);
      }
      CHECK_WITHIN(conescan::norm(n), 1.0, 2 * eps);
    }
  }
  // Hand-derived: roll 90 deg puts the nadir on body +y; pitch 90 deg on body -x.
  check_vec(conescan::nadir_in_body(deg(90), 0.0), vec3<double>(0, 1, 0), eps);
  check_vec(conescan::nadir_in_body(0.0, deg(90)), vec3<double>(-1, 0, 0), eps);
}

TEST_CASE("roll_pitch_from_nadir inverts nadir_in_body", "[attitude][round_trip]") {
  // For |pitch| < 90 deg and roll in (-180, 180] the round trip is exact to rounding: atan2 of
  // components with 2 eps relative error each. Tolerance 4 eps (times 1/cos pitch for roll,
  // whose components shrink as cos pitch).
  for (double roll : angles_deg) {
    for (double pitch : {-89.9, -60.0, -1.0, 0.0, 0.01, 45.0, 89.9}) {
      INFO("roll " << roll << " pitch " << pitch);
      const vec3<double> n = conescan::nadir_in_body(deg(roll), deg(pitch));
      const double tol = 4 * eps / std::cos(deg(pitch)) + 4 * eps;
      for (double length : {1.0, 1e-3, 7e6}) {  // any length (MODEL §2: any nadir estimate)
        const conescan::roll_pitch<double> rp = conescan::roll_pitch_from_nadir(n * length);
        CHECK_WITHIN(rp.roll, deg(roll), tol * 4);
        CHECK_WITHIN(rp.pitch, deg(pitch), tol);
      }
    }
  }
  // |pitch| > 90 deg is the same nadir as pitch' = 180 - pitch with roll + 180: the inverse
  // returns that equivalent in [-90, 90], which maps back to the same nadir.
  const vec3<double> n = conescan::nadir_in_body(deg(10), deg(100));
  const conescan::roll_pitch<double> rp = conescan::roll_pitch_from_nadir(n);
  CHECK_WITHIN(rp.pitch, deg(80), 8 * eps);
  CHECK_WITHIN(rp.roll, deg(-170), 8 * eps);
  check_vec(conescan::nadir_in_body(rp.roll, rp.pitch), n, 4 * eps);
}

TEST_CASE("scan frame: orthonormal, right-handed, e1 the projection of body +z", "[scan_frame]") {
  // MODEL §4: e3 = S = (cos a cos b, cos a sin b, sin a); e1 = unit projection of body +z on the
  // plane normal to S (rebuilt here as z - (z.S) S, normalised); e2 = e3 x e1.
  const vec3<double> body_z(0, 0, 1);
  for (double alpha : {-89.9, -60.0, -20.0, 0.0, 0.5, 20.0, 45.0, 89.0, 89.9}) {
    for (double beta : angles_deg) {
      INFO("alpha " << alpha << " beta " << beta);
      const double a = deg(alpha), b = deg(beta);
      const conescan::scan_frame<double> f = conescan::scan_frame_from_mounting(a, b);
      REQUIRE(f.state == status::ok);
      check_vec(f.e3,
                vec3<double>(std::cos(a) * std::cos(b), std::cos(a) * std::sin(b), std::sin(a)),
                2 * eps);
      const vec3<double> projection = body_z - f.e3 * conescan::dot(body_z, f.e3);
      // Normalising a projection of length cos a costs 1/cos a in relative accuracy.
      check_vec(f.e1, conescan::unit(projection), 8 * eps / std::cos(a));
      CHECK(conescan::dot(f.e1, body_z) > 0);  // towards nadir, not away from it
      check_right_handed_orthonormal(f.e1, f.e2, f.e3, 8 * eps);
      // Nominal nadir angle eta0 = 90 deg - alpha (MODEL §4).
      CHECK_WITHIN(conescan::nominal_nadir_angle(f), deg(90) - a, 8 * eps);
    }
  }
  // Hand-derived: alpha = 0, beta = 90 deg (the paper's head): S = +y, e1 = +z, e2 = +x.
  const conescan::scan_frame<double> paper = conescan::scan_frame_from_mounting(0.0, deg(90));
  check_vec(paper.e3, vec3<double>(0, 1, 0), eps);
  check_vec(paper.e1, vec3<double>(0, 0, 1), eps);
  check_vec(paper.e2, vec3<double>(1, 0, 0), eps);
}

TEST_CASE("scan frame: |alpha| >= 90 deg is invalid, on both sides", "[scan_frame][status]") {
  const double half_pi = conescan::pi<double>() / 2;
  for (double sign : {1.0, -1.0}) {
    INFO("sign " << sign);
    const conescan::scan_frame<double> at = conescan::scan_frame_from_mounting(sign * half_pi, 0.3);
    CHECK(at.state == status::invalid);
    CHECK(std::isnan(at.e1.x));
    CHECK(conescan::scan_frame_from_mounting(sign * deg(90.5), 0.3).state == status::invalid);
    const conescan::scan_frame<double> inside =
        conescan::scan_frame_from_mounting(sign * std::nextafter(half_pi, 0.0), 0.3);
    CHECK(inside.state == status::ok);
    check_right_handed_orthonormal(inside.e1, inside.e2, inside.e3, 8 * eps);
  }
  for (double bad :
       {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    CHECK(conescan::scan_frame_from_mounting(bad, 0.3).state == status::invalid);
    CHECK(conescan::scan_frame_from_mounting(0.3, bad).state == status::invalid);
  }
}

TEST_CASE("direction_in_scan_frame and scan_angles_of are inverses", "[scan_frame][round_trip]") {
  // Polar angle in (0, pi) and azimuth in [-pi, pi]: the pair is unique (up to the cut at
  // +-pi), so the round trip recovers both to a few ulp (azimuth: relative to its radial part
  // sin psi).
  const conescan::scan_frame<double> f = conescan::scan_frame_from_mounting(deg(20), deg(-35));
  for (double psi : {0.001, 1.0, 30.0, 45.0, 90.0, 120.0, 179.0}) {
    for (double phi : {-179.0, -90.0, -1.0, 0.0, 12.5, 90.0, 180.0}) {
      INFO("psi " << psi << " phi " << phi);
      const vec3<double> d = conescan::direction_in_scan_frame(f, deg(psi), deg(phi));
      CHECK_WITHIN(conescan::norm(d), 1.0, 4 * eps);
      const conescan::scan_angles<double> back = conescan::scan_angles_of(f, d);
      CHECK_WITHIN(back.polar, deg(psi), 8 * eps);
      // At phi = 180 deg rounding may land on either side of the cut: compare modulo 2 pi.
      CHECK_WITHIN(conescan::wrap_pi(back.azimuth - deg(phi)), 0.0, 8 * eps / std::sin(deg(psi)));
      CHECK(back.azimuth >= -conescan::pi<double>());  // atan2 gives -pi for a -0 e2 part
      CHECK(back.azimuth <= conescan::pi<double>());
    }
  }
  // Hand-derived: psi = 0 is e3; psi = 90 deg at phi = 0 and 90 deg are e1 and e2.
  check_vec(conescan::direction_in_scan_frame(f, 0.0, 1.234), f.e3, 0.0);
  check_vec(conescan::direction_in_scan_frame(f, deg(90), 0.0), f.e1, 2 * eps);
  check_vec(conescan::direction_in_scan_frame(f, deg(90), deg(90)), f.e2, 2 * eps);
}

TEST_CASE("dcm_eci_from_orbit: the LVLH frame of MODEL §2", "[orbital_frame]") {
  // Hand-worked circular equatorial orbit: r = 7000 km x, v = 7.5 km/s y. Then z_o = -x,
  // y_o = -(x cross y)/|.| = -z, x_o = y_o cross z_o = (-z) cross (-x) = y: along the velocity.
  const mat3<double> c =
      conescan::dcm_eci_from_orbit(vec3<double>(7e6, 0, 0), vec3<double>(0, 7.5e3, 0));
  check_vec(c[0], vec3<double>(0, 1, 0), eps);
  check_vec(c[1], vec3<double>(0, 0, -1), eps);
  check_vec(c[2], vec3<double>(-1, 0, 0), eps);
  // General (eccentric, inclined) state: the defining properties.
  const vec3<double> r(5.1e6, -3.3e6, 4.2e6), v(2.1e3, 6.4e3, 1.3e3);
  const mat3<double> o = conescan::dcm_eci_from_orbit(r, v);
  check_right_handed_orthonormal(o[0], o[1], o[2], 8 * eps);
  check_vec(o[2], -conescan::unit(r), 4 * eps);
  check_vec(o[1], -conescan::unit(conescan::cross(r, v)), 4 * eps);
  CHECK(conescan::dot(o[0], v) > 0);  // along-track, in the sense of motion
  CHECK_WITHIN(conescan::dot(o[0], r), 0.0, 8 * eps * conescan::norm(r));
}
