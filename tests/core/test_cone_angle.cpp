// The misaligned cone angle psi: corrected Eq. (1) of the paper (MODEL §4), in double.
//
// Expected values come from the definition, not from the implementation: psi is the polar angle
// (from S) of the line of sight L at azimuth phi_b (from A's azimuth) that makes the angle gamma
// with the optical axis A, A being sigma from S. That is checked
//  - geometrically, by building A and L as vectors in long double and measuring their angle;
//  - through the spherical-triangle identity cos gamma = cos sigma cos psi + sin sigma sin psi
//    cos phi_b (MODEL §4) and the triangle inequality |gamma - sigma| <= psi <= gamma + sigma;
//  - at hand-derived points: phi_b = 0 (L, A and S coplanar, L beyond A) gives gamma + sigma,
//    phi_b = 180 deg gives gamma - sigma, phi_b = +-90 deg gives cos psi = cos gamma / cos sigma;
//  - against the paper's quadratic form (misaligned_cone_angle_quadratic).
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <vector>

#include "conescan/cone_angle.hpp"
#include "conescan/vector.hpp"
#include "support/adl_scalar.hpp"
#include "support/approx.hpp"

using conescan::misaligned_cone_angle;
using conescan::misaligned_cone_angle_quadratic;
using conescan::misaligned_cone_angle_slope;
using conescan::status;
using conescan_test::deg;
using conescan_test::eps;

namespace {

constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();
constexpr double inf = std::numeric_limits<double>::infinity();

struct cone_case {
  double gamma, sigma, phi_b;
};

// gamma from near 0 to near 90 deg; sigma from 0 to 0.99 gamma (plus the paper's 0.02 deg);
// phi_b over more than a full turn, including the hand-derived points and values off the grid.
std::vector<cone_case> cone_grid() {
  const int gammas_tenths_deg[] = {5, 10, 50, 100, 200, 300, 450, 600, 750, 850, 895};
  const double sigma_fractions[] = {0, 1e-9, 1e-6, 1e-3, 0.1, 0.5, 0.9, 0.99};
  std::vector<cone_case> grid;
  for (int g : gammas_tenths_deg) {
    const double gamma = deg<double>(g, 10);
    std::vector<double> sigmas;
    for (double f : sigma_fractions) sigmas.push_back(f * gamma);
    if (gamma > deg<double>(2, 100)) sigmas.push_back(deg<double>(2, 100));
    for (double s : sigmas) {
      for (int p = -360; p <= 360; p += 15) grid.push_back({gamma, s, deg<double>(p)});
      for (int p : {-1799, -937, -1, 1, 73, 899, 901, 1234, 1799, 10000})
        grid.push_back({gamma, s, deg<double>(p, 10)});
    }
  }
  return grid;
}

/// Angle between A and the line of sight L(psi, phi_b), built as vectors in long double: the
/// definition of psi (MODEL §4). A lies in the e1-e3 plane (phi_a = 0), so L's azimuth is phi_b.
long double angle_optical_axis_to_line_of_sight(double sigma, double psi, double phi_b) {
  const long double s = sigma, p = psi, f = phi_b;
  const conescan::vec3<long double> a(std::sin(s), 0.0L, std::cos(s));
  const conescan::vec3<long double> l(std::sin(p) * std::cos(f), std::sin(p) * std::sin(f),
                                      std::cos(p));
  return conescan::angle_between(a, l);
}

}  // namespace

TEST_CASE("misaligned_cone_angle is the polar angle of the line of sight at gamma from A",
          "[cone_angle][eq1]") {
  // Tolerance: 4 ulp of the larger of the two terms atan2(h, cos sigma) (|.| <= sigma) and
  // acos(.) (<= gamma) whose sum is psi, i.e. 4 eps (gamma + sigma) absolute. The long double
  // evaluation of the angle adds ~1e-19. d(angle)/d(psi) <= 1, so the check cannot be looser
  // than the error of psi itself (it is blind only where L moves along the cone about A).
  for (const cone_case& c : cone_grid()) {
    const conescan::result<double> psi = misaligned_cone_angle(c.gamma, c.sigma, c.phi_b);
    INFO("gamma " << c.gamma << " sigma " << c.sigma << " phi_b " << c.phi_b);
    REQUIRE(psi.ok());
    const double tol = 4 * eps<double>() * (c.gamma + c.sigma);
    CHECK_WITHIN(angle_optical_axis_to_line_of_sight(c.sigma, psi.value, c.phi_b),
                 static_cast<long double>(c.gamma), static_cast<long double>(tol));
    // The spherical triangle SAH (MODEL §4), residual of one rounding per term.
    const double residual = std::cos(c.sigma) * std::cos(psi.value) +
                            std::sin(c.sigma) * std::sin(psi.value) * std::cos(c.phi_b) -
                            std::cos(c.gamma);
    CHECK(std::abs(residual) <= 8 * eps<double>());
    // Triangle inequality on the sphere: the root that is gamma when sigma = 0.
    CHECK(psi.value >= c.gamma - c.sigma - tol);
    CHECK(psi.value <= c.gamma + c.sigma + tol);
  }
}

TEST_CASE("misaligned_cone_angle at hand-derived azimuths", "[cone_angle][eq1]") {
  // phi_b = 0: S, A and L coplanar with A between them: psi = gamma + sigma.
  // phi_b = 180 deg: A on the other side of S: psi = gamma - sigma.
  // phi_b = +-90 deg: cos phi_b = 0 and the identity reduces to cos psi = cos gamma / cos sigma
  // (evaluated in long double). Tolerance 4 eps (gamma + sigma), as above.
  for (int g : {1, 10, 45, 80}) {
    for (double f : {0.0, 1e-6, 0.02 / 45, 0.3, 0.9}) {
      const double gamma = deg<double>(g), sigma = f * gamma;
      const double tol = 4 * eps<double>() * (gamma + sigma);
      INFO("gamma " << gamma << " sigma " << sigma);
      CHECK_WITHIN(misaligned_cone_angle(gamma, sigma, 0.0).value, gamma + sigma, tol);
      CHECK_WITHIN(misaligned_cone_angle(gamma, sigma, conescan::pi<double>()).value, gamma - sigma,
                   tol);
      const long double right_angle = std::acos(std::cos(static_cast<long double>(gamma)) /
                                                std::cos(static_cast<long double>(sigma)));
      for (double phi_b : {deg<double>(90), deg<double>(-90)}) {
        // cos(pi/2 in double) = 6e-17, not 0: its effect, sigma * 6e-17, is below tol.
        CHECK_WITHIN(static_cast<long double>(misaligned_cone_angle(gamma, sigma, phi_b).value),
                     right_angle, static_cast<long double>(tol));
      }
    }
  }
}

TEST_CASE("misaligned_cone_angle: sigma = 0 gives psi = gamma exactly", "[cone_angle][eq1]") {
  // With sigma = 0 the optical axis is the spin axis and the line of sight lies on the nominal
  // cone at every azimuth (MODEL §4): no rounding is acceptable, the bias model and the sigma = 0
  // identities of MODEL §5 and §6 rely on it.
  // gamma (deg) = num / den: 1e-6, 0.5, 1, 7, 10, 33.3, 45, 60, 89, 89.999.
  const int gammas[][2] = {{1, 1000000}, {1, 2},  {1, 1},  {7, 1},  {10, 1},
                           {333, 10},    {45, 1}, {60, 1}, {89, 1}, {89999, 1000}};
  for (const auto& g : gammas) {
    for (int p = -360; p <= 360; p += 30) {
      const double gamma = deg<double>(g[0], g[1]), phi_b = deg<double>(p);
      INFO("gamma " << gamma << " phi_b " << phi_b);
      const conescan::result<double> psi = misaligned_cone_angle(gamma, 0.0, phi_b);
      REQUIRE(psi.ok());
      CHECK(psi.value == gamma);
      CHECK(misaligned_cone_angle_slope(0.0, phi_b, psi.value) == 0.0);
    }
  }
}

TEST_CASE("corrected Eq. (1): the quadratic form gives the same psi", "[cone_angle][eq1]") {
  // The quadratic form returns acos(cos psi): a rounding e of cos psi moves psi by e / sin psi,
  // and its radicand cos^2 sigma + h^2 - cos^2 gamma = sin^2 gamma - sin^2 sigma sin^2 phi_b
  // cancels as sigma -> gamma near phi_b = +-90 deg, where the sqrt's error is amplified by
  // h / sqrt(radicand). Tolerance: 8 eps (1 + 1/sin psi + 1/sqrt(radicand)) times (gamma + sigma)
  // for the stable form's own error; both sides are derived from the conditioning above.
  for (const cone_case& c : cone_grid()) {
    const conescan::result<double> stable = misaligned_cone_angle(c.gamma, c.sigma, c.phi_b);
    const conescan::result<double> quadratic =
        misaligned_cone_angle_quadratic(c.gamma, c.sigma, c.phi_b);
    INFO("gamma " << c.gamma << " sigma " << c.sigma << " phi_b " << c.phi_b);
    REQUIRE(stable.ok());
    REQUIRE(quadratic.ok());
    const double s_perp = std::sin(c.sigma) * std::sin(c.phi_b);
    const double radicand = std::sin(c.gamma) * std::sin(c.gamma) - s_perp * s_perp;
    const double tol = 8 * eps<double>() *
                       (1 + 1 / std::sin(stable.value) + 1 / std::sqrt(radicand)) *
                       (1 + c.gamma + c.sigma);
    CHECK_WITHIN(quadratic.value, stable.value, tol);
  }
}

TEST_CASE("misaligned_cone_angle_slope is d psi / d phi", "[cone_angle]") {
  // Central difference with step 1e-5 rad: truncation error psi''' h^2 / 6 < 1e-11 for the
  // smooth psi(phi_b) here, rounding error eps / h ~ 2e-11. Tolerance 1e-9.
  const double h = 1e-5;
  for (int g : {5, 30, 45, 80}) {
    for (double f : {0.001, 0.1, 0.5, 0.9}) {
      for (int p = -180; p <= 180; p += 20) {
        const double gamma = deg<double>(g), sigma = f * gamma, phi_b = deg<double>(p);
        const double psi = misaligned_cone_angle(gamma, sigma, phi_b).value;
        const double numeric = (misaligned_cone_angle(gamma, sigma, phi_b + h).value -
                                misaligned_cone_angle(gamma, sigma, phi_b - h).value) /
                               (2 * h);
        INFO("gamma " << gamma << " sigma " << sigma << " phi_b " << phi_b);
        CHECK_WITHIN(misaligned_cone_angle_slope(sigma, phi_b, psi), numeric, 1e-9);
      }
    }
  }
}

TEST_CASE("misaligned_cone_angle statuses on both sides of each domain boundary",
          "[cone_angle][status]") {
  // MODEL §7: gamma in (0, 90 deg), sigma in [0, gamma), finite inputs; invalid otherwise, with a
  // NaN value. Both forms share the domain, but the quadratic form is also invalid where cos psi
  // rounds to 1 (psi below ~1.5e-8 rad: acos has no digit of it left; it returned 0).
  const double half_pi = conescan::pi<double>() / 2;
  const double gamma = deg<double>(45), sigma = deg<double>(1), phi_b = deg<double>(30);
  auto check_both = [](double g, double s, double p, bool valid) {
    INFO("gamma " << g << " sigma " << s << " phi_b " << p);
    const conescan::result<double> stable = misaligned_cone_angle(g, s, p);
    const bool acos_resolves = !(stable.ok() && stable.value < 1e-7);
    const conescan::result<double> forms[] = {stable, misaligned_cone_angle_quadratic(g, s, p)};
    for (const conescan::result<double>& r : forms) {
      if (valid && !acos_resolves && &r == &forms[1]) {
        CHECK(r.state == status::invalid);
      } else if (valid) {
        CHECK(r.state == status::ok);
        CHECK(std::isfinite(r.value));
      } else {
        CHECK(r.state == status::invalid);
        CHECK(std::isnan(r.value));
      }
    }
  };
  SECTION("gamma > 0") {
    check_both(0.0, 0.0, phi_b, false);
    check_both(-0.0, 0.0, phi_b, false);
    check_both(-deg<double>(1), 0.0, phi_b, false);
    check_both(std::numeric_limits<double>::denorm_min(), 0.0, phi_b, true);
    check_both(1e-12, 1e-13, phi_b, true);
  }
  SECTION("gamma < 90 deg") {
    check_both(half_pi, sigma, phi_b, false);
    check_both(deg<double>(91), sigma, phi_b, false);
    check_both(std::nextafter(half_pi, 0.0), sigma, phi_b, true);
    check_both(std::nextafter(half_pi, 0.0), 0.0, phi_b, true);
  }
  SECTION("sigma >= 0") {
    check_both(gamma, -std::numeric_limits<double>::denorm_min(), phi_b, false);
    check_both(gamma, -deg<double>(1, 100), phi_b, false);
    check_both(gamma, 0.0, phi_b, true);
    check_both(gamma, -0.0, phi_b, true);  // -0 == 0: sigma = 0 is in the domain
  }
  SECTION("sigma < gamma") {
    check_both(gamma, gamma, phi_b, false);
    check_both(gamma, deg<double>(50), phi_b, false);
    for (double p : {0.0, deg<double>(90), deg<double>(-90), deg<double>(180), phi_b})
      check_both(gamma, std::nextafter(gamma, 0.0), p, true);
  }
  SECTION("non-finite inputs") {
    for (double bad : {not_a_number, inf, -inf}) {
      check_both(bad, sigma, phi_b, false);
      check_both(gamma, bad, phi_b, false);
      check_both(gamma, sigma, bad, false);
    }
    check_both(gamma, sigma, deg<double>(1000000), true);  // large but finite azimuths are fine
  }
}
