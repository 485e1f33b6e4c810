// The fast method of MODEL §12's crossings (include/conescan/sensor_physics/fast.hpp) and the
// limb's antiderivatives it rests on (include/conescan/sensor_physics/profile_antiderivatives.hpp), tag
// [physics-fast]:
//  - the antiderivatives against a long double quadrature of their definition, for every scalar;
//  - the field's across-mean against a dense quadrature across the field (sphere, ellipsoid, the
//    surface inside the field);
//  - the fast crossings against the exact chain (sensor_physics.hpp) on the cases its own tests
//    use (square field, lag at k = 1/2 and k != 1/2, fixed and slope locators, delta50 = 0, a
//    brighter disk, no lag, sphere and the apparent-horizon ellipsoid) along an orbit, and on
//    120 random scenes; against the brute-force reference on the brief's case;
//  - outside its domain (circle, season term, pencil, step profile, dimmer disk, short pulse) the
//    exact chain's own result, bit for bit, and the row counted as the exact chain's;
//  - the reductions: normalised crossings unmoved by the radiance's scale, 300 random scenes in
//    the reduction settings equal to MODEL §5's geometry to 1e-9 deg;
//  - statuses and hostile inputs; float, double, long double and the ADL scalar.
// [.physics-fast-slow]: more cases against the reference (minutes).
#include <catch2/catch.hpp>
#include <cmath>
#include <memory>
#include <random>
#include <typeinfo>
#include <vector>

#include "conescan/sensor_physics/fast.hpp"
#include "support/adl_scalar.hpp"
#include "support/approx.hpp"
#include "support/sensor_physics_scene.hpp"

using conescan::crossings;
using conescan::field_shape;
using conescan::locator_kind;
using conescan::physics_method;
using conescan::sensor_physics_fast_head_of;
using conescan::sensor_physics_fast_workspace;
using conescan::sensor_physics_settings;
using conescan::status;
using conescan_test::make_physics_scene;
using conescan_test::physics_scene;
using conescan_test::physics_scene_options;
using conescan_test::random_reduction_scene;

#define CHECK_CLOSE(actual, expected, tolerance)                                     \
  CHECK_WITHIN(static_cast<long double>(actual), static_cast<long double>(expected), \
               static_cast<long double>(tolerance))

namespace {

constexpr long double pi_ld = 3.14159265358979323846264338327950288L;

template <class T>
long double in_degrees(const T& rad) {
  return static_cast<long double>(rad) * 180 / pi_ld;
}

/// l_(k)(x) by its definition, (-1)^k int_x^inf (t - x)^(k-1) / (k-1)! l(t) dt, in long double:
/// composite 20-point Gauss-Legendre on panels of 1/4 up to x + 80 (l < 1e-34 beyond).
long double antiderivative_by_quadrature(int k, long double x) {
  static const conescan::gauss_legendre_rule<long double, 20> rule =
      conescan::gauss_legendre_rule_of<long double, 20>();
  const long double ln2 = std::log(2.0L);
  long double factorial = 1;
  for (int j = 2; j < k; ++j) factorial *= j;
  long double sum = 0;
  for (int p = 0; p < 320; ++p) {
    const long double a = x + p * 0.25L;
    for (int i = 0; i < 20; ++i) {
      const long double t = a + (rule.nodes[i] + 1) * 0.125L;
      sum += rule.weights[i] * 0.125L * std::pow(t - x, static_cast<long double>(k - 1)) /
             factorial * -std::expm1(-ln2 * std::exp(-t));
    }
  }
  return k % 2 == 0 ? sum : -sum;
}

template <class T>
std::unique_ptr<sensor_physics_fast_workspace<T>> fast_workspace() {
  return std::make_unique<sensor_physics_fast_workspace<T>>();
}

/// The fast crossings of a test scene (sphere or ellipsoid, as the scene says).
template <class T>
crossings<T> fast(const physics_scene<T>& scene, const conescan::sensor_physics_fast_head<T>& head,
                  const T& sin_sun, sensor_physics_fast_workspace<T>& work) {
  return scene.options.ellipsoid
             ? conescan::sensor_physics_fast_crossings(head, scene.head.circle(), scene.ellipsoid,
                                                       sin_sun, scene.geometric, work)
             : conescan::sensor_physics_fast_crossings(head, scene.head.circle(), scene.sphere,
                                                       sin_sun, scene.geometric, work);
}

/// The brief's physics: a 1.5 deg square field, 1 ms of lag at 1 rev/s, the normalised locator
/// at 1/2, H = 7 km, delta50 = 40 km.
template <class T>
sensor_physics_settings<T> brief_settings() {
  sensor_physics_settings<T> s;
  s.field = {conescan::deg_to_rad(conescan_test::scene_value<T>(1.5L)), field_shape::square};
  s.spin_hz = T(1);
  s.tau_s = T(1) / T(1000);
  s.offset_m = T(40000);
  return s;
}

/// The apparent-horizon ellipsoid of the exact chain's tests: polar radius 12 km lower, centre
/// 4 km off along the pole, a rolled and misaligned head.
physics_scene_options apparent_horizon() {
  physics_scene_options o;
  o.ellipsoid = true;
  o.b_m = 6356752.314245L + 40000 - 12000;
  o.centre_shift_m = 4000;
  o.roll_deg = 2;
  o.sigma_deg = 0.3L;
  o.phi_a_deg = 60;
  return o;
}

/// A row of the paper's ellipse (a = 7280 km, e = 0.1) at true anomaly nu, the pole turning in
/// the orbit plane (the benchmark's rows).
physics_scene_options orbit_row(long double nu_deg, bool ellipsoid) {
  physics_scene_options o;
  const long double nu = nu_deg * pi_ld / 180;
  o.distance_m = 7280000.0L * (1 - 0.01L) / (1 + 0.1L * std::cos(nu));
  o.polar_x = std::cos(nu);
  o.polar_y = 0;
  o.polar_z = std::sin(nu);
  o.ellipsoid = ellipsoid;
  o.b_m = 6356752.314245L + 40000;
  return o;
}

/// Fast against exact on one scene: both ok, the crossings within tolerance_deg; the worst
/// difference kept. Returns whether the fast path served the row (the exact chain's rows are
/// the exact chain's results bit for bit).
bool compare_with_exact(const physics_scene_options& o, const sensor_physics_settings<double>& s,
                        double sin_sun, double tolerance_deg, long double& worst) {
  const auto scene = make_physics_scene<double>(o);
  REQUIRE(scene.geometric.state == status::ok);
  auto exact_work = std::make_unique<conescan::sensor_physics_workspace<double>>();
  auto work = fast_workspace<double>();
  const crossings<double> e =
      scene.physics(conescan::sensor_physics_head_of(s), sin_sun, *exact_work);
  const crossings<double> f = fast(scene, sensor_physics_fast_head_of(s), sin_sun, *work);
  REQUIRE(e.state == status::ok);
  REQUIRE(f.state == status::ok);
  const long double d_in = in_degrees(f.phi_in - e.phi_in);
  const long double d_out = in_degrees(f.phi_out - e.phi_out);
  INFO("fast - exact: in " << static_cast<double>(d_in) << " out " << static_cast<double>(d_out)
                           << " deg");
  CHECK_CLOSE(d_in, 0, tolerance_deg);
  CHECK_CLOSE(d_out, 0, tolerance_deg);
  worst = std::max(worst, std::max(std::fabs(d_in), std::fabs(d_out)));
  return work->last == physics_method::fast;
}

}  // namespace

TEMPLATE_TEST_CASE("the limb's antiderivatives against a quadrature of their definition",
                   "[physics-fast]", float, double, long double, conescan_test::adl_real) {
  using T = TestType;
  const auto table = conescan::limb_antiderivatives_of<T>();
  REQUIRE(table.state == status::ok);
  // float: the table's Chebyshev sums round to a few ulp of their largest term.
  const long double tolerance = std::is_same_v<T, float> ? 2e-6L : 4e-15L;
  long double worst = 0;
  // Both sides of the continuation (x_low), the panels, and the series (x_high = 8).
  for (long double x = -9; x <= 14; x += 0.37L) {
    T l[5];
    conescan::limb_antiderivatives_at(table, conescan_test::scene_value<T>(x), l);
    for (int k = 1; k <= 5; ++k) {
      const long double expected = antiderivative_by_quadrature(k, x);
      const long double scale = std::max(1.0L, std::fabs(expected));
      const long double error = std::fabs(static_cast<long double>(l[k - 1]) - expected) / scale;
      worst = std::max(worst, error);
      INFO("x " << static_cast<double>(x) << " k " << k);
      CHECK(error <= tolerance);
    }
  }
  WARN("limb antiderivatives: worst relative error " << static_cast<double>(worst));
}

TEST_CASE("the limb's antiderivatives are antiderivatives, continuous at the table's seams",
          "[physics-fast]") {
  const auto table = conescan::limb_antiderivatives_of<double>();
  const auto profile = conescan::radiance_profile_of(1.0, 0.0, 1.0);  // x = delta
  auto at = [&](double x, int k) {
    double l[5];
    conescan::limb_antiderivatives_at(table, x, l);
    return k == 0 ? conescan::limb_fraction(profile, x) : l[k - 1];
  };
  // l_(k)' = l_(k-1), by a fourth-order central difference (step 1e-3: error ~1e-13).
  for (double x : {-6.0, -3.9, -1.0, 0.0, 0.7, 2.5, 7.9, 8.1, 12.0})
    for (int k = 1; k <= 5; ++k) {
      const double e = 1e-3;
      const double d =
          (at(x - 2 * e, k) - 8 * at(x - e, k) + 8 * at(x + e, k) - at(x + 2 * e, k)) / (12 * e);
      INFO("x " << x << " k " << k);
      CHECK_CLOSE(d, at(x, k - 1), 1e-10 * std::max(1.0, std::fabs(at(x, k - 1))));
    }
  // The seams: the continuation below x_low, panel ends, the series above x_high.
  for (double seam : {table.x_low, table.x_low + table.panel_width, table.x_high})
    for (int k = 1; k <= 5; ++k) {
      const double below = at(std::nextafter(seam, -1e9), k), above = at(seam, k);
      CHECK_CLOSE(below, above, 4e-15 * std::max(1.0, std::fabs(above)));
    }
  // Far above the knee every l_(k) tends to (-1)^k ln 2 e^-x.
  CHECK(at(30.0, 1) / (-std::log(2.0) * std::exp(-30.0)) == Approx(1).epsilon(1e-12));
  CHECK(at(30.0, 4) / (std::log(2.0) * std::exp(-30.0)) == Approx(1).epsilon(1e-12));
}

TEST_CASE("the field's across-mean against a dense quadrature across the field", "[physics-fast]") {
  // The across-mean S(psi) = int L(delta(psi, b)) db / 2B of fast_detail::across_mean against
  // 400 panels of 16-point Gauss in b, split where the surface crosses the field (found by
  // bisection): within 1e-9 of L0 (measured 2.4e-10, the series' truncation at order 5).
  auto check = [](const physics_scene<double>& scene, const auto& surface, double offset,
                  double disk) {
    sensor_physics_settings<double> s = brief_settings<double>();
    s.offset_m = offset;
    s.disk = disk;
    const auto head = sensor_physics_fast_head_of(s);
    const auto circle = scene.head.circle();
    const auto probe = conescan::physics_detail::probe_of(surface);
    const double b_max = s.field.fov_rad / 2;
    static const auto rule = conescan::gauss_legendre_rule_of<double, 16>();
    double worst = 0;
    for (double t = -0.06; t <= 0.06; t += 0.0021) {
      const double psi = scene.geometric.phi_out + t;
      conescan::fast_detail::across_geometry<double> g;
      REQUIRE(conescan::fast_detail::across_geometry_at(circle, surface, probe, psi,
                                                        std::cos(b_max), std::sin(b_max), g));
      const double mean = conescan::fast_detail::across_mean(head, g);
      auto height = [&](double b) {
        return conescan::physics_detail::exact_height(circle, surface, probe, psi, b).height_m;
      };
      std::vector<double> cuts{-b_max, b_max};
      if ((height(-b_max) < 0) != (height(b_max) < 0)) {
        double lo = -b_max, hi = b_max;
        for (int i = 0; i < 200; ++i) {
          const double m = (lo + hi) / 2;
          ((height(m) < 0) == (height(lo) < 0) ? lo : hi) = m;
        }
        cuts.insert(cuts.begin() + 1, (lo + hi) / 2);
      }
      long double sum = 0;
      for (std::size_t c = 0; c + 1 < cuts.size(); ++c)
        for (int p = 0; p < 400; ++p) {
          const double w = (cuts[c + 1] - cuts[c]) / 400, a = cuts[c] + p * w;
          for (int i = 0; i < 16; ++i)
            sum += rule.weights[i] * w / 2 *
                   conescan::radiance(head.exact.profile, 1.0,
                                      height(a + (rule.nodes[i] + 1) * w / 2));
        }
      const double expected = static_cast<double>(sum / (2 * b_max));
      worst = std::max(worst, std::fabs(mean - expected));
      INFO("t " << t << " delta50 " << offset << " L_disk " << disk);
      CHECK_CLOSE(mean, expected, 1e-9);
    }
    return worst;
  };
  const auto sphere = make_physics_scene<double>(physics_scene_options{});
  const auto ellipsoid = make_physics_scene<double>(apparent_horizon());
  double worst = 0;
  for (double offset : {40000.0, 10000.0, 0.0})
    for (double disk : {1.0, 1.5}) {
      worst = std::max(worst, check(sphere, sphere.sphere, offset, disk));
      worst = std::max(worst, check(ellipsoid, ellipsoid.ellipsoid, offset, disk));
    }
  WARN("across-mean: worst |fast - quadrature| " << worst << " of L0");
}

TEST_CASE("fast against the exact chain: the brief's case and its variants along an orbit",
          "[physics-fast]") {
  // The exact chain is itself within ~1e-7 deg of the reference (docs/SENSOR_PHYSICS.md); the
  // fast method within 4e-8 deg of the finer reference on these rows (the doc's table). The
  // tolerance 3e-7 deg covers both.
  const double tolerance = 3e-7;
  long double worst = 0;
  for (bool ellipsoid : {false, true})
    for (long double nu : {0.0L, 50.0L, 100.0L, 180.0L, 260.0L}) {
      const physics_scene_options o = orbit_row(nu, ellipsoid);
      INFO("nu " << static_cast<double>(nu) << " ellipsoid " << ellipsoid);
      auto s = brief_settings<double>();
      SECTION("brief") {
        CHECK(compare_with_exact(o, s, 0.0, tolerance, worst));
      }
      SECTION("k = 0.3 and 0.7") {
        for (double k : {0.3, 0.7}) {
          s.locator = {locator_kind::normalised, k};
          CHECK(compare_with_exact(o, s, 0.0, tolerance, worst));
        }
      }
      SECTION("fixed threshold") {
        s.locator = {locator_kind::fixed, 0.3};
        CHECK(compare_with_exact(o, s, 0.0, tolerance, worst));
      }
      SECTION("slope") {
        s.locator = {locator_kind::slope, 0.5};
        CHECK(compare_with_exact(o, s, 0.0, tolerance, worst));
      }
      SECTION("delta50 = 0: the radiance jumps at the surface inside the field") {
        s.offset_m = 0;
        CHECK(compare_with_exact(o, s, 0.0, tolerance, worst));
      }
      SECTION("a disk brighter than the limb") {
        s.disk = 1.5;
        CHECK(compare_with_exact(o, s, 0.0, tolerance, worst));
      }
      SECTION("no lag") {
        s.tau_s = 0;
        CHECK(compare_with_exact(o, s, 0.0, tolerance, worst));
      }
      SECTION("a 0.5 deg field, 2 ms, H = 4 km") {
        s.field.fov_rad = conescan::deg_to_rad(0.5);
        s.tau_s = 2e-3;
        s.scale_m = 4000;
        CHECK(compare_with_exact(o, s, 0.0, tolerance, worst));
      }
    }
  CHECK(compare_with_exact(apparent_horizon(), brief_settings<double>(), 0.3, tolerance, worst));
  WARN("fast - exact: worst " << static_cast<double>(worst) << " deg");
}

TEST_CASE("fast against the exact chain on 120 random scenes, the reference where they differ",
          "[physics-fast][brute-force]") {
  std::mt19937_64 random(20261203);  // fixed seed
  auto uniform = [&](double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(random);
  };
  long double worst = 0;
  int compared = 0, exact_rows = 0, refereed = 0;
  for (int i = 0; i < 120; ++i) {
    physics_scene_options o;
    o.alpha_deg = uniform(-20, 20);
    o.beta_deg = uniform(-180, 180);
    o.gamma_deg = uniform(35, 55);
    o.sigma_deg = uniform(0, 0.5);
    o.phi_a_deg = uniform(-180, 180);
    o.roll_deg = uniform(-5, 5);
    o.pitch_deg = uniform(-5, 5);
    o.distance_m = uniform(6.9e6, 7.6e6);
    o.ellipsoid = i % 2 == 1;
    o.a_m = 6378137.0 + 40000;
    o.b_m = 6356752.314245 + 40000 - (i % 4 == 3 ? uniform(0, 20000) : 0);
    o.centre_shift_m = i % 4 == 3 ? uniform(-8000, 8000) : 0;
    o.polar_x = uniform(-1, 1);
    o.polar_y = uniform(-1, 1);
    o.polar_z = uniform(-1, 1);
    const auto scene = make_physics_scene<double>(o);
    if (scene.geometric.state != status::ok || scene.geometric.chord() < 0.6) continue;
    sensor_physics_settings<double> s;
    s.field.fov_rad = conescan::deg_to_rad(uniform(0.3, 2.0));
    s.spin_hz = 1;
    s.tau_s = uniform(2e-4, 2e-3);  // the reference's grid (0.01 deg) well inside the lag
    s.scale_m = uniform(4000, 10000);
    s.offset_m = uniform(0, 50000);
    s.disk = uniform(1, 1.5);
    // The threshold locators: on random fields the slope locator's extremum is often flat or a
    // corner of y' (the surface inside the field), where the exact chain and the reference
    // themselves differ by 1e-6 to 1e-1 deg (measured); it is tested on the orbit rows.
    s.locator = {i % 2 == 0 ? locator_kind::normalised : locator_kind::fixed, uniform(0.2, 0.8)};
    INFO("scene " << i);
    const auto scene_of = make_physics_scene<double>(o);
    auto exact_work = std::make_unique<conescan::sensor_physics_workspace<double>>();
    auto work = fast_workspace<double>();
    const crossings<double> e =
        scene_of.physics(conescan::sensor_physics_head_of(s), 0.0, *exact_work);
    const crossings<double> f = fast(scene_of, sensor_physics_fast_head_of(s), 0.0, *work);
    REQUIRE(e.state == status::ok);
    REQUIRE(f.state == status::ok);
    ++compared;
    if (work->last == physics_method::exact) {
      ++exact_rows;
      continue;
    }
    const long double d = std::max(std::fabs(in_degrees(f.phi_in - e.phi_in)),
                                   std::fabs(in_degrees(f.phi_out - e.phi_out)));
    worst = std::max(worst, d);
    if (d <= 3e-7) continue;
    // The two methods disagree: the reference decides (the exact chain's own error exceeds
    // 1e-6 deg on some of these scenes, the surface inside the field: measured).
    const auto r = conescan_test::reference_crossings(
        scene_of.reference(0), conescan_test::reference_settings_of(s),
        (scene_of.geometric.phi_in + scene_of.geometric.phi_out) / 2, conescan::deg_to_rad(0.01));
    REQUIRE(r.crossings.state == status::ok);
    ++refereed;
    const long double fast_in = in_degrees(f.phi_in - r.crossings.phi_in);
    const long double fast_out = in_degrees(f.phi_out - r.crossings.phi_out);
    WARN("scene " << i << ": fast - exact " << static_cast<double>(d) << " deg; fast - reference "
                  << static_cast<double>(fast_in) << ", " << static_cast<double>(fast_out)
                  << "; exact - reference "
                  << static_cast<double>(in_degrees(e.phi_in - r.crossings.phi_in)) << ", "
                  << static_cast<double>(in_degrees(e.phi_out - r.crossings.phi_out)));
    CHECK_CLOSE(fast_in, 0, 1e-6);
    CHECK_CLOSE(fast_out, 0, 1e-6);
  }
  CHECK(compared > 80);
  // A field nearly parallel to the limb (its across heights not monotone) is the exact chain's.
  CHECK(exact_rows < compared / 10);
  WARN(exact_rows << " of " << compared << " random scenes served by the exact chain, " << refereed
                  << " refereed by the reference");
  WARN("fast - exact on random scenes: worst " << static_cast<double>(worst) << " deg");
}

TEST_CASE("fast against the reference: the brief's case", "[physics-fast][brute-force]") {
  // The reference at h = 0.02 deg is itself within ~1.5e-7 deg of its limit; the contract is
  // 1e-6 deg (measured at h = 0.005 deg: docs/SENSOR_PHYSICS.md, "The fast method").
  for (const physics_scene_options& o : {physics_scene_options{}, apparent_horizon()}) {
    const auto scene = make_physics_scene<double>(o);
    const auto s = brief_settings<double>();
    auto work = fast_workspace<double>();
    const crossings<double> f = fast(scene, sensor_physics_fast_head_of(s), 0.0, *work);
    REQUIRE(f.state == status::ok);
    CHECK(work->last == physics_method::fast);
    const auto r = conescan_test::reference_crossings(
        scene.reference(0), conescan_test::reference_settings_of(s),
        (scene.geometric.phi_in + scene.geometric.phi_out) / 2, conescan::deg_to_rad(0.02));
    REQUIRE(r.crossings.state == status::ok);
    const long double d_in = in_degrees(f.phi_in - r.crossings.phi_in);
    const long double d_out = in_degrees(f.phi_out - r.crossings.phi_out);
    WARN("fast - reference (h 0.02 deg): in " << static_cast<double>(d_in) << " out "
                                              << static_cast<double>(d_out) << " deg");
    CHECK_CLOSE(d_in, 0, 1e-6);
    CHECK_CLOSE(d_out, 0, 1e-6);
  }
}

TEST_CASE("fast against the reference: every case the fast path serves", "[.physics-fast-slow]") {
  auto run = [](const physics_scene_options& o, const sensor_physics_settings<double>& s,
                double h_deg) {
    const auto scene = make_physics_scene<double>(o);
    auto work = fast_workspace<double>();
    const crossings<double> f = fast(scene, sensor_physics_fast_head_of(s), 0.0, *work);
    REQUIRE(f.state == status::ok);
    CHECK(work->last == physics_method::fast);
    const auto r = conescan_test::reference_crossings(
        scene.reference(0), conescan_test::reference_settings_of(s),
        (scene.geometric.phi_in + scene.geometric.phi_out) / 2, conescan::deg_to_rad(h_deg));
    REQUIRE(r.crossings.state == status::ok);
    const long double d_in = in_degrees(f.phi_in - r.crossings.phi_in);
    const long double d_out = in_degrees(f.phi_out - r.crossings.phi_out);
    WARN("fast - reference (h " << h_deg << " deg): in " << static_cast<double>(d_in) << " out "
                                << static_cast<double>(d_out) << " deg");
    CHECK_CLOSE(d_in, 0, 1e-6);
    CHECK_CLOSE(d_out, 0, 1e-6);
  };
  auto s = brief_settings<double>();
  SECTION("k = 0.3") {
    s.locator = {locator_kind::normalised, 0.3};
    run(physics_scene_options{}, s, 0.01);
  }
  SECTION("fixed threshold") {
    s.locator = {locator_kind::fixed, 0.3};
    run(physics_scene_options{}, s, 0.01);
  }
  SECTION("slope") {
    s.locator = {locator_kind::slope, 0.5};
    run(physics_scene_options{}, s, 0.005);
  }
  SECTION("delta50 = 0") {
    s.offset_m = 0;
    run(physics_scene_options{}, s, 0.01);
  }
  SECTION("brighter disk, apparent horizon") {
    s.disk = 1.5;
    run(apparent_horizon(), s, 0.01);
  }
}

TEST_CASE("outside its domain the fast method is the exact chain, bit for bit", "[physics-fast]") {
  auto work = fast_workspace<double>();
  auto exact_work = std::make_unique<conescan::sensor_physics_workspace<double>>();
  auto same = [&](const physics_scene<double>& scene, const sensor_physics_settings<double>& s,
                  double sin_sun) {
    const crossings<double> f = fast(scene, sensor_physics_fast_head_of(s), sin_sun, *work);
    const crossings<double> e =
        scene.physics(conescan::sensor_physics_head_of(s), sin_sun, *exact_work);
    CHECK(work->last == physics_method::exact);
    CHECK(f.state == e.state);
    CHECK(conescan_test::same_or_both_nan(f.phi_in, e.phi_in));
    CHECK(conescan_test::same_or_both_nan(f.phi_out, e.phi_out));
  };
  const auto scene = make_physics_scene<double>(physics_scene_options{});
  auto s = brief_settings<double>();
  SECTION("circle") {
    s.field.shape = field_shape::circle;
    same(scene, s, 0.0);
  }
  SECTION("season term") {
    s.season_amplitude = 0.2;
    same(scene, s, 0.3);
  }
  SECTION("pencil") {
    s.field.fov_rad = 0;
    same(scene, s, 0.0);
  }
  SECTION("step profile") {
    s.scale_m = 0;
    s.offset_m = 20000;
    same(scene, s, 0.0);
  }
  SECTION("a disk dimmer than the limb") {
    s.disk = 0.8;
    same(scene, s, 0.0);
  }
  SECTION("a short pulse: the plateau shorter than 20 Lambda") {
    physics_scene_options o;
    o.alpha_deg = -16.4L;  // the cone tilted away from the Earth: a chord of ~12 deg
    const auto short_scene = make_physics_scene<double>(o);
    REQUIRE(short_scene.geometric.state == status::ok);
    s.tau_s = 5e-3;  // 20 Lambda = 36 deg
    same(short_scene, s, 0.0);
  }
  CHECK(work->fast_rows == 0);
  CHECK(work->exact_rows == 1);
}

TEST_CASE("normalised and slope crossings of the fast path do not move when L0 is scaled",
          "[physics-fast]") {
  auto work = fast_workspace<double>();
  const auto scene = make_physics_scene<double>(physics_scene_options{});
  for (locator_kind kind : {locator_kind::normalised, locator_kind::slope}) {
    auto s = brief_settings<double>();
    s.locator = {kind, 0.5};
    s.disk = 1.2;
    const crossings<double> base = fast(scene, sensor_physics_fast_head_of(s), 0.0, *work);
    REQUIRE(base.state == status::ok);
    for (double plateau : {0.25, 3.7}) {
      s.plateau = plateau;
      const crossings<double> c = fast(scene, sensor_physics_fast_head_of(s), 0.0, *work);
      REQUIRE(c.state == status::ok);
      CHECK(work->last == physics_method::fast);
      // The slope locator's extremum is the root of y'', to ~1e-8 deg (as the exact chain's).
      const double tolerance = kind == locator_kind::slope ? 1e-7 : 1e-10;
      CHECK_CLOSE(in_degrees(c.phi_in), in_degrees(base.phi_in), tolerance);
      CHECK_CLOSE(in_degrees(c.phi_out), in_degrees(base.phi_out), tolerance);
    }
  }
}

TEST_CASE("the fast method in the reduction settings: 300 random scenes are the geometry",
          "[physics-fast]") {
  // The reduction settings (pencil, no lag, normalised 1/2, delta50 = 0) are outside the fast
  // path's domain (a pencil): the fast method returns the exact chain's crossings, which are
  // MODEL §5's.
  std::mt19937_64 random(20261127);
  auto uniform = [&](double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(random);
  };
  auto work = fast_workspace<double>();
  int compared = 0;
  for (int i = 0; i < 300; ++i) {
    const physics_scene_options o = random_reduction_scene(uniform, i);
    const auto scene = make_physics_scene<double>(o);
    if (scene.geometric.state != status::ok) continue;
    sensor_physics_settings<double> s;
    s.scale_m = uniform(1000, 20000);
    s.plateau = uniform(0.2, 5);
    s.disk = uniform(1, 3);
    s.offset_m = 0;
    const crossings<double> c =
        fast(scene, sensor_physics_fast_head_of(s), uniform(-0.4, 0.4), *work);
    INFO("scene " << i);
    REQUIRE(c.state == status::ok);
    CHECK_CLOSE(in_degrees(c.phi_in), in_degrees(scene.geometric.phi_in), 1e-9);
    CHECK_CLOSE(in_degrees(c.phi_out), in_degrees(scene.geometric.phi_out), 1e-9);
    ++compared;
  }
  CHECK(compared > 200);
  CHECK(work->fast_rows == 0);
}

TEST_CASE("the fast method's statuses and hostile inputs", "[physics-fast]") {
  auto work = fast_workspace<double>();
  const auto scene = make_physics_scene<double>(physics_scene_options{});
  const double nan = std::nan("");
  // Invalid settings: the head is invalid, every row too.
  auto s = brief_settings<double>();
  s.tau_s = -1;
  CHECK(sensor_physics_fast_head_of(s).state == status::invalid);
  CHECK(fast(scene, sensor_physics_fast_head_of(s), 0.0, *work).state == status::invalid);
  s = brief_settings<double>();
  s.locator.threshold = nan;
  CHECK(fast(scene, sensor_physics_fast_head_of(s), 0.0, *work).state == status::invalid);
  // Per row: a non-finite Sun, a broken surface, the geometry's own statuses.
  const auto head = sensor_physics_fast_head_of(brief_settings<double>());
  CHECK(fast(scene, head, nan, *work).state == status::invalid);
  conescan::sphere_surface<double> broken = scene.sphere;
  broken.state = status::invalid;
  CHECK(conescan::sensor_physics_fast_crossings(head, scene.head.circle(), broken, 0.0,
                                                scene.geometric, *work)
            .state == status::invalid);
  CHECK(conescan::sensor_physics_fast_crossings(head, scene.head.circle(), scene.sphere, 0.0,
                                                crossings<double>::failed(status::miss), *work)
            .state == status::miss);
  // A field as wide along the scan as the chord: grazing (the row's own check).
  physics_scene_options o;
  o.alpha_deg = -16.7L;
  const auto narrow = make_physics_scene<double>(o);
  REQUIRE(narrow.geometric.state == status::ok);
  auto wide = brief_settings<double>();
  wide.field.fov_rad = narrow.geometric.chord() * std::sin(conescan::deg_to_rad(45.0)) * 1.001;
  CHECK(fast(narrow, sensor_physics_fast_head_of(wide), 0.0, *work).state == status::grazing);
  // A fixed threshold the plateau never reaches: miss, on the fast path; just below: ok.
  auto fixed = brief_settings<double>();
  fixed.locator = {locator_kind::fixed, 1.0001};
  CHECK(fast(scene, sensor_physics_fast_head_of(fixed), 0.0, *work).state == status::miss);
  CHECK(work->last == physics_method::fast);
  fixed.locator = {locator_kind::fixed, 0.9999};
  CHECK(fast(scene, sensor_physics_fast_head_of(fixed), 0.0, *work).state == status::ok);
  CHECK(work->last == physics_method::fast);
}

TEMPLATE_TEST_CASE("the fast method in every scalar type", "[physics-fast]", float, double,
                   long double, conescan_test::adl_real) {
  using T = TestType;
  auto work = fast_workspace<T>();
  auto reference_work = fast_workspace<double>();
  const auto scene = make_physics_scene<T>(physics_scene_options{});
  const auto scene_double = make_physics_scene<double>(physics_scene_options{});
  const crossings<T> c = fast(scene, sensor_physics_fast_head_of(brief_settings<T>()), T(0), *work);
  const crossings<double> d = fast(
      scene_double, sensor_physics_fast_head_of(brief_settings<double>()), 0.0, *reference_work);
  REQUIRE(c.state == status::ok);
  CHECK(work->last == physics_method::fast);
  // float: heights keep a few ulp of R (0.5 m), up to 1.4e-5 deg of azimuth (measured 4e-6 deg);
  // long double and the ADL type (long double inside) agree with double to its error (1e-11).
  const long double tolerance = std::is_same_v<T, float> ? 5e-5L : 1e-8L;
  WARN("fast in " << typeid(T).name() << " - double: in "
                  << static_cast<double>(in_degrees(c.phi_in) - in_degrees(d.phi_in)) << ", out "
                  << static_cast<double>(in_degrees(c.phi_out) - in_degrees(d.phi_out)) << " deg");
  CHECK_CLOSE(in_degrees(c.phi_in), in_degrees(d.phi_in), tolerance);
  CHECK_CLOSE(in_degrees(c.phi_out), in_degrees(d.phi_out), tolerance);
}
