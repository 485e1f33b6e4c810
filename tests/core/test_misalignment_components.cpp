// The head model as a calibration drives it (include/conescan/misalignment_components.hpp and the
// biases of sensor_head.hpp): the scan circle from the misalignment's components gives the
// crossings of scan_circle_of's circle, its derivatives (ceres::Jet) match central finite
// differences, also at sigma = 0 where (sigma, phi_A) have none, and a head's cone-angle and
// crossing biases move the truth and the measurement as MODEL §11 defines them.
#include <array>
#include <catch2/catch.hpp>
#include <cmath>

#include "conescan/misalignment_components.hpp"
#include "conescan/sensor_head.hpp"
#include "support/adl_scalar.hpp"

#ifdef CONESCAN_HAVE_CERES_JET
#include <ceres/jet.h>
#endif

using namespace conescan;

namespace {

constexpr double d = 3.14159265358979323846 / 180;

// A nadir 3 deg off the nominal (eta = 93 deg from S at azimuth 10 deg) on a disk of 60 deg:
// a scan well inside its domain.
template <class T>
vec3<T> test_nadir() {
  using std::cos;
  using std::sin;
  const T eta = T(93 * d), phi_n = T(10 * d);
  return vec3<T>(T(sin(eta) * cos(phi_n)), T(sin(eta) * sin(phi_n)), T(cos(eta)));
}

template <class T>
disk_trig<T> test_disk() {
  return disk_trig_of_angle(T(60 * d));
}

// Chord and phase (rad) of the component head.
template <class T>
std::array<T, 2> chord_and_phase(const T& gamma, const T& x, const T& y) {
  const crossings<T> c = component_crossings_sphere(gamma, x, y, test_nadir<T>(), test_disk<T>());
  return {c.chord(), c.phase()};
}

// Chord and phase (rad) on an oblate ellipsoid (WGS84-like semi-axes plus a horizon height h,
// m) seen from 7365 km along minus the test nadir, the polar axis tilted in the scan frame.
template <class T>
std::array<T, 2> ellipsoid_chord_and_phase(const T& gamma, const T& x, const T& y, const T& h) {
  const vec3<T> n = test_nadir<T>();
  const T distance = T(7365e3);
  const vec3<T> p(T(-distance * n.x), T(-distance * n.y), T(-distance * n.z));
  const vec3<T> polar = unit(vec3<T>(T(0.3), T(-0.5), T(0.8)));
  const crossings<T> c = component_crossings_ellipsoid(
      gamma, x, y, ellipsoid_horizon_of(p, polar, T(6378137.0 + h), T(6356752.3 + h)));
  return {c.chord(), c.phase()};
}

}  // namespace

TEST_CASE("misalignment components: the same crossings as (sigma, phi_A)", "[components]") {
  for (double sigma_deg : {0.0, 1e-7, 0.05, 0.57, 0.6, 2.0, 10.0}) {
    for (double phase_deg : {0.0, 60.0, 200.0, -90.0}) {
      const double sigma = sigma_deg * d, phase = phase_deg * d, gamma = 45 * d;
      const crossings<double> polar =
          scan_model_crossings_sphere(scan_circle_of(head_optics<double>{gamma, sigma, phase}),
                                      test_nadir<double>(), test_disk<double>());
      const crossings<double> cartesian =
          component_crossings_sphere(gamma, sigma * std::cos(phase), sigma * std::sin(phase),
                                     test_nadir<double>(), test_disk<double>());
      INFO("sigma " << sigma_deg << " phase " << phase_deg);
      REQUIRE(polar.state == status::ok);
      REQUIRE(cartesian.state == status::ok);
      CHECK(std::abs(cartesian.phi_in - polar.phi_in) < 1e-14);
      CHECK(std::abs(cartesian.phi_out - polar.phi_out) < 1e-14);
    }
  }
}

TEST_CASE("misalignment components: the circle is orthonormal, u = e1 at sigma = 0",
          "[components]") {
  const scan_circle<double> at_zero = scan_circle_from_components(45 * d, 0.0, 0.0);
  REQUIRE(at_zero.state == status::ok);
  CHECK(at_zero.u.x == 1);
  CHECK(at_zero.v.y == 1);
  CHECK(at_zero.axis.z == 1);
  for (double sigma : {1e-9, 0.009, 0.011, 0.3}) {
    const scan_circle<double> c =
        scan_circle_from_components(45 * d, sigma * std::cos(2.0), sigma * std::sin(2.0));
    CHECK(std::abs(dot(c.u, c.u) - 1) < 4e-16);
    CHECK(std::abs(dot(c.v, c.v) - 1) < 4e-16);
    CHECK(std::abs(dot(c.u, c.axis)) < 4e-16);
    const vec3<double> w = cross(c.axis, c.u) - c.v;  // v = A x u: theta grows with phi
    CHECK(norm(w) < 4e-16);
  }
}

TEST_CASE("misalignment components: domain", "[components]") {
  const double nan = std::nan("");
  CHECK(scan_circle_from_components(45 * d, 0.0, 0.0).state == status::ok);
  CHECK(scan_circle_from_components(0.0, 0.0, 0.0).state == status::invalid);
  CHECK(scan_circle_from_components(90 * d, 0.0, 0.0).state == status::invalid);
  CHECK(scan_circle_from_components(10 * d, 10 * d, 0.0).state ==
        status::invalid);  // sigma = gamma
  CHECK(scan_circle_from_components(10 * d, 9.99 * d, 0.0).state == status::ok);
  CHECK(scan_circle_from_components(45 * d, nan, 0.0).state == status::invalid);
  CHECK(component_crossings_sphere(45 * d, nan, 0.0, test_nadir<double>(), test_disk<double>())
            .state == status::invalid);
}

TEST_CASE("misalignment components: the series' limit is in the scalar's own terms",
          "[components]") {
  CHECK(misalignment_series_limit<double>() == Approx(1.2207e-4).epsilon(1e-3));
  CHECK(misalignment_series_limit<float>() == Approx(0.01858).epsilon(1e-3));
  // Both sides of the switch agree with the direct forms to an ulp or two, in float too.
  for (float sigma : {0.99f * std::sqrt(misalignment_series_limit<float>()),
                      1.01f * std::sqrt(misalignment_series_limit<float>())}) {
    const vec3<float> a = optical_axis_from_components(sigma, 0.0f);
    CHECK(std::abs(a.x - std::sin(sigma)) <= 2 * std::numeric_limits<float>::epsilon() * sigma);
    CHECK(std::abs(a.z - std::cos(sigma)) <= 2 * std::numeric_limits<float>::epsilon());
  }
  // The ADL-only test scalar compiles and agrees with double.
  using adl = conescan_test::adl_real;
  const adl x = conescan_test::scalar_from<adl>(1e-3L), y = conescan_test::scalar_from<adl>(2e-3L);
  const scan_circle<adl> c = scan_circle_from_components(conescan_test::deg<adl>(45), x, y);
  CHECK(c.state == status::ok);
  const scan_circle<double> reference = scan_circle_from_components(45 * d, 1e-3, 2e-3);
  CHECK(std::abs(static_cast<double>(static_cast<long double>(c.u.x)) - reference.u.x) < 1e-15);
}

TEST_CASE("sensor head biases: dgamma moves the truth cone, not the processing", "[components]") {
  const head_optics<double> optics{45 * d, 0.0, 0.0};
  const sensor_head<double> nominal = sensor_head<double>::from_mounting(0, 90 * d, optics);
  const sensor_head<double> biased = sensor_head<double>::from_mounting(
      0, 90 * d, optics, {0, 0}, default_attitude_envelope<double>(),
      {0.1 * d, 0.02 * d, 0.05 * d});
  REQUIRE(biased.state() == status::ok);
  CHECK(biased.circle().cos_gamma == Approx(std::cos(45.1 * d)).epsilon(1e-15));
  CHECK(biased.inversion().cos_gamma == nominal.inversion().cos_gamma);
  const crossings<double> truth = biased.scan_crossings(test_nadir<double>(), test_disk<double>());
  const crossings<double> measured = biased.measured(truth, 0, 0);
  CHECK(measured.phi_in - truth.phi_in == Approx(0.02 * d).epsilon(1e-12));
  CHECK(measured.phi_out - truth.phi_out == Approx(0.05 * d).epsilon(1e-12));
  // The same truth from the component model with gamma + dgamma.
  const crossings<double> components =
      component_crossings_sphere(45.1 * d, 0.0, 0.0, test_nadir<double>(), test_disk<double>());
  CHECK(std::abs(components.phi_in - truth.phi_in) < 1e-14);
  // Out of domain: gamma + dgamma at 90 deg, or a bias not finite.
  CHECK(sensor_head<double>::from_mounting(0, 0, optics, {0, 0}, 0.1, {45 * d, 0, 0}).state() ==
        status::invalid);
  CHECK(
      sensor_head<double>::from_mounting(0, 0, optics, {0, 0}, 0.1, {0, std::nan(""), 0}).state() ==
      status::invalid);
}

#ifdef CONESCAN_HAVE_CERES_JET
TEST_CASE("misalignment components: Jet derivatives match finite differences",
          "[components][jet]") {
  using jet = ceres::Jet<double, 3>;
  // At sigma = 0 (the fit's start) and at sigma = 0.05 deg and 2 deg (both sides of the series).
  for (const std::array<double, 2> xy :
       {std::array<double, 2>{0, 0}, {0.025 * d, 0.0433 * d}, {-1.0 * d, 1.7 * d}}) {
    const double gamma = 45 * d;
    const std::array<jet, 2> j = chord_and_phase(jet(gamma, 0), jet(xy[0], 1), jet(xy[1], 2));
    const double h = 1e-7;
    for (int k = 0; k < 3; ++k) {
      std::array<double, 3> plus{gamma, xy[0], xy[1]}, minus = plus;
      plus[k] += h;
      minus[k] -= h;
      const auto p = chord_and_phase(plus[0], plus[1], plus[2]);
      const auto m = chord_and_phase(minus[0], minus[1], minus[2]);
      for (int q = 0; q < 2; ++q) {
        const double numeric = (p[q] - m[q]) / (2 * h);
        INFO("x " << xy[0] << " y " << xy[1] << " quantity " << q << " parameter " << k << ": jet "
                  << j[q].v[k] << ", numeric " << numeric);
        CHECK(std::isfinite(j[q].v[k]));
        CHECK(std::abs(j[q].v[k] - numeric) < 1e-7);
      }
    }
    const auto value = chord_and_phase(gamma, xy[0], xy[1]);
    CHECK(std::abs(j[0].a - value[0]) < 1e-13);  // Jet's own atan2, sqrt: a few ulp
  }
}

TEST_CASE("misalignment components: Jet derivatives through the ellipsoid's Newton steps",
          "[components][jet]") {
  // The crossings on the ellipsoid come from Newton iterations: their Jets must carry the
  // derivatives of the converged root (the calibration's horizon terms and misalignment on
  // --earth wgs84), with respect to gamma, x, y and the horizon height.
  using jet = ceres::Jet<double, 4>;
  const std::array<double, 4> at{45 * d, 0.025 * d, 0.0433 * d, 40e3};
  const std::array<jet, 2> j =
      ellipsoid_chord_and_phase(jet(at[0], 0), jet(at[1], 1), jet(at[2], 2), jet(at[3], 3));
  const auto value = ellipsoid_chord_and_phase(at[0], at[1], at[2], at[3]);
  REQUIRE(std::isfinite(value[0]));
  for (int k = 0; k < 4; ++k) {
    const double h = k == 3 ? 1.0 : 1e-7;  // 1 m of horizon, 1e-7 rad of angle
    std::array<double, 4> plus = at, minus = at;
    plus[k] += h;
    minus[k] -= h;
    const auto p = ellipsoid_chord_and_phase(plus[0], plus[1], plus[2], plus[3]);
    const auto m = ellipsoid_chord_and_phase(minus[0], minus[1], minus[2], minus[3]);
    for (int q = 0; q < 2; ++q) {
      const double numeric = (p[q] - m[q]) / (2 * h);
      INFO("quantity " << q << " parameter " << k << ": jet " << j[q].v[k] << ", numeric "
                       << numeric);
      CHECK(std::abs(j[q].v[k] - numeric) < 1e-7 * (k == 3 ? 1e-6 : 1) + 1e-6 * std::abs(numeric));
    }
  }
}
#endif
