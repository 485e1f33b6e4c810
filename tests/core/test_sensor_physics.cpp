// The sensor physics chain (include/conescan/sensor_physics.hpp, MODEL §12) against the closed
// forms and reductions of MODEL §12:
//  - pencil beam, no lag, normalised 1/2, delta50 = 0: MODEL §5's crossings to 1e-9 deg for any
//    H, plateau and L_disk >= 1, on the sphere, the inflated ellipsoid and the apparent horizon
//    (float, double, long double); for L_disk < 1 the crossing sits at the closed-form height
//    H ln(ln 2 / -ln(1 - L_disk/2)), both sides of L_disk = 1 (docs/SENSOR_PHYSICS.md, Decisions);
//  - a step edge with lag: both crossings late by omega tau ln 2 at k = 1/2 (0.249533 deg at 1
//    rev/s and 1 ms), the chord changed by omega tau ln((1 - k)/k) otherwise;
//  - the fixed threshold's height delta50 + H ln(ln 2 / -ln(1 - T/L0));
//  - normalised and slope crossings unmoved by the radiance's scale; the slope locator where y''
//    = 0 on the exact pencil signal, and at delta50 - 0.36651 H on a uniform sweep;
//  - the statuses: a field wider than the chord, a threshold never reached, hostile settings;
//  - 300 random scenes in the reduction settings equal the geometry to 1e-9 deg.
// The chain against the brute-force reference: tests/core/test_sensor_physics_reference.cpp.
#include <catch2/catch.hpp>
#include <cmath>
#include <memory>
#include <random>

#include "conescan/sensor_physics.hpp"
#include "support/adl_scalar.hpp"
#include "support/approx.hpp"
#include "support/sensor_physics_compare.hpp"
#include "support/sensor_physics_scene.hpp"

using conescan::crossings;
using conescan::field_shape;
using conescan::locator_kind;
using conescan::sensor_physics_head_of;
using conescan::sensor_physics_settings;
using conescan::sensor_physics_workspace;
using conescan::status;
using conescan_test::make_physics_scene;
using conescan_test::physics_scene_options;
using conescan_test::random_reduction_scene;

/// CHECK_WITHIN with every argument in long double (the quantities mix scalar types).
#define CHECK_CLOSE(actual, expected, tolerance)                                     \
  CHECK_WITHIN(static_cast<long double>(actual), static_cast<long double>(expected), \
               static_cast<long double>(tolerance))

namespace {

template <class T>
long double in_degrees(const T& rad) {
  return static_cast<long double>(rad) * 180 / 3.14159265358979323846264338327950288L;
}

template <class T>
std::unique_ptr<sensor_physics_workspace<T>> workspace() {
  return std::make_unique<sensor_physics_workspace<T>>();
}

/// The reduction settings: pencil beam, no lag, normalised 1/2, delta50 = 0.
template <class T>
sensor_physics_settings<T> reduction_settings(long double scale_m, long double plateau,
                                              long double disk) {
  sensor_physics_settings<T> s;
  s.scale_m = conescan_test::scene_value<T>(scale_m);
  s.plateau = conescan_test::scene_value<T>(plateau);
  s.disk = conescan_test::scene_value<T>(disk);
  s.offset_m = T(0);
  return s;
}

/// The scenes the reductions run on: the paper's head on a sphere, a rolled head with a
/// misalignment at phi_A = 60 deg on the inflated WGS84 ellipsoid, and the same on an apparent
/// horizon (polar radius 12 km lower, centre 4 km off along the pole).
std::vector<physics_scene_options> reduction_scenes() {
  std::vector<physics_scene_options> scenes(3);
  scenes[1].ellipsoid = scenes[2].ellipsoid = true;
  scenes[1].b_m = scenes[2].b_m = 6356752.314245L + 40000;
  scenes[1].roll_deg = scenes[2].roll_deg = 3;
  scenes[1].pitch_deg = scenes[2].pitch_deg = -2;
  scenes[1].sigma_deg = scenes[2].sigma_deg = 0.3L;
  scenes[1].phi_a_deg = scenes[2].phi_a_deg = 60;
  scenes[1].alpha_deg = scenes[2].alpha_deg = 15;
  scenes[2].b_m -= 12000;
  scenes[2].centre_shift_m = 4000;
  return scenes;
}

}  // namespace

TEMPLATE_TEST_CASE("pencil, no lag, normalised 1/2, delta50 = 0 is MODEL §5's geometry",
                   "[physics]", float, double, long double, conescan_test::adl_real) {
  using T = TestType;
  // float: the tangent height keeps a few ulp of R (0.5 m), 1.4e-5 deg of azimuth; the
  // geometric crossings in float carry the same.
  const long double tolerance_deg = std::is_same_v<T, float> ? 2e-4L : 1e-9L;
  auto work = workspace<T>();
  for (const physics_scene_options& o : reduction_scenes()) {
    const auto scene = make_physics_scene<T>(o);
    REQUIRE(scene.geometric.state == status::ok);
    for (long double scale : {1000.0L, 7000.0L, 20000.0L})
      for (long double plateau : {0.5L, 1.0L, 3.0L})
        for (long double disk : {1.0L, 1.5L}) {
          const auto head = sensor_physics_head_of(reduction_settings<T>(scale, plateau, disk));
          const crossings<T> c = scene.physics(head, T(0), *work);
          INFO("ellipsoid " << o.ellipsoid << " H " << scale << " L0 " << plateau << " L_disk "
                            << disk);
          REQUIRE(c.state == status::ok);
          CHECK_CLOSE(in_degrees(c.phi_in), in_degrees(scene.geometric.phi_in), tolerance_deg);
          CHECK_CLOSE(in_degrees(c.phi_out), in_degrees(scene.geometric.phi_out), tolerance_deg);
        }
  }
}

TEST_CASE("a disk dimmer than the limb's plateau moves the normalised crossing to its height",
          "[physics]") {
  // Decision (docs/SENSOR_PHYSICS.md): the peak is the pulse's true peak. With delta50 = 0 the
  // sky side reaches L0/2 at the surface and the disk is L_disk L0: for L_disk >= 1 the level
  // L_disk L0 / 2 >= L0/2 is passed in the surface's jump (the geometry); for 1/2 <= L_disk < 1
  // it is passed on the sky side, where l = L_disk / 2.
  auto work = workspace<double>();
  for (const physics_scene_options& o : reduction_scenes()) {
    const auto scene = make_physics_scene<double>(o);
    for (double disk : {0.5, 0.8, 0.999999, 1.0, 1.000001}) {
      const auto head = sensor_physics_head_of(reduction_settings<double>(7000, 1, disk));
      const crossings<double> c = scene.physics(head, 0.0, *work);
      REQUIRE(c.state == status::ok);
      const double expected =
          disk >= 1 ? 0.0 : 7000 * std::log(std::log(2.0) / -std::log1p(-disk / 2));
      INFO("ellipsoid " << o.ellipsoid << " L_disk " << disk << " expected height " << expected);
      // Heights at the crossings, 1e-6 m: 3e-11 rad of azimuth at 2e6 m/rad.
      CHECK_CLOSE(scene.height_at(c.phi_in).height_m, expected, 1e-6);
      CHECK_CLOSE(scene.height_at(c.phi_out).height_m, expected, 1e-6);
      if (disk >= 1) {
        CHECK_CLOSE(c.phi_in, scene.geometric.phi_in, 1e-11);
        CHECK_CLOSE(c.phi_out, scene.geometric.phi_out, 1e-11);
      }
    }
  }
}

TEST_CASE("the fixed threshold detects delta50 + H ln(ln 2 / -ln(1 - T/L0))", "[physics]") {
  auto work = workspace<double>();
  for (const physics_scene_options& o : reduction_scenes()) {
    const auto scene = make_physics_scene<double>(o);
    for (double threshold : {0.1, 0.3, 0.5, 0.9})
      for (double offset : {0.0, 25000.0, 40000.0}) {
        sensor_physics_settings<double> s;
        s.locator = {locator_kind::fixed, threshold};
        s.offset_m = offset;
        const auto head = sensor_physics_head_of(s);
        const crossings<double> c = scene.physics(head, 0.0, *work);
        const double expected = offset + 7000 * std::log(std::log(2.0) / -std::log1p(-threshold));
        INFO("ellipsoid " << o.ellipsoid << " T " << threshold << " delta50 " << offset);
        if (expected < 0) {
          // The sky side never reaches T above the surface: it is passed in the jump.
          REQUIRE(c.state == status::ok);
          CHECK_CLOSE(c.phi_in, scene.geometric.phi_in, 1e-11);
          continue;
        }
        REQUIRE(c.state == status::ok);
        CHECK_CLOSE(scene.height_at(c.phi_in).height_m, expected, 1e-6);
        CHECK_CLOSE(scene.height_at(c.phi_out).height_m, expected, 1e-6);
        CHECK(conescan::fixed_threshold_height(head.profile, threshold) == Approx(expected));
      }
  }
}

TEST_CASE("a step edge with lag delays both crossings by omega tau ln(1/(1-k)), ln(1/k)",
          "[physics]") {
  // A step profile at the surface (H = 0, delta50 = 0): the pencil signal is 0 in space and
  // L_disk L0 on the disk, so y = P (1 - e^{-(phi - phi_in)/Lambda}) after Earth-in and
  // P e^{-(phi - phi_out)/Lambda} after Earth-out: the level k P is passed Lambda ln(1/(1-k))
  // and Lambda ln(1/k) late. At 1 rev/s and 1 ms, Lambda = 0.36 deg; at k = 1/2 both crossings
  // are late by 0.36 ln 2 = 0.249533 deg: the chord unchanged, the phase shifted.
  auto work = workspace<double>();
  const double lambda_deg = 0.36;
  CHECK(lambda_deg * std::log(2.0) == Approx(0.249533).epsilon(1e-6));
  for (const physics_scene_options& o : reduction_scenes()) {
    const auto scene = make_physics_scene<double>(o);
    for (double k : {0.5, 0.1, 0.3, 0.9}) {
      sensor_physics_settings<double> s;
      s.scale_m = 0;
      s.offset_m = 0;
      s.spin_hz = 1;
      s.tau_s = 1e-3;
      s.locator = {locator_kind::normalised, k};
      const crossings<double> c = scene.physics(sensor_physics_head_of(s), 0.0, *work);
      REQUIRE(c.state == status::ok);
      INFO("ellipsoid " << o.ellipsoid << " k " << k);
      CHECK_CLOSE(in_degrees(c.phi_in - scene.geometric.phi_in), lambda_deg * std::log(1 / (1 - k)),
                  1e-9);
      CHECK_CLOSE(in_degrees(c.phi_out - scene.geometric.phi_out), lambda_deg * std::log(1 / k),
                  1e-9);
      CHECK_CLOSE(in_degrees(c.chord() - scene.geometric.chord()),
                  lambda_deg * std::log((1 - k) / k), 1e-9);
      if (k == 0.5) CHECK_CLOSE(in_degrees(c.phase() - scene.geometric.phase()), 0.249533, 1e-6);
    }
  }
}

TEST_CASE("normalised and slope crossings do not move when the radiance is scaled", "[physics]") {
  auto work = workspace<double>();
  physics_scene_options o;
  const auto scene = make_physics_scene<double>(o);
  for (locator_kind kind : {locator_kind::normalised, locator_kind::slope})
    for (double fov : {0.0, 1.0}) {
      sensor_physics_settings<double> s;
      s.field.fov_rad = conescan::deg_to_rad(fov);
      s.spin_hz = 1;
      s.tau_s = 1e-3;
      s.offset_m = 40000;
      s.disk = 0.8;  // a jump at the surface: its terms scale too
      s.locator = {kind, 0.5};
      const crossings<double> base = scene.physics(sensor_physics_head_of(s), 0.0, *work);
      REQUIRE(base.state == status::ok);
      for (double plateau : {0.25, 3.7}) {
        s.plateau = plateau;
        const crossings<double> c = scene.physics(sensor_physics_head_of(s), 0.0, *work);
        INFO("slope " << (kind == locator_kind::slope) << " fov " << fov << " L0 " << plateau);
        REQUIRE(c.state == status::ok);
        // The slope locator's extremum is the root of y'', whose rounding leaves ~1e-8 deg
        // (docs/SENSOR_PHYSICS.md); the normalised crossing moves by rounding only.
        const double tolerance = kind == locator_kind::slope ? 1e-7 : 1e-10;
        CHECK_CLOSE(in_degrees(c.phi_in), in_degrees(base.phi_in), tolerance);
        CHECK_CLOSE(in_degrees(c.phi_out), in_degrees(base.phi_out), tolerance);
      }
    }
}

namespace {

/// A pencil swept at a uniform rate: y = l(delta) with delta = -rate phi (heights falling).
struct uniform_sweep {
  conescan::radiance_profile<double> profile;
  double rate_m_per_rad;
  conescan::lag_point<double> at(double phi) const {
    const auto d = conescan::limb_fraction_with_derivatives(profile, -rate_m_per_rad * phi);
    return {d.value, -rate_m_per_rad * d.first};
  }
};

}  // namespace

TEST_CASE("the slope locator sits at delta50 + H ln ln 2 on a uniform sweep", "[physics]") {
  // MODEL §12: delta50 + H ln(ln 2) = delta50 - 0.36651 H, where l = 1 - 1/e.
  for (double scale : {2000.0, 7000.0})
    for (double offset : {0.0, 40000.0}) {
      const uniform_sweep sweep{conescan::radiance_profile_of(scale, offset, 1.0), 2.0e6};
      std::vector<double> phi;
      for (int i = 0; i <= 400; ++i) phi.push_back(-0.05 + 0.1 * i / 400);
      const conescan::result<double> found =
          conescan::steepest_crossing(sweep, phi.data(), static_cast<int>(phi.size()), 1);
      REQUIRE(found.ok());
      const double height = -2.0e6 * found.value;
      CHECK_CLOSE(height, offset - 0.36651292058 * scale, 1e-3);
      CHECK_CLOSE(conescan::steepest_height(sweep.profile), offset - 0.36651292058 * scale, 1e-6);
      CHECK(conescan::limb_fraction(sweep.profile, conescan::steepest_height(sweep.profile)) ==
            Approx(1 - std::exp(-1.0)).epsilon(1e-14));
    }
}

TEST_CASE("the slope locator on the scan is where the exact pencil signal's slope peaks",
          "[physics]") {
  // On a real scan the rate of height change varies across the profile, so the extremum of
  // dy/dphi differs from delta50 - 0.36651 H by a few tens of metres (MODEL §12: 0.04 km on the
  // paper's orbit). The chain's slope crossing without lag is checked against the extremum of
  // the exact pencil signal l(delta(phi)), delta from tangent_height_of, found independently by a
  // dense search and parabolic refinement of finite differences.
  auto work = workspace<double>();
  const auto scene = make_physics_scene<double>(physics_scene_options{});
  sensor_physics_settings<double> s;
  s.offset_m = 40000;
  s.locator = {locator_kind::slope, 0.5};
  const auto head = sensor_physics_head_of(s);
  const crossings<double> c = scene.physics(head, 0.0, *work);
  REQUIRE(c.state == status::ok);
  auto signal = [&](double phi) {
    return conescan::limb_fraction(head.profile, scene.height_at(phi).height_m);
  };
  // The extremum of the slope is a root of the second derivative (a flat maximum would be
  // found only to the square root of the rounding): five-point differences, O(e^4), e = 1e-5
  // rad, and bisection on their sign near the chain's crossing.
  auto second = [&](double phi) {
    const double e = 1e-5;
    return (-signal(phi + 2 * e) + 16 * signal(phi + e) - 30 * signal(phi) + 16 * signal(phi - e) -
            signal(phi - 2 * e)) /
           (12 * e * e);
  };
  double lo = c.phi_in - 2e-3, hi = c.phi_in + 2e-3;
  // The rising crossing: the slope grows before it (second derivative > 0) and falls after.
  REQUIRE(second(lo) > 0);
  REQUIRE(second(hi) < 0);
  for (int i = 0; i < 60; ++i) {
    const double m = (lo + hi) / 2;
    if (second(m) > 0)
      lo = m;
    else
      hi = m;
  }
  CHECK_CLOSE(in_degrees(c.phi_in), in_degrees((lo + hi) / 2), 1e-8);
  // Its height: delta50 - 0.36651 H plus the rate's change across the profile (tens of m).
  CHECK_CLOSE(scene.height_at(c.phi_in).height_m, 40000 - 0.36651 * 7000, 100.0);
}

TEST_CASE("a field as wide as the chord is grazing; a level never passed is a miss", "[physics]") {
  auto work = workspace<double>();
  // Roll the paper's head until the chord is about 4 deg.
  physics_scene_options o;
  o.roll_deg = 0;
  o.pitch_deg = 0;
  o.alpha_deg = -16.7L;  // the cone tilts away from the Earth: a chord of 9.7 deg
  const auto scene = make_physics_scene<double>(o);
  REQUIRE(scene.geometric.state == status::ok);
  const double chord = scene.geometric.chord();
  INFO("chord " << in_degrees(chord) << " deg");
  REQUIRE(chord < conescan::deg_to_rad(20.0));
  // The field's along-scan width is fov / sin(gamma): just wider than the chord, just narrower.
  const double sin_gamma = std::sin(conescan::deg_to_rad(45.0));
  sensor_physics_settings<double> s;
  s.offset_m = 40000;
  s.field.fov_rad = chord * sin_gamma * 1.001;
  CHECK(scene.physics(sensor_physics_head_of(s), 0.0, *work).state == status::grazing);
  // A field the chord holds many times over measures it (a field whose outer lines miss the
  // surface near a crossing is grazing too, for the same reason: the pulse is narrower than it).
  s.field.fov_rad = conescan::deg_to_rad(0.1);
  CHECK(scene.physics(sensor_physics_head_of(s), 0.0, *work).state == status::ok);

  const auto paper = make_physics_scene<double>(physics_scene_options{});
  sensor_physics_settings<double> f;
  f.offset_m = 40000;
  f.locator = {locator_kind::fixed, 1.0001};  // above the plateau L_disk L0 = 1
  CHECK(paper.physics(sensor_physics_head_of(f), 0.0, *work).state == status::miss);
  f.locator = {locator_kind::fixed, 0.9999};
  CHECK(paper.physics(sensor_physics_head_of(f), 0.0, *work).state == status::ok);
  // A disk dimmer than the level between the limbs: two pulses.
  sensor_physics_settings<double> d;
  d.offset_m = 40000;
  d.disk = 0.3;
  CHECK(paper.physics(sensor_physics_head_of(d), 0.0, *work).state == status::multiple);
  d.disk = 0.6;
  CHECK(paper.physics(sensor_physics_head_of(d), 0.0, *work).state == status::ok);
}

TEST_CASE("a window of many cells is computed within the workspace", "[physics]") {
  // Found by the sanitizers on a drawn scene: a 0.4 deg field at 3.6 rev/s with 1.7 ms of lag
  // over a bright disk (L_disk 1.98) below a limb 1.55 km under the surface, H = 8.3 km. Its
  // window's lattice has more cells than 2 x max_pieces, which overran the breaks' array. With
  // the season term the lag's history lengthens the window further, past the pieces the
  // workspace holds when cut at every cell: the cells where the field lies wholly on the disk or
  // in the sky are then joined (smooth there), and the row is computed. Two crossings with the
  // season term in one window (a 1 deg field, H = 100 m, 4 rev/s, 2 ms) outgrew a workspace of
  // 160 pieces and 32 panels and were invalid; the workspace now holds twice that, and the row is
  // computed (docs/SENSOR_PHYSICS.md, decision 14; 2e-13 deg from the brute-force reference). No
  // scene found since outgrows it (a probe of 30: fields of 0.1-2.5 deg, H down to 1 cm, up to 8
  // rev/s and 4 ms, the season term at 0.3).
  auto work = workspace<double>();
  const auto paper = make_physics_scene<double>(physics_scene_options{});
  sensor_physics_settings<double> s;
  s.field = {conescan::deg_to_rad(0.4), field_shape::square};
  s.offset_m = -1550;
  s.scale_m = 8343;
  s.disk = 1.9755;
  s.spin_hz = 3.6;
  s.tau_s = 1.7247e-3;
  const auto many = paper.physics(sensor_physics_head_of(s), 0.3, *work);
  CHECK(many.state == status::ok);
  CHECK(std::isfinite(many.phi_in));
  CHECK(std::isfinite(many.phi_out));
  s.season_amplitude = -0.1;
  const auto season = paper.physics(sensor_physics_head_of(s), 0.3, *work);
  CHECK(season.state == status::ok);
  CHECK(std::isfinite(season.phi_in));
  CHECK(std::isfinite(season.phi_out));
  s.field = {conescan::deg_to_rad(1.0), field_shape::square};
  s.offset_m = 0;
  s.scale_m = 100;
  s.disk = 1;
  s.spin_hz = 4;
  s.tau_s = 2e-3;
  s.season_amplitude = 0.3;
  const auto merged = paper.physics(sensor_physics_head_of(s), 0.3, *work);
  CHECK(merged.state == status::ok);
  CHECK(std::isfinite(merged.phi_in));
  CHECK(std::isfinite(merged.phi_out));
  CHECK_FALSE(work->cache.outgrown);
}

TEST_CASE("a step profile's window with the season term and a long lag fits the workspace",
          "[physics][brute-force]") {
  // Found by a randomized scan of conescan-sim rows: a pencil on a step profile (H = 0, delta50
  // 27 km) with 1.6 ms of lag at 3.8 rev/s, WGS84 with the horizon 34.9 km up, went `invalid` from
  // ok below ~260 km as soon as the season term was on (A = -0.0073): the window's geometry had
  // eight lattice steps of margin a side, and H = 0's step is a whole geometry panel (0.2 rad), so
  // with the lag's history the window spanned more than a turn (32 panels). The margin is now at
  // most two panels. Both sides (270 km, which fitted before, and 200 km), both seasons: ok, and
  // the reference's crossings (exact for a step: measured within 2e-14 deg).
  for (const double altitude_km : {270.0, 200.0})
    for (const double season : {-0.0073, 0.2}) {
      physics_scene_options o;
      o.ellipsoid = true;
      o.a_m = 6378137.0L + 34863;
      o.b_m = 6356752.314245L + 34863;
      o.distance_m = 6378137.0L + 1000 * altitude_km;
      o.polar_x = 0.1L;
      o.polar_y = 0.2L;
      o.polar_z = 1;
      sensor_physics_settings<double> s;
      s.spin_hz = 3.8084;
      s.tau_s = 1.6037e-3;
      s.scale_m = 0;
      s.offset_m = 26969;
      s.season_amplitude = season;
      s.locator = {locator_kind::fixed, 0.218};
      INFO("altitude " << altitude_km << " km, season " << season);
      conescan_test::compare_with_reference(o, s, std::sin(conescan::deg_to_rad(18.093)), 0.01,
                                            conescan::rad_to_deg(1e-12));
    }
}

TEST_CASE("the slope locator with lag takes a jump's side where it is the steeper",
          "[physics][brute-force]") {
  // Found by a randomized scan of conescan-sim rows (the phase alternating by 0.034 deg from row
  // to row): a pencil with 0.87 ms of lag at 0.84 rev/s, H = 11.7 km, delta50 = 6.3 km (l(0) =
  // 0.70: the output's slope jumps by 0.3 / Lambda at the surface's cut). At Earth-out the slope's
  // extremum is that jump's side near 990-995 km, the knee's smooth one at 1000 km; samples of y'
  // stepped over the jump and took the knee, 0.08 deg from the reference. Measured since: within
  // 2e-14 deg at the cut, 2.5e-8 at the knee (the reference's grid, h = 0.01 deg).
  for (const double altitude_km : {990.0, 995.0, 1000.0}) {
    physics_scene_options o;
    o.a_m = 6378137.0L + 43619;
    o.distance_m = 6378137.0L + 1000 * altitude_km;
    sensor_physics_settings<double> s;
    s.spin_hz = 0.8396;
    s.tau_s = 0.8705e-3;
    s.scale_m = 11685;
    s.offset_m = 6292;
    s.season_amplitude = 0.1411;
    s.locator = {locator_kind::slope, 0.5};
    INFO("altitude " << altitude_km << " km");
    conescan_test::compare_with_reference(o, s, std::sin(conescan::deg_to_rad(-8.739)), 0.01, 1e-7);
  }
}

TEST_CASE("a disk far dimmer than the limb is two pulses, however dim", "[physics]") {
  // delta50 = 0, a pencil without lag: the output rises to L0/2 just above the surface and drops
  // to L_disk L0 on the disk, so the normalised level L0/4 is passed up, then down at the jump
  // wherever L_disk < 1/4: multiple, for every such disk. The windows' samples step over the peak
  // just above the jump; the refined peak joins them (a disk of 1e-12 to 1e-4 was once a miss,
  // its window wider and its last sky sample below the level, while 0 and 1e-3 were multiple).
  // Both sides of 1/4, the paper's perigee (the CLI's first row) and the paper's head.
  auto work = workspace<double>();
  physics_scene_options o;
  o.distance_m = 6552000;
  o.a_m = 6378137;
  const auto scene = make_physics_scene<double>(o);
  REQUIRE(scene.geometric.state == status::ok);
  for (long double disk : {0.0L, 1e-12L, 1e-9L, 1e-6L, 1e-4L, 1e-3L, 0.01L, 0.1L, 0.2499L}) {
    INFO("L_disk " << static_cast<double>(disk));
    const auto head = sensor_physics_head_of(reduction_settings<double>(7000, 1, disk));
    CHECK(scene.physics(head, 0.0, *work).state == status::multiple);
  }
  for (long double disk : {0.2501L, 0.3L, 0.45L}) {
    INFO("L_disk " << static_cast<double>(disk));
    const auto head = sensor_physics_head_of(reduction_settings<double>(7000, 1, disk));
    const crossings<double> c = scene.physics(head, 0.0, *work);
    REQUIRE(c.state == status::ok);
    // The level L0/4 on the sky side: H ln(ln 2 / -ln(3/4)); the peak, at the jump, refined to
    // 1e-9 of its bracket: 1e-5 m (5e-12 rad).
    const double expected = 7000 * std::log(std::log(2.0) / -std::log(0.75));
    CHECK_CLOSE(scene.height_at(c.phi_in).height_m, expected, 1e-5);
    CHECK_CLOSE(scene.height_at(c.phi_out).height_m, expected, 1e-5);
  }
  // The fixed locator alike: a level of 0.3 L0 passed up in the sky, then down at the jump.
  sensor_physics_settings<double> f = reduction_settings<double>(7000, 1, 1e-9L);
  f.locator = {locator_kind::fixed, 0.3};
  CHECK(scene.physics(sensor_physics_head_of(f), 0.0, *work).state == status::multiple);
}

TEST_CASE("hostile settings and inputs are invalid, never garbage", "[physics]") {
  const double nan = std::nan(""), inf = std::numeric_limits<double>::infinity();
  auto bad = [](auto change) {
    sensor_physics_settings<double> s;
    change(s);
    return conescan::sensor_physics_settings_status(s);
  };
  CHECK(bad([](auto&) {}) == status::ok);
  CHECK(bad([&](auto& s) { s.field.fov_rad = nan; }) == status::invalid);
  CHECK(bad([&](auto& s) { s.field.fov_rad = -1e-9; }) == status::invalid);
  CHECK(bad([&](auto& s) { s.field.fov_rad = 2.0; }) == status::invalid);
  // The narrowest field, 0.001 deg (narrower ones cost the chain cells as 1/fov), on both sides.
  CHECK(bad([&](auto& s) { s.field.fov_rad = conescan::deg_to_rad(0.001); }) == status::ok);
  CHECK(bad([&](auto& s) { s.field.fov_rad = conescan::deg_to_rad(0.000999); }) == status::invalid);
  CHECK(bad([&](auto& s) { s.field.fov_rad = 1e-12; }) == status::invalid);
  // The slope locator's shortest lag, 1e-6 rad of scan azimuth (2 pi spin tau), on both sides;
  // the level locators have none.
  auto slope_lag = [&](double lag_rad, locator_kind kind) {
    return bad([&](auto& s) {
      s.spin_hz = 1;
      s.tau_s = lag_rad / (2 * 3.14159265358979323846);
      s.locator = {kind, 0.5};
    });
  };
  CHECK(slope_lag(1.01e-6, locator_kind::slope) == status::ok);
  CHECK(slope_lag(0.99e-6, locator_kind::slope) == status::invalid);
  CHECK(slope_lag(1e-12, locator_kind::normalised) == status::ok);
  CHECK(bad([&](auto& s) { s.tau_s = 1e-3; }) == status::invalid);  // lag without spin
  CHECK(bad([&](auto& s) { s.tau_s = -1e-3, s.spin_hz = 1; }) == status::invalid);
  CHECK(bad([&](auto& s) { s.spin_hz = -1; }) == status::invalid);
  CHECK(bad([&](auto& s) { s.spin_hz = inf; }) == status::invalid);
  CHECK(bad([&](auto& s) { s.locator.threshold = 0; }) == status::invalid);
  CHECK(bad([&](auto& s) { s.locator.threshold = 1; }) == status::invalid);
  CHECK(bad([&](auto& s) { s.locator.threshold = nan; }) == status::invalid);
  CHECK(bad([&](auto& s) { s.locator = {locator_kind::fixed, 0.0}; }) == status::invalid);
  CHECK(bad([&](auto& s) { s.locator = {locator_kind::fixed, 2.0}; }) == status::ok);
  // The lowest level, 1e-8 L0 (the chain's tolerances are fractions of L0), on both sides: a
  // fixed T, and a normalised k over the faintest pulse (1e-3 L0).
  CHECK(bad([&](auto& s) { s.locator = {locator_kind::fixed, 1e-8}; }) == status::ok);
  CHECK(bad([&](auto& s) { s.locator = {locator_kind::fixed, 0.99e-8}; }) == status::invalid);
  CHECK(bad([&](auto& s) {
          s.locator = {locator_kind::fixed, 1e-8}, s.plateau = 2;
        }) == status::invalid);
  CHECK(bad([&](auto& s) { s.locator = {locator_kind::normalised, 1e-5}; }) == status::ok);
  CHECK(bad([&](auto& s) { s.locator = {locator_kind::normalised, 0.99e-5}; }) == status::invalid);
  CHECK(bad([&](auto& s) { s.locator = {locator_kind::slope, 7.0}; }) == status::ok);
  CHECK(bad([&](auto& s) { s.scale_m = -1; }) == status::invalid);
  CHECK(bad([&](auto& s) { s.scale_m = 0; }) == status::ok);
  CHECK(bad([&](auto& s) { s.scale_m = 1e-310; }) == status::invalid);  // 1 / H overflows
  CHECK(bad([&](auto& s) { s.scale_m = 1e-300; }) == status::ok);
  CHECK(bad([&](auto& s) { s.offset_m = inf; }) == status::invalid);
  CHECK(bad([&](auto& s) { s.disk = -0.1; }) == status::invalid);
  CHECK(bad([&](auto& s) { s.season_amplitude = 1; }) == status::invalid);
  CHECK(bad([&](auto& s) { s.season_amplitude = -0.999; }) == status::ok);
  CHECK(bad([&](auto& s) { s.plateau = 0; }) == status::invalid);

  // Per row: a field reaching S, a non-finite Sun, a season factor <= 0, a surface not ok.
  auto work = workspace<double>();
  const auto scene = make_physics_scene<double>(physics_scene_options{});
  sensor_physics_settings<double> s;
  s.field.fov_rad = conescan::deg_to_rad(89.99);
  CHECK(scene.physics(sensor_physics_head_of(s), 0.0, *work).state == status::invalid);
  s.field.fov_rad = 0;
  CHECK(scene.physics(sensor_physics_head_of(s), nan, *work).state == status::invalid);
  s.season_amplitude = 0.9;
  CHECK(scene.physics(sensor_physics_head_of(s), 0.45, *work).state == status::invalid);
  CHECK(scene.physics(sensor_physics_head_of(s), 0.3, *work).state == status::ok);
  s.season_amplitude = 0;
  // A subnormal H (it crashed the chain's piece bookkeeping): invalid; a tiny normal one runs.
  s.scale_m = 1e-310;
  CHECK(sensor_physics_head_of(s).profile.state == status::invalid);
  CHECK(scene.physics(sensor_physics_head_of(s), 0.0, *work).state == status::invalid);
  s.scale_m = 1e-300;
  CHECK(scene.physics(sensor_physics_head_of(s), 0.0, *work).state == status::ok);
  s.scale_m = 7000;
  const auto bad_head =
      sensor_physics_head_of(sensor_physics_settings<double>{{-1.0, field_shape::square}});
  CHECK(scene.physics(bad_head, 0.0, *work).state == status::invalid);
  conescan::sphere_surface<double> broken = scene.sphere;
  broken.state = status::invalid;
  CHECK(conescan::sensor_physics_crossings(sensor_physics_head_of(s), scene.head.circle(), broken,
                                           0.0, scene.geometric, *work)
            .state == status::invalid);
  // The geometry's own statuses pass through.
  const crossings<double> miss = crossings<double>::failed(status::miss);
  CHECK(conescan::sensor_physics_crossings(sensor_physics_head_of(s), scene.head.circle(),
                                           scene.sphere, 0.0, miss, *work)
            .state == status::miss);
}

TEST_CASE("300 random scenes in the reduction settings are the geometry to 1e-9 deg", "[physics]") {
  std::mt19937_64 random(20261127);  // fixed seed
  auto uniform = [&](double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(random);
  };
  auto work = workspace<double>();
  int compared = 0;
  for (int i = 0; i < 300; ++i) {
    const physics_scene_options o = random_reduction_scene(uniform, i);
    const auto scene = make_physics_scene<double>(o);
    if (scene.geometric.state != status::ok) continue;
    const auto head = sensor_physics_head_of(
        reduction_settings<double>(uniform(1000, 20000), uniform(0.2, 5), uniform(1, 3)));
    const crossings<double> c = scene.physics(head, uniform(-0.4, 0.4), *work);
    INFO("scene " << i);
    REQUIRE(c.state == status::ok);
    CHECK_CLOSE(in_degrees(c.phi_in), in_degrees(scene.geometric.phi_in), 1e-9);
    CHECK_CLOSE(in_degrees(c.phi_out), in_degrees(scene.geometric.phi_out), 1e-9);
    ++compared;
  }
  CHECK(compared > 200);
}
