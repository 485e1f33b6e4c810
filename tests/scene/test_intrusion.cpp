// Sun and Moon in the scan (include/conescan/intrusion.hpp, MODEL §13): each boundary of the rule
// on both sides, in every scalar (on the cone by fov/2 + r +- d; pulses that just meet and just
// miss the Earth pulse, across 0/2 pi; a body just hidden and just visible on a sphere and on an
// ellipsoid), the verdict's order, hostile inputs, and the rule on real orbits: a head whose spin
// axis is the orbit normal, and the Sun seasons of an 800 km sun-synchronous orbit with a
// pitch-axis head (the day counts are printed by `conescan_tests "[intrusion]" -s` and quoted in
// docs/SUN_MOON.md).
//
// Test code of the generic cases follows the core's rules (ADL math, constants from integers).
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "conescan/intrusion.hpp"
#include "conescan/orbital_frame.hpp"
#include "conescan/sensor_head.hpp"
#include "orbit/kepler.hpp"
#include "orbit/wgs84.hpp"
#include "sources/sun_moon.hpp"
#include "support/adl_scalar.hpp"
#include "support/approx.hpp"

using namespace conescan;
using conescan_test::deg;
using conescan_test::eps;
using conescan_test::scalar_from;

namespace {

/// A unit vector at angle psi from the circle's axis A, at angle theta about A from u.
template <class T>
vec3<T> at_angle_from_axis(const scan_circle<T>& c, const T& psi, const T& theta) {
  using std::cos;
  using std::sin;
  return scaled(c.axis, T(cos(psi))) +
         scaled(scaled(c.u, T(cos(theta))) + scaled(c.v, T(sin(theta))), T(sin(psi)));
}

template <class T>
crossings<T> earth_crossings(const T& phi_in, const T& phi_out) {
  return {phi_in, phi_out, status::ok, 0};
}

/// The MODEL §13 numbers of the boundary tests: the Sun's radius, a 1 deg field.
template <class T>
struct rule_numbers {
  T radius = deg<T>(2666, 10000);
  T fov = deg<T>(1);
  T gamma = deg<T>(45);
  T reach() const { return fov / T(2) + radius; }
  T body_half_width() const {
    using std::sin;
    return reach() / sin(gamma);
  }
  T earth_widening() const {
    using std::sin;
    return fov / T(2) / sin(gamma);
  }
};

}  // namespace

TEMPLATE_TEST_CASE("on the cone: |angle(A, X) - gamma| <= fov/2 + r, both sides of both edges",
                   "[intrusion]", CONESCAN_TEST_SCALARS) {
  using T = TestType;
  const rule_numbers<T> n;
  // A misaligned head: the cone is about A, not S.
  const scan_circle<T> circle = scan_circle_of(head_optics<T>{n.gamma, deg<T>(1, 50), deg<T>(30)});
  REQUIRE(circle.state == status::ok);
  const T d = T(256) * eps<T>();
  const crossings<T> none = crossings<T>::failed(status::miss);
  for (int side : {-1, 1}) {
    for (const T theta : {T(0), deg<T>(100), deg<T>(-170)}) {
      const T edge = n.gamma + T(side) * n.reach();
      const body_intrusion<T> inside = body_intrusion_of(
          circle, none, at_angle_from_axis(circle, T(edge - T(side) * d), theta), n.radius, n.fov);
      const body_intrusion<T> outside = body_intrusion_of(
          circle, none, at_angle_from_axis(circle, T(edge + T(side) * d), theta), n.radius, n.fov);
      REQUIRE(inside.state == status::ok);
      REQUIRE(outside.state == status::ok);
      CHECK(inside.on_cone);
      CHECK_FALSE(outside.on_cone);
      // Without crossings there is no Earth pulse to meet.
      CHECK_FALSE(inside.meets_earth_pulse);
      CHECK_WITHIN(inside.cone_offset, T(T(side) * (n.reach() - d)), T(d / T(8)));
    }
  }
  // A pencil beam and a point: off the cone by d is off.
  CHECK_FALSE(
      body_intrusion_of(circle, none, at_angle_from_axis(circle, T(n.gamma + d), T(1)), T(0), T(0))
          .on_cone);
}

TEMPLATE_TEST_CASE("cone_offset: sign, range and the length of X", "[intrusion]",
                   CONESCAN_TEST_SCALARS) {
  using T = TestType;
  const scan_circle<T> circle = scan_circle_of(head_optics<T>{deg<T>(45), T(0), T(0)});
  const T tolerance = T(64) * eps<T>();
  // Along A: -gamma; opposite A: pi - gamma; on S's normal plane: +45 deg; any length.
  CHECK_WITHIN(cone_offset(circle, vec3<T>(T(0), T(0), T(3))).value, T(-deg<T>(45)), tolerance);
  CHECK_WITHIN(cone_offset(circle, vec3<T>(T(0), T(0), T(-1))).value, deg<T>(135), tolerance);
  CHECK_WITHIN(cone_offset(circle, vec3<T>(T(0), T(1000), T(0))).value, deg<T>(45), tolerance);
  CHECK_WITHIN(cone_offset(circle, vec3<T>(T(1), T(0), T(1))).value, T(0), tolerance);
  // Hostile: zero or non-finite X, an invalid circle.
  const T nan = std::numeric_limits<T>::quiet_NaN();
  const T inf = std::numeric_limits<T>::infinity();
  CHECK(cone_offset(circle, vec3<T>(T(0))).state == status::invalid);
  CHECK(cone_offset(circle, vec3<T>(nan, T(0), T(1))).state == status::invalid);
  CHECK(cone_offset(circle, vec3<T>(T(0), inf, T(1))).state == status::invalid);
  const scan_circle<T> bad = scan_circle_of(head_optics<T>{deg<T>(95), T(0), T(0)});
  CHECK(cone_offset(bad, vec3<T>(T(1), T(0), T(1))).state == status::invalid);
  const body_intrusion<T> refused = body_intrusion_of(circle, crossings<T>::failed(status::miss),
                                                      vec3<T>(T(1), T(0), T(1)), T(-1), T(0));
  CHECK(refused.state == status::invalid);
  CHECK_FALSE(refused.cone_offset == refused.cone_offset);  // NaN
  CHECK(body_intrusion_of(circle, crossings<T>::failed(status::miss), vec3<T>(T(1), T(0), T(1)),
                          T(0), nan)
            .state == status::invalid);
}

TEST_CASE("cone_offset against long double, random directions", "[intrusion]") {
  std::mt19937_64 rng(1913);
  std::uniform_real_distribution<double> angle(-3.14159, 3.14159), cone(0.05, 1.5);
  double worst = 0;
  for (int k = 0; k < 20000; ++k) {
    const head_optics<double> optics{cone(rng), 0.001 * cone(rng), angle(rng)};
    const head_optics<long double> optics_ld{optics.gamma, optics.sigma, optics.phi_a};
    const vec3<double> x(angle(rng), angle(rng), angle(rng));
    const vec3<long double> x_ld(x.x, x.y, x.z);
    const double ours = cone_offset(scan_circle_of(optics), x).value;
    const long double reference = cone_offset(scan_circle_of(optics_ld), x_ld).value;
    worst = std::max(worst, static_cast<double>(std::abs(ours - reference)));
  }
  INFO("worst |double - long double| " << worst << " rad");
  CHECK(worst < 2e-15);
}

TEMPLATE_TEST_CASE("pulses that just meet and just miss the Earth pulse, across 0 and 2 pi",
                   "[intrusion]", CONESCAN_TEST_SCALARS) {
  using T = TestType;
  const rule_numbers<T> n;
  // sigma = 0: the nearest line of sight has X's own azimuth about S.
  const scan_circle<T> circle = scan_circle_of(head_optics<T>{n.gamma, T(0), T(0)});
  const T d = T(256) * eps<T>() * T(8);
  const T two_pi = T(2) * pi<T>();
  const T reach = n.body_half_width() + n.earth_widening();
  struct earth_case {
    T phi_in, phi_out;
  };
  // An Earth pulse away from 0, one across 0, one ending just before 2 pi; each body azimuth
  // also written a turn away, so that only the circle's distance decides.
  const earth_case cases[] = {
      {deg<T>(100), deg<T>(190)}, {deg<T>(-20), deg<T>(30)}, {deg<T>(300), deg<T>(3595, 10)}};
  for (const earth_case& e : cases) {
    const crossings<T> earth = earth_crossings(e.phi_in, e.phi_out);
    for (int turns : {-1, 0, 1}) {
      const T shift = T(turns) * two_pi;
      for (int side : {-1, 1}) {
        const T edge = side > 0 ? T(e.phi_out + reach) : T(e.phi_in - reach);
        const T meet_azimuth = edge - T(side) * d + shift;
        const T miss_azimuth = edge + T(side) * d + shift;
        const body_intrusion<T> meet = body_intrusion_of(
            circle, earth,
            direction_in_scan_frame(
                scan_frame<T>{vec3<T>(T(1), T(0), T(0)), vec3<T>(T(0), T(1), T(0)),
                              vec3<T>(T(0), T(0), T(1)), status::ok},
                n.gamma, meet_azimuth),
            n.radius, n.fov);
        const body_intrusion<T> miss = body_intrusion_of(
            circle, earth,
            direction_in_scan_frame(
                scan_frame<T>{vec3<T>(T(1), T(0), T(0)), vec3<T>(T(0), T(1), T(0)),
                              vec3<T>(T(0), T(0), T(1)), status::ok},
                n.gamma, miss_azimuth),
            n.radius, n.fov);
        INFO("Earth " << static_cast<long double>(e.phi_in) << " .. "
                      << static_cast<long double>(e.phi_out) << ", side " << side << ", turns "
                      << turns);
        REQUIRE(meet.on_cone);
        REQUIRE(miss.on_cone);
        CHECK(meet.meets_earth_pulse);
        CHECK_FALSE(miss.meets_earth_pulse);
        CHECK(intrusion_status(earth, meet, false, miss, false) == status::sun);
        CHECK(intrusion_status(earth, miss, false, meet, false) == status::moon);
        CHECK(intrusion_status(earth, miss, false, miss, false) == status::ok);
      }
    }
  }
}

TEMPLATE_TEST_CASE("arcs_overlap: touching, apart, covering the circle", "[intrusion]",
                   CONESCAN_TEST_SCALARS) {
  using T = TestType;
  const T two_pi = T(2) * pi<T>();
  const T d = T(64) * eps<T>();
  // Touching arcs meet, across the cut at 0 = 2 pi.
  CHECK(arcs_overlap(T(two_pi - T(1) / T(10)), T(1) / T(20), T(1) / T(10), T(3) / T(20)));
  CHECK_FALSE(
      arcs_overlap(T(two_pi - T(1) / T(10)), T(1) / T(20), T(1) / T(10), T(T(3) / T(20) - d)));
  CHECK(arcs_overlap(T(-T(1) / T(10)), T(1) / T(20), T(T(1) / T(10) + T(3) * two_pi),
                     T(T(3) / T(20) + d)));
  // Half-widths summing to pi cover the circle, wherever the centres are.
  CHECK(arcs_overlap(T(0), T(pi<T>() / T(2)), T(pi<T>()), T(pi<T>() / T(2))));
  CHECK_FALSE(arcs_overlap(T(0), T(pi<T>() / T(2)), T(pi<T>()), T(pi<T>() / T(2) - T(1) / T(100))));
  // NaN meets nothing.
  const T nan = std::numeric_limits<T>::quiet_NaN();
  CHECK_FALSE(arcs_overlap(nan, T(1), T(0), T(1)));
  CHECK_FALSE(arcs_overlap(T(0), T(1) / T(10), T(1), nan));
}

TEMPLATE_TEST_CASE("a body's pulse centre is the nearest line of sight, misaligned too",
                   "[intrusion]", CONESCAN_TEST_SCALARS) {
  using T = TestType;
  using std::cos;
  const head_optics<T> optics{deg<T>(45), deg<T>(2), deg<T>(70)};
  const scan_circle<T> circle = scan_circle_of(optics);
  const scan_frame<T> axes{vec3<T>(T(1), T(0), T(0)), vec3<T>(T(0), T(1), T(0)),
                           vec3<T>(T(0), T(0), T(1)), status::ok};
  const vec3<T> x = at_angle_from_axis(circle, deg<T>(46), deg<T>(123));
  const body_pulse<T> pulse = body_pulse_of(circle, x, deg<T>(1, 4), T(0));
  REQUIRE(pulse.state == status::ok);
  // The line of sight at phi_X makes gamma with A (it is on the circle) and is nearer X than its
  // neighbours at phi_X +- 0.1 deg.
  auto line_at = [&](const T& phi) {
    const T psi = misaligned_cone_angle(optics.gamma, optics.sigma, T(phi - optics.phi_a)).value;
    return direction_in_scan_frame(axes, psi, phi);
  };
  const T nearest = angle_between(line_at(pulse.azimuth), x);
  CHECK_WITHIN(nearest, deg<T>(1), T(T(1024) * eps<T>()));
  CHECK(angle_between(line_at(T(pulse.azimuth + deg<T>(1, 10))), x) > nearest);
  CHECK(angle_between(line_at(T(pulse.azimuth - deg<T>(1, 10))), x) > nearest);
  // The half-width is eps / sin gamma, capped at pi.
  CHECK_WITHIN(pulse.half_width, T(deg<T>(1, 4) / T(cos(deg<T>(45)))), T(T(16) * eps<T>()));
  CHECK(body_pulse_of(circle, x, deg<T>(100), deg<T>(60)).half_width == pi<T>());
  // X along A: every azimuth is as near; the pulse covers the circle (an aligned head, whose A
  // and u are exact in every scalar).
  const scan_circle<T> aligned = scan_circle_of(head_optics<T>{deg<T>(45), T(0), deg<T>(70)});
  const body_pulse<T> along = body_pulse_of(aligned, aligned.axis, T(0), T(0));
  CHECK(along.state == status::ok);
  CHECK(along.half_width == pi<T>());
  CHECK(body_pulse_of(circle, vec3<T>(T(0)), T(0), T(0)).state == status::invalid);
}

TEMPLATE_TEST_CASE("the Earth pulse widened by the field", "[intrusion]", CONESCAN_TEST_SCALARS) {
  using T = TestType;
  using std::sin;
  const scan_circle<T> circle = scan_circle_of(head_optics<T>{deg<T>(45), T(0), T(0)});
  const body_pulse<T> pulse =
      earth_pulse_of(earth_crossings(deg<T>(10), deg<T>(70)), circle, deg<T>(2));
  REQUIRE(pulse.state == status::ok);
  CHECK_WITHIN(pulse.azimuth, deg<T>(40), T(T(16) * eps<T>()));
  CHECK_WITHIN(pulse.half_width, T(deg<T>(30) + deg<T>(1) / sin(deg<T>(45))), T(T(16) * eps<T>()));
  CHECK(earth_pulse_of(crossings<T>::failed(status::grazing), circle, T(0)).state ==
        status::invalid);
  CHECK(earth_pulse_of(earth_crossings(T(0), T(1)), circle, T(-1)).state == status::invalid);
}

TEMPLATE_TEST_CASE("a body just hidden and just visible behind a sphere", "[intrusion]",
                   CONESCAN_TEST_SCALARS) {
  using T = TestType;
  using std::asin;
  using std::cos;
  using std::sin;
  // km as the unit: float keeps its digits.
  const T radius = T(6378), r = T(7178), distance = T(384400);
  const vec3<T> satellite(r, T(0), T(0));
  const T rho = asin(radius / r);
  const T d = T(4096) * eps<T>();
  auto body_at = [&](const T& from_nadir) {
    return scaled(vec3<T>(T(-cos(from_nadir)), T(sin(from_nadir)), T(0)), distance);
  };
  const body_visibility below = body_hidden_by_sphere(body_at(T(rho - d)), satellite, radius);
  const body_visibility above = body_hidden_by_sphere(body_at(T(rho + d)), satellite, radius);
  REQUIRE(below.state == status::ok);
  REQUIRE(above.state == status::ok);
  CHECK(below.hidden);
  CHECK_FALSE(above.hidden);
  // Straight down, but nearer than the surface: in front of the Earth, visible.
  CHECK_FALSE(
      body_hidden_by_sphere(scaled(body_at(T(0)), T(T(1) / T(1000))), satellite, radius).hidden);
  CHECK(body_hidden_by_sphere(body_at(T(0)), satellite, radius).hidden);
  // Behind the satellite (away from the Earth).
  CHECK_FALSE(body_hidden_by_sphere(body_at(pi<T>()), satellite, radius).hidden);
  // Hostile: the satellite inside, the body at the satellite, NaN.
  CHECK(body_hidden_by_sphere(body_at(T(0)), vec3<T>(T(100), T(0), T(0)), radius).state ==
        status::invalid);
  CHECK(body_hidden_by_sphere(vec3<T>(T(0)), satellite, radius).state == status::invalid);
  CHECK(
      body_hidden_by_sphere(body_at(T(0)), satellite, std::numeric_limits<T>::quiet_NaN()).state ==
      status::invalid);
}

TEST_CASE("a body just hidden and just visible behind the WGS84 ellipsoid", "[intrusion]") {
  const double a = 6378137.0 + 40e3, b = 6356752.314245 + 40e3;  // a 40 km horizon
  const vec3<double> p(5.0e6, 2.0e6, 5.0e6);
  const vec3<double> polar(0, 0, 1);
  const ellipsoid_horizon<double> surface = ellipsoid_horizon_of(p, polar, a, b);
  REQUIRE(surface.state == status::ok);
  // In the plane of -p and a direction across it, the angle from -p where the line of sight is
  // tangent: a bisection in long double on the ellipsoid's own equation.
  const vec3<double> down = unit(-p);
  for (const vec3<double>& toward : {unit(cross(p, polar)), unit(cross(p, cross(p, polar)))}) {
    auto hits = [&](long double angle) {
      const long double c = std::cos(angle), s = std::sin(angle);
      const long double dx = c * down.x + s * toward.x, dy = c * down.y + s * toward.y,
                        dz = c * down.z + s * toward.z;
      // |p + t d| on the scaled ellipsoid: (P.D)^2 - |D|^2 (|P|^2 - 1) with P, D scaled.
      const long double px = p.x / a, py = p.y / a, pz = p.z / static_cast<long double>(b);
      const long double ex = dx / a, ey = dy / a, ez = dz / static_cast<long double>(b);
      const long double pd = px * ex + py * ey + pz * ez;
      return pd < 0 &&
             pd * pd - (ex * ex + ey * ey + ez * ez) * (px * px + py * py + pz * pz - 1) > 0;
    };
    long double low = 0, high = 1.5;  // hits at 0, not at 1.5 rad
    for (int k = 0; k < 200; ++k) (hits(0.5L * (low + high)) ? low : high) = 0.5L * (low + high);
    const double tangent = static_cast<double>(0.5L * (low + high));
    for (double side : {-1.0, 1.0}) {
      const double angle = tangent + side * 1e-9;
      const vec3<double> d = down * std::cos(angle) + toward * std::sin(angle);
      const body_visibility v = body_hidden_by_ellipsoid(surface, a, d * 3.844e8);
      REQUIRE(v.state == status::ok);
      CHECK(v.hidden == (side < 0));
    }
  }
  // On a sphere (a = b) it is the sphere's test, for random directions.
  const ellipsoid_horizon<double> round = ellipsoid_horizon_of(p, polar, a, a);
  std::mt19937_64 rng(5);
  std::normal_distribution<double> normal;
  for (int k = 0; k < 2000; ++k) {
    const vec3<double> x = vec3<double>(normal(rng), normal(rng), normal(rng)) * 1e7;
    CHECK(body_hidden_by_ellipsoid(round, a, x).hidden == body_hidden_by_sphere(x, p, a).hidden);
  }
  CHECK(body_hidden_by_ellipsoid(surface, -a, vec3<double>(1, 0, 0)).state == status::invalid);
  CHECK(body_hidden_by_ellipsoid(surface, a, vec3<double>(0.0)).state == status::invalid);
}

TEMPLATE_TEST_CASE("the verdict: crossings first, then the Sun, then the Moon", "[intrusion]",
                   CONESCAN_TEST_SCALARS) {
  using T = TestType;
  const crossings<T> earth = earth_crossings(T(0), T(1));
  const body_intrusion<T> meets{T(0), true, true, status::ok};
  const body_intrusion<T> apart{T(1), false, false, status::ok};
  const body_intrusion<T> bad{std::numeric_limits<T>::quiet_NaN(), false, false, status::invalid};
  CHECK(intrusion_status(earth, meets, false, meets, false) == status::sun);
  CHECK(intrusion_status(earth, meets, true, meets, false) == status::moon);
  CHECK(intrusion_status(earth, meets, true, meets, true) == status::ok);
  CHECK(intrusion_status(earth, apart, false, apart, false) == status::ok);
  CHECK(intrusion_status(earth, bad, false, apart, false) == status::invalid);
  CHECK(intrusion_status(earth, apart, false, bad, false) == status::invalid);
  for (status s :
       {status::miss, status::engulfed, status::grazing, status::multiple, status::invalid})
    CHECK(intrusion_status(crossings<T>::failed(s), meets, false, meets, false) == s);
}

TEMPLATE_TEST_CASE("body_angular_radius: domain and value", "[intrusion]", CONESCAN_TEST_SCALARS) {
  using T = TestType;
  using std::asin;
  CHECK_WITHIN(body_angular_radius(T(1), T(2)).value, T(pi<T>() / T(6)), T(T(8) * eps<T>()));
  CHECK(body_angular_radius(T(2), T(2)).state == status::invalid);
  CHECK(body_angular_radius(T(0), T(2)).state == status::invalid);
  CHECK(body_angular_radius(T(1), std::numeric_limits<T>::infinity()).state == status::invalid);
}

// --- The rule on real orbits (double; the orbit layer and the ephemeris) ----------------------

namespace {

constexpr double degree = std::numbers::pi / 180;

sources::instant utc(const char* text) {
  return (sources::parse_epoch(text, sources::time_scale::utc)).value();
}

const sources::sun_moon_track& track_of(const checked<sources::sun_moon_track>& r) {
  return r.value();
}

/// One row of a head on a Kepler orbit with zero attitude (body = orbital frame), the body at
/// body_tod_m (geocentric) seen from the satellite: its intrusion against the head's sphere
/// crossings (R = WGS84 a), and whether the Earth hides it.
struct head_row {
  body_intrusion<double> body;
  crossings<double> earth;
  bool hidden;
  double from_nadir_rad;  ///< the body's angle from the nadir
  double rho_rad;         ///< the Earth disk's angular radius
};

head_row row_of(const sensor_head<double>& head, const orbit::orbit_state& s,
                const vec3<double>& body_tod_m, double body_radius_m, double fov) {
  const double radius = orbit::wgs84().a_m;
  const sources::body_view view = sources::view_from(body_tod_m, body_radius_m, s.r_eci_m);
  const mat3<double> eci_from_body = dcm_eci_from_orbit(s.r_eci_m, s.v_eci_m_s);
  const vec3<double> x_scan =
      head.in_scan_frame(apply_transpose(eci_from_body, view.direction_tod));
  const vec3<double> nadir_scan = head.in_scan_frame(vec3<double>(0, 0, 1));
  const crossings<double> earth =
      head.scan_crossings(nadir_scan, disk_trig_of(radius, norm(s.r_eci_m)));
  const body_visibility v =
      body_hidden_by_sphere(view.direction_tod * view.distance_m, s.r_eci_m, radius);
  return {body_intrusion_of(head.circle(), earth, x_scan, view.angular_radius_rad, fov), earth,
          v.hidden, angle_between(-s.r_eci_m, view.direction_tod),
          std::asin(radius / norm(s.r_eci_m))};
}

}  // namespace

TEST_CASE("a head whose spin axis is the orbit normal sees the Sun on its cone all orbit or never",
          "[intrusion][orbit]") {
  // The paper's orbit, two-body; the head at beta = -90 deg: S = -y_o, the orbit normal. The Sun
  // turns about S once per orbit at a fixed angle from it (its own motion, 0.07 deg an orbit,
  // and its parallax, 1e-3 deg, apart); the Moon's parallax moves it by up to a degree.
  const orbit::earth_constants& w = orbit::wgs84();
  const orbit::elements el{7280e3, 0.1, 97.7 * degree, 200 * degree, 30 * degree, 0};
  const orbit::kepler_orbit path(el, orbit::two_body_rates(el, w.gm_m3_s2), w.gm_m3_s2);
  const double period = orbit::orbital_period_s(el.a_m, w.gm_m3_s2);
  const sources::instant t0 = utc("2026-03-01T00:00:00");
  const auto made = sources::sun_moon_track::over(t0, sources::add_seconds(t0, period));
  REQUIRE((made.ok() ? nullptr : &made.error()) == nullptr);
  const sources::sun_moon_track& sky = track_of(made);
  auto angle_from_spin_axis = [&](double t, bool moon) {
    const orbit::orbit_state s = path.state_at(t);
    const sources::sun_moon_positions p = sky.at(sources::add_seconds(t0, t));
    const vec3<double> normal = unit(cross(s.r_eci_m, s.v_eci_m_s));
    return angle_between(normal, (moon ? p.moon_tod_m : p.sun_tod_m) - s.r_eci_m);
  };
  double sun_low = 10, sun_high = 0, moon_low = 10, moon_high = 0;
  for (double t = 0; t <= period; t += 30) {
    sun_low = std::min(sun_low, angle_from_spin_axis(t, false));
    sun_high = std::max(sun_high, angle_from_spin_axis(t, false));
    moon_low = std::min(moon_low, angle_from_spin_axis(t, true));
    moon_high = std::max(moon_high, angle_from_spin_axis(t, true));
  }
  INFO("the Sun's angle from S varies by " << (sun_high - sun_low) / degree
                                           << " deg over the orbit, the Moon's by "
                                           << (moon_high - moon_low) / degree << " deg");
  CHECK((sun_high - sun_low) / degree < 0.08);
  CHECK((moon_high - moon_low) / degree < 2.1);
  // A cone through the Sun: on the cone at every row; one 0.1 deg beyond its reach: at none.
  // S = +n (beta = -90 deg) when the Sun is on the normal's side of the orbit plane, else -n.
  const bool normal_side = sun_high < 90 * degree;
  const double low = normal_side ? sun_low : 180 * degree - sun_high;
  const double high = normal_side ? sun_high : 180 * degree - sun_low;
  const double radius = 0.2666 * degree;
  for (double gamma : {0.5 * (low + high), high + radius + 0.1 * degree}) {
    const bool through = gamma < high;
    const sensor_head<double> head = sensor_head<double>::from_mounting(
        0.0, (normal_side ? -90 : 90) * degree, {gamma, 0.0, 0.0});
    REQUIRE(head.state() == status::ok);
    int on = 0, rows = 0;
    for (double t = 0; t <= period; t += 30, ++rows) {
      const orbit::orbit_state s = path.state_at(t);
      const head_row r = row_of(head, s, sky.at(sources::add_seconds(t0, t)).sun_tod_m,
                                sources::sun_radius_m, 0.0);
      REQUIRE(r.body.state == status::ok);
      on += r.body.on_cone ? 1 : 0;
    }
    CHECK(on == (through ? rows : 0));
  }
}

namespace {

/// The Sun against the two pitch-axis heads (alpha = 0, beta = +-90 deg, gamma) of an 800 km
/// circular sun-synchronous orbit (J2 node drift) through 2026, with its ascending node at
/// `ltan_hours` of mean local time on 2026-01-01: the days on which the Sun is on a head's cone at
/// some sample (every 10 min), and the range of the Sun's angle above the orbit plane (beta_sun).
struct season {
  int days_plus = 0, days_minus = 0;  // heads at beta = +90 deg (S = -orbit normal) and -90 deg
  int first_day_plus = -1;
  double beta_sun_low_deg = 90, beta_sun_high_deg = -90;
};

season sun_season(double ltan_hours, double gamma, double fov, const sources::sun_moon_track& sky,
                  const sources::instant& t0) {
  const orbit::earth_constants& w = orbit::wgs84();
  const double a = w.a_m + 800e3;
  const double inclination =
      std::acos(orbit::sun_synchronous_cos_inclination(a, 0.0, w.gm_m3_s2, w.j2, w.a_m));
  // The mean Sun's right ascension at t0 (its mean longitude, Astronomical Almanac section C).
  const sources::julian_date tt = sources::tt_julian_date(t0);
  const double mean_sun_deg = 280.460 + 0.9856474 * (tt.jd1 + tt.jd2 - 2451545.0);
  const double raan = (mean_sun_deg + (ltan_hours - 12.0) * 15.0) * degree;
  const orbit::elements el{a, 0.0, inclination, raan, 0.0, 0.0};
  const orbit::kepler_orbit path(el, orbit::j2_secular_rates(el, w.gm_m3_s2, w.j2, w.a_m),
                                 w.gm_m3_s2);
  sensor_head<double> heads[2] = {
      sensor_head<double>::from_mounting(0.0, 90 * degree, {gamma, 0.0, 0.0}),
      sensor_head<double>::from_mounting(0.0, -90 * degree, {gamma, 0.0, 0.0})};
  season result;
  for (int day = 0; day < 365; ++day) {
    bool on[2] = {false, false};
    for (int k = 0; k < 144; ++k) {
      const double t = day * 86400.0 + k * 600.0;
      const orbit::orbit_state s = path.state_at(t);
      const vec3<double> sun = sky.at(sources::add_seconds(t0, t)).sun_tod_m;
      const vec3<double> normal = unit(cross(s.r_eci_m, s.v_eci_m_s));
      const double beta_sun = std::asin(dot(normal, unit(sun - s.r_eci_m))) / degree;
      result.beta_sun_low_deg = std::min(result.beta_sun_low_deg, beta_sun);
      result.beta_sun_high_deg = std::max(result.beta_sun_high_deg, beta_sun);
      for (int h = 0; h < 2; ++h)
        on[h] = on[h] || row_of(heads[h], s, sun, sources::sun_radius_m, fov).body.on_cone;
    }
    if (on[0] && result.first_day_plus < 0) result.first_day_plus = day;
    result.days_plus += on[0] ? 1 : 0;
    result.days_minus += on[1] ? 1 : 0;
  }
  return result;
}

}  // namespace

TEST_CASE("Sun seasons of pitch-axis heads on an 800 km sun-synchronous orbit",
          "[intrusion][orbit][season]") {
  const sources::instant t0 = utc("2026-01-01T00:00:00");
  const auto made = sources::sun_moon_track::over(t0, sources::add_seconds(t0, 366 * 86400.0));
  REQUIRE((made.ok() ? nullptr : &made.error()) == nullptr);
  const sources::sun_moon_track& sky = track_of(made);
  const double gamma = 45 * degree, sun_radius_deg = 0.2666;
  for (double fov_deg : {0.0, 1.0, 2.0}) {
    const double reach = fov_deg / 2 + sun_radius_deg;
    for (double ltan : {9.0, 10.5}) {
      const season s = sun_season(ltan, gamma, fov_deg * degree, sky, t0);
      INFO("LTAN " << ltan << " h, fov " << fov_deg << " deg: beta_sun " << s.beta_sun_low_deg
                   << " .. " << s.beta_sun_high_deg << " deg; Sun on the cone of the +y head on "
                   << s.days_plus << " days (first: day " << s.first_day_plus
                   << "), of the -y head on " << s.days_minus << " days");
      // The rule: a head with S = -+ orbit normal has the Sun on its cone when beta_sun is within
      // fov/2 + r_Sun of -+(90 deg - gamma); a season exists where the year's range reaches it.
      const bool plus_reached = s.beta_sun_low_deg <= -45 + reach;
      const bool minus_reached = s.beta_sun_high_deg >= 45 - reach;
      CHECK((s.days_plus > 0) == plus_reached);
      CHECK((s.days_minus > 0) == minus_reached);
      if (ltan == 10.5) CHECK(s.days_plus + s.days_minus == 0);
      if (ltan == 9.0) CHECK(s.days_plus > 0);
      SUCCEED();  // the INFO above is printed with -s
    }
  }
}

TEST_CASE("in a Sun season the Sun corrupts the crossings only at the limb",
          "[intrusion][orbit][season]") {
  // The first day of the 09:00 orbit's season for the +y head: every second of the day through
  // the whole row (sphere crossings, the Sun's pulse, its visibility, the verdict).
  const sources::instant t0 = utc("2026-01-01T00:00:00");
  const auto made = sources::sun_moon_track::over(t0, sources::add_seconds(t0, 366 * 86400.0));
  REQUIRE((made.ok() ? nullptr : &made.error()) == nullptr);
  const sources::sun_moon_track& sky = track_of(made);
  const double gamma = 45 * degree;
  const season s = sun_season(9.0, gamma, 0.0, sky, t0);
  REQUIRE(s.first_day_plus >= 0);
  const orbit::earth_constants& w = orbit::wgs84();
  const double a = w.a_m + 800e3;
  const double inclination =
      std::acos(orbit::sun_synchronous_cos_inclination(a, 0.0, w.gm_m3_s2, w.j2, w.a_m));
  const sources::julian_date tt = sources::tt_julian_date(t0);
  const double raan = (280.460 + 0.9856474 * (tt.jd1 + tt.jd2 - 2451545.0) - 45.0) * degree;
  const orbit::elements el{a, 0.0, inclination, raan, 0.0, 0.0};
  const orbit::kepler_orbit path(el, orbit::j2_secular_rates(el, w.gm_m3_s2, w.j2, w.a_m),
                                 w.gm_m3_s2);
  const sensor_head<double> head =
      sensor_head<double>::from_mounting(0.0, 90 * degree, {gamma, 0.0, 0.0});
  int lost = 0, on_cone = 0, events = 0;
  bool previous = false;
  double farthest_from_limb = 0;
  for (int k = 0; k < 86400; ++k) {
    const double t = s.first_day_plus * 86400.0 + k;
    const head_row r = row_of(head, path.state_at(t), sky.at(sources::add_seconds(t0, t)).sun_tod_m,
                              sources::sun_radius_m, 0.0);
    REQUIRE(r.earth.state == status::ok);
    const status verdict = intrusion_status(r.earth, r.body, r.hidden, r.body, true);
    on_cone += r.body.on_cone ? 1 : 0;
    const bool sun = verdict == status::sun;
    if (sun) {
      ++lost;
      farthest_from_limb = std::max(farthest_from_limb, std::abs(r.from_nadir_rad - r.rho_rad));
      CHECK(r.from_nadir_rad > r.rho_rad);  // visible: above the limb
    }
    events += sun && !previous ? 1 : 0;
    previous = sun;
  }
  INFO("day " << s.first_day_plus << ": Sun on the cone in " << on_cone << " s, crossings lost in "
              << lost << " s, " << events << " events, the Sun at most "
              << farthest_from_limb / degree << " deg above the limb");
  CHECK(lost > 0);
  CHECK(events >= 2);
  // At the limb: within the pulse's reach of a crossing (w_Sun = 0.377 deg of azimuth).
  CHECK(farthest_from_limb / degree < 0.4);
}
