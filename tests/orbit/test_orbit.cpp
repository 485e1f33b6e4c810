// The orbit layer (MODEL §3): Kepler, anomalies, J2 secular rates, sun-synchronous inclination,
// geodetic conversion.
#include <algorithm>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "conescan/orbital_frame.hpp"
#include "conescan/scalar.hpp"
#include "orbit/geodetic.hpp"
#include "orbit/kepler.hpp"
#include "orbit/wgs84.hpp"
#include "support/adl_scalar.hpp"

using namespace conescan;
using namespace conescan::orbit;
using conescan_test::eps;
using conescan_test::same_or_both_nan;

namespace {
const double deg = pi<double>() / 180;
const elements paper{7280e3, 0.1, 97.7 * deg, 0, 0, 0};

/// E - e sin E - M in long double, written (1 - e) E + e (E - sin E) - M with a series for
/// E - sin E where E is small, so that it keeps its relative accuracy as E -> 0 for e -> 1.
long double kepler_residual(long double ecc, long double e, long double m) {
  if (std::abs(ecc) >= 0.5L) return ecc - e * std::sin(ecc) - m;
  // E - sin E = E^3/3! - E^5/5! + ...: 12 terms leave less than 0.5^27 / 27! relative.
  long double term = ecc * ecc * ecc / 6, sum = 0;
  for (int k = 5; k <= 27; k += 2) {
    sum += term;
    term *= -ecc * ecc / ((k - 1) * k);
  }
  return (1 - e) * ecc + e * sum - m;
}

/// E of Kepler's equation for M in (-pi, pi], independently of src/orbit/kepler.cpp: bisection
/// in long double (11 more bits than double) of the bracket M <= E <= min(M / (1 - e), pi)
/// (E - M = e sin E, between 0 and e E), to adjacent long doubles.
long double kepler_long_double(long double m, long double e) {
  long double lo = std::abs(m), hi = std::min(lo / (1 - e), pi<long double>());
  for (int i = 0; i < 400; ++i) {
    const long double mid = (lo + hi) / 2;
    if (mid == lo || mid == hi) break;
    (kepler_residual(mid, e, std::abs(m)) < 0 ? lo : hi) = mid;
  }
  return std::copysign((lo + hi) / 2, m);
}

/// The error double's E may have: 4 eps of the terms E, e sin E, M of the residual, divided by
/// the slope 1 - e cos E (the conditioning of the root), and 2 ulp of E itself.
double kepler_tolerance(double ecc, double m, double e) {
  return 4 * eps<double>() * (std::abs(ecc) + e * std::abs(std::sin(ecc)) + std::abs(m)) /
             (1 - e * std::cos(ecc)) +
         2 * eps<double>() * std::abs(ecc);
}
}  // namespace

TEST_CASE("orbit: WGS84 constants come from GeographicLib", "[orbit]") {
  const earth_constants& w = wgs84();
  // Defining constants of WGS84 (NIMA TR8350.2): a = 6378137 m, 1/f = 298.257223563,
  // GM = 3.986004418e14 m^3/s^2; J2 = 1.08262982131e-3 derived (GeographicLib's docs).
  CHECK(w.a_m == 6378137.0);
  CHECK(1 / w.f == Approx(298.257223563).epsilon(1e-12));
  CHECK(w.gm_m3_s2 == 3.986004418e14);
  CHECK(w.j2 == Approx(1.08262982131e-3).epsilon(1e-9));
  CHECK(w.b_m == Approx(6356752.314245).margin(1e-6));
}

TEST_CASE("orbit: Kepler's equation is solved to rounding for 0 <= e < 1", "[orbit][kepler]") {
  for (double e : {0.0, 1e-9, 0.1, 0.5, 0.9, 0.99, 0.999999}) {
    for (double m = -20.0; m <= 20.0; m += 0.37) {
      const double ecc = eccentric_anomaly(m, e);
      INFO("e = " << e << ", M = " << m);
      // Residual of E - e sin E = M, relative to the size of the terms.
      CHECK(std::abs(ecc - e * std::sin(ecc) - m) <= 8e-16 * (std::abs(m) + 1));
    }
  }
  // Both sides of the corner e -> 1, M -> 0, where 1 - e cos E vanishes.
  CHECK(std::isfinite(eccentric_anomaly(1e-12, 0.999999)));
  CHECK(eccentric_anomaly(0.0, 0.5) == 0.0);
}

TEST_CASE("orbit: solve_kepler's sine and cosine are those of its E", "[orbit][kepler]") {
  // The last Newton step is taken by the angle-difference formulas (src/orbit/kepler.cpp): sin E
  // and cos E must still be those of the reduced E to a few ulp, and E that of a long double
  // solve to its conditioning.
  for (double e : {0.0, 1e-9, 0.1, 0.5, 0.9, 0.99, 0.999999}) {
    for (double m = -20.0; m <= 20.0; m += 0.0137) {
      const kepler_solution k = solve_kepler(m, e);
      // E - turns is the reduced angle to an ulp of E (the subtraction rounds), so the
      // tolerance is 3 ulp of E: 3 eps on the first turn, where turns = 0 and it is exact.
      const double reduced = k.eccentric_anomaly_rad - k.turns_rad;
      const double tolerance = 3 * eps<double>() * std::max(1.0, std::abs(k.eccentric_anomaly_rad));
      INFO("e = " << e << ", M = " << m);
      CHECK(std::abs(reduced) <= pi<double>() + tolerance);
      CHECK(std::abs(k.sin_e - std::sin(reduced)) <= tolerance);
      CHECK(std::abs(k.cos_e - std::cos(reduced)) <= tolerance);
      // E itself, turns included: the reduced root's conditioning and an ulp of E (the sum).
      const double reduced_m = wrap_pi(m);
      const long double expected = k.turns_rad + kepler_long_double(reduced_m, e);
      CHECK(std::abs(k.eccentric_anomaly_rad - static_cast<double>(expected)) <=
            kepler_tolerance(reduced, reduced_m, e) + eps<double>() * std::abs(expected));
    }
  }
}

TEST_CASE("orbit: Kepler solves several at once are each solve's", "[orbit][kepler]") {
  // Lanes that return at once (M = 0), converge in different numbers of steps (tiny, small and
  // large M, whole turns), in a count that is not a multiple of kepler_lanes: bit for bit.
  for (double e : {0.0, 0.1, 0.9, 0.999999}) {
    const std::vector<double> m = {0.0, 1e-300, 3e-9, 0.5, -2.9, 3.14159, 40.0, -1e-12, 1.0, 2.5};
    std::vector<kepler_solution> batch(m.size());
    solve_kepler(m.data(), e, batch.data(), m.size());
    for (std::size_t i = 0; i < m.size(); ++i) {
      const kepler_solution single = solve_kepler(m[i], e);
      INFO("e = " << e << ", M = " << m[i]);
      CHECK(batch[i].eccentric_anomaly_rad == single.eccentric_anomaly_rad);
      CHECK(batch[i].turns_rad == single.turns_rad);
      CHECK(batch[i].sin_e == single.sin_e);
      CHECK(batch[i].cos_e == single.cos_e);
    }
  }
  // And the states of a two-body orbit.
  const kepler_orbit orbit(paper, two_body_rates(paper, wgs84().gm_m3_s2), wgs84().gm_m3_s2);
  const std::vector<double> t = {0, 10, 20.5, 3000, 6100, 7, 1e6};
  std::vector<orbit_state> states(t.size());
  orbit.states_at(t.data(), states.data(), t.size());
  for (std::size_t i = 0; i < t.size(); ++i) {
    const orbit_state single = orbit.state_at(t[i]);
    INFO("t = " << t[i]);
    CHECK(states[i].r_eci_m == single.r_eci_m);
    CHECK(states[i].v_eci_m_s == single.v_eci_m_s);
    CHECK(states[i].true_anomaly_rad == single.true_anomaly_rad);
  }
}

TEST_CASE("orbit: Kepler's E keeps its relative accuracy for small M", "[orbit][kepler]") {
  // E ~ M / (1 - e) -> 0: a stopping test in absolute terms accepts a last step computed from a
  // residual at an E many times the answer (M = 1e-12, e = 0.01 once came back 300 ulp off).
  // Both sides of the 2^-26 relative step bound and of the small-E start (M < 2^-10 (1 - e)),
  // down to M = 1e-300, both signs; sin E and cos E too.
  for (double e : {1e-9, 0.001, 0.01, 0.1, 0.5, 0.9, 0.99}) {
    for (double magnitude : {0.5, 1e-4, 1e-8, 3e-9, 1e-10, 1e-12, 1e-15, 1e-20, 1e-100, 1e-300}) {
      for (double m : {magnitude, -magnitude}) {
        const kepler_solution k = solve_kepler(m, e);
        const auto reference = kepler_long_double(m, e);
        INFO("e = " << e << ", M = " << m << ", E = " << k.eccentric_anomaly_rad);
        const double tolerance = kepler_tolerance(k.eccentric_anomaly_rad, m, e);
        CHECK(std::abs(k.eccentric_anomaly_rad - static_cast<double>(reference)) <= tolerance);
        // sin E and cos E carry E's own error (its conditioning) and their rounding.
        CHECK(std::abs(k.sin_e - static_cast<double>(std::sin(reference))) <=
              tolerance + 2 * eps<double>() * std::abs(k.sin_e));
        CHECK(std::abs(k.cos_e - static_cast<double>(std::cos(reference))) <=
              tolerance * std::abs(k.sin_e) + 2 * eps<double>());
      }
    }
  }
}

TEST_CASE("orbit: Kepler's E keeps its relative accuracy as e -> 1", "[orbit][kepler]") {
  // E - e sin E cancels where E is small and e near 1, though E(M) is well conditioned there
  // (relative condition (M / E) / (1 - e cos E) ~ 1): the plain residual returned E 1e6 ulp off
  // at e = 0.999999, M = 1.5e-10. With the series form the solve keeps 1.3 ulp (measured over
  // M in [1e-12, 3]); the tolerance is 3 ulp, against the long double bisection.
  for (double e : {0.5, 0.9, 0.99, 0.999, 0.999999}) {
    for (double m = 1e-12; m < 3; m *= 1.19) {
      const double ecc = eccentric_anomaly(m, e);
      const long double reference = kepler_long_double(m, e);
      INFO("e = " << e << ", M = " << m);
      CHECK(std::abs(static_cast<long double>(ecc) - reference) <= 3 * eps<double>() * reference);
    }
  }
}

TEST_CASE("orbit: the true anomaly from sin E and cos E is the half-angle form's",
          "[orbit][kepler]") {
  // true_anomaly_from_kepler switches form at cos E = 0 and must agree with the half-angle
  // form (one atan2 of sin(E/2), cos(E/2)) on both sides of it, at the apsides and along many
  // turns: to 4 ulp of nu, times 1 / sqrt(1 - e), the conditioning of tan(E/2) -> tan(nu/2).
  for (double e : {0.0, 0.1, 0.5, 0.9, 0.99}) {
    std::vector<double> mean_anomalies;
    for (double m = -20.0; m <= 20.0; m += 0.0173) mean_anomalies.push_back(m);
    for (double turn : {-2.0, 0.0, 1.0})  // the apsides and E = +-pi/2 (M = +-pi/2 -+ e)
      for (double m :
           {0.0, pi<double>(), -pi<double>(), pi<double>() / 2 - e, -pi<double>() / 2 + e})
        mean_anomalies.push_back(m + 2 * pi<double>() * turn);
    for (double m : mean_anomalies) {
      const kepler_solution k = solve_kepler(m, e);
      const double nu = true_anomaly_from_kepler(k, e);
      const double expected = true_anomaly_from_eccentric(k.eccentric_anomaly_rad, e);
      INFO("e = " << e << ", M = " << m << ": nu " << nu << ", expected " << expected);
      CHECK(std::abs(nu - expected) <=
            4 * eps<double>() * std::max(1.0, std::abs(expected)) / std::sqrt(1 - e));
    }
  }
}

TEST_CASE("orbit: anomaly conversions round-trip and keep whole turns", "[orbit][kepler]") {
  for (double e : {0.0, 0.1, 0.7, 0.95})
    for (double ecc = -15.0; ecc <= 15.0; ecc += 0.29) {
      const double nu = true_anomaly_from_eccentric(ecc, e);
      CHECK(eccentric_from_true_anomaly(nu, e) == Approx(ecc).margin(1e-12));
      // nu and E share the same half-plane and the same turn count.
      CHECK(std::floor(nu / (2 * pi<double>()) + 0.5) ==
            std::floor(ecc / (2 * pi<double>()) + 0.5));
    }
}

TEST_CASE("orbit: perigee, apogee and period of the paper's orbit", "[orbit][kepler]") {
  const double gm = wgs84().gm_m3_s2;
  const double period = orbital_period_s(paper.a_m, gm);
  // 2 pi sqrt(a^3/GM) for a = 7280 km.
  CHECK(period == Approx(2 * pi<double>() * std::sqrt(7280e3 * 7280e3 * 7280e3 / gm)));
  CHECK(period == Approx(6181.70).margin(0.01));
  const secular_rates rates = two_body_rates(paper, gm);
  const orbit_state perigee = state_at(paper, rates, gm, 0);
  const orbit_state apogee = state_at(paper, rates, gm, period / 2);
  const orbit_state again = state_at(paper, rates, gm, period);
  CHECK(norm(perigee.r_eci_m) == Approx(7280e3 * 0.9).margin(1e-6));
  CHECK(norm(apogee.r_eci_m) == Approx(7280e3 * 1.1).margin(1e-6));
  CHECK(apogee.true_anomaly_rad == Approx(pi<double>()).margin(1e-12));
  CHECK(norm(again.r_eci_m - perigee.r_eci_m) < 1e-6);
  // Vis-viva: v^2 = GM (2/r - 1/a) at any time.
  for (double t = 0; t < period; t += 500) {
    const orbit_state s = state_at(paper, rates, gm, t);
    const double r = norm(s.r_eci_m), v = norm(s.v_eci_m_s);
    CHECK(v * v == Approx(gm * (2 / r - 1 / paper.a_m)).epsilon(1e-13));
    // Angular momentum is conserved and along the orbit normal of inclination i.
    const vec3<double> h = unit(cross(s.r_eci_m, s.v_eci_m_s));
    CHECK(h.z == Approx(std::cos(paper.i_rad)).margin(1e-14));
  }
}

TEST_CASE("orbit: the orbital frame is right-handed with z at geocentric nadir", "[orbit]") {
  const double gm = wgs84().gm_m3_s2;
  const orbit_state s = state_at(paper, two_body_rates(paper, gm), gm, 1234);
  const mat3<double> m = dcm_eci_from_orbit(s.r_eci_m, s.v_eci_m_s);
  CHECK(dot(m[2], unit(s.r_eci_m)) == Approx(-1).margin(1e-15));
  CHECK(norm(cross(m[0], m[1]) - m[2]) < 1e-15);
  // On an eccentric orbit x_o leads the radius by 90 deg, not along the velocity.
  CHECK(dot(m[0], unit(s.v_eci_m_s)) < 1);
  CHECK(dot(m[0], unit(s.v_eci_m_s)) > 0.99);
}

TEST_CASE("orbit: sun-synchronous inclination and node drift (MODEL §3)", "[orbit][j2]") {
  const earth_constants& w = wgs84();
  const double cos_i = sun_synchronous_cos_inclination(7280e3, 0, w.gm_m3_s2, w.j2, w.a_m);
  const double i_deg = std::acos(cos_i) / deg;
  // A regression: 99.0 deg to 0.05 deg for a = 7280 km, e = 0.
  CHECK(i_deg == Approx(99.0).margin(0.05));
  const elements ss{7280e3, 0, std::acos(cos_i), 0, 0, 0};
  const secular_rates rates = j2_secular_rates(ss, w.gm_m3_s2, w.j2, w.a_m);
  // 360 deg per tropical year = 0.9856 deg/day.
  CHECK(rates.raan_dot * 86400 / deg == Approx(360 / tropical_year_days).epsilon(1e-12));
  CHECK(rates.raan_dot * 86400 / deg == Approx(0.9856).margin(5e-5));
  // MODEL §3's a = 7280 km, e = 0.1 example: 98.86 deg.
  CHECK(std::acos(sun_synchronous_cos_inclination(7280e3, 0.1, w.gm_m3_s2, w.j2, w.a_m)) / deg ==
        Approx(98.86).margin(0.005));
  // The critical inclination freezes the perigee: 5 cos^2 i = 1.
  const elements critical{7280e3, 0.1, std::acos(std::sqrt(0.2)), 0, 0, 0};
  CHECK(std::abs(j2_secular_rates(critical, w.gm_m3_s2, w.j2, w.a_m).argp_dot) < 1e-20);
}

TEST_CASE("orbit: geodetic altitude and latitude on WGS84", "[orbit][geodetic]") {
  const earth_constants& w = wgs84();
  // Points of the ellipsoid itself, x = a cos u, z = b sin u (parametric latitude u): altitude 0,
  // geodetic latitude atan(a/b tan u).
  for (double u_deg = -90; u_deg <= 90; u_deg += 7.5) {
    const double u = u_deg * deg;
    const vec3<double> p(w.a_m * std::cos(u), 0, w.b_m * std::sin(u));
    const geodetic_position g = geodetic_from_eci(p);
    CHECK(g.alt_m == Approx(0).margin(1e-8));
    CHECK(g.lat_rad == Approx(std::atan2(w.a_m * std::sin(u), w.b_m * std::cos(u))).margin(1e-14));
    // The local radius is the distance to that surface point.
    CHECK(wgs84_radius_along(p) == Approx(norm(p)).epsilon(1e-15));
  }
  // Longitude never matters (MODEL §2): rotate about z.
  const geodetic_position a = geodetic_from_eci(vec3<double>(7000e3, 0, 1000e3));
  const geodetic_position b = geodetic_from_eci(vec3<double>(0, -7000e3, 1000e3));
  CHECK(a.alt_m == Approx(b.alt_m).margin(1e-8));
}

// geodetic_from_eci's closed form against GeographicLib's Geocentric::Reverse, the library the
// guide names for geodetic conversions. Tolerances: 1e-15 rad in latitude (both are within
// 4e-16 rad of a 50-digit evaluation, measured on 2e5 points) and 8 eps max(a, |r|) in height
// (the height is a difference of lengths of order max(a, |r|): both carry that rounding).
TEST_CASE("orbit: geodetic closed form agrees with GeographicLib", "[orbit][geodetic]") {
  const earth_constants& w = wgs84();
  auto check_agrees = [&](const vec3<double>& p) {
    const geodetic_position fast = geodetic_from_eci(p);
    const geodetic_position reference = geodetic_from_eci_geographiclib(p);
    INFO("x " << p.x << " y " << p.y << " z " << p.z);
    CHECK(std::abs(fast.lat_rad - reference.lat_rad) <= 1e-15);
    CHECK(std::abs(fast.alt_m - reference.alt_m) <= 8 * eps<double>() * std::max(w.a_m, norm(p)));
  };
  // Directions over the whole sphere at distances from 50 km (just outside the region about
  // the centre that the closed form leaves to GeographicLib) to 1e9 m, log-spaced.
  for (double distance_m = 50e3; distance_m <= 1e9; distance_m *= 1.7) {
    for (double lat_deg = -90; lat_deg <= 90; lat_deg += 3.75) {
      for (double lon_deg : {0.0, 37.0, 135.0, -100.0}) {
        const double c = std::cos(lat_deg * deg);
        check_agrees(distance_m * vec3<double>(c * std::cos(lon_deg * deg),
                                               c * std::sin(lon_deg * deg),
                                               std::sin(lat_deg * deg)));
      }
    }
  }
  // Both sides of where the closed form hands over: (R/a)^2 + (1-e^2)(z/a)^2 = e^4, i.e.
  // R = a e^2 (~42.7 km) in the equatorial plane and z = a e^2 / sqrt(1 - e^2) on the axis.
  const double e2 = w.f * (2 - w.f);
  const double equatorial_edge_m = w.a_m * e2, polar_edge_m = equatorial_edge_m / (1 - w.f);
  for (double scale : {0.5, 0.999, 1.001, 2.0}) {
    check_agrees(vec3<double>(scale * equatorial_edge_m, 0, 0));
    check_agrees(vec3<double>(0, 0, scale * polar_edge_m));
    check_agrees(vec3<double>(0.7 * scale * equatorial_edge_m, 0, 0.7 * scale * polar_edge_m));
  }
  check_agrees(vec3<double>(0, 0, 0));
  // Beyond 1e20 m GeographicLib takes over again.
  check_agrees(vec3<double>(3e20, 1e20, -2e20));
}

TEST_CASE("orbit: geodetic closed form against 50 digits", "[orbit][geodetic]") {
  // The same closed form in cpp_bin_float_50 is the truth to ~1e-45 outside the hand-over region
  // (it is exact in exact arithmetic). Double keeps it to 4e-16 rad and 7e-16 max(a, r), measured
  // on 2e5 points (GeographicLib: 3.6e-16 rad, 5.3e-16 max(a, r)); the tolerances leave 2x.
  using big = boost::multiprecision::cpp_bin_float_50;
  const earth_constants& w = wgs84();
  const big a = w.a_m, f = w.f, e2 = f * (2 - f), e2m = (1 - f) * (1 - f), e4 = e2 * e2;
  double worst_lat = 0, worst_alt = 0;
  for (double distance_m = 100e3; distance_m <= 1e9; distance_m *= 1.37) {
    for (double lat_deg = -89; lat_deg <= 90; lat_deg += 7.3) {
      const double c = std::cos(lat_deg * deg);
      const vec3<double> p = distance_m * vec3<double>(c * 0.6, c * 0.8, std::sin(lat_deg * deg));
      const big x = p.x, y = p.y, z = p.z, axis = sqrt(x * x + y * y);
      const big pp = (axis / a) * (axis / a), q = e2m * (z / a) * (z / a), r = (pp + q - e4) / 6;
      const big s = e4 * pp * q / 4, r3 = r * r * r;
      const big t = cbrt(s + r3 + sqrt(s * (2 * r3 + s)));
      const big u = r + t + r * r / t, v = sqrt(u * u + e4 * q), uv = u + v;
      const big wk = e2 * (uv - q) / (2 * v), k = uv / (sqrt(uv + wk * wk) + wk), k2 = k + e2;
      const big d = k * axis / k2;
      const big lat = atan2(z / k, axis / k2), alt = (1 - e2m / k) * sqrt(d * d + z * z);
      const geodetic_position g = geodetic_from_eci(p);
      worst_lat = std::max(worst_lat, std::abs(static_cast<double>(big(g.lat_rad) - lat)));
      worst_alt = std::max(worst_alt, std::abs(static_cast<double>(big(g.alt_m) - alt)) /
                                          std::max(w.a_m, distance_m));
    }
  }
  CHECK(worst_lat <= 8e-16);
  CHECK(worst_alt <= 1.4e-15);
}

TEST_CASE("orbit: geodetic of several points at once is each point's", "[orbit][geodetic]") {
  // Lanes mix the closed form and GeographicLib's hand-over (the centre, NaN, beyond 1e20 m), and
  // the count is not a multiple of geodetic_lanes: every result must be bit for bit the single
  // point's.
  const double nan = std::nan("");
  const std::vector<vec3<double>> points = {{6552e3, 0, 0},  {0, 0, 0},       {7000e3, 1e3, -2e6},
                                            {nan, 0, 7e6},   {4e20, 0, 1e20}, {0, 0, 6.4e6},
                                            {1e5, 2e5, 3e5}, {30e3, 0, 0},    {-7e6, 3e6, 2.5e6}};
  std::vector<geodetic_position> batch(points.size());
  geodetic_from_eci(points.data(), batch.data(), points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const geodetic_position single = geodetic_from_eci(points[i]);
    INFO("point " << i);
    CHECK(same_or_both_nan(batch[i].lat_rad, single.lat_rad));
    CHECK(same_or_both_nan(batch[i].alt_m, single.alt_m));
  }
}

TEST_CASE("orbit: geodetic on the axis, in the equator, and out of range", "[orbit][geodetic]") {
  const earth_constants& w = wgs84();
  // On the axis: latitude +-90 deg exactly, height |z| - b.
  const geodetic_position north = geodetic_from_eci(vec3<double>(0, 0, 7000e3));
  CHECK(north.lat_rad == pi<double>() / 2);
  CHECK(north.alt_m == Approx(7000e3 - w.b_m).margin(1e-8));
  const geodetic_position south = geodetic_from_eci(vec3<double>(0, 0, -7000e3));
  CHECK(south.lat_rad == -pi<double>() / 2);
  CHECK(south.alt_m == Approx(7000e3 - w.b_m).margin(1e-8));
  // In the equator: latitude 0 exactly, height r - a.
  const geodetic_position equator = geodetic_from_eci(vec3<double>(7000e3, 0, 0));
  CHECK(equator.lat_rad == 0);
  CHECK(equator.alt_m == Approx(7000e3 - w.a_m).margin(1e-8));
  // NaN in, NaN out (no silent number).
  const geodetic_position bad = geodetic_from_eci(vec3<double>(std::nan(""), 0, 7000e3));
  CHECK(std::isnan(bad.lat_rad));
  CHECK(std::isnan(bad.alt_m));
}
