// One row of the sensor physics' chain against the brute-force reference
// (sensor_physics_reference.hpp), for the Catch2 tests: both crossings within a tolerance, the
// differences printed for the record.
#pragma once

#include <catch2/catch.hpp>
#include <memory>

#include "support/approx.hpp"
#include "support/sensor_physics_scene.hpp"

namespace conescan_test {

/// The chain's crossings of scene o with settings s against the reference's (grid step h_deg),
/// in degrees: each within tolerance_deg.
inline void compare_with_reference(const physics_scene_options& o,
                                   const conescan::sensor_physics_settings<double>& s,
                                   double sin_sun, double h_deg, double tolerance_deg) {
  const auto scene = make_physics_scene<double>(o);
  REQUIRE(scene.geometric.state == conescan::status::ok);
  auto work = std::make_unique<conescan::sensor_physics_workspace<double>>();
  const auto chain = scene.physics(conescan::sensor_physics_head_of(s), sin_sun, *work);
  REQUIRE(chain.state == conescan::status::ok);
  const auto reference = reference_crossings_of(scene, s, sin_sun, h_deg);
  REQUIRE(reference.crossings.state == conescan::status::ok);
  const long double to_deg = 180 / 3.14159265358979323846264338327950288L;
  const long double d_in = (chain.phi_in - reference.crossings.phi_in) * to_deg;
  const long double d_out = (chain.phi_out - reference.crossings.phi_out) * to_deg;
  INFO("chain - reference: in " << static_cast<double>(d_in) << " deg, out "
                                << static_cast<double>(d_out) << " deg");
  WARN("chain - reference: in " << static_cast<double>(d_in) << " out "
                                << static_cast<double>(d_out) << " deg");
  CHECK_WITHIN(d_in, 0.0L, static_cast<long double>(tolerance_deg));
  CHECK_WITHIN(d_out, 0.0L, static_cast<long double>(tolerance_deg));
}

}  // namespace conescan_test
