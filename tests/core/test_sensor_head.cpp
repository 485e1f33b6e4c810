// The sensor-head model (include/conescan/sensor_head.hpp): each step is the core function it
// names, the whole chain recovers a perfect head's attitude in every scalar type, an invalid head
// refuses every step, and the truth crossings and processing differentiate with ceres::Jet (the
// calibration's automatic derivatives) to the finite-difference derivatives.
#include <array>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "conescan/sensor_head.hpp"
#include "support/adl_scalar.hpp"
#include "support/approx.hpp"

#ifdef CONESCAN_HAVE_CERES_JET
#include <ceres/jet.h>
#endif

using conescan::crossings;
using conescan::head_optics;
using conescan::sensor_head;
using conescan::status;
using conescan::vec3;

namespace {

template <class T>
T deg(int d) {
  return conescan::deg_to_rad(T(d));
}

/// A perfect head (sigma = 0) seeing a sphere it assumes exactly: each truth model, processed,
/// must give back the true roll and pitch. Returns the largest roll/pitch error (rad).
template <class T>
T perfect_head_error(int alpha, int beta, int roll, int pitch) {
  using std::abs;
  const sensor_head<T> head =
      sensor_head<T>::from_mounting(deg<T>(alpha), deg<T>(beta), {deg<T>(45), T(0), deg<T>(30)});
  REQUIRE(head.state() == status::ok);
  const T r = T(7200000), radius = T(6378137);
  const vec3<T> nadir_body = conescan::nadir_in_body(deg<T>(roll), deg<T>(pitch));
  const conescan::disk_trig<T> disk = conescan::disk_trig_of(radius, r);
  const conescan::scan_angles<T> nadir = conescan::scan_angles_of(head.frame(), nadir_body);
  const T rho = conescan::disk_angular_radius(radius, r).value;
  // The ellipsoid of one radius, seen from r below the satellite: in body axes the satellite is
  // at -r nadir_body, the polar axis anywhere.
  const conescan::ellipsoid_horizon<T> sphere_as_ellipsoid = conescan::ellipsoid_horizon_of(
      conescan::scaled(nadir_body, T(-r)), vec3<T>(T(0), T(1), T(0)), radius, radius);
  const crossings<T> truths[] = {
      head.bias_crossings(head.bias_cone_angle(), nadir.polar, nadir.azimuth, rho),
      head.scan_crossings(head.in_scan_frame(nadir_body), disk),
      head.scan_crossings(head.in_scan_frame(sphere_as_ellipsoid))};
  T worst = T(0);
  for (const crossings<T>& truth : truths) {
    REQUIRE(truth.state == status::ok);
    const conescan::head_estimate<T> e = head.process(head.measured(truth, T(0), T(0)), disk);
    REQUIRE(e.state == status::ok);
    const conescan::roll_pitch<T> rp = conescan::roll_pitch_from_nadir(e.nadir);
    const T roll_error = abs(T(rp.roll - deg<T>(roll))),
            pitch_error = abs(T(rp.pitch - deg<T>(pitch)));
    if (roll_error > worst) worst = roll_error;
    if (pitch_error > worst) worst = pitch_error;
    if (abs(T(e.eta_s - nadir.polar)) > worst) worst = abs(T(e.eta_s - nadir.polar));
  }
  return worst;
}

}  // namespace

TEMPLATE_TEST_CASE("sensor head: a perfect head recovers the attitude in every scalar",
                   "[sensor_head][scalar]", CONESCAN_TEST_SCALARS) {
  // The chord inversion amplifies the crossings' rounding by |d eta / d Phi| (below 3 here): a
  // few hundred eps of T.
  using T = TestType;
  for (int alpha : {0, 20, -15})
    for (int roll : {0, 3})
      for (int pitch : {0, -2}) {
        INFO("alpha " << alpha << " roll " << roll << " pitch " << pitch);
        CHECK(perfect_head_error<T>(alpha, 90, roll, pitch) <=
              T(std::numeric_limits<T>::epsilon() * T(512)));
      }
}

TEST_CASE("sensor head: a perfect head recovers the attitude in 50 digits",
          "[sensor_head][scalar]") {
  using R = boost::multiprecision::cpp_bin_float_50;
  const R worst = perfect_head_error<R>(20, -90, 3, -2);
  CHECK(worst <= R(1e-45));
}

TEST_CASE("sensor head: each step is the core function it names", "[sensor_head]") {
  const double d = conescan::pi<double>() / 180;
  const head_optics<double> optics{45 * d, 0.5 * d, 70 * d};
  const sensor_head<double> head =
      sensor_head<double>::from_mounting(10 * d, 90 * d, optics, {0.01 * d, 0.005 * d});
  const conescan::scan_frame<double> frame = conescan::scan_frame_from_mounting(10 * d, 90 * d);
  const vec3<double> nadir_body = conescan::nadir_in_body(2 * d, -1 * d);
  const conescan::scan_angles<double> nadir = conescan::scan_angles_of(frame, nadir_body);
  const double r = 7000000, radius = 6378137, rho = std::asin(radius / r);
  const conescan::disk_trig<double> disk = conescan::disk_trig_of(radius, r);
  CHECK(head.eta0() == Approx(conescan::nominal_nadir_angle(frame)).margin(1e-15));
  // 1. Truth: the scan model on the sphere is the closed form from the angles (which adds one
  // rounding of the nadir's angles), the bias model its own function exactly.
  const crossings<double> scan = head.scan_crossings(head.in_scan_frame(nadir_body), disk);
  const crossings<double> scan_angles =
      conescan::scan_model_crossings_sphere(optics, nadir.polar, nadir.azimuth, rho);
  REQUIRE(scan.state == status::ok);
  CHECK_WITHIN(scan.chord(), scan_angles.chord(), 1e-14);
  CHECK_WITHIN(conescan::wrap_pi(scan.phase() - scan_angles.phase()), 0.0, 1e-14);
  const crossings<double> bias =
      head.bias_crossings(head.bias_cone_angle(), nadir.polar, nadir.azimuth, rho);
  const crossings<double> bias_free =
      conescan::bias_model_crossings(optics, nadir.polar, nadir.azimuth, rho);
  CHECK(bias.phi_in == bias_free.phi_in);
  CHECK(bias.phi_out == bias_free.phi_out);
  // 2. Measurement errors: noise x draw on each crossing, then the telemetry step.
  const crossings<double> measured = head.measured(scan, 1.5, -0.7);
  const crossings<double> by_hand = conescan::quantised(
      conescan::with_crossing_noise(scan, 0.01 * d * 1.5, 0.01 * d * -0.7), 0.005 * d);
  CHECK(measured.phi_in == by_hand.phi_in);
  CHECK(measured.phi_out == by_hand.phi_out);
  // 3. Processing: process_head with the head's angles (which evaluates their trigonometry).
  const conescan::head_estimate<double> e = head.process(measured, disk);
  const conescan::head_estimate<double> e_free =
      conescan::process_head(frame, optics.gamma, rho, measured);
  REQUIRE(e.state == status::ok);
  CHECK_WITHIN(e.eta_s, e_free.eta_s, 1e-15);
  CHECK_WITHIN(e.nadir.x, e_free.nadir.x, 1e-15);
  CHECK_WITHIN(e.nadir.y, e_free.nadir.y, 1e-15);
  CHECK_WITHIN(e.nadir.z, e_free.nadir.z, 1e-15);
}

TEST_CASE("sensor head: an invalid head refuses every step", "[sensor_head][status]") {
  const double d = conescan::pi<double>() / 180;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const vec3<double> nadir(0, 0, 1);
  const conescan::disk_trig<double> disk = conescan::disk_trig_of(6378137.0, 7000000.0);
  const sensor_head<double> heads[] = {
      sensor_head<double>::from_mounting(90 * d, 0, {45 * d, 0, 0}),      // alpha = 90 deg
      sensor_head<double>::from_mounting(0, 0, {45 * d, 45 * d, 0}),      // sigma = gamma
      sensor_head<double>::from_mounting(0, 0, {45 * d, 0, nan}),         // phi_A not finite
      sensor_head<double>::from_mounting(0, 0, {45 * d, 0, 0}, {-1, 0}),  // negative noise
      sensor_head<double>::from_mounting(0, 0, {45 * d, 0, 0}, {0, nan}),
      sensor_head<double>::from_mounting(0, 0, {45 * d, 0, 0}, {0, 0}, 91 * d),  // envelope
      sensor_head<double>::from_mounting(0, 0, {45 * d, 0, 0}, {0, 0}, -1e-9)};
  for (const sensor_head<double>& head : heads) {
    CHECK(head.state() == status::invalid);
    CHECK(head.bias_cone_angle().state == status::invalid);
    CHECK(head.scan_crossings(nadir, disk).state == status::invalid);
    const crossings<double> fine{-1.0, 1.0, status::ok, 0};
    CHECK(head.process(fine, disk).state == status::invalid);
    CHECK(std::isnan(head.process(fine, disk).nadir.x));
  }
  // A valid head passes a failed measurement's status through, and refuses a bad disk.
  const sensor_head<double> good = sensor_head<double>::from_mounting(0, 90 * d, {45 * d, 0, 0});
  CHECK(good.process(crossings<double>::failed(status::miss), disk).state == status::miss);
  const crossings<double> fine{-1.0, 1.0, status::ok, 0};
  CHECK(good.process(fine, conescan::disk_trig_of(7000000.0, 6378137.0)).state == status::invalid);
}

#ifdef CONESCAN_HAVE_CERES_JET
TEST_CASE("sensor head: chord and phase differentiate with ceres::Jet", "[sensor_head][jet]") {
  // The calibration (MODEL §11) predicts each measured chord and phase from sigma, phi_A and the
  // cone angle: the scan model's closed form and the processing, instantiated with Jet, give
  // their derivatives. They must match central differences of the double model (step 1e-6 rad:
  // truncation ~1e-12, rounding ~1e-10 relative).
  using jet = ceres::Jet<double, 3>;
  const double d = conescan::pi<double>() / 180;
  const double gamma = 45 * d, sigma = 0.5 * d, phi_a = 70 * d;
  auto predict = [&](auto g, auto s, auto p) {
    using T = decltype(g);
    const sensor_head<T> head =
        sensor_head<T>::from_mounting(T(10 * d), T(90 * d), head_optics<T>{g, s, p});
    const vec3<T> nadir_body = conescan::nadir_in_body(T(2 * d), T(-1 * d));
    const conescan::disk_trig<T> disk = conescan::disk_trig_of(T(6378137), T(7000000));
    const crossings<T> c = head.scan_crossings(head.in_scan_frame(nadir_body), disk);
    REQUIRE(c.state == status::ok);
    const conescan::head_estimate<T> e = head.process(c, disk);
    REQUIRE(e.state == status::ok);
    return std::array<T, 3>{c.chord(), c.phase(), e.eta_s};
  };
  const std::array<jet, 3> j = predict(jet(gamma, 0), jet(sigma, 1), jet(phi_a, 2));
  const double h = 1e-6;
  const double x[3] = {gamma, sigma, phi_a};
  for (int k = 0; k < 3; ++k) {
    double up[3] = {x[0], x[1], x[2]}, down[3] = {x[0], x[1], x[2]};
    up[k] += h;
    down[k] -= h;
    const std::array<double, 3> a = predict(up[0], up[1], up[2]);
    const std::array<double, 3> b = predict(down[0], down[1], down[2]);
    for (int q = 0; q < 3; ++q) {
      const double numeric = (a[q] - b[q]) / (2 * h);
      INFO("quantity " << q << " (chord, phase, eta_s), parameter " << k
                       << " (gamma, sigma, phi_A): jet " << j[q].v[k] << ", numeric " << numeric);
      CHECK(j[q].v[k] == Approx(numeric).margin(1e-8).epsilon(1e-6));
    }
  }
  // The values themselves are the double model's, to a rounding or two (Jet's own atan2 and
  // sqrt are written in other terms than libm's).
  const std::array<double, 3> plain = predict(gamma, sigma, phi_a);
  for (int q = 0; q < 3; ++q) CHECK_WITHIN(j[q].a, plain[q], 1e-15);
}
#endif
