// The rigid field's mean (include/conescan/sensor_physics/field_mean.hpp, MODEL §12 "Field of
// view") against the brute-force reference's (tests/support/sensor_physics_reference.hpp: an
// iterated Gauss quadrature split at the surface, the step and the knee, long double, no shared
// code), and the chain's crossings continuous in H down to the step.
#include <catch2/catch.hpp>
#include <cmath>
#include <memory>
#include <random>

#include "conescan/sensor_physics.hpp"
#include "support/sensor_physics_scene.hpp"

using conescan::deg_to_rad;
using conescan::field_shape;
using conescan::rad_to_deg;
using conescan::sensor_physics_settings;
using conescan::status;

namespace {

/// The production field mean at phi for a scene and settings.
template <class Surface>
double field_mean(const conescan_test::physics_scene<double>& sc, const Surface& surface,
                  const sensor_physics_settings<double>& s, double sin_sun, double phi) {
  const auto profile = conescan::radiance_profile_of(s.scale_m, s.offset_m, s.disk);
  const double sin_obliquity = std::sin(deg_to_rad(23.44));
  const conescan::field_radiance<double> radiance{&profile, s.plateau,
                                                  s.season_amplitude * sin_sun / sin_obliquity};
  const auto rules = conescan::field_rules_of<double>();
  return conescan::field_mean_at(
      conescan::field_patch_at(sc.head.circle(), surface, s.field, phi, s.season_amplitude != 0),
      radiance, rules);
}

}  // namespace

TEST_CASE("the field's mean: random patches, profiles and Earths against the brute force",
          "[physics][brute-force]") {
  // 24 scenes: sphere or apparent-horizon ellipsoid, square or circle of 0.1 to 2 deg, H from 0
  // (the step) to 10 km (log-uniform from 1 m), delta50 0 to 50 km, a disk 0.5 to 1.5, the
  // season term every third; the mean at the Earth-in crossing and 0.3 field widths either side
  // (the patch across the limb). Measured: within 1.1e-11 of L0 (a crossing: ~1e-11 deg).
  std::mt19937_64 rng(33);
  auto uniform = [&rng](double a, double b) {
    return std::uniform_real_distribution<double>(a, b)(rng);
  };
  double worst = 0;
  for (int t = 0; t < 24; ++t) {
    conescan_test::physics_scene_options o;
    o.alpha_deg = uniform(-10, 10);
    o.gamma_deg = uniform(40, 50);
    o.sigma_deg = uniform(0, 0.3);
    o.phi_a_deg = uniform(-180, 180);
    o.ellipsoid = t % 2 == 1;
    o.b_m = 6356752.314245L + 40000 - (t % 4 == 3 ? 12000 : 0);
    const auto sc = conescan_test::make_physics_scene<double>(o);
    REQUIRE(sc.geometric.state == status::ok);
    sensor_physics_settings<double> s;
    s.field = {deg_to_rad(uniform(0.1, 2)), t % 3 == 1 ? field_shape::circle : field_shape::square};
    s.scale_m = t % 5 == 0 ? 0.0 : std::exp(uniform(std::log(1.0), std::log(10000.0)));
    s.offset_m = uniform(0, 50000);
    s.disk = uniform(0.5, 1.5);
    s.season_amplitude = t % 3 == 2 ? 0.2 : 0.0;
    const double sin_sun = 0.35;
    const auto reference_scene = sc.reference(sin_sun);
    const auto reference_settings = conescan_test::reference_settings_of(s);
    for (double offset : {-0.3, 0.0, 0.3}) {
      const double phi = sc.geometric.phi_in + offset * s.field.fov_rad / 0.7;
      const double fast = o.ellipsoid ? field_mean(sc, sc.ellipsoid, s, sin_sun, phi)
                                      : field_mean(sc, sc.sphere, s, sin_sun, phi);
      const long double brute =
          conescan_test::reference_field_mean(reference_scene, reference_settings, phi);
      INFO("scene " << t << " offset " << offset << " H " << s.scale_m << " fov "
                    << rad_to_deg(s.field.fov_rad));
      CHECK(std::abs(static_cast<long double>(fast) - brute) <= 2e-11L);
      worst =
          std::max(worst, static_cast<double>(std::abs(static_cast<long double>(fast) - brute)));
    }
  }
  WARN("field mean against the reference: worst " << worst << " of L0");
}

TEST_CASE("the chain's crossings are continuous in H down to the step", "[physics]") {
  // A field's crossings move with H by about 0.21 H of height (the profile's mean above its 50 %
  // point, for fields wider than the profile; less for narrower ones): at most 0.25 H / rate
  // between H and the step, and nothing jumps at any scale (MODEL §12: continuous in H). The
  // paper's head at the paper's radius, 0.1 and 2 deg fields, both shapes, no lag.
  conescan_test::physics_scene_options o;
  o.sigma_deg = 0;
  const auto sc = conescan_test::make_physics_scene<double>(o);
  auto work = std::make_unique<conescan::sensor_physics_workspace<double>>();
  const double rate = 2.0e6;  // m of height per rad of scan at the crossing (measured: 2.1e6)
  for (int shape = 0; shape < 2; ++shape)
    for (double fov : {0.1, 2.0}) {
      sensor_physics_settings<double> s;
      s.field = {deg_to_rad(fov), shape == 0 ? field_shape::square : field_shape::circle};
      s.offset_m = 40000;
      s.scale_m = 0;
      const auto step = sc.physics(conescan::sensor_physics_head_of(s), 0.0, *work);
      REQUIRE(step.state == status::ok);
      for (double h : {1e-6, 1e-3, 1.0, 10.0, 100.0, 1000.0, 10000.0}) {
        s.scale_m = h;
        const auto c = sc.physics(conescan::sensor_physics_head_of(s), 0.0, *work);
        INFO("fov " << fov << " shape " << shape << " H " << h << ": in "
                    << (c.phi_in - step.phi_in) << " out " << (c.phi_out - step.phi_out)
                    << " rad, bound " << 0.25 * h / rate);
        REQUIRE(c.state == status::ok);
        CHECK(std::abs(c.phi_in - step.phi_in) <= 0.25 * h / rate + 1e-13);
        CHECK(std::abs(c.phi_out - step.phi_out) <= 0.25 * h / rate + 1e-13);
      }
    }
}

TEST_CASE("an aligned head's phase stays 0 with a small field on a sharp limb", "[physics]") {
  // conescan-sim --model scan --a-km 7280 --e 0.1 --m0-deg 200 --horizon-km 40
  // --radiance-scale-km 0.001 --head alpha=0,beta=90,sigma=0,fov=0.1: the sector field's 32 lines
  // gave a phase of -0.0032 deg; a symmetric scene's crossings are symmetric.
  conescan_test::physics_scene_options o;
  o.sigma_deg = 0;
  o.distance_m = 7971541.760651037L;
  const auto sc = conescan_test::make_physics_scene<double>(o);
  auto work = std::make_unique<conescan::sensor_physics_workspace<double>>();
  for (double h : {0.0, 1.0, 10.0, 7000.0})
    for (int shape = 0; shape < 2; ++shape) {
      sensor_physics_settings<double> s;
      s.field = {deg_to_rad(0.1), shape == 0 ? field_shape::square : field_shape::circle};
      s.scale_m = h;
      const auto c = sc.physics(conescan::sensor_physics_head_of(s), 0.0, *work);
      INFO("H " << h << " shape " << shape);
      REQUIRE(c.state == status::ok);
      CHECK(std::abs(rad_to_deg(c.phase())) <= 1e-11);
    }
}
