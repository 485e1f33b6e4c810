// Scalar genericity of the core (STYLE.md practices 2 and 9): the main properties, run for
// float, double, long double and conescan_test::adl_real (math by ADL only, no floating
// literals, not IEEE to GLM). Tolerances are multiples of std::numeric_limits<T>::epsilon(),
// times the conditioning where one is involved (stated at each check). The expected values are
// the identities of the double-only tests (test_cone_angle.cpp, test_half_chord.cpp,
// test_nadir_angle.cpp, test_scan_model.cpp), where their derivations are given.
//
// Test code here follows the core's own rules (ADL math, constants from integers), so that
// compiling it for adl_real also proves the tests generic.
#include <catch2/catch.hpp>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <type_traits>
#include <vector>

#include "conescan/conescan.hpp"
#include "support/adl_scalar.hpp"
#include "support/approx.hpp"

using conescan::status;
using conescan::vec3;
using conescan_test::adl_real;
using conescan_test::deg;
using conescan_test::eps;
using conescan_test::scalar_from;

// adl_real is only a meaningful probe if it refuses what it claims to refuse.
static_assert(std::is_constructible_v<adl_real, int>);
static_assert(std::is_convertible_v<int, adl_real>);
static_assert(!std::is_constructible_v<adl_real, double>);
static_assert(!std::is_constructible_v<adl_real, float>);
static_assert(!std::is_convertible_v<adl_real, double>);
static_assert(!std::is_convertible_v<adl_real, long double>);
static_assert(std::numeric_limits<adl_real>::is_specialized);
static_assert(!std::numeric_limits<adl_real>::is_iec559);

namespace {

template <class T>
T absolute(const T& x) {
  using std::abs;
  return abs(x);
}

template <class T>
long double ld(const T& x) {
  return static_cast<long double>(x);
}

/// |d eta / d Phi| of Eq. (5) by implicit differentiation (test_nadir_angle.cpp), long double.
long double amplification(long double gamma, long double eta, long double phi) {
  const long double denominator =
      std::sin(gamma) * std::cos(eta) * std::cos(phi) - std::cos(gamma) * std::sin(eta);
  return std::abs(std::sin(gamma) * std::sin(eta) * std::sin(phi) / denominator);
}

}  // namespace

TEMPLATE_TEST_CASE("pi, wrapping and finiteness in every scalar", "[scalar]",
                   CONESCAN_TEST_SCALARS) {
  using T = TestType;
  const T pi = conescan::pi<T>();
  const T pi_ref = scalar_from<T>(3.14159265358979323846264338327950288L);
  CHECK_WITHIN(pi, pi_ref, T(eps<T>() * 4));
  CHECK_WITHIN(conescan::deg_to_rad(T(180)), pi, T(eps<T>() * 4));
  CHECK_WITHIN(conescan::rad_to_deg(pi), T(180), T(eps<T>() * 256));
  // wrap_pi onto (-pi, pi]: both sides of the cut.
  CHECK(conescan::wrap_pi(pi) == pi);
  CHECK(conescan::wrap_pi(T(-pi)) == pi);
  CHECK_WITHIN(conescan::wrap_pi(T(5)), T(T(5) - T(2) * pi), T(eps<T>() * 16));
  CHECK_WITHIN(conescan::wrap_pi(T(-5)), T(T(2) * pi - T(5)), T(eps<T>() * 16));
  CHECK_WITHIN(conescan::wrap_pi(T(pi + T(1) / T(1000))), T(T(1) / T(1000) - pi), T(eps<T>() * 16));
  CHECK_WITHIN(conescan::wrap_pi(T(-pi + T(1) / T(1000))), T(-pi + T(1) / T(1000)),
               T(eps<T>() * 16));
  CHECK(conescan::wrap_pi(T(0)) == T(0));
  // wrap_two_pi onto [0, 2 pi).
  const T two_pi = T(2) * pi;
  CHECK(conescan::wrap_two_pi(two_pi) == T(0));
  CHECK(conescan::wrap_two_pi(T(0)) == T(0));
  const T tiny_negative = T(-std::numeric_limits<T>::denorm_min());
  const T wrapped = conescan::wrap_two_pi(tiny_negative);
  CHECK(wrapped >= T(0));
  CHECK(wrapped < two_pi);
  CHECK_WITHIN(conescan::wrap_two_pi(T(-1)), T(two_pi - T(1)), T(eps<T>() * 16));
  // is_finite and not_a_number.
  const T nan = conescan::not_a_number<T>();
  CHECK_FALSE(nan == nan);
  CHECK_FALSE(conescan::is_finite(nan));
  CHECK_FALSE(conescan::is_finite(std::numeric_limits<T>::infinity()));
  CHECK_FALSE(conescan::is_finite(T(-std::numeric_limits<T>::infinity())));
  CHECK(conescan::is_finite(std::numeric_limits<T>::max()));
  CHECK(conescan::is_finite(T(0)));
}

TEMPLATE_TEST_CASE("misaligned_cone_angle in every scalar", "[scalar][cone_angle]",
                   CONESCAN_TEST_SCALARS) {
  using T = TestType;
  using std::cos;
  using std::sin;
  for (int g : {1, 10, 45, 80}) {
    for (int phi_b_deg : {-180, -90, -30, 0, 45, 90, 135, 180, 270}) {
      const T gamma = deg<T>(g), phi_b = deg<T>(phi_b_deg);
      INFO("gamma " << g << " phi_b " << phi_b_deg);
      // sigma = 0: exactly gamma (MODEL §4: A = S).
      CHECK(conescan::misaligned_cone_angle(gamma, T(0), phi_b).value == gamma);
      for (int sigma_per_mille : {1, 100, 500, 900}) {
        const T sigma = gamma * T(sigma_per_mille) / T(1000);
        const conescan::result<T> psi = conescan::misaligned_cone_angle(gamma, sigma, phi_b);
        REQUIRE(psi.ok());
        // The spherical triangle SAH (MODEL §4): one rounding per term.
        const T residual =
            cos(sigma) * cos(psi.value) + sin(sigma) * sin(psi.value) * cos(phi_b) - cos(gamma);
        CHECK(absolute(residual) <= T(eps<T>() * 8));
        // The paper's quadratic form: acos conditioning 1/sin psi (test_cone_angle.cpp).
        const conescan::result<T> quadratic =
            conescan::misaligned_cone_angle_quadratic(gamma, sigma, phi_b);
        REQUIRE(quadratic.ok());
        CHECK_WITHIN(quadratic.value, psi.value, T(eps<T>() * 64 * (T(1) + T(1) / sin(psi.value))));
      }
    }
    // Hand-derived: phi_b = 0 gives gamma + sigma, phi_b = pi gives gamma - sigma.
    const T gamma = deg<T>(g), sigma = gamma / T(3);
    const T tol = T(4) * eps<T>() * (gamma + sigma);
    CHECK_WITHIN(conescan::misaligned_cone_angle(gamma, sigma, T(0)).value, T(gamma + sigma), tol);
    CHECK_WITHIN(conescan::misaligned_cone_angle(gamma, sigma, conescan::pi<T>()).value,
                 T(gamma - sigma), tol);
  }
  // Statuses on both sides of each domain boundary (MODEL §7).
  const T gamma = deg<T>(45), half_pi = conescan::pi<T>() / T(2);
  const T small = T(eps<T>() * 64);
  CHECK(conescan::misaligned_cone_angle(T(0), T(0), T(0)).state == status::invalid);
  CHECK(conescan::misaligned_cone_angle(small, T(0), T(0)).ok());
  CHECK(conescan::misaligned_cone_angle(half_pi, T(0), T(0)).state == status::invalid);
  CHECK(conescan::misaligned_cone_angle(T(half_pi - small), T(0), T(0)).ok());
  CHECK(conescan::misaligned_cone_angle(gamma, T(-small), T(0)).state == status::invalid);
  CHECK(conescan::misaligned_cone_angle(gamma, gamma, T(0)).state == status::invalid);
  CHECK(conescan::misaligned_cone_angle(gamma, T(gamma - small), half_pi).ok());
  CHECK(conescan::misaligned_cone_angle(gamma, T(0), conescan::not_a_number<T>()).state ==
        status::invalid);
  CHECK(conescan::misaligned_cone_angle(gamma, std::numeric_limits<T>::infinity(), T(0)).state ==
        status::invalid);
}

TEMPLATE_TEST_CASE("half chord, then inversion, recovers eta in every scalar",
                   "[scalar][round_trip][eq3][eq6]", CONESCAN_TEST_SCALARS) {
  // Round trip of test_nadir_angle.cpp. The chord carries a few ulp, amplified by |d eta / d Phi|
  // (long double, below 50 where compared): tolerance 32 eps (1 + amplification). eta must be one
  // of the two roots, and the inversion with eta0 = eta must return it; both roots are covered.
  using T = TestType;
  int plus_count = 0, minus_count = 0;
  for (int g : {20, 45, 60}) {
    for (int r : {10, 30, 45, 62, 80}) {
      for (int e = 3; e < 180; e += 7) {
        const T gamma = deg<T>(g), rho = deg<T>(r), eta = deg<T>(e);
        const conescan::result<T> phi = conescan::half_chord(gamma, eta, rho);
        if (!phi.ok()) continue;
        const long double amp = amplification(ld(gamma), ld(eta), ld(phi.value));
        if (amp > 50) continue;
        INFO("gamma " << g << " rho " << r << " eta " << e << " amplification " << amp);
        const T tol = eps<T>() * T(32) * scalar_from<T>(1 + amp);
        const conescan::nadir_angle_roots<T> roots =
            conescan::nadir_angle_roots_from_chord(gamma, rho, phi.value);
        REQUIRE(roots.state == status::ok);
        const T to_plus = absolute(T(roots.plus - eta)), to_minus = absolute(T(roots.minus - eta));
        CHECK((to_plus <= tol || to_minus <= tol));
        (to_plus <= to_minus ? plus_count : minus_count) += 1;
        // Envelope 0: the round trip, not the ambiguity of roots within 10 deg of eta0.
        const conescan::result<T> eta_s =
            conescan::nadir_angle_from_chord(gamma, rho, phi.value, eta, T(0));
        REQUIRE(eta_s.ok());
        CHECK_WITHIN(eta_s.value, eta, tol);
      }
    }
  }
  CHECK(plus_count > 50);
  CHECK(minus_count > 5);
}

TEMPLATE_TEST_CASE("forward and inverse statuses on both sides in every scalar", "[scalar][status]",
                   CONESCAN_TEST_SCALARS) {
  // Boundaries of test_half_chord.cpp and test_nadir_angle.cpp; margins scaled to T.
  using T = TestType;
  const T half = T(1) / T(2), quarter = T(1) / T(4), three_quarters = T(3) / T(4);
  // delta: 4 ulp of 0.5 and 0.75, and small enough that the sliver of chord it opens
  // (~sqrt(delta), Eq. (3) near the tangency) stays below the grazing threshold even in float.
  const T delta = T(eps<T>() * 2);
  // miss at the exact tangency eta = psi + rho (0.5 + 0.25 = 0.75, exact in binary), grazing
  // just inside, ok well inside.
  CHECK(conescan::half_chord(half, three_quarters, quarter).state == status::miss);
  CHECK(conescan::half_chord(half, T(three_quarters + delta), quarter).state == status::miss);
  CHECK(conescan::half_chord(half, T(three_quarters - delta), quarter).state == status::grazing);
  CHECK(conescan::half_chord(half, half, quarter).ok());
  // engulfed at psi + eta = rho.
  CHECK(conescan::half_chord(half, half, T(1)).state == status::engulfed);
  CHECK(conescan::half_chord(half, T(half - delta), T(1)).state == status::engulfed);
  CHECK(conescan::half_chord(half, T(half + delta), T(1)).state == status::grazing);
  // The grazing threshold itself, with a margin above T's rounding of the chord (x 1e6 eps).
  const T phi_min = conescan::grazing_half_chord_min<T>();
  const T margin = T(eps<T>() * 1000000);
  CHECK(conescan::classify_half_chord(T(phi_min * (T(1) + margin))) == status::ok);
  CHECK(conescan::classify_half_chord(T(phi_min * (T(1) - margin))) == status::grazing);
  const T gamma = deg<T>(45), rho = deg<T>(30), eta0 = deg<T>(75);
  CHECK(conescan::nadir_angle_from_chord(gamma, rho, T(phi_min * (T(1) + margin)), eta0).ok());
  CHECK(conescan::nadir_angle_from_chord(gamma, rho, T(phi_min * (T(1) - margin)), eta0).state ==
        status::grazing);
  // Fold: gamma = 45, rho_p = 30 deg have no real root beyond Phi = 45 deg; just before it the
  // roots merge and the amplification exceeds fold_amplification_max().
  // fold_margin: the root separation it opens, ~sqrt(fold_margin), must keep the amplification
  // above the threshold (30) in float too (it is ~200 there, ~1e6 in double).
  const T fold_margin = T(eps<T>() * 32);
  CHECK(conescan::nadir_angle_roots_from_chord(gamma, rho, T(deg<T>(45) + fold_margin)).state ==
        status::fold);
  CHECK(conescan::nadir_angle_roots_from_chord(gamma, rho, T(deg<T>(45) - fold_margin)).state ==
        status::ok);
  CHECK(conescan::nadir_angle_from_chord(gamma, rho, T(deg<T>(45) - fold_margin), eta0).state ==
        status::fold);
  CHECK(conescan::nadir_angle_from_chord(gamma, rho, deg<T>(20), eta0).ok());
  // Invalid.
  CHECK(conescan::half_chord(T(0), half, quarter).state == status::invalid);
  CHECK(conescan::half_chord(half, half, conescan::not_a_number<T>()).state == status::invalid);
  CHECK(conescan::nadir_angle_from_chord(gamma, rho, T(-eps<T>()), eta0).state == status::invalid);
}

TEMPLATE_TEST_CASE("sigma = 0 through bias model and processing in every scalar",
                   "[scalar][sigma0][processing]", CONESCAN_TEST_SCALARS) {
  // MODEL §6 with a perfect head: eta_s = eta and roll/pitch = truth up to rounding, a few ulp
  // amplified by |d eta / d Phi| (below 50 here): tolerance 32 eps (1 + amplification).
  using T = TestType;
  int compared = 0;
  for (int alpha : {-10, 0, 20}) {  // eta0 = 100, 90, 70 deg: the 45 deg cone meets the Earth
    for (int beta : {0, 90}) {
      const conescan::scan_frame<T> frame =
          conescan::scan_frame_from_mounting(deg<T>(alpha), deg<T>(beta));
      REQUIRE(frame.state == status::ok);
      for (int roll : {-3, 0, 2}) {
        for (int pitch : {-2, 0, 1}) {
          const vec3<T> n = conescan::nadir_in_body(deg<T>(roll), deg<T>(pitch));
          const conescan::scan_angles<T> nadir = conescan::scan_angles_of(frame, n);
          const T rho = conescan::disk_angular_radius(T(6378137), T(7280000)).value;
          const conescan::head_optics<T> optics{deg<T>(45), T(0), deg<T>(30)};
          const conescan::crossings<T> c =
              conescan::bias_model_crossings(optics, nadir.polar, nadir.azimuth, rho);
          REQUIRE(c.state == status::ok);
          const long double amp =
              amplification(ld(optics.gamma), ld(nadir.polar), ld(c.half_chord()));
          if (amp > 50) continue;
          ++compared;
          INFO("alpha " << alpha << " beta " << beta << " roll " << roll << " pitch " << pitch);
          const conescan::head_estimate<T> e = conescan::process_head(frame, optics.gamma, rho, c);
          REQUIRE(e.state == status::ok);
          const T tol = eps<T>() * T(32) * scalar_from<T>(1 + amp);
          CHECK_WITHIN(e.eta_s, nadir.polar, tol);
          const conescan::roll_pitch<T> sensed = conescan::roll_pitch_from_nadir(e.nadir);
          CHECK_WITHIN(sensed.roll, deg<T>(roll), tol);
          CHECK_WITHIN(sensed.pitch, deg<T>(pitch), tol);
        }
      }
    }
  }
  CHECK(compared > 40);
}

TEMPLATE_TEST_CASE("frames in every scalar", "[scalar][attitude][scan_frame]",
                   CONESCAN_TEST_SCALARS) {
  using T = TestType;
  const T tol = T(eps<T>() * 16);
  for (int alpha : {-60, 0, 20, 89}) {
    for (int beta : {-120, 0, 90}) {
      const conescan::scan_frame<T> f =
          conescan::scan_frame_from_mounting(deg<T>(alpha), deg<T>(beta));
      REQUIRE(f.state == status::ok);
      CHECK_WITHIN(conescan::dot(f.e1, f.e1), T(1), tol);
      CHECK_WITHIN(conescan::dot(f.e1, f.e2), T(0), tol);
      CHECK_WITHIN(conescan::dot(f.e1, f.e3), T(0), tol);
      CHECK_WITHIN(conescan::dot(f.e2, f.e3), T(0), tol);
      const vec3<T> e1_cross_e2 = conescan::cross(f.e1, f.e2);
      CHECK_WITHIN(e1_cross_e2.x, f.e3.x, tol);
      CHECK_WITHIN(e1_cross_e2.y, f.e3.y, tol);
      CHECK_WITHIN(e1_cross_e2.z, f.e3.z, tol);
      CHECK(f.e1.z > T(0));  // e1 leans towards body +z (nominal nadir)
      CHECK_WITHIN(conescan::nominal_nadir_angle(f), T(deg<T>(90) - deg<T>(alpha)), tol);
      const vec3<T> d = conescan::direction_in_scan_frame(f, deg<T>(70), deg<T>(-40));
      const conescan::scan_angles<T> back = conescan::scan_angles_of(f, d);
      CHECK_WITHIN(back.polar, deg<T>(70), tol);
      CHECK_WITHIN(back.azimuth, deg<T>(-40), tol);
    }
  }
  CHECK(conescan::scan_frame_from_mounting(T(conescan::pi<T>() / T(2)), T(0)).state ==
        status::invalid);
  CHECK(conescan::scan_frame_from_mounting(T(conescan::pi<T>() / T(2) - T(eps<T>() * 8)), T(0))
            .state == status::ok);
  for (int roll : {-170, -5, 0, 30, 180}) {
    for (int pitch : {-80, 0, 45}) {
      const vec3<T> n = conescan::nadir_in_body(deg<T>(roll), deg<T>(pitch));
      const conescan::mat3<T> c =
          conescan::dcm_body_from_orbit(deg<T>(roll), deg<T>(pitch), deg<T>(25));
      CHECK(n.x == c[2].x);
      CHECK(n.y == c[2].y);
      CHECK(n.z == c[2].z);
      const conescan::roll_pitch<T> rp = conescan::roll_pitch_from_nadir(n);
      CHECK_WITHIN(conescan::wrap_pi(T(rp.roll - deg<T>(roll))), T(0), T(tol * T(8)));
      CHECK_WITHIN(rp.pitch, deg<T>(pitch), tol);
    }
  }
  const conescan::mat3<T> o =
      conescan::dcm_eci_from_orbit(vec3<T>(T(7000000), T(0), T(0)), vec3<T>(T(0), T(7500), T(0)));
  CHECK_WITHIN(o[0].y, T(1), tol);   // x_o along the velocity on a circular orbit
  CHECK_WITHIN(o[1].z, T(-1), tol);  // y_o the negative orbit normal
  CHECK_WITHIN(o[2].x, T(-1), tol);  // z_o the geocentric nadir
}

TEMPLATE_TEST_CASE("scan models in every scalar", "[scalar][scan_model]", CONESCAN_TEST_SCALARS) {
  // MODEL §5 identities of test_scan_model.cpp with tolerances in T's epsilon: sigma = 0 is the
  // closed form; zero attitude with phi_a = 0 is symmetric with the closed form at its own psi;
  // the ellipsoid with a_eq = b_pol is the sphere. The crossings are Newton roots to ~4 ulp of
  // max(1, |phi|): tolerance 64 eps.
  using T = TestType;
  using std::asin;
  using std::cos;
  using std::sin;
  const T tol = T(eps<T>() * 64);
  const T gamma = deg<T>(45), rho = conescan::disk_angular_radius(T(6378137), T(7280000)).value;
  for (int e : {50, 75, 90, 100}) {
    const T eta = deg<T>(e);
    INFO("eta " << e);
    // sigma = 0.
    const T aligned = conescan::half_chord(gamma, eta, rho).value;
    const conescan::crossings<T> c0 = conescan::scan_model_crossings_sphere(
        conescan::head_optics<T>{gamma, T(0), T(0)}, eta, T(1) / T(3), rho);
    REQUIRE(c0.state == status::ok);
    CHECK_WITHIN(c0.phi_in, T(T(1) / T(3) - aligned), tol);
    CHECK_WITHIN(c0.phi_out, T(T(1) / T(3) + aligned), tol);
    // Symmetric misaligned scan, psi at the crossings' own azimuths.
    for (int phi_a : {0, 180}) {
      const conescan::head_optics<T> o{gamma, deg<T>(1, 2), deg<T>(phi_a)};
      const conescan::crossings<T> c = conescan::scan_model_crossings_sphere(o, eta, T(0), rho);
      REQUIRE(c.state == status::ok);
      CHECK(c.iterations <= 2 * conescan::bracketed_newton_max_iterations<T>());
      CHECK_WITHIN(c.phi_in, T(-c.phi_out), tol);
      const T psi =
          conescan::misaligned_cone_angle(gamma, o.sigma, T(c.half_chord() - o.phi_a)).value;
      CHECK_WITHIN(c.half_chord(), conescan::half_chord(psi, eta, rho).value, tol);
    }
    // Ellipsoid with a_eq = b_pol in the frame e1, e2, e3 = x, y, z; satellite at
    // -r (sin eta cos 20 deg, sin eta sin 20 deg, cos eta), so the centre is at (eta, 20 deg).
    const conescan::scan_frame<T> f{vec3<T>(T(1), T(0), T(0)), vec3<T>(T(0), T(1), T(0)),
                                    vec3<T>(T(0), T(0), T(1)), status::ok};
    const T r = T(7280000), radius = T(6378137), phi_n = deg<T>(20);
    const vec3<T> p(-r * sin(eta) * cos(phi_n), -r * sin(eta) * sin(phi_n), -r * cos(eta));
    const conescan::head_optics<T> o{gamma, deg<T>(1, 2), deg<T>(70)};
    const conescan::crossings<T> on_sphere =
        conescan::scan_model_crossings_sphere(o, eta, phi_n, T(asin(radius / r)));
    const conescan::crossings<T> on_ellipsoid =
        conescan::scan_model_crossings_ellipsoid(o, f, p, radius, radius);
    REQUIRE(on_sphere.state == status::ok);
    REQUIRE(on_ellipsoid.state == status::ok);
    CHECK(on_ellipsoid.iterations <= 2 * conescan::bracketed_newton_max_iterations<T>());
    // The satellite position and the centre's angles carry a few ulp each: tolerance x 4.
    CHECK_WITHIN(on_ellipsoid.phi_in, on_sphere.phi_in, T(tol * T(4)));
    CHECK_WITHIN(on_ellipsoid.phi_out, on_sphere.phi_out, T(tol * T(4)));
  }
  // Statuses (hand-derived boundaries of test_scan_model.cpp): phi_n = phi_a = 0, gamma = 30,
  // sigma = 1 deg, eta = 50 deg: miss below rho = 19 deg.
  const conescan::head_optics<T> o{deg<T>(30), deg<T>(1), T(0)};
  // The margin opens a half chord ~sqrt(1.65 margin) (Eq. (3) near the tangency), below the
  // grazing threshold in every T, and is larger than T's rounding of the boundary.
  const T rho_b = deg<T>(19), margin = T(eps<T>() * 8);
  CHECK(conescan::scan_model_crossings_sphere(o, deg<T>(50), T(0), T(rho_b - margin)).state ==
        status::miss);
  CHECK(conescan::scan_model_crossings_sphere(o, deg<T>(50), T(0), T(rho_b + margin)).state ==
        status::grazing);
  CHECK(conescan::scan_model_crossings_sphere(o, deg<T>(50), T(0), deg<T>(21)).state == status::ok);
}

TEMPLATE_TEST_CASE("the paper's printed forms, DCM products and head combination in every scalar",
                   "[scalar][eq3][eq6][processing]", CONESCAN_TEST_SCALARS) {
  // Instantiates the rest of the core's templates for every T (half_chord_acos, the quadratic
  // Eq. (6), apply/apply_transpose, combine_heads) and checks them against their stable
  // counterparts, with the acos conditioning of test_half_chord.cpp / test_nadir_angle.cpp.
  using T = TestType;
  using std::sin;
  const T gamma = deg<T>(45), rho = deg<T>(60);
  for (int e : {40, 70, 100}) {
    const T eta = deg<T>(e);
    const conescan::result<T> stable = conescan::half_chord(gamma, eta, rho);
    const conescan::result<T> printed = conescan::half_chord_acos(gamma, eta, rho);
    REQUIRE(stable.ok());
    REQUIRE(printed.ok());
    INFO("eta " << e);
    CHECK_WITHIN(printed.value, stable.value,
                 T(eps<T>() * 32 / (sin(gamma) * sin(eta) * sin(stable.value))));
    const conescan::nadir_angle_roots<T> roots =
        conescan::nadir_angle_roots_from_chord(gamma, rho, stable.value);
    const conescan::result<T> quadratic =
        conescan::nadir_angle_from_chord_quadratic(gamma, rho, stable.value);
    REQUIRE(quadratic.ok());
    CHECK_WITHIN(quadratic.value, roots.plus,
                 T(eps<T>() * 32 * (T(1) + T(1) / sin(roots.plus)) *
                   (T(1) + T(1) / sin(roots.half_separation))));
  }
  const conescan::mat3<T> c = conescan::dcm_body_from_orbit(deg<T>(3), deg<T>(-7), deg<T>(100));
  const vec3<T> v(T(1), T(-2), T(3));
  const vec3<T> back = conescan::apply_transpose(c, conescan::apply(c, v));
  CHECK_WITHIN(back.x, v.x, T(eps<T>() * 32));
  CHECK_WITHIN(back.y, v.y, T(eps<T>() * 32));
  CHECK_WITHIN(back.z, v.z, T(eps<T>() * 32));
  // Normalised mean of the ok heads (MODEL §6): (1, 0, 0) and (0, 0, 1) give (1, 0, 1)/sqrt(2).
  const T nan = conescan::not_a_number<T>();
  const conescan::head_estimate<T> heads[] = {
      {nan, vec3<T>(T(1), T(0), T(0)), status::ok},
      {nan, vec3<T>(T(0), T(1), T(0)), status::miss},
      {nan, vec3<T>(T(0), T(0), T(1)), status::ok},
  };
  const conescan::head_estimate<T> all = conescan::combine_heads<T>(heads, heads + 3);
  REQUIRE(all.state == status::ok);
  using std::sqrt;
  CHECK_WITHIN(all.nadir.x, T(T(1) / sqrt(T(2))), T(eps<T>() * 4));
  CHECK(all.nadir.y == T(0));
  CHECK_WITHIN(all.nadir.z, T(T(1) / sqrt(T(2))), T(eps<T>() * 4));
  CHECK(conescan::combine_heads<T>(heads + 1, heads + 2).state == status::none);
}

TEMPLATE_TEST_CASE("wrap_pi: the one-turn fast path returns remainder's value bit for bit",
                   "[scalar][wrap]", float, double, long double) {
  // x -+ 2 pi for pi < |x| < 3 pi is exact (Sterbenz); remainder(x, 2 pi) is the reference, with
  // -pi mapped to pi. Both sides of every cut: +-pi, +-3 pi (as T rounds it, and the exact 3 pi
  // rounded the other way), and their neighbours.
  using T = TestType;
  const T pi = conescan::pi<T>(), two_pi = T(2) * pi;
  auto reference = [&](T x) {
    const T y = std::remainder(x, two_pi);
    return y <= -pi ? y + two_pi : y;
  };
  std::vector<T> xs;
  for (T x = T(-12); x <= T(12); x += T(1) / T(1024) + std::numeric_limits<T>::epsilon())
    xs.push_back(x);
  for (T cut : {pi, T(3) * pi, T(3 * conescan::pi<long double>()), -pi, -T(3) * pi}) {
    for (T direction : {T(-100), T(100)}) {
      T x = cut;
      for (int i = 0; i < 8; ++i, x = std::nextafter(x, direction)) xs.push_back(x);
    }
  }
  long mismatches = 0;
  for (T x : xs) {
    if (conescan::wrap_pi(x) == reference(x)) continue;
    if (++mismatches <= 3) UNSCOPED_INFO(std::hexfloat << x << " -> " << conescan::wrap_pi(x));
  }
  CHECK(mismatches == 0);
}
