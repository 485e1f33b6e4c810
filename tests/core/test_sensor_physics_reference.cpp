// The chain (include/conescan/sensor_physics/chain.hpp) against the brute-force reference
// (tests/support/sensor_physics_reference.hpp: dense 2-D field quadrature, the exact hold on a
// uniform grid over the whole turn, long double, no shared code), MODEL §12.
//  - [physics]: a pencil with lag on the sphere and the apparent-horizon ellipsoid, and a
//    1.5 deg square field with 1 ms of lag at 1 rev/s and the normalised locator: within
//    1e-6 deg (measured: 1e-8 deg and below, the reference's own error; see
//    docs/SENSOR_PHYSICS.md);
//  - [.physics-slow] (run with "[.physics-slow]"): the circle, the season term, a disk dimmer
//    than the limb, the default delta50 = 0 with a field, a step profile with a field, the
//    fixed and slope locators, the ellipsoid with everything: each within 1e-6 deg; minutes.
#include <catch2/catch.hpp>
#include <cmath>
#include <memory>
#include <random>

#include "support/sensor_physics_compare.hpp"
#include "support/sensor_physics_scene.hpp"

using conescan::locator_kind;
using conescan::sensor_physics_settings;
using conescan::status;

namespace {

/// The chain's crossings against the reference's (grid step h_deg), in degrees.
void compare(const conescan_test::physics_scene_options& o,
             const sensor_physics_settings<double>& s, double sin_sun, double h_deg,
             double tolerance_deg) {
  conescan_test::compare_with_reference(o, s, sin_sun, h_deg, tolerance_deg);
}

sensor_physics_settings<double> square_field_with_lag() {
  sensor_physics_settings<double> s;
  s.field.fov_rad = conescan::deg_to_rad(1.5);
  s.spin_hz = 1;
  s.tau_s = 1e-3;
  s.offset_m = 40000;
  return s;
}

conescan_test::physics_scene_options apparent_horizon() {
  conescan_test::physics_scene_options o;
  o.ellipsoid = true;
  o.b_m = 6356752.314245L + 40000 - 12000;
  o.centre_shift_m = 4000;
  o.roll_deg = 2;
  o.sigma_deg = 0.3L;
  o.phi_a_deg = 60;
  return o;
}

}  // namespace

TEST_CASE("chain against reference: a pencil with lag", "[physics][brute-force]") {
  sensor_physics_settings<double> s = square_field_with_lag();
  s.field.fov_rad = 0;
  // The pencil's sharper signal needs the reference's finer grid: at h = 0.01 deg it is still
  // 2e-7 deg from its limit (measured), at 0.005 deg 1e-8.
  compare(conescan_test::physics_scene_options{}, s, 0.0, 0.005, 1e-7);
  compare(apparent_horizon(), s, 0.0, 0.005, 1e-7);
}

TEST_CASE("chain against reference: 1.5 deg square, 1 ms lag, normalised",
          "[physics][brute-force]") {
  // The reference at h = 0.02 deg is itself within ~1.5e-7 deg of its limit (measured against h
  // = 0.01 and 0.005 deg); the chain was within 3e-9 deg of the h = 0.005 deg reference.
  compare(conescan_test::physics_scene_options{}, square_field_with_lag(), 0.0, 0.02, 1e-6);
}

TEST_CASE("chain against reference: every feature", "[.physics-slow]") {
  auto s = square_field_with_lag();
  SECTION("circle") {
    s.field.shape = conescan::field_shape::circle;
    compare(conescan_test::physics_scene_options{}, s, 0.0, 0.01, 1e-6);
  }
  SECTION("season term") {
    s.season_amplitude = 0.2;
    compare(conescan_test::physics_scene_options{}, s, 0.3, 0.01, 1e-6);
  }
  SECTION("disk dimmer than the limb") {
    s.disk = 0.8;
    compare(conescan_test::physics_scene_options{}, s, 0.0, 0.01, 1e-6);
  }
  SECTION("delta50 = 0 with a field") {
    s.offset_m = 0;
    compare(conescan_test::physics_scene_options{}, s, 0.0, 0.01, 1e-6);
  }
  SECTION("step profile with a field") {
    s.scale_m = 0;
    s.offset_m = 20000;
    s.field.fov_rad = conescan::deg_to_rad(1.0);
    compare(conescan_test::physics_scene_options{}, s, 0.0, 0.01, 1e-6);
  }
  SECTION("fixed threshold") {
    s.locator = {locator_kind::fixed, 0.3};
    compare(conescan_test::physics_scene_options{}, s, 0.0, 0.01, 1e-6);
  }
  SECTION("slope") {
    s.locator = {locator_kind::slope, 0.5};
    compare(conescan_test::physics_scene_options{}, s, 0.0, 0.005, 1e-6);
  }
  SECTION("apparent horizon, season, dim disk") {
    s.season_amplitude = 0.2;
    s.disk = 0.9;
    compare(apparent_horizon(), s, 0.3, 0.01, 1e-6);
  }
}

TEST_CASE("chain against reference: random heads, fields, lags, locators, profiles and Earths",
          "[physics][brute-force]") {
  // Eight scenes drawn over the whole of MODEL §12 at once: a misaligned head at an attitude
  // within 2 deg, sphere, ellipsoid or apparent horizon; a pencil or a square or circle of 0.1 to
  // 2 deg; 0.5 to 4 rev/s with 0 to 2 ms of lag; each locator; H from the step to 10 km; delta50
  // to 60 km; a disk 0.8 to 1.2 of the limb; the season term on half. Every crossing within 1e-6
  // deg of the reference, whose own grid error is ~1e-7 deg at these steps.
  std::mt19937_64 rng(2026);
  auto uniform = [&rng](double a, double b) {
    return std::uniform_real_distribution<double>(a, b)(rng);
  };
  for (int t = 0; t < 8; ++t) {
    conescan_test::physics_scene_options o;
    // The spin axis 83 to 97 deg from the nadir and cones of 42 to 50 deg against an Earth of 60
    // to 66 deg radius: both crossings at least 5 deg from grazing.
    o.alpha_deg = uniform(-5, 5);
    o.gamma_deg = uniform(42, 50);
    o.sigma_deg = uniform(0, 0.4);
    o.phi_a_deg = uniform(-180, 180);
    o.roll_deg = uniform(-2, 2);
    o.pitch_deg = uniform(-2, 2);
    o.distance_m = uniform(7.0e6, 7.4e6);
    o.ellipsoid = t % 2 == 1;
    o.b_m = 6356752.314245L + 40000 - (t % 4 == 3 ? uniform(0, 15000) : 0);
    o.centre_shift_m = t % 4 == 3 ? uniform(-8000, 8000) : 0;
    sensor_physics_settings<double> s;
    const bool pencil = t % 4 == 2;
    s.field = {pencil ? 0.0 : conescan::deg_to_rad(uniform(0.1, 2)),
               t % 3 == 1 ? conescan::field_shape::circle : conescan::field_shape::square};
    s.spin_hz = uniform(0.5, 4);
    s.tau_s = t % 3 == 0 ? 0.0 : uniform(0.1e-3, 2e-3);
    s.locator =
        t % 3 == 0 ? conescan::horizon_locator<double>{locator_kind::normalised, uniform(0.3, 0.7)}
        : t % 3 == 1 ? conescan::horizon_locator<double>{locator_kind::fixed, uniform(0.2, 0.6)}
                     : conescan::horizon_locator<double>{locator_kind::slope, 0.5};
    s.scale_m = t % 4 == 0 ? 0.0 : std::exp(uniform(std::log(10.0), std::log(10000.0)));
    s.offset_m = uniform(0, 60000);
    s.disk = uniform(0.8, 1.2);
    s.season_amplitude = t % 2 == 0 ? uniform(-0.3, 0.3) : 0.0;
    INFO("scene " << t << ": fov " << conescan::rad_to_deg(s.field.fov_rad) << " deg, shape "
                  << static_cast<int>(s.field.shape) << ", spin " << s.spin_hz << " rev/s, tau "
                  << s.tau_s << " s, locator " << static_cast<int>(s.locator.kind) << " "
                  << s.locator.threshold << ", H " << s.scale_m << " m, delta50 " << s.offset_m
                  << " m, disk " << s.disk << ", A " << s.season_amplitude);
    compare(o, s, 0.35, pencil ? 0.005 : 0.01, 1e-6);
  }
}
