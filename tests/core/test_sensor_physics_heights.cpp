// Tangent heights (include/conescan/sensor_physics/height.hpp) and the limb profile
// (sensor_physics/profile.hpp), MODEL §12:
//  - on the sphere delta = |p| sin angle(d, -p) - (R + h_h) for d.p < 0, |p| - R otherwise, and
//    a line that meets the sphere has delta < 0 (MODEL's -inf); against the reference's vector
//    form in long double;
//  - on the ellipsoid (inflated, apparent) delta = 0 exactly at MODEL §5's crossings, the sphere's
//    value when the ellipsoid is a sphere, and the reference's vector form elsewhere; the tangent
//    point's geodetic latitude likewise;
//  - the profile: l(delta50) = 1/2 for every H, the steepest point delta50 + H ln ln 2, the
//    10-90 % width 3.0844 H, a clean saturation far below the knee and a clean tail far above,
//    its derivatives against differences; the season factor's sign and size;
//  - the chain's geometry polynomials against the exact heights (the 1e-7 m they promise).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <memory>
#include <random>

#include "conescan/sensor_physics/geodetic_latitude.hpp"
#include "conescan/sensor_physics/height.hpp"
#include "conescan/sensor_physics/profile.hpp"
#include "support/adl_scalar.hpp"
#include "support/approx.hpp"
#include "support/sensor_physics_scene.hpp"

#define CHECK_CLOSE(actual, expected, tolerance)                                     \
  CHECK_WITHIN(static_cast<long double>(actual), static_cast<long double>(expected), \
               static_cast<long double>(tolerance))

using conescan::status;
using conescan::vec3;
using conescan_test::ld;
using conescan_test::vec3l;

TEMPLATE_TEST_CASE("the WGS84 geodetic latitude against the forward closed form", "[physics]",
                   float, double, long double) {
  // From geodetic latitude and height to (rho, z) by the forward closed form (no iteration), in
  // long double, and back by wgs84_sin_geodetic_latitude: every 2.5 deg of latitude, from the
  // surface to 10^6 km up, within a few ulp of T.
  using T = TestType;
  const ld a = conescan::wgs84_equatorial_radius_m<ld>(), f = conescan::wgs84_flattening<ld>();
  const ld e2 = f * (2 - f);
  CHECK(a == 6378137.0L);
  CHECK(1 / f == Approx(298.257223563).epsilon(1e-15));
  ld worst = 0;
  for (int i = -36; i <= 36; ++i)
    for (ld height_m : {0.0L, 40000.0L, 700000.0L, 36000000.0L, 1e9L}) {
      const ld latitude = i * 2.5L * 3.14159265358979323846L / 180;
      const ld sin_lat = std::sin(latitude);
      const ld n = a / std::sqrt(1 - e2 * sin_lat * sin_lat);
      const ld rho = (n + height_m) * std::cos(latitude), z = (n * (1 - e2) + height_m) * sin_lat;
      const T got = conescan::wgs84_sin_geodetic_latitude(static_cast<T>(rho), static_cast<T>(z));
      worst = std::max(worst, std::fabs(static_cast<ld>(got) - sin_lat));
    }
  // float's inputs alone carry 6e-8 of relative rounding.
  CHECK(worst <= 8 * std::numeric_limits<T>::epsilon());
  // The centre has no latitude: 0.
  CHECK(conescan::wgs84_sin_geodetic_latitude(T(0), T(0)) == T(0));
}

TEMPLATE_TEST_CASE("the tangent height on a sphere", "[physics]", float, double, long double) {
  using T = TestType;
  const T radius = T(6418137), distance = T(7280000);
  const vec3<T> nadir(T(0), T(0), T(1)), polar = conescan::unit(vec3<T>(T(1), T(2), T(2)));
  const auto s = conescan::sphere_surface_of(nadir, radius, distance, polar);
  REQUIRE(s.state == status::ok);
  const conescan_test::reference_scene r{
      0,       0,       0, false, vec3l(0, 0, 7280000), vec3l(1.0L / 3, 2.0L / 3, 2.0L / 3),
      6418137, 6418137, 0};
  // float keeps a few ulp of R and |p| (0.5 m each): 4 m.
  const long double tolerance = std::is_same_v<T, float> ? 4.0L : 1e-6L;
  for (int i = 0; i <= 40; ++i) {
    // Lines from the nadir to 100 deg off it, at an azimuth of 30 deg.
    const long double beta = 2.5L * i * 3.14159265358979323846L / 180, azimuth = 0.5L;
    const vec3l dl(std::sin(beta) * std::cos(azimuth), std::sin(beta) * std::sin(azimuth),
                   std::cos(beta));
    const vec3<T> d(static_cast<T>(dl.x), static_cast<T>(dl.y), static_cast<T>(dl.z));
    const auto h = conescan::tangent_height_of(s, d);
    REQUIRE(h.state == status::ok);
    const auto expected = conescan_test::reference_height_of(r, dl);
    INFO("beta " << beta * 180 / 3.14159265358979323846L << " deg");
    CHECK_CLOSE(h.height_m, expected.height, tolerance);
    CHECK_CLOSE(h.sin_latitude, expected.sin_latitude, 64 * std::numeric_limits<T>::epsilon());
    // MODEL §12's closed form for d.p < 0, and the satellite's altitude beyond 90 deg.
    const long double closed = beta < 3.14159265358979323846L / 2
                                   ? 7280000 * std::sin(beta) - 6418137
                                   : 7280000.0L - 6418137;
    CHECK_CLOSE(h.height_m, closed, tolerance);
    CHECK(h.meets_surface() == (closed < 0));
    if (closed < 0) CHECK(std::isinf(static_cast<double>(h.spec_height())));
  }
  // Hostile: a non-finite direction, a surface not ok.
  CHECK(conescan::tangent_height_of(s, vec3<T>(T(std::nan("")), T(0), T(1))).state ==
        status::invalid);
  CHECK(conescan::sphere_surface_of(nadir, distance, radius, polar).state == status::invalid);
  CHECK(conescan::sphere_surface_of(vec3<T>(T(0), T(0), T(2)), radius, distance, polar).state ==
        status::invalid);
}

TEST_CASE("the tangent height on the ellipsoid: 0 at MODEL §5's crossings, the reference elsewhere",
          "[physics]") {
  std::mt19937_64 random(7);
  auto uniform = [&](double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(random);
  };
  int checked = 0;
  for (int i = 0; i < 60; ++i) {
    conescan_test::physics_scene_options o;
    o.ellipsoid = true;
    o.roll_deg = uniform(-5, 5);
    o.pitch_deg = uniform(-5, 5);
    o.alpha_deg = uniform(-20, 20);
    o.sigma_deg = uniform(0, 0.5);
    o.phi_a_deg = uniform(-180, 180);
    o.distance_m = uniform(6.9e6, 8e6);
    o.a_m = 6378137 + 40000;
    o.b_m = 6356752.314245 + 40000 - uniform(0, 20000);
    o.centre_shift_m = uniform(-8000, 8000);
    o.polar_x = uniform(-1, 1);
    o.polar_y = uniform(-1, 1);
    o.polar_z = uniform(-1, 1);
    const auto scene = conescan_test::make_physics_scene<double>(o);
    if (scene.geometric.state != status::ok) continue;
    // 0 at the crossings: the tangency g = 0 of MODEL §5 (rounding of the crossings, 1e-13 rad
    // at 2e6 m/rad: 2e-7 m).
    CHECK_CLOSE(scene.height_at(scene.geometric.phi_in).height_m, 0, 1e-6);
    CHECK_CLOSE(scene.height_at(scene.geometric.phi_out).height_m, 0, 1e-6);
    // Elsewhere against the reference's vector form.
    const auto r = scene.reference(0);
    for (int k = 0; k < 8; ++k) {
      const double phi = scene.geometric.phi_in + uniform(-0.3, 0.3);
      const vec3<double> d = scene.line_of_sight(phi);
      const auto expected = conescan_test::reference_height_of(r, vec3l(d.x, d.y, d.z));
      const auto h = conescan::tangent_height_of(scene.ellipsoid, d);
      CHECK_CLOSE(h.height_m, expected.height, 1e-6);
      CHECK_CLOSE(h.sin_latitude, expected.sin_latitude, 1e-13);
    }
    ++checked;
  }
  CHECK(checked > 40);
  // An ellipsoid that is a sphere gives the sphere's heights and latitudes.
  conescan_test::physics_scene_options o;
  o.roll_deg = 2;
  const auto sphere = conescan_test::make_physics_scene<double>(o);
  o.ellipsoid = true;
  const auto round = conescan_test::make_physics_scene<double>(o);
  for (int k = 0; k < 20; ++k) {
    const double phi = -1 + 0.1 * k;
    const auto a = sphere.height_at(phi), b = round.height_at(phi);
    CHECK_CLOSE(a.height_m, b.height_m, 1e-6);
    CHECK_CLOSE(a.sin_latitude, b.sin_latitude, 1e-14);
  }
}

TEMPLATE_TEST_CASE("the limb profile", "[physics]", float, double, long double,
                   conescan_test::adl_real) {
  using T = TestType;
  const long double eps = static_cast<long double>(conescan_test::eps<T>());
  for (int scale_km : {1, 7, 20}) {
    const T scale = T(scale_km * 1000);
    const auto p = conescan::radiance_profile_of(scale, T(40000), T(1));
    REQUIRE(p.state == status::ok);
    // l(delta50) = 1/2.
    CHECK_CLOSE(conescan::limb_fraction(p, T(40000)), 0.5L, 8 * eps);
    // The steepest point and its value 1 - 1/e.
    const T steepest = conescan::steepest_height(p);
    CHECK_CLOSE(steepest, 40000 + scale_km * 1000 * std::log(std::log(2.0L)), 64 * eps * 40000);
    CHECK_CLOSE(conescan::limb_fraction(p, steepest), 1 - std::exp(-1.0L), 64 * eps);
    // The 10-90 % width: ln(ln 10 / ln(10/9)) H = 3.0844 H.
    const T h10 = conescan::fixed_threshold_height(p, T(1) / T(10));
    const T h90 = conescan::fixed_threshold_height(p, T(9) / T(10));
    CHECK_CLOSE((h10 - h90) / scale, std::log(std::log(10.0L) / std::log(10.0L / 9)), 1e4L * eps);
    CHECK_CLOSE(conescan::limb_fraction(p, h10), 0.1L, 1e3L * eps);
    // Saturation far below the knee: exactly 1, no NaN; the tail far above: tiny and positive.
    for (int x : {-5, -40, -1000, -100000}) {
      const T height = T(40000) + T(x) * scale;
      CHECK(conescan::limb_fraction(p, height) == T(1));
      const auto d = conescan::limb_fraction_with_derivatives(p, height);
      CHECK(d.value == T(1));
      CHECK(d.first == T(0));
    }
    const T tail = conescan::limb_fraction(p, T(T(40000) + T(30) * scale));
    CHECK(tail > T(0));
    const long double v = std::log(2.0L) * std::exp(-30.0L);
    CHECK_CLOSE(static_cast<long double>(tail) / (-std::expm1(-v)), 1, 1e4L * eps);
    // Derivatives against central differences (double and wider).
    if (eps < 1e-10L) {
      const long double e = 1e-3L * scale_km * 1000;
      for (int x = -3; x <= 6; ++x) {
        const T height = T(40000) + T(x) * scale;
        const auto d = conescan::limb_fraction_with_derivatives(p, height);
        auto l = [&](long double dh) {
          return static_cast<long double>(conescan::limb_fraction_with_derivatives(
                                              p, T(height + conescan_test::scalar_from<T>(dh)))
                                              .value);
        };
        auto l1 = [&](long double dh) {
          return static_cast<long double>(conescan::limb_fraction_with_derivatives(
                                              p, T(height + conescan_test::scalar_from<T>(dh)))
                                              .first);
        };
        auto l2 = [&](long double dh) {
          return static_cast<long double>(conescan::limb_fraction_with_derivatives(
                                              p, T(height + conescan_test::scalar_from<T>(dh)))
                                              .second);
        };
        const long double s = 1.0L / (scale_km * 1000);
        CHECK_CLOSE(d.first, (l(e) - l(-e)) / (2 * e), 1e-6L * s);
        CHECK_CLOSE(d.second, (l1(e) - l1(-e)) / (2 * e), 1e-6L * s * s);
        CHECK_CLOSE(d.third, (l2(e) - l2(-e)) / (2 * e), 1e-6L * s * s * s);
      }
    }
  }
  // The step edge.
  const auto step = conescan::radiance_profile_of(T(0), T(20000), T(1));
  CHECK(conescan::limb_fraction(step, T(19999)) == T(1));
  CHECK(conescan::limb_fraction(step, T(20000)) == T(1) / T(2));
  CHECK(conescan::limb_fraction(step, T(20001)) == T(0));
  // Hostile parameters.
  CHECK(conescan::radiance_profile_of(T(-1), T(0), T(1)).state == status::invalid);
  CHECK(conescan::radiance_profile_of(T(1), T(0), T(-1)).state == status::invalid);
  CHECK(conescan::radiance_profile_of(
            conescan_test::scalar_from<T>(std::numeric_limits<long double>::infinity()), T(0), T(1))
            .state == status::invalid);
  // The disk below the surface.
  const auto p = conescan::radiance_profile_of(T(7000), T(0), T(13) / T(10));
  CHECK(conescan::radiance(p, T(2), T(-1)) == T(2) * T(13) / T(10));
  CHECK_CLOSE(conescan::radiance(p, T(2), T(0)), 1, 8 * eps);
}

TEST_CASE("the season factor", "[physics]") {
  // L0 = 1 + A sin(phi_t) sin(delta_sun) / sin 23.44 deg: the summer hemisphere brighter.
  const double solstice = std::sin(conescan::deg_to_rad(23.44));
  CHECK(conescan::season_factor(0.2, 1.0, solstice) == Approx(1.2).epsilon(1e-15));
  CHECK(conescan::season_factor(0.2, -1.0, solstice) == Approx(0.8).epsilon(1e-15));
  CHECK(conescan::season_factor(0.2, 0.5, -solstice) == Approx(0.9).epsilon(1e-15));
  CHECK(conescan::season_factor(0.0, 1.0, solstice) == 1.0);
  // A = 0.2 gives the 1.5 pole-to-pole ratio of model atmospheres at solstice.
  CHECK(conescan::season_factor(0.2, 1.0, solstice) /
            conescan::season_factor(0.2, -1.0, solstice) ==
        Approx(1.5));
}

TEST_CASE("the chain's geometry polynomials hold the exact heights", "[physics]") {
  // The windows' heights along their line of sight are Legendre polynomials on panels of 0.2
  // rad (sensor_physics/chain.hpp): the largest error against the exact heights over a window.
  conescan_test::physics_scene_options o;
  o.ellipsoid = true;
  o.roll_deg = 2;
  o.b_m = 6356752.314245 + 40000;
  const auto scene = conescan_test::make_physics_scene<double>(o);
  conescan::sensor_physics_settings<double> s;
  s.field.fov_rad = conescan::deg_to_rad(1.5);
  s.offset_m = 40000;
  s.spin_hz = 1;
  s.tau_s = 1e-3;
  const auto head = conescan::sensor_physics_head_of(s);
  auto work = std::make_unique<conescan::sensor_physics_workspace<double>>();
  REQUIRE(scene.physics(head, 0.0, *work).state == status::ok);
  const auto& w = work->window[0];
  const auto probe = conescan::probe_of(scene.ellipsoid);
  double worst = 0;
  for (int k = 0; k <= 200; ++k) {
    const double phi = w.geometry.start + w.geometry.width * w.geometry.panels * k / 200.0;
    const double exact =
        conescan::exact_height(scene.head.circle(), scene.ellipsoid, probe, phi).height_m;
    worst = std::max(worst, std::abs(w.geometry.height_at(phi) - exact));
  }
  INFO("worst " << worst << " m over " << w.geometry.panels << " panels");
  CHECK(worst < 1e-7);
}
