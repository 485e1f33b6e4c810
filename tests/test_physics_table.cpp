// The physics table: the core's tensor Chebyshev box (conescan/chebyshev_box.hpp) on functions
// whose values are known, where it gives up, and the scene's table of the sensor physics' crossing
// shifts (src/scene/physics_table.hpp) against the chain it tabulates, alone and in a scene.
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <memory>
#include <random>

#include "conescan/chebyshev_box.hpp"
#include "conescan/sensor_physics.hpp"
#include "scene/physics_table.hpp"
#include "scene/simulation.hpp"
#include "support/adl_scalar.hpp"
#include "support/scene_of.hpp"
#include "support/sensor_physics_scene.hpp"

using namespace conescan;
using conescan_test::scene_of;

namespace {

using box3 = chebyshev_box<double, 2, 4096>;

// Two analytic outputs of three variables.
bool smooth(const std::array<double, 3>& x, std::array<double, 2>& out) {
  out = {std::exp(x[0]) * std::sin(x[1]) + x[2] * x[2], std::cos(x[0] * x[1] + x[2])};
  return true;
}

// Points of the box from a fixed sequence, none on a node.
std::array<double, 3> inside(const std::array<double, 3>& lo, const std::array<double, 3>& hi,
                             int k) {
  std::array<double, 3> x{};
  for (int d = 0; d < 3; ++d) {
    const double u = std::fmod(0.137 + k * (0.381966 + 0.1 * d), 1.0);
    x[d] = lo[d] + (hi[d] - lo[d]) * u;
  }
  return x;
}

}  // namespace

TEST_CASE("chebyshev box: an analytic function to its tolerance, and held variables",
          "[physics-table]") {
  auto box = std::make_unique<box3>();
  const std::array<double, 3> lo{-1, 0.5, 2}, hi{0.5, 2, 2.25};
  const auto report = chebyshev_box_build(*box, lo, hi, smooth, 1e-12, 100000);
  REQUIRE(report.ok);
  CHECK(report.worst_check <= 1e-12);
  for (int k = 0; k < 200; ++k) {
    const auto x = inside(lo, hi, k);
    std::array<double, 2> exact{};
    smooth(x, exact);
    const auto fitted = chebyshev_box_value(*box, x);
    CHECK(std::abs(fitted[0] - exact[0]) <= 2e-12);
    CHECK(std::abs(fitted[1] - exact[1]) <= 2e-12);
  }
  // A variable with lo == hi has one node and the function's value there.
  const std::array<double, 3> lo2{-1, 1.25, 2}, hi2{0.5, 1.25, 2};
  REQUIRE(chebyshev_box_build(*box, lo2, hi2, smooth, 1e-12, 100000).ok);
  CHECK(box->nodes[1] == 1);
  CHECK(box->nodes[2] == 1);
  std::array<double, 2> exact{};
  smooth({0.1, 1.25, 2}, exact);
  CHECK(std::abs(chebyshev_box_value(*box, {0.1, 1.25, 2})[0] - exact[0]) <= 1e-12);
  // contains: both sides of each edge, and the held variables' slack.
  CHECK(box->contains({-1, 1.25, 2}, 0));
  CHECK(box->contains({0.5, 1.25, 2}, 0));
  CHECK_FALSE(box->contains({std::nextafter(-1.0, -2.0), 1.25, 2}, 0));
  CHECK_FALSE(box->contains({std::nextafter(0.5, 1.0), 1.25, 2}, 0));
  CHECK(box->contains({0, 1.25 + 1e-13, 2}, 1e-12));
  CHECK_FALSE(box->contains({0, 1.25 + 1e-11, 2}, 1e-12));
  CHECK_FALSE(box->contains({std::nan(""), 1.25, 2}, 1e-12));
}

TEMPLATE_TEST_CASE("chebyshev box in every scalar", "[physics-table][scalar]",
                   CONESCAN_TEST_SCALARS) {
  using T = TestType;
  // exp(x) cos(y) on [0, 1] x [-1, 1], z held, to a thousand ulp of the scalar.
  auto f = [](const std::array<T, 3>& x, std::array<T, 1>& out) {
    using std::cos;
    using std::exp;
    out[0] = exp(x[0]) * cos(x[1]) + x[2];
    return true;
  };
  auto box = std::make_unique<chebyshev_box<T, 1, 1024>>();
  const T tolerance = T(1000) * std::numeric_limits<T>::epsilon();
  const auto report =
      chebyshev_box_build(*box, {T(0), T(-1), T(2)}, {T(1), T(1), T(2)}, f, tolerance, 100000);
  REQUIRE(report.ok);
  CHECK(box->nodes[2] == 1);
  const std::array<T, 3> x{T(3) / T(7), T(-2) / T(9), T(2)};
  std::array<T, 1> exact{};
  f(x, exact);
  using std::abs;
  CHECK(abs(chebyshev_box_value(*box, x)[0] - exact[0]) <= tolerance);
}

TEST_CASE("chebyshev box: where it gives up", "[physics-table]") {
  auto box = std::make_unique<box3>();
  const std::array<double, 3> lo{-1, 0, 0}, hi{1, 0, 0};
  // A kink: no series of 64 terms holds |x| to 1e-9.
  auto kink = [](const std::array<double, 3>& x, std::array<double, 2>& out) {
    out = {std::abs(x[0]), 0.0};
    return true;
  };
  CHECK_FALSE(chebyshev_box_build(*box, lo, hi, kink, 1e-9, 100000).ok);
  // A function that fails at a point, or is not finite there.
  auto fails = [](const std::array<double, 3>& x, std::array<double, 2>& out) {
    out = {x[0], x[0]};
    return x[0] < 0.9;
  };
  CHECK_FALSE(chebyshev_box_build(*box, lo, hi, fails, 1e-9, 100000).ok);
  auto infinite = [](const std::array<double, 3>& x, std::array<double, 2>& out) {
    out = {1 / (x[0] - x[0]), 0.0};
    return true;
  };
  CHECK_FALSE(chebyshev_box_build(*box, lo, hi, infinite, 1e-9, 100000).ok);
  // The budget: never more evaluations than it allows.
  const std::array<double, 3> lo1{-1, 0.5, 2}, hi1{1, 0.5, 2};
  const auto poor = chebyshev_box_build(*box, lo1, hi1, smooth, 1e-15, 40);
  CHECK_FALSE(poor.ok);
  CHECK(poor.evaluations <= 40);
  CHECK(chebyshev_box_build(*box, lo1, hi1, smooth, 1e-9, 21).evaluations <= 21);
}

TEST_CASE("physics table: the chain's shifts to 1e-7 deg over a box with attitude",
          "[physics-table][many-chain-rows]") {
  // The paper's head (sigma 0.02 deg, phi_A 30 deg) over the paper's ellipse and half a degree of
  // attitude, a 1.5 deg square field with 1 ms of lag: the table against the chain at
  // points of the box that are not its nodes.
  sensor_physics_settings<double> s;
  s.field = {deg_to_rad(1.5), field_shape::square};
  s.spin_hz = 1;
  s.tau_s = 1e-3;
  s.offset_m = 40000;
  const auto physics = sensor_physics_head_of(s);
  conescan_test::physics_scene_options o;
  o.phi_a_deg = 30;
  const auto sc = conescan_test::make_physics_scene<double>(o);
  const double radius = static_cast<double>(o.a_m);
  scene::physics_table_range range;
  range.add({6552000, deg_to_rad(89.5), deg_to_rad(-0.5)});
  range.add({8008000, deg_to_rad(90.5), deg_to_rad(0.5)});
  long evaluations = 0;
  const auto table =
      scene::physics_table::of(physics, sc.head, radius, range, 1000000, &evaluations);
  REQUIRE(table);
  INFO(table->pieces() << " pieces of up to " << table->report().nodes[0] << " x "
                       << table->report().nodes[1] << " x " << table->report().nodes[2] << ", "
                       << evaluations << " evaluations");
  CHECK(table->pieces() > 1);
  CHECK(table->report().worst_check <= scene::physics_table_tolerance_rad);
  auto work = std::make_unique<sensor_physics_workspace<double>>();
  double worst = 0;
  for (int k = 0; k < 25; ++k) {
    const auto x = inside(range.lo, range.hi, k);
    const scene::physics_table_row row = scene::physics_row_at(physics, sc.head, radius, x, *work);
    REQUIRE(row.geometric.state == status::ok);
    const crossings<double>& direct = row.physics;
    REQUIRE(direct.state == status::ok);
    crossings<double> by_table{};
    REQUIRE(table->crossings_at(x, row.geometric, by_table));
    worst = std::max({worst, std::abs(by_table.phi_in - direct.phi_in),
                      std::abs(by_table.phi_out - direct.phi_out)});
  }
  CHECK(rad_to_deg(worst) <= 1e-7);
  // Outside the box, or a chord the chain would give a status of its own (the field wider than
  // the chord) or the build never saw: not by table.
  crossings<double> unused{};
  const crossings<double> g = sc.geometric;
  const auto middle = inside(range.lo, range.hi, 3);
  REQUIRE(table->crossings_at(middle, g, unused));
  crossings<double> narrow = g;
  narrow.phi_out = narrow.phi_in + deg_to_rad(2.0);  // the field is 1.5 / sin 45 = 2.12 deg along
  CHECK_FALSE(table->crossings_at(middle, narrow, unused));
  crossings<double> wide = g;
  wide.phi_out = wide.phi_in + deg_to_rad(179.0);
  CHECK_FALSE(table->crossings_at(middle, wide, unused));
  CHECK_FALSE(table->crossings_at({8008001, deg_to_rad(90.0), 0.0}, g, unused));
  CHECK_FALSE(table->crossings_at({7000000, deg_to_rad(90.6), 0.0}, g, unused));
  // Too few rows to pay for it: no table, and nothing spent.
  CHECK_FALSE(scene::physics_table::of(physics, sc.head, radius, range, 80, &evaluations));
  CHECK(evaluations == 0);
}

TEST_CASE("physics table: a scene's rows by table are its rows by the chain to 1e-7 deg",
          "[physics-table]") {
  // Two orbits at 10 s (1237 rows) pay for a table; their first 20 rows alone do not. Both heads
  // have the physics on; the rows they share agree to the table's tolerance.
  const std::vector<std::pair<std::string, std::string>> common{
      {"model", "scan"},
      {"processing-horizon-km", "40"},
      {"radiance-offset-km", "40"},
      {"step-s", "10"},
      {"head", "fov=1.5,spin-hz=1,tau-ms=1"},
      {"head", "beta=-90,sigma=0.1,phase=40,fov=1,spin-hz=2,tau-ms=0.5,threshold=0.4"}};
  auto with = [&](const std::string& duration) {
    auto options = common;
    options.push_back({"duration-s", duration});
    return scene::simulation::of(scene_of(options)).value();
  };
  const scene::simulation whole = with("12360"), start = with("190");
  REQUIRE(whole.physics_by_table(0));
  REQUIRE(whole.physics_by_table(1));
  CHECK_FALSE(start.physics_by_table(0));
  std::vector<scene::row> a(start.rows(), whole.make_row()), b(start.rows(), start.make_row());
  whole.compute_rows(0, a.size(), a.data());
  start.compute_rows(0, b.size(), b.data());
  for (std::size_t k = 0; k < a.size(); ++k)
    for (std::size_t h = 0; h < 2; ++h) {
      REQUIRE(a[k].heads[h].state == status::ok);
      CHECK(std::abs(rad_to_deg(a[k].heads[h].chord_rad - b[k].heads[h].chord_rad)) <= 2e-7);
      CHECK(std::abs(rad_to_deg(a[k].heads[h].phase_rad - b[k].heads[h].phase_rad)) <= 1e-7);
    }
}

TEST_CASE("physics table: random heads, physics and boxes against the chain",
          "[physics-table][many-chain-rows]") {
  // 8 random scenes: the head's mounting, cone and misalignment; the field (pencil, square,
  // circle), lag, locator (normalised, fixed, slope), profile and disk; a box of distances and,
  // every other scene, of attitudes. Where a table is built, the row at 40 random points of its
  // box has the chain's status, and crossings within 5e-7 deg of the chain (the table holds it to
  // 1e-7 deg at its checks). Where no table is built the scene runs the chain: nothing to compare,
  // but most boxes must get one.
  std::mt19937_64 rng(2026);
  auto uniform = [&rng](double a, double b) {
    return std::uniform_real_distribution<double>(a, b)(rng);
  };
  int built = 0;
  for (int t = 0; t < 8; ++t) {
    sensor_physics_settings<double> s;
    s.field = {deg_to_rad(t % 5 == 0 ? 0.0 : uniform(0.1, 2)),
               t % 4 == 3 ? field_shape::circle : field_shape::square};
    s.spin_hz = uniform(0.5, 3);
    s.tau_s = t % 3 == 0 ? 0 : uniform(0, 2e-3);
    s.offset_m = uniform(0, 50000);
    s.scale_m = uniform(3000, 10000);
    s.disk = uniform(1, 2);
    s.locator = t % 7 == 0 ? horizon_locator<double>{locator_kind::fixed, uniform(0.2, 0.8)}
                : t % 11 == 0
                    ? horizon_locator<double>{locator_kind::slope, 0.5}
                    : horizon_locator<double>{locator_kind::normalised, uniform(0.2, 0.8)};
    REQUIRE(sensor_physics_settings_status(s) == status::ok);
    const auto physics = sensor_physics_head_of(s);
    conescan_test::physics_scene_options o;
    o.alpha_deg = uniform(-10, 10);
    o.beta_deg = uniform(-180, 180);
    o.gamma_deg = uniform(40, 50);
    o.sigma_deg = uniform(0, 0.5);
    o.phi_a_deg = uniform(-180, 180);
    o.a_m = 6378137 + uniform(0, 40000);
    const auto sc = conescan_test::make_physics_scene<double>(o);
    const double radius = static_cast<double>(o.a_m);
    const double r_lo = radius + uniform(500e3, 800e3), r_hi = r_lo + uniform(0, 1000e3);
    const double wander = deg_to_rad(t % 2 == 1 ? uniform(0.1, 1) : 0.0);
    const double eta = std::acos(sc.nadir_scan.z),
                 phi = std::atan2(sc.nadir_scan.y, sc.nadir_scan.x);
    scene::physics_table_range range;
    range.add({r_lo, eta - wander, phi - wander});
    range.add({r_hi, eta + wander, phi + wander});
    const auto table = scene::physics_table::of(physics, sc.head, radius, range, 100000000);
    if (!table) continue;
    ++built;
    auto work = std::make_unique<sensor_physics_workspace<double>>();
    for (int k = 0; k < 40; ++k) {
      const auto x = inside(range.lo, range.hi, k);
      const scene::physics_table_row row =
          scene::physics_row_at(physics, sc.head, radius, x, *work);
      crossings<double> by_table{};
      if (row.geometric.state != status::ok || !table->crossings_at(x, row.geometric, by_table))
        continue;
      const crossings<double>& chain = row.physics;
      INFO("scene " << t << " point " << k);
      REQUIRE(by_table.state == chain.state);
      if (chain.state != status::ok) continue;
      CHECK(rad_to_deg(std::abs(by_table.phi_in - chain.phi_in)) <= 5e-7);
      CHECK(rad_to_deg(std::abs(by_table.phi_out - chain.phi_out)) <= 5e-7);
    }
  }
  CHECK(built >= 4);
}
