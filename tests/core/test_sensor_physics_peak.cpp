// The normalised locator's peak where the season term brightens the disk along the scan (MODEL
// §12: the level is a fraction of the output's largest value anywhere). The output can peak at
// the end of a window's samples, or beyond them on the disk's side: past the Earth-in window's
// last sample, or in the Earth-out window's lag history before its first (chain.hpp,
// keep_disk_side_peak). Before the fix the chain took the largest sample there for the peak: on
// the benchmark's orbit, at true anomalies 120-122 and 308-316 deg, the level was low and the
// crossings up to 2.5e-4 deg off the reference under ok (a dense search of the chain's own output
// found the peak the reference has, to 1e-10, on every row of seven variants of the scene).
//  - [physics][brute-force]: two of those rows against the reference, square and circle.
#include <catch2/catch.hpp>

#include "conescan/sensor_physics.hpp"
#include "support/sensor_physics_compare.hpp"
#include "support/sensor_physics_scene.hpp"

using conescan::field_shape;
using conescan_test::benchmark_physics;
using conescan_test::benchmark_row;

TEST_CASE("the normalised locator's peak beyond the samples, against the reference",
          "[physics][brute-force]") {
  // Measured with the fix (h = 0.02 deg): row 122 within 1.6e-10 deg, row 312 within 5.7e-10 deg
  // (before: 1.45e-4 and 2.5e-4 deg).
  SECTION("the Earth-in window's end, 122 deg") {
    conescan_test::compare_with_reference(benchmark_row(122),
                                          benchmark_physics(field_shape::square),
                                          conescan_test::benchmark_sin_sun, 0.02, 1e-6);
  }
  SECTION("312 deg, a circle") {
    conescan_test::compare_with_reference(benchmark_row(312),
                                          benchmark_physics(field_shape::circle),
                                          conescan_test::benchmark_sin_sun, 0.02, 1e-6);
  }
}
