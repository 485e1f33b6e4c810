// conescan-sensor-physics-scan: a random scan of MODEL §12's chain against the brute-force
// reference (tests/support/sensor_physics_reference.hpp), one row per scene, over the whole of
// the sensor physics at once. Each scene draws, in a fixed order from its seed:
//  - a head misaligned within 5 deg (cone 42 to 50 deg, sigma to 0.5 deg) at an attitude within
//    3 deg, 6900 to 8000 km from the centre; the sphere, WGS84's inflated ellipsoid or a
//    flattened, shifted apparent horizon (scene i % 3), 0 to 60 km up; with --any-altitude 1,
//    6600 to 42 200 km from the centre (log-uniform: 220 km up to beyond the geostationary
//    orbit) and the cone 90 deg - f rho, f from 0.2 to 0.8 of the Earth's angular radius rho
//    (the same number of draws: a seed's other draws are the same in both families);
//  - a pencil, or a square or circle of 0.05 to 2.5 deg; 0.2 to 5 rev/s with no lag (three
//    scenes in ten) or up to 4 ms;
//  - each locator (the normalised threshold 0.2 to 0.8, the fixed 0.1 to 0.7, the slope);
//  - H: the step (15 %) or 1 m to 60 km, log-uniform; delta50 to 80 km; a disk 0.6 to 1.4 L0;
//  - the season term on two scenes in three (|A| <= 0.4, sin of the Sun's declination <= 0.4).
// It prints each scene, both statuses and the crossings' differences in degrees, and a summary;
// it exits 1 where a crossing is off by more than the tolerance or the statuses differ. Not
// compared: a scene whose geometric crossings are not ok, and a square on a step with the slope
// locator and no lag (its slope is flat-topped: outside the reference's domain).
// The reference takes seconds to a minute a scene: this is the nightly job of
// docs/SENSOR_PHYSICS.md ("A random scan against the reference"), not a ctest.
//
// Usage: conescan-sensor-physics-scan [--seed S] [--scenes N] [--first F] [--only I]
//                                     [--tolerance-deg T] [--any-altitude 0|1] [--grid-deg G]
//                                     [--chain-only 0|1]
// Defaults: seed 1, scenes 0 to 49, every one of them, T = 1e-6 deg, the low orbits, the
// reference's grid 0.005 deg for a pencil and 0.01 deg with a field (G replaces it: a finer grid
// tells the reference's own error from the chain's). With --only,
// the scene's every parameter to 17 digits as well, to make it a regression test. --chain-only 1
// prints the chain's crossings to 13 digits and skips the reference: two builds' outputs, diffed,
// show which scenes a change of the chain moves (only those need the reference).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <random>

#include "bench_options.hpp"
#include "conescan/sensor_physics.hpp"
#include "support/sensor_physics_scene.hpp"

using namespace conescan;

namespace {

struct options {
  unsigned long seed = 1;
  int scenes = 50;
  int first = 0;
  int only = -1;
  double tolerance_deg = 1e-6;
  bool any_altitude = false;
  double grid_deg = 0;  // the reference's grid; 0: its default for the scene
  bool chain_only = false;
};

options parse(int argc, char** argv) {
  const char* usage =
      "[--seed S] [--scenes N] [--first F] [--only I] [--tolerance-deg T] [--any-altitude 0|1] "
      "[--grid-deg G] [--chain-only 0|1]";
  options o;
  for (int i = 1; i < argc; ++i) {
    if (i + 1 >= argc) bench::exit_with_usage(argv[0], usage);
    char* end = nullptr;
    const char* name = argv[i];
    const char* value = argv[++i];
    const double v = std::strtod(value, &end);
    if (end == value || *end != '\0' || !std::isfinite(v) || v < 0)
      bench::exit_with_usage(argv[0], usage);
    if (!std::strcmp(name, "--seed"))
      o.seed = static_cast<unsigned long>(v);
    else if (!std::strcmp(name, "--scenes"))
      o.scenes = static_cast<int>(v);
    else if (!std::strcmp(name, "--first"))
      o.first = static_cast<int>(v);
    else if (!std::strcmp(name, "--only"))
      o.only = static_cast<int>(v);
    else if (!std::strcmp(name, "--tolerance-deg"))
      o.tolerance_deg = v;
    else if (!std::strcmp(name, "--grid-deg") && v > 0)
      o.grid_deg = v;
    else if (!std::strcmp(name, "--any-altitude") && (v == 0 || v == 1))
      o.any_altitude = v == 1;
    else if (!std::strcmp(name, "--chain-only") && (v == 0 || v == 1))
      o.chain_only = v == 1;
    else
      bench::exit_with_usage(argv[0], usage);
  }
  return o;
}

struct scene_draw {
  conescan_test::physics_scene_options geometry;
  sensor_physics_settings<double> physics;
  double sin_sun = 0;
};

template <class Uniform>
conescan_test::physics_scene_options random_geometry(Uniform& uniform, int i, bool any_altitude) {
  conescan_test::physics_scene_options o;
  o.alpha_deg = uniform(-5, 5);
  o.beta_deg = uniform(-180, 180);
  const double cone_draw = any_altitude ? uniform(0.2, 0.8) : uniform(42, 50);
  o.sigma_deg = uniform(0, 0.5);
  o.phi_a_deg = uniform(-180, 180);
  o.roll_deg = uniform(-3, 3);
  o.pitch_deg = uniform(-3, 3);
  o.distance_m =
      any_altitude ? std::exp(uniform(std::log(6.6e6), std::log(4.22e7))) : uniform(6.9e6, 8.0e6);
  const double horizon_m = uniform(0, 60000);
  // The cone where the scan crosses the disk: 90 deg less a share of the Earth's angular radius.
  o.gamma_deg =
      any_altitude
          ? 90 - cone_draw * rad_to_deg(std::asin(6378137.0 / static_cast<double>(o.distance_m)))
          : cone_draw;
  const bool apparent = i % 3 == 2;
  o.ellipsoid = i % 3 != 0;
  o.a_m = 6378137.0 + horizon_m;
  o.b_m = 6356752.314245 + horizon_m - (apparent ? uniform(0, 20000) : 0);
  o.centre_shift_m = apparent ? uniform(-8000, 8000) : 0;
  o.polar_x = uniform(-1, 1);
  o.polar_y = uniform(-1, 1);
  o.polar_z = uniform(-1, 1);
  return o;
}

template <class Uniform>
scene_draw random_scene(Uniform& uniform, int i, bool any_altitude) {
  scene_draw d;
  d.geometry = random_geometry(uniform, i, any_altitude);
  sensor_physics_settings<double>& s = d.physics;
  const int field = static_cast<int>(uniform(0, 3));  // pencil, square, circle
  s.field = {field == 0 ? 0.0 : deg_to_rad(uniform(0.05, 2.5)),
             field == 2 ? field_shape::circle : field_shape::square};
  s.spin_hz = uniform(0.2, 5);
  s.tau_s = uniform(0, 1) < 0.3 ? 0.0 : uniform(0, 4e-3);
  const int locator = static_cast<int>(uniform(0, 3));
  s.locator = locator == 0   ? horizon_locator<double>{locator_kind::normalised, uniform(0.2, 0.8)}
              : locator == 1 ? horizon_locator<double>{locator_kind::fixed, uniform(0.1, 0.7)}
                             : horizon_locator<double>{locator_kind::slope, 0.5};
  const double step = uniform(0, 1);
  s.scale_m = step < 0.15 ? 0.0 : std::exp(uniform(0, std::log(60000.0)));
  s.offset_m = uniform(0, 80000);
  s.disk = uniform(0.6, 1.4);
  const bool season = uniform(0, 1) < 0.67;
  s.season_amplitude = season ? uniform(-0.4, 0.4) : 0.0;
  d.sin_sun = uniform(-0.4, 0.4);
  return d;
}

// The scene option's words (src/scene/head_spec.cpp), for the record only.
const char* locator_word(locator_kind kind) {
  return kind == locator_kind::normalised ? "normalised"
         : kind == locator_kind::fixed    ? "fixed"
                                          : "slope";
}

void print_scene(int i, const scene_draw& d) {
  const sensor_physics_settings<double>& s = d.physics;
  std::printf(
      "scene %d: fov %.4g deg %s, %.4g rev/s, tau %.4g ms, %s %.4g, H %.5g m, delta50 %.5g m, "
      "disk %.4g, A %.4g, sin_sun %.3g, %s, %.0f km from the centre, cone %.4g deg\n",
      i, rad_to_deg(s.field.fov_rad), s.field.shape == field_shape::circle ? "circle" : "square",
      s.spin_hz, s.tau_s * 1e3, locator_word(s.locator.kind), s.locator.threshold, s.scale_m,
      s.offset_m, s.disk, s.season_amplitude, d.sin_sun,
      !d.geometry.ellipsoid            ? "sphere"
      : d.geometry.centre_shift_m != 0 ? "apparent"
                                       : "ellipsoid",
      static_cast<double>(d.geometry.distance_m) / 1000, static_cast<double>(d.geometry.gamma_deg));
}

/// A scene's every parameter to 17 digits, as a regression test's options
/// (tests/core/test_sensor_physics_reference.cpp): printed for --only.
void print_scene_exactly(const scene_draw& d) {
  const conescan_test::physics_scene_options& o = d.geometry;
  const sensor_physics_settings<double>& s = d.physics;
  std::printf(
      "  head: alpha %.17g, beta %.17g, gamma %.17g, sigma %.17g, phi_a %.17g deg; roll %.17g, "
      "pitch %.17g deg; distance %.17g m\n",
      static_cast<double>(o.alpha_deg), static_cast<double>(o.beta_deg),
      static_cast<double>(o.gamma_deg), static_cast<double>(o.sigma_deg),
      static_cast<double>(o.phi_a_deg), static_cast<double>(o.roll_deg),
      static_cast<double>(o.pitch_deg), static_cast<double>(o.distance_m));
  std::printf(
      "  earth: ellipsoid %d, a %.17g m, b %.17g m, centre shift %.17g m, polar (%.17g, %.17g, "
      "%.17g)\n",
      o.ellipsoid ? 1 : 0, static_cast<double>(o.a_m), static_cast<double>(o.b_m),
      static_cast<double>(o.centre_shift_m), static_cast<double>(o.polar_x),
      static_cast<double>(o.polar_y), static_cast<double>(o.polar_z));
  std::printf(
      "  physics: fov %.17g deg, %.17g rev/s, tau %.17g s, threshold %.17g, H %.17g m, delta50 "
      "%.17g m, disk %.17g, A %.17g, sin_sun %.17g\n",
      rad_to_deg(s.field.fov_rad), s.spin_hz, s.tau_s, s.locator.threshold, s.scale_m, s.offset_m,
      s.disk, s.season_amplitude, d.sin_sun);
}

enum class verdict { agree, beyond_tolerance, statuses_differ, not_compared };

/// One scene's chain against the reference; prints the comparison.
verdict compare_scene(const scene_draw& d, const options& o,
                      sensor_physics_workspace<double>& work) {
  const double tolerance_deg = o.tolerance_deg;
  const sensor_physics_settings<double>& s = d.physics;
  if (s.field.fov_rad > 0 && s.field.shape == field_shape::square && s.scale_m == 0 &&
      s.tau_s == 0 && s.locator.kind == locator_kind::slope) {
    std::printf("  a square on a step, its slope flat-topped: outside the reference's domain\n");
    return verdict::not_compared;
  }
  const auto scene = conescan_test::make_physics_scene<double>(d.geometry);
  if (scene.geometric.state != status::ok) {
    std::printf("  geometric %s: not compared\n", to_string(scene.geometric.state));
    return verdict::not_compared;
  }
  using clock = std::chrono::steady_clock;
  const auto t0 = clock::now();
  const auto chain = scene.physics(sensor_physics_head_of(s), d.sin_sun, work);
  const auto t1 = clock::now();
  if (o.chain_only) {
    std::printf("  chain %s (%.1f ms): in %.13f deg, out %.13f deg\n", to_string(chain.state),
                std::chrono::duration<double, std::milli>(t1 - t0).count(),
                rad_to_deg(chain.phi_in), rad_to_deg(chain.phi_out));
    return verdict::not_compared;
  }
  // The reference's grid: 0.005 deg for a pencil's sharper signal, 0.01 deg with a field (its own
  // error ~1e-7 deg at these steps; tests/core/test_sensor_physics_reference.cpp).
  const double h_deg = o.grid_deg > 0 ? o.grid_deg : s.field.fov_rad == 0 ? 0.005 : 0.01;
  const auto reference = conescan_test::reference_crossings_of(scene, s, d.sin_sun, h_deg);
  const auto t2 = clock::now();
  std::printf("  chain %s (%.1f ms), reference %s (%.1f s)\n", to_string(chain.state),
              std::chrono::duration<double, std::milli>(t1 - t0).count(),
              to_string(reference.crossings.state), std::chrono::duration<double>(t2 - t1).count());
  if (o.only >= 0 && reference.crossings.state == status::ok)  // a test's reference values
    std::printf("  reference: in %.13Lf deg, out %.13Lf deg, peak %.9Lf\n",
                rad_to_deg(reference.crossings.phi_in), rad_to_deg(reference.crossings.phi_out),
                reference.peak);
  if (chain.state != reference.crossings.state) return verdict::statuses_differ;
  if (chain.state != status::ok) return verdict::agree;
  // Differences of azimuths, a turn apart taken as the same: over a disk darker than a broad
  // limb the rising crossing is the far edge's, which the chain writes a turn on from the
  // reference (in + chord).
  auto turn_difference = [](double a_rad, long double b_rad) {
    const double apart_deg = rad_to_deg(a_rad - static_cast<double>(b_rad));
    return apart_deg - 360 * std::round(apart_deg / 360);
  };
  const double d_in = turn_difference(chain.phi_in, reference.crossings.phi_in);
  const double d_out = turn_difference(chain.phi_out, reference.crossings.phi_out);
  const bool within = std::fabs(d_in) <= tolerance_deg && std::fabs(d_out) <= tolerance_deg;
  std::printf("  chain - reference: in %.3g deg, out %.3g deg%s\n", d_in, d_out,
              within ? "" : "  BEYOND TOLERANCE");
  return within ? verdict::agree : verdict::beyond_tolerance;
}

}  // namespace

int main(int argc, char** argv) {
  const options o = parse(argc, argv);
  std::mt19937_64 rng(o.seed);
  auto uniform = [&rng](double a, double b) {
    return std::uniform_real_distribution<double>(a, b)(rng);
  };
  auto work = std::make_unique<sensor_physics_workspace<double>>();
  int counts[4] = {0, 0, 0, 0};
  for (int i = 0; i < o.scenes; ++i) {
    const scene_draw d =
        random_scene(uniform, i, o.any_altitude);  // drawn for every i: a scene keeps its seed
    if (i < o.first || (o.only >= 0 && i != o.only)) continue;
    print_scene(i, d);
    if (o.only >= 0) print_scene_exactly(d);
    ++counts[static_cast<int>(compare_scene(d, o, *work))];
    std::fflush(stdout);
  }
  std::printf(
      "seed %lu: %d agree within %.3g deg, %d beyond it, %d statuses differ, %d not compared\n",
      o.seed, counts[0], o.tolerance_deg, counts[1], counts[2], counts[3]);
  return counts[1] + counts[2] > 0 ? 1 : 0;
}
