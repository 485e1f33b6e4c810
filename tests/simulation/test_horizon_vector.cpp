// Horizon-vector processing (include/conescan/horizon_vector.hpp): the nadir fitted to all
// crossings at once.
//
// Expected values:
//  - One head: the fit solves the same two equations n . h_i = cos rho_p as MODEL §6's chord/phase
//    inversion (n = cos eta_s e3 + sin eta_s (cos m e1 + sin m e2) gives n . h = cos gamma cos
//    eta_s + sin gamma sin eta_s cos(phi - m) with phi - m = +-Phi_s), so seeded near
//    process_head's nadir it must return it, whatever the misalignment and rho_p (no noise).
//  - Several heads with exact crossings (aligned optics, rho_p = rho): the true nadir satisfies
//    every equation, so it is the least-squares minimum.
//  - The condition figure in closed form: two crossings theta apart about n on the horizon circle
//    of radius rho give J rows sin rho (cos(theta/2), +-sin(theta/2)), so J^T J = 2 sin^2 rho
//    diag(cos^2(theta/2), sin^2(theta/2)) and condition = max(cot, tan)(theta/2).
//
// Templated tests follow the core's own rules (ADL math, constants from integers), so that they
// compile for conescan_test::adl_real too.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "conescan/attitude.hpp"
#include "conescan/bias_model.hpp"
#include "conescan/horizon_vector.hpp"
#include "conescan/nadir_angle.hpp"
#include "conescan/processing.hpp"
#include "conescan/scan_frame.hpp"
#include "simulation/random.hpp"
#include "support/adl_scalar.hpp"
#include "support/approx.hpp"

using conescan::angle_between;
using conescan::append_horizon_vectors;
using conescan::horizon_condition;
using conescan::horizon_condition_max;
using conescan::horizon_nadir_fit;
using conescan::horizon_vector;
using conescan::nadir_from_horizon_vectors;
using conescan::status;
using conescan::vec3;
using conescan_test::deg;
using conescan_test::eps;
using conescan_test::scalar_from;

namespace {

/// A unit vector tilted from the unit n by the angle `by` (rad) towards the direction of `towards`
/// projected on the plane normal to n.
template <class T>
vec3<T> tilted(const vec3<T>& n, const vec3<T>& towards, const T& by) {
  using std::cos;
  using std::sin;
  const vec3<T> p = conescan::unit(towards - conescan::scaled(n, conescan::dot(towards, n)));
  return conescan::scaled(n, cos(by)) + conescan::scaled(p, sin(by));
}

/// A horizon circle of angular radius rho about the unit n, with an orthonormal pair (u, v)
/// normal to n; point(a) is the horizon direction at azimuth a about n.
template <class T>
struct horizon_circle {
  vec3<T> n, u, v;
  T cos_rho, sin_rho;

  vec3<T> point(const T& a) const {
    using std::cos;
    using std::sin;
    return conescan::scaled(n, cos_rho) + conescan::scaled(u, T(sin_rho * cos(a))) +
           conescan::scaled(v, T(sin_rho * sin(a)));
  }
};

/// A circle about a generic n (no component zero, so no axis-aligned special case), radius rho.
template <class T>
horizon_circle<T> generic_circle(const T& cos_rho) {
  using std::sqrt;
  const vec3<T> n = conescan::unit(vec3<T>(T(2), T(-3), T(6)));  // |(2,-3,6)| = 7
  const vec3<T> u = conescan::unit(conescan::cross(n, vec3<T>(T(1), T(0), T(0))));
  const vec3<T> v = conescan::cross(n, u);
  return {n, u, v, cos_rho, T(sqrt(T(T(1) - cos_rho * cos_rho)))};
}

}  // namespace

TEST_CASE("one head: the fit equals the chord/phase inversion", "[horizon_vector]") {
  // A grid of mountings, cone angles, Earth radii, true nadirs, misalignments and assumed radii.
  // Where process_head is ok and its two roots are apart (half separation >= 0.02 rad, so that a
  // seed 0.005 rad off lies in the right root's basin), the fit from that seed must return its
  // nadir to 1e-12 rad. It may call a fold only with a condition above the threshold (near
  // grazing and where eta -> 0 with gamma ~ rho: see horizon_condition_max).
  int compared = 0, folds = 0, close_roots = 0;
  double worst = 0;
  int worst_iterations = 0;
  for (double alpha_deg : {-30.0, -10.0, 0.0, 10.0, 20.0, 35.0}) {
    for (double beta_deg : {0.0, 90.0, 200.0}) {
      const conescan::scan_frame<double> frame = conescan::scan_frame_from_mounting(
          conescan::deg_to_rad(alpha_deg), conescan::deg_to_rad(beta_deg));
      REQUIRE(frame.state == status::ok);
      const double eta0 = conescan::nominal_nadir_angle(frame);
      for (double gamma_deg : {30.0, 45.0, 60.0}) {
        for (double rho_deg : {20.0, 45.0, 61.0, 75.0}) {
          for (double eta_offset_deg : {-15.0, -5.0, 0.0, 5.0, 15.0}) {
            for (double phi_n : {0.0, 0.3, -2.0}) {
              for (const conescan::head_optics<double>& optics :
                   {conescan::head_optics<double>{conescan::deg_to_rad(gamma_deg), 0, 0},
                    conescan::head_optics<double>{conescan::deg_to_rad(gamma_deg),
                                                  conescan::deg_to_rad(0.5), 0},
                    conescan::head_optics<double>{conescan::deg_to_rad(gamma_deg),
                                                  conescan::deg_to_rad(0.5), 1.2}}) {
                for (double rho_p_offset_deg : {0.0, 0.3}) {
                  const double eta = eta0 + conescan::deg_to_rad(eta_offset_deg);
                  const double rho = conescan::deg_to_rad(rho_deg);
                  const double rho_p = conescan::deg_to_rad(rho_deg + rho_p_offset_deg);
                  if (eta <= 0 || eta >= conescan::pi<double>()) continue;
                  const conescan::crossings<double> c =
                      conescan::bias_model_crossings(optics, eta, phi_n, rho);
                  const conescan::head_estimate<double> head =
                      conescan::process_head(frame, optics.gamma, rho_p, c);
                  if (head.state != status::ok) continue;
                  const conescan::nadir_angle_roots<double> roots =
                      conescan::nadir_angle_roots_from_chord(optics.gamma, rho_p, c.half_chord());
                  if (roots.half_separation < 0.02) {
                    ++close_roots;
                    continue;
                  }
                  vec3<double> h[2];
                  REQUIRE(append_horizon_vectors(frame, optics.gamma, c, h, 0, 2) == 2);
                  const vec3<double> seed = tilted(head.nadir, vec3<double>(0.6, -0.8, 0.1), 0.005);
                  const horizon_nadir_fit<double> fit =
                      nadir_from_horizon_vectors(h, 2, std::cos(rho_p), seed);
                  INFO("alpha " << alpha_deg << " beta " << beta_deg << " gamma " << gamma_deg
                                << " rho " << rho_deg << " eta " << eta << " phi_n " << phi_n
                                << " sigma " << optics.sigma << " phi_a " << optics.phi_a
                                << " rho_p " << rho_p << " condition " << fit.condition
                                << " iterations " << fit.iterations);
                  if (fit.state == status::fold) {
                    ++folds;
                    CHECK(fit.condition > horizon_condition_max<double>());
                    continue;
                  }
                  REQUIRE(fit.ok());
                  const double error = angle_between(fit.nadir, head.nadir);
                  CHECK(error <= 1e-12);
                  CHECK(fit.iterations <= 6);
                  if (error > worst) worst = error;
                  if (fit.iterations > worst_iterations) worst_iterations = fit.iterations;
                  ++compared;
                }
              }
            }
          }
        }
      }
    }
  }
  INFO("compared " << compared << " folds " << folds << " close roots " << close_roots << " worst "
                   << worst << " rad, iterations <= " << worst_iterations);
  CHECK(compared > 3000);
  CHECK(folds < compared / 50);
}

TEST_CASE("one head approaching a fold: the fit follows the chord/phase inversion",
          "[horizon_vector]") {
  // Earth of 20 deg, gamma 45 deg: the fold lies at eta ~ 41.2 deg. The spin axis's nadir angle
  // walks towards it (mounting alpha = 90 deg - eta, so the root nearest eta0 is the truth).
  // While process_head is ok (amplification <= fold_amplification_max(), 30) the fit, seeded
  // 1e-4 rad off, returns its nadir to 1e-12 rad; its condition grows with the amplification and
  // stays below the fit's own threshold there (condition / amplification ~ 1.5 here:
  // horizon_condition_max's comment).
  const double gamma = conescan::deg_to_rad(45.0), rho = conescan::deg_to_rad(20.0);
  const conescan::head_optics<double> optics{gamma, 0, 0};
  int compared = 0;
  double largest_condition = 0;
  for (int hundredths = 3800; hundredths <= 4135; ++hundredths) {
    const double eta = conescan::deg_to_rad(hundredths / 100.0);
    const conescan::scan_frame<double> frame =
        conescan::scan_frame_from_mounting(conescan::pi<double>() / 2 - eta, 0.3);
    const conescan::crossings<double> c = conescan::bias_model_crossings(optics, eta, 0.2, rho);
    REQUIRE(c.state == status::ok);
    // Envelope 0: this walk is about the fold; within 10 deg of it both roots are ambiguous.
    const conescan::head_estimate<double> head =
        conescan::process_head(frame, gamma, rho, c, conescan::nominal_nadir_angle(frame), 0.0);
    if (head.state != status::ok) continue;
    vec3<double> h[2];
    REQUIRE(append_horizon_vectors(frame, gamma, c, h, 0, 2) == 2);
    const horizon_nadir_fit<double> fit = nadir_from_horizon_vectors(
        h, 2, std::cos(rho), tilted(head.nadir, vec3<double>(0, 1, 0), 1e-4));
    INFO("eta " << hundredths << "/100 deg, condition " << fit.condition);
    REQUIRE(fit.ok());
    CHECK(angle_between(fit.nadir, head.nadir) <= 1e-12);
    if (fit.condition > largest_condition) largest_condition = fit.condition;
    ++compared;
  }
  INFO("largest condition " << largest_condition);
  CHECK(compared > 250);
  CHECK(largest_condition > 40);  // 1.5 x the amplification of 30 where process_head stops
  CHECK(largest_condition < horizon_condition_max<double>());
}

TEST_CASE("one head: the seed selects one of two mirror solutions", "[horizon_vector]") {
  // The paper's head (alpha 0, beta 90 deg, gamma 45 deg) on an Earth of 61 deg: the chord
  // inversion's roots are eta = 90 deg (the truth) and ~ -21 deg (the mirror). Both satisfy both
  // equations; they are mirror images about the plane of h_1, h_2; a seed near either returns it.
  const conescan::scan_frame<double> frame =
      conescan::scan_frame_from_mounting(0.0, conescan::deg_to_rad(90.0));
  const double gamma = conescan::deg_to_rad(45.0), rho = conescan::deg_to_rad(61.0);
  const double eta = conescan::deg_to_rad(90.0), phi_n = 0.01;
  const conescan::crossings<double> c =
      conescan::bias_model_crossings(conescan::head_optics<double>{gamma, 0, 0}, eta, phi_n, rho);
  REQUIRE(c.state == status::ok);
  const conescan::nadir_angle_roots<double> roots =
      conescan::nadir_angle_roots_from_chord(gamma, rho, c.half_chord());
  REQUIRE(roots.state == status::ok);
  const vec3<double> plus = conescan::direction_in_scan_frame(frame, roots.plus, c.phase());
  const vec3<double> minus = conescan::direction_in_scan_frame(frame, roots.minus, c.phase());
  vec3<double> h[2];
  REQUIRE(append_horizon_vectors(frame, gamma, c, h, 0, 2) == 2);
  for (const vec3<double>& root : {plus, minus})
    for (const vec3<double>& hi : h)
      CHECK(std::abs(conescan::dot(root, hi) - std::cos(rho)) < 1e-15);
  const vec3<double> p = conescan::unit(conescan::cross(h[0], h[1]));
  const vec3<double> mirrored = plus - conescan::scaled(p, 2 * conescan::dot(plus, p));
  CHECK(angle_between(mirrored, minus) < 1e-14);
  CHECK(angle_between(plus, minus) > 1.0);

  const horizon_nadir_fit<double> near_plus =
      nadir_from_horizon_vectors(h, 2, std::cos(rho), tilted(plus, vec3<double>(1, 0, 0), 0.2));
  const horizon_nadir_fit<double> near_minus =
      nadir_from_horizon_vectors(h, 2, std::cos(rho), tilted(minus, vec3<double>(1, 0, 0), 0.2));
  REQUIRE(near_plus.ok());
  REQUIRE(near_minus.ok());
  CHECK(angle_between(near_plus.nadir, plus) < 1e-14);
  CHECK(angle_between(near_minus.nadir, minus) < 1e-14);
  // The plus root is the truth (body +z rotated by phi_n about S) and what process_head returns.
  const conescan::head_estimate<double> head = conescan::process_head(frame, gamma, rho, c);
  REQUIRE(head.state == status::ok);
  CHECK(angle_between(head.nadir, plus) < 1e-14);
  // Seeded from the nominal nadir (body +z) it finds the truth too.
  const horizon_nadir_fit<double> from_nominal =
      nadir_from_horizon_vectors(h, 2, std::cos(rho), vec3<double>(0, 0, 1));
  REQUIRE(from_nominal.ok());
  CHECK(angle_between(from_nominal.nadir, plus) < 1e-14);
}

TEMPLATE_TEST_CASE("several heads with exact crossings: the fit is the true nadir",
                   "[horizon_vector]", CONESCAN_TEST_SCALARS) {
  // Aligned optics, rho_p = rho, a true attitude of a few degrees, seeded with the nominal nadir
  // (body +z). The fit's error is a few eps x condition (condition < 3 here): 64 eps.
  using T = TestType;
  const T gamma = deg<T>(45), rho = deg<T>(61);
  const vec3<T> truth = conescan::nadir_in_body(deg<T>(3, 2), deg<T>(-2));
  struct mounting {
    int alpha_deg, beta_deg;
  };
  struct head_set {
    mounting heads[3];
    std::size_t size;
  };
  const head_set sets[] = {{{{0, 90}, {0, -90}, {0, 0}}, 2},
                           {{{10, 0}, {10, 120}, {10, 240}}, 3},
                           {{{0, 90}, {20, 0}, {0, 0}}, 2}};
  for (const head_set& set : sets) {
    const vec3<T> zero(T(0));  // GLM's vec has no default constructor for a non-trivial T
    vec3<T> h[6] = {zero, zero, zero, zero, zero, zero};
    std::size_t count = 0;
    for (std::size_t k = 0; k < set.size; ++k) {
      const mounting& m = set.heads[k];
      const conescan::scan_frame<T> frame =
          conescan::scan_frame_from_mounting(deg<T>(m.alpha_deg), deg<T>(m.beta_deg));
      const conescan::scan_angles<T> angles = conescan::scan_angles_of(frame, truth);
      const conescan::crossings<T> c = conescan::bias_model_crossings(
          conescan::head_optics<T>{gamma, T(0), T(0)}, angles.polar, angles.azimuth, rho);
      REQUIRE(c.state == status::ok);
      count = append_horizon_vectors(frame, gamma, c, h, count, 6);
    }
    REQUIRE(count == 2 * set.size);
    using std::cos;
    const horizon_nadir_fit<T> fit =
        nadir_from_horizon_vectors(h, count, T(cos(rho)), vec3<T>(T(0), T(0), T(1)));
    INFO("heads " << set.size << " condition " << fit.condition << " iterations "
                  << fit.iterations);
    REQUIRE(fit.ok());
    CHECK_WITHIN(angle_between(fit.nadir, truth), T(0), T(eps<T>() * T(64)));
    CHECK(fit.condition >= T(1));
    CHECK(fit.condition < T(3));
    CHECK(fit.iterations <= 8);
    // The condition at the truth, computed alone, is the fit's.
    CHECK_WITHIN(horizon_condition(h, count, truth), fit.condition,
                 T(eps<T>() * T(64) * fit.condition));
  }
}

TEST_CASE("a head at a fold: the fit with a second head still finds the nadir",
          "[horizon_vector]") {
  // Earth of 20 deg (a high orbit), gamma 45 deg. Head A sees the nadir at eta = 41.2 deg, next to
  // its fold (tan eta = tan gamma cos Phi): process_head refuses it, and so does the fit of its
  // two crossings alone. Head B (eta 60 deg) is well conditioned. MODEL §6's mean drops A and uses
  // B alone; the fit uses all four crossings, with a condition near 1.
  const double gamma = conescan::deg_to_rad(45.0), rho = conescan::deg_to_rad(20.0);
  const vec3<double> truth(0, 0, 1);
  const conescan::head_optics<double> optics{gamma, 0, 0};
  const conescan::scan_frame<double> frame_a =
      conescan::scan_frame_from_mounting(conescan::deg_to_rad(90 - 41.2), 0.0);
  const conescan::scan_frame<double> frame_b =
      conescan::scan_frame_from_mounting(conescan::deg_to_rad(30.0), conescan::pi<double>());
  vec3<double> h[4];
  std::size_t count = 0;
  for (const conescan::scan_frame<double>* frame : {&frame_a, &frame_b}) {
    const conescan::scan_angles<double> angles = conescan::scan_angles_of(*frame, truth);
    const conescan::crossings<double> c =
        conescan::bias_model_crossings(optics, angles.polar, angles.azimuth, rho);
    REQUIRE(c.state == status::ok);
    const conescan::head_estimate<double> head = conescan::process_head(*frame, gamma, rho, c);
    CHECK(head.state == (frame == &frame_a ? status::fold : status::ok));
    count = append_horizon_vectors(*frame, gamma, c, h, count, 4);
  }
  REQUIRE(count == 4);
  const vec3<double> seed = tilted(truth, vec3<double>(1, 1, 0), 0.02);
  const horizon_nadir_fit<double> alone = nadir_from_horizon_vectors(h, 2, std::cos(rho), seed);
  INFO("head A alone: condition " << alone.condition);
  CHECK(alone.state == status::fold);
  CHECK(alone.condition > horizon_condition_max<double>());
  const horizon_nadir_fit<double> both = nadir_from_horizon_vectors(h, 4, std::cos(rho), seed);
  INFO("both heads: condition " << both.condition);
  REQUIRE(both.ok());
  CHECK(angle_between(both.nadir, truth) < 1e-13);
  CHECK(both.condition < 3);
}

TEST_CASE("biased, noisy crossings: the fit settles near the truth and the mean of the heads",
          "[horizon_vector]") {
  // Two heads (alpha 0, beta +-90 deg, gamma 45 deg), misaligned 0.02 deg (scan-independent bias
  // model), rho_p 0.01 deg off the truth, and 0.01 deg of Gaussian noise on every crossing (the
  // project's generator, fixed seed). The residuals no longer vanish: Gauss-Newton converges
  // linearly but fast (residuals ~1e-4, lambda_min ~1), so it settles in a few steps. The fit and
  // MODEL §6's mean are two estimators of the same data: both within ~0.05 deg of the truth.
  const double gamma = conescan::deg_to_rad(45.0), rho = conescan::deg_to_rad(61.0);
  const double rho_p = rho + conescan::deg_to_rad(0.01), noise = conescan::deg_to_rad(0.01);
  const vec3<double> truth = conescan::nadir_in_body(conescan::deg_to_rad(0.5), 0.0);
  const conescan::head_optics<double> optics{gamma, conescan::deg_to_rad(0.02), 0.7};
  const conescan::scan_frame<double> frames[2] = {
      conescan::scan_frame_from_mounting(0.0, conescan::deg_to_rad(90.0)),
      conescan::scan_frame_from_mounting(0.0, conescan::deg_to_rad(-90.0))};
  int worst_iterations = 0;
  double worst_to_truth = 0, worst_to_mean = 0;
  for (std::uint64_t row = 0; row < 200; ++row) {
    vec3<double> h[4];
    conescan::head_estimate<double> heads[2];
    std::size_t count = 0;
    for (std::uint64_t k = 0; k < 2; ++k) {
      const conescan::scan_angles<double> angles = conescan::scan_angles_of(frames[k], truth);
      conescan::crossings<double> c =
          conescan::bias_model_crossings(optics, angles.polar, angles.azimuth, rho);
      REQUIRE(c.state == status::ok);
      c.phi_in += noise * conescan::scene::standard_normal(11, 0, row, k, 0);
      c.phi_out += noise * conescan::scene::standard_normal(11, 0, row, k, 1);
      heads[k] = conescan::process_head(frames[k], gamma, rho_p, c);
      REQUIRE(heads[k].state == status::ok);
      count = append_horizon_vectors(frames[k], gamma, c, h, count, 4);
    }
    const conescan::head_estimate<double> mean = conescan::combine_heads<double>(heads, heads + 2);
    const horizon_nadir_fit<double> fit =
        nadir_from_horizon_vectors(h, count, std::cos(rho_p), vec3<double>(0, 0, 1));
    REQUIRE(fit.ok());
    worst_iterations = std::max(worst_iterations, fit.iterations);
    worst_to_truth = std::max(worst_to_truth, angle_between(fit.nadir, truth));
    worst_to_mean = std::max(worst_to_mean, angle_between(fit.nadir, mean.nadir));
  }
  INFO("iterations <= " << worst_iterations
                        << ", to truth <= " << conescan::rad_to_deg(worst_to_truth)
                        << " deg, to the mean <= " << conescan::rad_to_deg(worst_to_mean)
                        << " deg");
  CHECK(worst_iterations <= 8);
  CHECK(worst_to_truth < conescan::deg_to_rad(0.05));
  CHECK(worst_to_mean < conescan::deg_to_rad(0.05));
}

TEMPLATE_TEST_CASE("the condition grows as the crossings bunch together", "[horizon_vector]",
                   CONESCAN_TEST_SCALARS) {
  // Two crossings theta apart about n: condition = cot(theta/2) (header comment); three crossings
  // at 0, +-theta/2 grow alike. Relative accuracy ~eps x condition: checked to sqrt(eps).
  using T = TestType;
  using std::cos;
  using std::sqrt;
  using std::tan;
  const horizon_circle<T> circle = generic_circle<T>(T(cos(deg<T>(61))));
  const T tol = T(sqrt(eps<T>()));
  T previous_two = T(0), previous_three = T(0);
  for (int tenths_deg : {900, 600, 300, 100, 30, 10, 5, 1}) {
    const T theta = deg<T>(tenths_deg, 10);
    const vec3<T> two[2] = {circle.point(T(theta / T(2))), circle.point(T(-theta / T(2)))};
    const vec3<T> three[3] = {two[0], circle.point(T(0)), two[1]};
    const T expected = T(T(1) / tan(T(theta / T(2))));
    const T c2 = horizon_condition(two, 2, circle.n);
    const T c3 = horizon_condition(three, 3, circle.n);
    INFO("theta " << tenths_deg << "/10 deg: two " << c2 << " (expected " << expected << "), three "
                  << c3);
    CHECK_WITHIN(c2, expected, T(tol * expected));
    CHECK(c2 > previous_two);
    CHECK(c3 > previous_three);
    previous_two = c2;
    previous_three = c3;
    // The fit from a seed 0.001 rad off: ok and on the truth below the threshold, fold above.
    const vec3<T> seed = tilted(circle.n, circle.v, T(T(1) / T(1000)));
    const horizon_nadir_fit<T> fit = nadir_from_horizon_vectors(two, 2, circle.cos_rho, seed);
    if (expected < horizon_condition_max<T>() * T(9) / T(10)) {
      REQUIRE(fit.ok());
      CHECK_WITHIN(fit.condition, expected, T(tol * expected));
      // Rounding floor of the fit: 16 eps x condition / sin rho.
      CHECK_WITHIN(angle_between(fit.nadir, circle.n), T(0),
                   T(T(16) * eps<T>() * expected / circle.sin_rho));
    } else {
      CHECK(fit.state == status::fold);
    }
  }
  // Towards the fold: crossings opposite each other through n (theta -> 180 deg).
  T previous = T(0);
  for (int tenths_deg : {1500, 1700, 1780, 1795}) {
    const T theta = deg<T>(tenths_deg, 10);
    const vec3<T> two[2] = {circle.point(T(theta / T(2))), circle.point(T(-theta / T(2)))};
    const T c2 = horizon_condition(two, 2, circle.n);
    CHECK_WITHIN(c2, tan(T(theta / T(2))), T(tol * c2));
    CHECK(c2 > previous);
    previous = c2;
  }
}

TEMPLATE_TEST_CASE("statuses on both sides of their boundaries", "[horizon_vector][status]",
                   CONESCAN_TEST_SCALARS) {
  using T = TestType;
  using std::atan;
  using std::cos;
  const T inf = std::numeric_limits<T>::infinity();
  const T nan = conescan::not_a_number<T>();
  const horizon_circle<T> circle = generic_circle<T>(T(cos(deg<T>(61))));
  const vec3<T> seed = tilted(circle.n, circle.u, T(T(1) / T(1000)));
  const vec3<T> three[3] = {circle.point(T(0)), circle.point(deg<T>(100)),
                            circle.point(deg<T>(230))};

  SECTION("count: 2 is the least") {
    CHECK(nadir_from_horizon_vectors(three, 0, circle.cos_rho, seed).state == status::invalid);
    CHECK(nadir_from_horizon_vectors(three, 1, circle.cos_rho, seed).state == status::invalid);
    CHECK(nadir_from_horizon_vectors(three, 2, circle.cos_rho, seed).ok());
    CHECK(nadir_from_horizon_vectors(three, 3, circle.cos_rho, seed).ok());
    CHECK(nadir_from_horizon_vectors(static_cast<const vec3<T>*>(nullptr), 3, circle.cos_rho, seed)
              .state == status::invalid);
    const horizon_nadir_fit<T> bad = nadir_from_horizon_vectors(three, 1, circle.cos_rho, seed);
    CHECK(bad.nadir.x != bad.nadir.x);  // NaN
    CHECK(bad.condition != bad.condition);
    CHECK(conescan::is_finite(horizon_condition(three, 2, circle.n)));
    CHECK_FALSE(conescan::is_finite(horizon_condition(three, 1, circle.n)));
  }

  SECTION("cos rho_p: open interval (0, 1)") {
    for (const T& c : {T(0), T(1), T(-1) / T(2), T(3) / T(2), nan, inf, T(-inf)}) {
      INFO("cos_rho " << c);
      CHECK(nadir_from_horizon_vectors(three, 3, c, seed).state == status::invalid);
    }
    // Just inside each end, with crossings consistent with it: ok, and on the truth.
    for (const T& c : {T(T(1) / T(1000)), T(T(1) - T(1) / T(1000))}) {
      INFO("cos_rho " << c);
      const horizon_circle<T> edge = generic_circle<T>(c);
      const vec3<T> h[3] = {edge.point(T(0)), edge.point(deg<T>(100)), edge.point(deg<T>(230))};
      const horizon_nadir_fit<T> fit =
          nadir_from_horizon_vectors(h, 3, c, tilted(edge.n, edge.u, T(T(1) / T(1000))));
      REQUIRE(fit.ok());
      // sin rho = 0.045 at the small end: the fit's rounding floor grows as 1 / sin rho.
      CHECK_WITHIN(angle_between(fit.nadir, edge.n), T(0), T(T(64) * eps<T>() / edge.sin_rho));
    }
  }

  SECTION("non-finite horizon vectors and guesses") {
    for (const T& bad : {nan, inf}) {
      vec3<T> h[3] = {three[0], three[1], three[2]};
      h[1].y = bad;
      CHECK(nadir_from_horizon_vectors(h, 3, circle.cos_rho, seed).state == status::invalid);
      CHECK(nadir_from_horizon_vectors(three, 3, circle.cos_rho, vec3<T>(T(0), bad, T(1))).state ==
            status::invalid);
    }
    CHECK(nadir_from_horizon_vectors(three, 3, circle.cos_rho, vec3<T>(T(0))).state ==
          status::invalid);
    // Any non-zero length is fine: the guess is normalised.
    CHECK(
        nadir_from_horizon_vectors(three, 3, circle.cos_rho, conescan::scaled(seed, T(1000))).ok());
  }

  SECTION("fold: the condition threshold, coincident and opposite crossings") {
    // Two crossings theta apart: condition cot(theta/2). At 0.9 and 1.1 times the threshold.
    for (int tenths : {9, 11}) {
      const T target = horizon_condition_max<T>() * T(tenths) / T(10);
      const T theta = T(2) * atan(T(T(1) / target));
      const vec3<T> h[2] = {circle.point(T(theta / T(2))), circle.point(T(-theta / T(2)))};
      const horizon_nadir_fit<T> fit = nadir_from_horizon_vectors(h, 2, circle.cos_rho, seed);
      INFO("target " << target << " condition " << fit.condition << " iterations "
                     << fit.iterations);
      CHECK(fit.state == (tenths < 10 ? status::ok : status::fold));
      CHECK_WITHIN(fit.condition, target, T(target / T(100)));
      if (tenths > 10) CHECK(fit.nadir.x != fit.nadir.x);  // NaN on failure
    }
    // Coincident crossings: the two gradient rows are equal, J^T J is exactly singular.
    const vec3<T> same[2] = {three[0], three[0]};
    const horizon_nadir_fit<T> coincident =
        nadir_from_horizon_vectors(same, 2, circle.cos_rho, seed);
    CHECK(coincident.state == status::fold);
    CHECK(coincident.condition == inf);
    CHECK(horizon_condition(same, 2, circle.n) == inf);
    // Opposite crossings through n: the two mirror solutions merge (the fold proper).
    const vec3<T> opposite[2] = {circle.point(T(0)), circle.point(conescan::pi<T>())};
    const horizon_nadir_fit<T> fold = nadir_from_horizon_vectors(opposite, 2, circle.cos_rho, seed);
    INFO("opposite: condition " << fold.condition << " iterations " << fold.iterations);
    CHECK(fold.state == status::fold);
    CHECK_FALSE(fold.condition <= horizon_condition_max<T>());
  }
}

TEST_CASE("append_horizon_vectors adds both crossings or none", "[horizon_vector]") {
  const conescan::scan_frame<double> frame =
      conescan::scan_frame_from_mounting(0.0, conescan::deg_to_rad(90.0));
  const double gamma = conescan::deg_to_rad(45.0);
  const conescan::crossings<double> c{-0.8, 0.8, status::ok, 0};
  vec3<double> h[3] = {vec3<double>(0), vec3<double>(0), vec3<double>(0)};
  CHECK(append_horizon_vectors(frame, gamma, c, h, 0, 3) == 2);
  CHECK(angle_between(h[0], horizon_vector(frame, gamma, -0.8)) == 0);
  CHECK(angle_between(h[1], horizon_vector(frame, gamma, 0.8)) == 0);
  CHECK(std::abs(conescan::norm(h[0]) - 1) < 1e-15);
  CHECK(std::abs(angle_between(h[0], frame.e3) - gamma) < 1e-15);
  CHECK(append_horizon_vectors(frame, gamma, c, h, 2, 3) == 2);  // one place left: none added
  CHECK(append_horizon_vectors(frame, gamma, conescan::crossings<double>::failed(status::miss), h,
                               0, 3) == 0);
  CHECK(append_horizon_vectors(frame, gamma, c, static_cast<vec3<double>*>(nullptr), 0, 3) == 0);
  const conescan::scan_frame<double> bad = conescan::scan_frame_from_mounting(2.0, 0.0);
  CHECK(append_horizon_vectors(bad, gamma, c, h, 0, 3) == 0);
}
