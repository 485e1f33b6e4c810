// The physics table: the core's tensor Chebyshev box (conescan/chebyshev_box.hpp) on functions
// whose values are known, where it gives up, and the scene's table of the sensor physics' crossing
// shifts (src/simulation/physics_table.hpp) against the chain it tabulates, alone and in a scene.
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <memory>
#include <random>

#include "conescan/chebyshev_box.hpp"
#include "conescan/sensor_physics.hpp"
#include "simulation/physics_table.hpp"
#include "simulation/simulation.hpp"
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

using scene_options = std::vector<std::pair<std::string, std::string>>;

// The scene of `options` run for `duration` seconds.
scene::simulation scene_for(scene_options options, const std::string& duration) {
  options.push_back({"duration-s", duration});
  return scene::simulation::of(scene_of(options)).value();
}

// The first rows of `whole` (by table) against `start`'s (the same scene's first rows, too few
// for a table: the chain's), head by head: the same statuses, ok where `all_ok`, within the
// table's tolerance (1e-7 deg in phase, twice that in the chord, a difference of two crossings).
// The paper's ellipse at 1 s with the 40 km limb and the season term (A = 0.2), on `earth`, with
// one head.
scene_options season_scene(const std::string& earth, const std::string& head) {
  return {{"earth", earth},
          {"model", "scan"},
          {"processing-horizon-km", "40"},
          {"radiance-offset-km", "40"},
          {"radiance-season", "0.2"},
          {"step-s", "1"},
          {"head", head}};
}

void check_table_rows_are_chain_rows(const scene::simulation& whole, const scene::simulation& start,
                                     bool all_ok) {
  std::vector<scene::row> a(start.rows(), whole.make_row()), b(start.rows(), start.make_row());
  whole.compute_rows(0, a.size(), a.data());
  start.compute_rows(0, b.size(), b.data());
  for (std::size_t k = 0; k < a.size(); ++k)
    for (std::size_t h = 0; h < whole.head_count(); ++h) {
      REQUIRE(a[k].heads[h].state == b[k].heads[h].state);
      if (all_ok) REQUIRE(a[k].heads[h].state == status::ok);
      CHECK(std::abs(rad_to_deg(a[k].heads[h].chord_rad - b[k].heads[h].chord_rad)) <= 2e-7);
      CHECK(std::abs(rad_to_deg(a[k].heads[h].phase_rad - b[k].heads[h].phase_rad)) <= 1e-7);
    }
}

// The scene over `duration` s takes its physics from a table, its first 20 rows alone (19 s) do
// not, and those rows are the same both ways.
void check_tabulated_scene(const scene_options& options, const char* duration, bool all_ok) {
  const scene::simulation whole = scene_for(options, duration), start = scene_for(options, "19");
  REQUIRE(whole.physics_by_table(0));
  CHECK_FALSE(start.physics_by_table(0));
  check_table_rows_are_chain_rows(whole, start, all_ok);
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
  // A function that fails at one check point only, the first of the spread ones, with points
  // checked after it: the box is not ok (a failure is not hidden by the checks after it), and is
  // where the function fails a hair away instead.
  const std::array<double, 3> lo2{-1, 0.5, 2}, hi2{1, 0.5, 2};
  const double first_check = lo2[0] + (hi2[0] - lo2[0]) * (40503.0 / 65536.0);
  for (const double at : {first_check, first_check + 1e-6}) {
    auto fails_at = [at](const std::array<double, 3>& x, std::array<double, 2>& out) {
      smooth(x, out);
      return x[0] != at;
    };
    const bool ok =
        chebyshev_box_fit_checked(*box, lo2, hi2, {24, 1, 1}, fails_at, 1e-9, 100000, 16).ok;
    CHECK(ok == (at != first_check));
  }
  // The budget: never more evaluations than it allows.
  const std::array<double, 3> lo1{-1, 0.5, 2}, hi1{1, 0.5, 2};
  const auto poor = chebyshev_box_build(*box, lo1, hi1, smooth, 1e-15, 40);
  CHECK_FALSE(poor.ok);
  CHECK(poor.evaluations <= 40);
  CHECK(chebyshev_box_build(*box, lo1, hi1, smooth, 1e-9, 21).evaluations <= 21);
}

namespace {

// A function that may be told the points it is about to be asked for
// (chebyshev_detail::prefetching): it records each batch it is told of and each point it is
// asked for, and counts the points asked for in a batch's order after it was told.
struct prefetch_recorder {
  using prefetching = void;
  std::vector<std::array<double, 3>>* told;
  std::vector<std::array<double, 3>>* asked;
  long* in_order;  // asked where the oldest point told and not yet asked is that point

  bool operator()(const std::array<double, 3>& x, std::array<double, 2>& out) const {
    asked->push_back(x);
    if (!told->empty() && told->front() == x) {
      told->erase(told->begin());
      ++*in_order;
    }
    return smooth(x, out);
  }
  template <class PointAt>
  void prefetch(int count, const PointAt& point_at) const {
    for (int i = 0; i < count; ++i) told->push_back(point_at(i));
  }
};

}  // namespace

TEST_CASE("chebyshev box: a function told of the points ahead is asked for them, in that order",
          "[physics-table]") {
  // The sweeps' fresh points, the nodes and the checks are told before they are asked for, in the
  // order asked; only the middle (one point, asked alone) is not. The box is the same as a plain
  // function's, to the bit, for the same evaluations.
  std::vector<std::array<double, 3>> told, asked;
  long in_order = 0;
  const prefetch_recorder f{&told, &asked, &in_order};
  const std::array<double, 3> lo{-1, 0.5, 2}, hi{0.5, 2, 2.25};
  auto told_box = std::make_unique<box3>();
  auto plain_box = std::make_unique<box3>();
  const auto with_prefetch = chebyshev_box_build(*told_box, lo, hi, f, 1e-12, 100000);
  const auto plain = chebyshev_box_build(*plain_box, lo, hi, smooth, 1e-12, 100000);
  REQUIRE(with_prefetch.ok);
  CHECK(with_prefetch.evaluations == plain.evaluations);
  CHECK(told_box->nodes == plain_box->nodes);
  CHECK(told_box->coefficients == plain_box->coefficients);
  CHECK(told.empty());                                     // every point told was asked for
  CHECK(in_order == static_cast<long>(asked.size()) - 1);  // all but the middle
  CHECK(static_cast<long>(asked.size()) == with_prefetch.evaluations);
}

TEST_CASE("chebyshev box: the sweeps' nodes and what they cost", "[physics-table]") {
  // Polynomials in x0 of known degree (x1 held, x2 varying but constant in f): the nested sweeps
  // (3, 5, 9, 17, 33 points, the middle shared) see their series end, so the nodes are the degree
  // plus one, exactly, once two coefficients past it are seen (a sweep of n points picks at most
  // n - 2), and the cost is the points swept: x0's, then x2's four (three nodes want two zero
  // coefficients past them: the five-point sweep).
  long calls = 0;
  int degree = 0;
  auto polynomial = [&](const std::array<double, 3>& x, std::array<double, 2>& out) {
    ++calls;
    double p = 1, t = 1;
    for (int k = 1; k <= degree; ++k) p += (t *= x[0]) / k;
    out = {p, 0.5 * p};
    return true;
  };
  const std::array<double, 3> lo{-1, 0.25, 0}, hi{1, 0.25, 3};
  const double tolerance = 1e-12;
  for (const auto& [d, nodes, cost] : std::vector<std::array<int, 3>>{
           {2, 3, 5 + 4}, {4, 5, 9 + 4}, {6, 7, 9 + 4}, {7, 8, 17 + 4}, {15, 16, 33 + 4}}) {
    degree = d;
    calls = 0;
    const auto plan = chebyshev_box_nodes<double, 2>(lo, hi, polynomial, tolerance, 1000);
    INFO("degree " << d);
    REQUIRE(plan.ok);
    CHECK(plan.nodes[0] == nodes);
    CHECK(plan.nodes[1] == 1);  // held: no sweep
    CHECK(plan.nodes[2] == 3);  // constant, but the default fewest is 3
    CHECK(plan.evaluations == cost);
    CHECK(calls == cost);
  }
  // Constant and linear where the caller allows them; a degree past most_nodes: 0, and the plan
  // stops at that variable (swept first here: `first`), the others unswept.
  degree = 1;
  auto plan = chebyshev_box_nodes<double, 2>(lo, hi, polynomial, tolerance, 1000, 16, 1);
  CHECK(plan.nodes[0] == 2);
  CHECK(plan.nodes[2] == 1);
  degree = 15;  // 16 terms: more than 15 nodes, the most a 17-point sweep picks
  calls = 0;
  plan = chebyshev_box_nodes<double, 2>(lo, hi, polynomial, tolerance, 1000, 15, 1, 2);
  CHECK(plan.nodes[2] == 1);  // swept first (`first`)
  CHECK_FALSE(plan.ok);
  CHECK(plan.nodes[0] == 0);
  CHECK(calls == 1 + 2 + 16);  // the middle, x2's two, x0's sweep to 17 points
  degree = 14;                 // 15 nodes: the most a 17-point sweep picks
  CHECK(chebyshev_box_nodes<double, 2>(lo, hi, polynomial, tolerance, 1000, 15, 1).nodes[0] == 15);
  degree = 16;
  calls = 0;
  plan = chebyshev_box_nodes<double, 2>(lo, hi, polynomial, tolerance, 1000, 15, 1, 0);
  CHECK_FALSE(plan.ok);
  CHECK(calls == 17);  // x0 swept first fails: x2 is never swept
  // ... and a 33-point sweep where 64 are allowed finds its 17.
  degree = 16;
  plan = chebyshev_box_nodes<double, 2>(lo, hi, polynomial, tolerance, 1000);
  CHECK(plan.ok);
  CHECK(plan.nodes[0] == 17);
  // The budget stops a sweep before it passes it.
  calls = 0;
  plan = chebyshev_box_nodes<double, 2>(lo, hi, polynomial, tolerance, 10);
  CHECK_FALSE(plan.ok);
  CHECK(calls <= 10);
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
  const scene_options common{
      {"model", "scan"},
      {"processing-horizon-km", "40"},
      {"radiance-offset-km", "40"},
      {"step-s", "10"},
      {"head", "fov=1.5,spin-hz=1,tau-ms=1"},
      {"head", "beta=-90,sigma=0.1,phase=40,fov=1,spin-hz=2,tau-ms=0.5,threshold=0.4"}};
  const scene::simulation whole = scene_for(common, "12360"), start = scene_for(common, "190");
  REQUIRE(whole.physics_by_table(0));
  REQUIRE(whole.physics_by_table(1));
  CHECK_FALSE(start.physics_by_table(0));
  check_table_rows_are_chain_rows(whole, start, true);
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

namespace {

// The ellipsoid table's rows: the paper's head (phi_A 30 deg) on WGS84's horizon 40 km up along
// an arc of a polar orbit of the paper's ellipse (nu from 0 to 0.6 rad), roll and pitch wandering
// over +-0.2 deg, the Sun's declination moving from 20 to 20.1 deg: a pencil with 1 ms of lag at
// 1 rev/s and the season term (A = 0.2), whose chain is fast enough to compare many rows.
struct ellipsoid_rows {
  sensor_physics_settings<double> settings;
  std::vector<conescan_test::physics_scene<double>> scenes;
  std::vector<double> sin_sun;
  double a_m = 0, b_m = 0;
};

ellipsoid_rows ellipsoid_arc(int count, double wander_deg, double nu_from = 0, double nu_to = 0.6) {
  ellipsoid_rows rows;
  rows.settings.spin_hz = 1;
  rows.settings.tau_s = 1e-3;
  rows.settings.offset_m = 40000;
  rows.settings.season_amplitude = 0.2;
  for (int i = 0; i < count; ++i) {
    const double nu = nu_from + (nu_to - nu_from) * i / (count - 1);
    conescan_test::physics_scene_options o;
    o.phi_a_deg = 30;
    o.ellipsoid = true;
    o.b_m = 6356752.314245L + 40000;
    o.distance_m = 7280000 * (1 - 0.01) / (1 + 0.1 * std::cos(nu));
    o.roll_deg = wander_deg * std::sin(3 * nu * 10);
    o.pitch_deg = wander_deg * std::cos(2 * nu * 10);
    o.polar_x = std::cos(nu);
    o.polar_y = 0;
    o.polar_z = std::sin(nu);
    rows.scenes.push_back(conescan_test::make_physics_scene<double>(o));
    rows.sin_sun.push_back(std::sin(deg_to_rad(20 + 0.1 * i / (count - 1))));
  }
  rows.a_m = static_cast<double>(rows.scenes.front().options.a_m);
  rows.b_m = static_cast<double>(rows.scenes.front().options.b_m);
  return rows;
}

struct ellipsoid_build {
  scene::ellipsoid_table_axes axes;
  std::shared_ptr<const scene::ellipsoid_physics_table> table;
  long evaluations = 0;
};

// The table of a scene of scene_rows rows, of which `rows` are a sample, each standing for
// rows_each of the scene's (0: scene_rows / their count), in the cells of cells_for_rows rows;
// with the cells' second pass (the rows along their curve) where `along`, as the scene's.
ellipsoid_build build_ellipsoid_table(const ellipsoid_rows& rows, long scene_rows,
                                      long cells_for_rows = 4096, long rows_each = 0,
                                      bool along = true, int threads = 1) {
  ellipsoid_build b;
  scene::ellipsoid_axes_finder finder;
  for (const auto& sc : rows.scenes) finder.add(sc.horizon.polar);
  b.axes = finder.axes();
  auto point = [&](std::size_t i) {
    return scene::ellipsoid_table_point_of(rows.scenes[i].horizon, rows.a_m, b.axes,
                                           rows.sin_sun[i]);
  };
  scene::ellipsoid_table_range range;
  for (std::size_t i = 0; i < rows.scenes.size(); ++i) range.add(point(i));
  scene::physics_table_cells<6> cells =
      scene::ellipsoid_physics_table::cells_for(range, cells_for_rows);
  // The cells count the scene's rows.
  if (rows_each == 0) rows_each = std::max(1L, scene_rows / static_cast<long>(rows.scenes.size()));
  for (std::size_t i = 0; i < rows.scenes.size(); ++i) cells.add(point(i), rows_each);
  if (along)
    for (std::size_t i = 0; i < rows.scenes.size(); ++i) cells.add_along(point(i));
  b.table = scene::ellipsoid_physics_table::of(sensor_physics_head_of(rows.settings),
                                               rows.scenes.front().head, rows.a_m, rows.b_m, b.axes,
                                               cells, scene_rows, &b.evaluations, threads);
  return b;
}

// The table at `at` against the chain there: false where the table does not serve it; else the
// statuses must agree, and `worst` takes the larger crossing difference (rad).
bool served_as_chain(const ellipsoid_build& b, const ellipsoid_rows& rows,
                     const sensor_physics_head<double>& physics,
                     const scene::ellipsoid_table_point& at, sensor_physics_workspace<double>& work,
                     double& worst) {
  const scene::physics_table_row row = scene::ellipsoid_row_at(
      physics, rows.scenes.front().head, rows.a_m, rows.b_m, b.axes, at, work);
  crossings<double> by_table{};
  if (row.geometric.state != status::ok || !b.table->crossings_at(at, row.geometric, by_table))
    return false;
  REQUIRE(by_table.state == row.physics.state);
  worst = std::max({worst, std::abs(by_table.phi_in - row.physics.phi_in),
                    std::abs(by_table.phi_out - row.physics.phi_out)});
  return true;
}

}  // namespace

TEST_CASE(
    "ellipsoid physics table: the chain's shifts to 1e-7 deg with attitude wander, WGS84 "
    "and the season term",
    "[physics-table][many-chain-rows]") {
  const ellipsoid_rows rows = ellipsoid_arc(200, 0.2);
  const ellipsoid_build b = build_ellipsoid_table(rows, 400000);
  REQUIRE(b.table);
  const auto& nodes = b.table->report().nodes;
  INFO(b.table->pieces() << " pieces of up to " << nodes[0] << " x " << nodes[1] << " x "
                         << nodes[2] << " x " << nodes[3] << " x " << nodes[4] << " x " << nodes[5]
                         << ", " << b.evaluations << " evaluations, " << b.table->chain_cells()
                         << " cells left to the chain");
  CHECK(b.table->report().worst_check <= scene::physics_table_tolerance_rad);
  const auto physics = sensor_physics_head_of(rows.settings);
  auto work = std::make_unique<sensor_physics_workspace<double>>();
  // Every row, and the point halfway to the next (not a row: served only inside a piece's box):
  // the table where it serves is the chain at that point, with the chain's status.
  int served_rows = 0, served_between = 0;
  double worst = 0;
  for (std::size_t i = 0; i + 1 < rows.scenes.size(); i += 3) {
    const auto x =
        scene::ellipsoid_table_point_of(rows.scenes[i].horizon, rows.a_m, b.axes, rows.sin_sun[i]);
    const auto next = scene::ellipsoid_table_point_of(rows.scenes[i + 1].horizon, rows.a_m, b.axes,
                                                      rows.sin_sun[i + 1]);
    scene::ellipsoid_table_point between{};
    for (int d = 0; d < 6; ++d) between[d] = (x[d] + next[d]) / 2;
    served_rows += served_as_chain(b, rows, physics, x, *work, worst);
    served_between += served_as_chain(b, rows, physics, between, *work, worst);
  }
  INFO("served " << served_rows << " rows and " << served_between << " points between them");
  CHECK(rad_to_deg(worst) <= 1e-7);
  CHECK(served_rows >= 60);  // 67 rows compared; a cell left to the chain serves none
  // The rows' own geometry (the scene's ellipsoid, not rebuilt from the variables): the same.
  for (std::size_t i = 0; i < rows.scenes.size(); i += 17) {
    const auto& sc = rows.scenes[i];
    crossings<double> by_table{};
    const auto x = scene::ellipsoid_table_point_of(sc.horizon, rows.a_m, b.axes, rows.sin_sun[i]);
    if (!b.table->crossings_at(x, sc.geometric, by_table)) continue;
    const crossings<double> chain = sc.physics(physics, rows.sin_sun[i], *work);
    REQUIRE(by_table.state == chain.state);
    CHECK(rad_to_deg(std::abs(by_table.phi_in - chain.phi_in)) <= 1e-7);
    CHECK(rad_to_deg(std::abs(by_table.phi_out - chain.phi_out)) <= 1e-7);
  }
  // Both sides of where it serves: a row's point is served, and not once a variable leaves its
  // piece's box (the distance 1 km beyond the arc's, the Sun beyond its range, the pole's angle
  // across the held one), nor at a chord the build never saw.
  const auto& sc = rows.scenes[100];
  const auto x = scene::ellipsoid_table_point_of(sc.horizon, rows.a_m, b.axes, rows.sin_sun[100]);
  crossings<double> unused{};
  REQUIRE(b.table->crossings_at(x, sc.geometric, unused));
  auto moved = [&](int d, double by) {
    auto y = x;
    y[d] += by;
    return y;
  };
  CHECK_FALSE(b.table->crossings_at(moved(0, 2000e3), sc.geometric, unused));
  CHECK_FALSE(b.table->crossings_at(moved(5, 0.01), sc.geometric, unused));
  CHECK_FALSE(b.table->crossings_at(moved(3, 0.01), sc.geometric, unused));
  CHECK(b.table->crossings_at(moved(3, 1e-13), sc.geometric, unused));
  crossings<double> wide = sc.geometric;
  wide.phi_out = wide.phi_in + deg_to_rad(179.0);
  CHECK_FALSE(b.table->crossings_at(x, wide, unused));
  // Too few rows to pay for it: no table, and nothing spent.
  CHECK_FALSE(build_ellipsoid_table(rows, 80).table);
}

TEST_CASE(
    "ellipsoid physics table: a WGS84 scene with the season term by table is its rows by "
    "the chain to 1e-7 deg",
    "[physics-table][many-chain-rows]") {
  // A day at 1 s (86 401 rows) pays for a table; its first 20 rows alone do not. A pencil with
  // lag and the season term of each row's Sun on WGS84's ellipsoid.
  const scene_options common = season_scene("wgs84", "sigma=0.05,phase=30,spin-hz=1,tau-ms=1");
  check_tabulated_scene(common, "86400", false);
}

TEST_CASE(
    "ellipsoid physics table: a sphere's scene with the season term by table is its rows by the "
    "chain to 1e-7 deg",
    "[physics-table][many-chain-rows]") {
  // The sphere with the season term: the six variables' table on an ellipsoid of semi-axes R, R,
  // its rows by the sphere's chain (sphere_row_at); a pencil from 256 rows, a field from 512.
  // Measured: a day of the pencil 0.40 s of CPU, of a 1.5 deg square 6.1 s (the chain on every
  // row some 21 s and 12 minutes).
  const scene_options pencil = season_scene("sphere", "sigma=0.05,phase=30,spin-hz=1,tau-ms=1");
  check_tabulated_scene(pencil, "86400", true);
  const scene_options square =
      season_scene("sphere", "sigma=0.05,phase=30,fov=1.5,spin-hz=1,tau-ms=1");
  check_tabulated_scene(square, "511", true);
  CHECK_FALSE(scene_for(square, "510").physics_by_table(0));
}

TEST_CASE(
    "ellipsoid physics table: a field's WGS84 scene by table is its rows by the chain to 1e-7 deg",
    "[physics-table][many-chain-rows]") {
  // A field's head is tabulated on WGS84 where its rows are many (512 or more, a budget of 128
  // evaluations): a circular orbit at 1 s, some 9 minutes (a build of a few dozen evaluations of
  // the 1.5 deg square's chain); its first 20 rows, and 511, run the chain.
  const scene_options common{{"earth", "wgs84"},
                             {"model", "scan"},
                             {"e", "0"},
                             {"processing-horizon-km", "40"},
                             {"radiance-offset-km", "40"},
                             {"step-s", "1"},
                             {"head", "sigma=0.05,phase=30,fov=1.5,spin-hz=1,tau-ms=1"}};
  check_tabulated_scene(common, "511", true);
  CHECK_FALSE(scene_for(common, "510").physics_by_table(0));
}

// The arc of the same orbit where the normalised locator's peak moves from the Earth-in window to
// the Earth-out window (nu 4.69 rad, found by the chain's peak_part): the crossings have a kink
// there. The build cuts the kink's cells out, to the chain, and builds a piece either side: 110
// evaluations (measured; 231 before the build read its plan's own values for the kink's places and
// the checks), where halving the failed pieces down to the kink took 502.
TEST_CASE(
    "ellipsoid physics table: the kink where the peak moves from one window to the other is "
    "cut out to the chain, the pieces beside it hold",
    "[physics-table][many-chain-rows]") {
  const ellipsoid_rows rows = ellipsoid_arc(200, 0, 4.55, 4.85);
  const auto physics = sensor_physics_head_of(rows.settings);
  auto work = std::make_unique<sensor_physics_workspace<double>>();
  const auto peak_part_of_row = [&](std::size_t i) {
    rows.scenes[i].physics(physics, rows.sin_sun[i], *work);
    return work->peak_part;
  };
  REQUIRE(peak_part_of_row(0) == 0);
  REQUIRE(peak_part_of_row(rows.scenes.size() - 1) == 1);
  const ellipsoid_build b = build_ellipsoid_table(rows, 400000);
  REQUIRE(b.table);
  INFO(b.table->pieces() << " pieces, " << b.evaluations << " evaluations, "
                         << b.table->chain_cells() << " cells left to the chain");
  CHECK(b.table->report().worst_check <= scene::physics_table_tolerance_rad);
  CHECK(b.evaluations <= 150);
  CHECK(b.table->chain_cells() >= 1);
  CHECK(b.table->chain_cells() <= 4);  // the kink's one or two cells, and one either side
  int served = 0;
  double worst = 0;
  for (std::size_t i = 0; i < rows.scenes.size(); ++i)
    served += served_as_chain(
        b, rows, physics,
        scene::ellipsoid_table_point_of(rows.scenes[i].horizon, rows.a_m, b.axes, rows.sin_sun[i]),
        *work, worst);
  INFO("served " << served << " of " << rows.scenes.size() << " rows");
  CHECK(rad_to_deg(worst) <= 1e-7);
  CHECK(served >= 180);  // 184: the rows of the four cells are the chain's
}

// An arc with attitude wander, with budgets short of the whole build's: the pieces built before
// the budget ran out serve their rows, to the chain's 1e-7 deg, and the rest are the chain's; the
// build never spends more than its budget.
TEST_CASE(
    "ellipsoid physics table: a budget that runs out keeps the pieces built, the rest of the "
    "rows to the chain",
    "[physics-table][many-chain-rows]") {
  const ellipsoid_rows rows = ellipsoid_arc(200, 0.2);
  const auto physics = sensor_physics_head_of(rows.settings);
  auto work = std::make_unique<sensor_physics_workspace<double>>();
  const ellipsoid_build whole = build_ellipsoid_table(rows, 400000);
  REQUIRE(whole.table);
  for (const long budget : {whole.evaluations * 3 / 4, whole.evaluations * 9 / 10}) {
    // Each of the 200 rows stands for 2000 of the scene's, so that its cells' pieces pay.
    const ellipsoid_build b = build_ellipsoid_table(rows, 4 * budget, 4096, 2000);
    INFO("budget " << budget << ": " << b.evaluations << " evaluations; the whole build "
                   << whole.evaluations);
    CHECK(b.evaluations <= budget);
    REQUIRE(b.table);
    CHECK(b.table->chain_cells() > whole.table->chain_cells());
    int served = 0;
    double worst = 0;
    for (std::size_t i = 0; i < rows.scenes.size(); ++i)
      served += served_as_chain(b, rows, physics,
                                scene::ellipsoid_table_point_of(rows.scenes[i].horizon, rows.a_m,
                                                                b.axes, rows.sin_sun[i]),
                                *work, worst);
    INFO("served " << served << " of " << rows.scenes.size() << " rows");
    CHECK(rad_to_deg(worst) <= 1e-7);
    CHECK(served >= 10);  // 49 and 99, measured; the whole build serves some 190
    CHECK(served < 180);
  }
}

namespace {

// The build asks the chain for the same points whatever the threads that compute them (they are
// computed ahead, together, where the build says which it will ask for): the same evaluations,
// pieces and cells, and every row the same to the bit, on one thread and on three.
void check_same_table_on_threads(const ellipsoid_rows& rows, long scene_rows, long rows_each) {
  const ellipsoid_build one = build_ellipsoid_table(rows, scene_rows, 4096, rows_each, true, 1);
  const ellipsoid_build three = build_ellipsoid_table(rows, scene_rows, 4096, rows_each, true, 3);
  REQUIRE(one.table);
  REQUIRE(three.table);
  CHECK(one.evaluations == three.evaluations);
  CHECK(one.table->pieces() == three.table->pieces());
  CHECK(one.table->chain_cells() == three.table->chain_cells());
  CHECK(one.table->report().worst_check == three.table->report().worst_check);
  int served = 0;
  for (std::size_t i = 0; i < rows.scenes.size(); ++i) {
    const auto& sc = rows.scenes[i];
    const auto x = scene::ellipsoid_table_point_of(sc.horizon, rows.a_m, one.axes, rows.sin_sun[i]);
    crossings<double> a{}, b{};
    const bool by_one = one.table->crossings_at(x, sc.geometric, a);
    REQUIRE(by_one == three.table->crossings_at(x, sc.geometric, b));
    if (!by_one) continue;
    ++served;
    CHECK(a.phi_in == b.phi_in);
    CHECK(a.phi_out == b.phi_out);
  }
  CHECK(served > 0);
}

}  // namespace

// The arc of the kink (its search's places computed together): some 110 evaluations of a pencil's
// chain, cheap enough for the sanitizers' suite.
TEST_CASE("ellipsoid physics table: the same table to the bit on one thread and on three",
          "[physics-table][threads]") {
  check_same_table_on_threads(ellipsoid_arc(200, 0, 4.55, 4.85), 400000, 0);
}

// The arc with attitude wander (pieces halved), whole and with a budget cut short.
TEST_CASE(
    "ellipsoid physics table: the same table to the bit on one thread and on three, with "
    "attitude wander and a short budget",
    "[physics-table][many-chain-rows][threads]") {
  const ellipsoid_rows wander = ellipsoid_arc(200, 0.2);
  check_same_table_on_threads(wander, 400000, 0);
  const long short_budget = build_ellipsoid_table(wander, 400000).evaluations * 3 / 4;
  check_same_table_on_threads(wander, 4 * short_budget, 2000);
}

// Cells keep the rows' box; the second pass carries each cell's rows along the line through its
// neighbours' middles, so that rows on a curve span their own spread about it, not the curve's
// change across the cell (on a day's orbit some 110 m of distance a cell).
TEST_CASE("physics table cells: rows along the curve they follow, a scatter in its box",
          "[physics-table]") {
  using point = std::array<double, 6>;
  scene::basic_physics_table_range<6> range;
  // Variable 4 splits; 0 follows it steeply (1e6 per unit, a curve), 5 scatters (the Sun's
  // declination over orbits hours apart); the rest are held.
  const auto row = [](int i) {
    const double s = i / 1000.0;
    return point{1e6 * s + 3e5 * s * s, 0.1, 0.2, 0.3, s, 1e-3 * std::sin(i * 2.3)};
  };
  for (int i = 0; i <= 1000; ++i) range.add(row(i));
  scene::physics_table_cells<6> cells(range, 4, 300);  // some cells with several rows
  for (int i = 0; i <= 1000; ++i) cells.add(row(i));
  int several = -1;
  for (int c = 0; c < 300 && several < 0; ++c)
    if (cells.rows[static_cast<std::size_t>(c)] >= 3) several = c;
  REQUIRE(several >= 0);
  const auto& box = cells.cells[static_cast<std::size_t>(several)];
  const double middle = cells.middle_of(several);
  // Before the second pass: the box, at any place.
  const auto before = cells.rows_at(several, box.lo[4]);
  CHECK(before.lo[0] == box.lo[0]);
  CHECK(before.hi[0] == box.hi[0]);
  CHECK(before.lo[4] == box.lo[4]);
  for (int i = 0; i <= 1000; ++i) cells.add_along(row(i));
  // After it: the curve's rows at the cell's ends within its curvature over the cell of the curve
  // there (the box spans the whole change, 1e6 times the cell's rows' spread), the scatter in its
  // box, the held variables as they are.
  const double spread = box.hi[4] - box.lo[4];
  REQUIRE(box.hi[0] - box.lo[0] > 0.9e6 * spread);
  for (double at : {box.lo[4], middle, box.hi[4]}) {
    const auto rows = cells.rows_at(several, at);
    const double curve = 1e6 * at + 3e5 * at * at;
    INFO("at " << at << ": [" << rows.lo[0] << ", " << rows.hi[0] << "] against " << curve);
    CHECK(rows.hi[0] - rows.lo[0] <= 1e-3 * (box.hi[0] - box.lo[0]));
    CHECK(std::abs((rows.lo[0] + rows.hi[0]) / 2 - curve) <= 3e5 * spread * spread + 1e-9);
    CHECK(rows.lo[5] == box.lo[5]);
    CHECK(rows.hi[5] == box.hi[5]);
    CHECK(rows.lo[1] == 0.1);
    CHECK(rows.hi[1] == 0.1);
    CHECK(rows.lo[4] == at);
    CHECK(rows.hi[4] == at);
  }
}

// The pole seen from an orbit-referenced attitude cones about the orbit's normal at the
// inclination i. Over a fraction of a turn the poles' cross products about the origin leave sin i
// cos i times a turning direction uncancelled, which near the equator outweighs the sin^2 i along
// the axis (a day of 15.3 turns at i = 3.8 deg had tilted w 18 deg, and the build took 8 932
// evaluations where it takes 280); about the poles' mean the axis is found for any fraction.
TEST_CASE(
    "ellipsoid table axes: the axis a pole cones about at any inclination and fraction of a turn",
    "[physics-table]") {
  const vec3<double> axis = unit(vec3<double>(0.3, -0.5, 0.8));
  const vec3<double> across = unit(cross(axis, vec3<double>(1, 0, 0)));
  const vec3<double> third = cross(axis, across);
  for (double inclination_deg : {0.5, 3.8, 45.0, 98.6}) {
    for (double turns : {0.3, 1.0, 15.3}) {
      scene::ellipsoid_axes_finder finder;
      const double i = deg_to_rad(inclination_deg);
      const int steps = 43000;
      for (int k = 0; k <= steps; ++k) {
        const double t = 2 * std::acos(-1.0) * turns * k / steps + 0.7;
        finder.add(scaled(axis, std::cos(i)) + scaled(across, std::sin(i) * std::cos(t)) +
                   scaled(third, std::sin(i) * std::sin(t)));
      }
      const vec3<double> w = finder.axes().w;
      INFO("i = " << inclination_deg << " deg over " << turns
                  << " turns: w . axis = " << dot(w, axis));
      CHECK(std::abs(dot(w, axis)) >= 1 - 1e-12);
    }
  }
}

// The arc's distance is a function of the pole's azimuth (as on a two-body orbit). In 64 cells of
// some six rows each a cell's box spans kilometres of it; carried along the curve, a cell's rows
// span its curvature across the cell (some 15 m): the distance takes fewer nodes, and the build
// half the evaluations (476 against 952, measured). In a day's cells, a row or two each, the
// distance's offsets span a millimetre and it takes one node (docs/SENSOR_PHYSICS.md, "On WGS84").
TEST_CASE("ellipsoid physics table: a distance that follows the pole's azimuth, along its curve",
          "[physics-table][many-chain-rows]") {
  const ellipsoid_rows rows = ellipsoid_arc(400, 0, 0, 0.6);
  const ellipsoid_build along = build_ellipsoid_table(rows, 400000, 64, 0, true);
  const ellipsoid_build boxes = build_ellipsoid_table(rows, 400000, 64, 0, false);
  REQUIRE(along.table);
  REQUIRE(boxes.table);
  INFO(along.evaluations << " evaluations along the curve, " << boxes.evaluations
                         << " with the cells' boxes; distance nodes "
                         << along.table->report().nodes[0] << " and "
                         << boxes.table->report().nodes[0]);
  CHECK(along.table->report().nodes[0] < boxes.table->report().nodes[0]);
  CHECK(10 * along.evaluations <= 6 * boxes.evaluations);
  CHECK(along.table->report().worst_check <= scene::physics_table_tolerance_rad);
  const auto physics = sensor_physics_head_of(rows.settings);
  auto work = std::make_unique<sensor_physics_workspace<double>>();
  int served = 0;
  double worst = 0;
  for (std::size_t i = 0; i < rows.scenes.size(); i += 2)
    served += served_as_chain(along, rows, physics,
                              scene::ellipsoid_table_point_of(rows.scenes[i].horizon, rows.a_m,
                                                              along.axes, rows.sin_sun[i]),
                              *work, worst);
  INFO("served " << served << " of " << (rows.scenes.size() + 1) / 2 << " rows");
  CHECK(served >= 190);
  CHECK(rad_to_deg(worst) <= 1e-7);
}

// One cell (cells_for with 1 row) holds every row: below physics_table_least_piece_evaluations
// rows the chain runs them for fewer evaluations than a piece would cost, and no piece is tried.
TEST_CASE(
    "ellipsoid physics table: rows fewer than a piece costs are the chain's, without an "
    "evaluation; as many are tried",
    "[physics-table]") {
  const int least = static_cast<int>(scene::physics_table_least_piece_evaluations);
  const ellipsoid_build below = build_ellipsoid_table(ellipsoid_arc(least - 1, 0.2), 400000, 1, 1);
  CHECK_FALSE(below.table);
  CHECK(below.evaluations == 0);
  const ellipsoid_build at = build_ellipsoid_table(ellipsoid_arc(least, 0.2), 400000, 1, 1);
  CHECK(at.evaluations > 0);
}

TEST_CASE("ellipsoid physics table: rows against the brute-force reference",
          "[physics-table][brute-force]") {
  // Two of the arc's rows by table against tests/support/sensor_physics_reference.hpp (long
  // double, no code shared with the chain or the table): within 1e-6 deg, the target.
  const ellipsoid_rows rows = ellipsoid_arc(60, 0.2);
  const ellipsoid_build b = build_ellipsoid_table(rows, 400000);
  REQUIRE(b.table);
  const long double to_deg = 180 / 3.14159265358979323846264338327950288L;
  for (std::size_t i : {std::size_t{7}, std::size_t{41}}) {
    const auto& sc = rows.scenes[i];
    crossings<double> by_table{};
    REQUIRE(b.table->crossings_at(
        scene::ellipsoid_table_point_of(sc.horizon, rows.a_m, b.axes, rows.sin_sun[i]),
        sc.geometric, by_table));
    const auto reference =
        conescan_test::reference_crossings_of(sc, rows.settings, rows.sin_sun[i], 0.02);
    REQUIRE(reference.crossings.state == status::ok);
    const long double d_in = (by_table.phi_in - reference.crossings.phi_in) * to_deg;
    const long double d_out = (by_table.phi_out - reference.crossings.phi_out) * to_deg;
    WARN("table - reference, row " << i << ": in " << static_cast<double>(d_in) << " out "
                                   << static_cast<double>(d_out) << " deg");
    CHECK(std::abs(static_cast<double>(d_in)) <= 1e-6);
    CHECK(std::abs(static_cast<double>(d_out)) <= 1e-6);
  }
}
