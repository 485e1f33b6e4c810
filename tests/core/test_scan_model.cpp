// The forward models of MODEL §5: bias (bias_model.hpp) and scan, on a sphere and on an ellipsoid
// (scan_model.hpp), in double.
//
// Expected values come from
//  - the cross-check MODEL §5 requires: zero attitude and phi_a = 0 or 180 deg give a symmetric
//    scan whose half chord is the closed form Eq. (3) with psi at the crossings' own azimuths;
//  - sigma = 0, where every model is the aligned closed form half_chord(gamma, eta, rho);
//  - the horizon condition itself, evaluated in long double at the solved crossings (the angle
//    from the line of sight to the nadir is rho; on the ellipsoid, the tangency residual g);
//  - a first-order perturbation of the crossings in sigma (derived below), for the size of the
//    phase error at phi_a = 90 deg and of the chord change at phi_a = 0;
//  - hand-derived miss/engulfed boundaries: with phi_n = phi_a = 0 the line of sight nearest the
//    nadir is at phi = 0, psi = gamma + sigma, and the farthest at phi = pi, psi = gamma - sigma.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <vector>

#include "conescan/attitude.hpp"
#include "conescan/bias_model.hpp"
#include "conescan/cone_angle.hpp"
#include "conescan/half_chord.hpp"
#include "conescan/orbital_frame.hpp"
#include "conescan/processing.hpp"
#include "conescan/scan_model.hpp"
#include "support/approx.hpp"

using conescan::crossings;
using conescan::deg_to_rad;
using conescan::half_chord;
using conescan::head_optics;
using conescan::misaligned_cone_angle;
using conescan::scan_frame;
using conescan::scan_model_crossings_ellipsoid;
using conescan::scan_model_crossings_sphere;
using conescan::status;
using conescan::vec3;

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();
constexpr double earth_radius_m = 6378137.0;                           // WGS84 a
constexpr double earth_polar_m = 6378137.0 * (1 - 1 / 298.257223563);  // WGS84 b = a (1 - f)

double deg(double d) {
  return deg_to_rad(d);
}

/// Angle from the true line of sight at scan azimuth phi (psi = psi(phi - phi_a), MODEL §4) to
/// the nadir (eta, phi_n), in long double: on the horizon it is rho (MODEL §5).
long double angle_to_nadir(const head_optics<double>& o, double phi, double eta, double phi_n) {
  const long double psi = misaligned_cone_angle<long double>(o.gamma, o.sigma, phi - o.phi_a).value;
  const long double f = phi, e = eta, fn = phi_n;
  const vec3<long double> l(std::sin(psi) * std::cos(f), std::sin(psi) * std::sin(f),
                            std::cos(psi));
  const vec3<long double> n(std::sin(e) * std::cos(fn), std::sin(e) * std::sin(fn), std::cos(e));
  return conescan::angle_between(l, n);
}

/// MODEL §5's ellipsoid tangency function at scan azimuth phi, in long double, normalised by
/// |D|^2: (P.D)^2 / |D|^2 - (|P|^2 - 1), with P, D the satellite position and the line of sight
/// scaled by 1/a (x, y) and 1/b (z). Also returns P.D, whose sign says in front (< 0) or behind.
struct tangency {
  long double g_normalised;
  long double p_dot_d;
};
tangency tangency_at(const head_optics<double>& o, const scan_frame<double>& f_eci,
                     const vec3<double>& p, double a, double b, double phi) {
  const long double psi = misaligned_cone_angle<long double>(o.gamma, o.sigma, phi - o.phi_a).value;
  const long double c = std::cos(static_cast<long double>(phi));
  const long double s = std::sin(static_cast<long double>(phi));
  auto ld = [](const vec3<double>& v) { return vec3<long double>(v.x, v.y, v.z); };
  const vec3<long double> d =
      ld(f_eci.e3) * std::cos(psi) + (ld(f_eci.e1) * c + ld(f_eci.e2) * s) * std::sin(psi);
  const long double al = a, bl = b;
  const vec3<long double> pp(p.x / al, p.y / al, p.z / bl), dd(d.x / al, d.y / al, d.z / bl);
  const long double pd = conescan::dot(pp, dd), d2 = conescan::dot(dd, dd);
  return {pd * pd / d2 - (conescan::dot(pp, pp) - 1), pd};
}

/// A scan frame expressed in ECI: body axes from the orbital frame at (p, v) and the attitude.
scan_frame<double> frame_in_eci(const scan_frame<double>& f_body, const vec3<double>& p,
                                const vec3<double>& v, double roll, double pitch, double yaw) {
  const conescan::mat3<double> eci_from_orbit = conescan::dcm_eci_from_orbit(p, v);
  const conescan::mat3<double> body_from_orbit = conescan::dcm_body_from_orbit(roll, pitch, yaw);
  auto to_eci = [&](const vec3<double>& e) {
    return conescan::apply(eci_from_orbit, conescan::apply_transpose(body_from_orbit, e));
  };
  return {to_eci(f_body.e1), to_eci(f_body.e2), to_eci(f_body.e3), f_body.state};
}

bool is_status_of_a_forward_model(status s) {
  return s == status::ok || s == status::miss || s == status::engulfed || s == status::grazing;
}

/// Invariants of any ok crossings (MODEL §5, crossings.hpp).
void check_well_formed(const crossings<double>& c) {
  CHECK(std::isfinite(c.phi_in));
  CHECK(std::isfinite(c.phi_out));
  CHECK(c.phi_out > c.phi_in);
  CHECK(c.chord() < 2 * conescan::pi<double>());
  CHECK(c.half_chord() >= conescan::grazing_half_chord_min<double>());
}

const int max_iterations_per_root = conescan::bracketed_newton_max_iterations<double>();

}  // namespace

TEST_CASE("scan model on a sphere, sigma = 0: the aligned closed form", "[scan_model][sigma0]") {
  // With sigma = 0, psi = gamma at every azimuth and the crossings are phi_n -+ half_chord(gamma,
  // eta, rho) (Eq. (3)). Tolerance 1e-13 rad (a few ulp of |phi_n| + Phi). Statuses agree with
  // the closed form's away from its boundaries.
  int compared = 0;
  for (double g : {20.0, 45.0, 60.0}) {
    for (double e : {10.0, 30.0, 60.0, 90.0, 110.0}) {
      for (double r : {20.0, 45.0, 61.2, 75.0}) {
        for (double phi_n : {0.0, 1.0, -2.5, 3.0}) {
          for (double phi_a : {0.0, 1.3}) {
            const head_optics<double> o{deg(g), 0.0, phi_a};
            const conescan::result<double> aligned = half_chord(deg(g), deg(e), deg(r));
            const crossings<double> c = scan_model_crossings_sphere(o, deg(e), phi_n, deg(r));
            INFO("gamma " << g << " eta " << e << " rho " << r << " phi_n " << phi_n);
            CHECK(c.state == aligned.state);
            if (!aligned.ok()) continue;
            ++compared;
            CHECK_WITHIN(c.phi_in, phi_n - aligned.value, 1e-13);
            CHECK_WITHIN(c.phi_out, phi_n + aligned.value, 1e-13);
            CHECK(c.iterations <= 2 * 6);  // Newton from the exact answer: a few steps at most
          }
        }
      }
    }
  }
  CHECK(compared > 100);
}

TEST_CASE("MODEL §5 cross-check: zero attitude, phi_a = 0 or 180 deg", "[scan_model][spec5]") {
  // Zero true attitude: the nadir is body +z, at eta = eta0 = 90 deg - alpha and phi_n = 0.
  // With phi_a = 0 or 180 deg, psi depends on cos(phi - phi_a) only, so the scan is symmetric
  // (phi_in = -phi_out, phase 0) and its half chord Phi solves Eq. (3) with psi at its own
  // azimuths, Phi_B = +-Phi - phi_a. Tolerance 1e-13 rad ("machine precision", MODEL §5).
  int compared = 0;
  for (double alpha : {-20.0, 0.0, 20.0, 40.0}) {
    const scan_frame<double> frame = conescan::scan_frame_from_mounting(deg(alpha), deg(90));
    const conescan::scan_angles<double> nadir =
        conescan::scan_angles_of(frame, conescan::nadir_in_body(0.0, 0.0));
    CHECK(nadir.azimuth == 0);
    for (double g : {30.0, 45.0, 60.0}) {
      for (double s : {0.02, 0.5, 2.0}) {
        for (double r_km : {6700.0, 7280.0, 8200.0}) {
          const double rho = std::asin(6378.137 / r_km);
          for (double phi_a : {0.0, 180.0}) {
            const head_optics<double> o{deg(g), deg(s), deg(phi_a)};
            const crossings<double> c = scan_model_crossings_sphere(o, nadir.polar, 0.0, rho);
            INFO("alpha " << alpha << " gamma " << g << " sigma " << s << " r " << r_km << " phi_a "
                          << phi_a << " status " << conescan::to_string(c.state));
            if (c.state != status::ok) continue;
            ++compared;
            check_well_formed(c);
            CHECK_WITHIN(c.phi_in, -c.phi_out, 1e-13);
            CHECK_WITHIN(c.phase(), 0.0, 1e-13);
            const double phi = c.half_chord();
            for (double phi_b : {phi - o.phi_a, -phi - o.phi_a}) {
              const double psi = misaligned_cone_angle(o.gamma, o.sigma, phi_b).value;
              const conescan::result<double> closed = half_chord(psi, nadir.polar, rho);
              REQUIRE(closed.ok());
              CHECK_WITHIN(phi, closed.value, 1e-13);
            }
          }
        }
      }
    }
  }
  CHECK(compared > 100);
}

TEST_CASE("scan model on a sphere puts both crossings on the horizon", "[scan_model]") {
  // Any attitude (phi_n != 0) and misalignment azimuth: at each solved azimuth the true line of
  // sight is rho from the nadir (long double geometry). The Newton iteration stops at a few ulp
  // of phi (<= 4 pi eps here), which moves that angle by at most as much: tolerance 1e-13.
  int compared = 0;
  for (double g : {30.0, 45.0}) {
    for (double s : {0.02, 1.0, 5.0}) {
      for (double phi_a : {-150.0, 0.0, 33.0, 90.0, 180.0}) {
        for (double e : {50.0, 70.0, 85.0}) {
          for (double phi_n : {-3.0, -0.2, 0.0, 1.7}) {
            const double rho = deg(62);
            const head_optics<double> o{deg(g), deg(s), deg(phi_a)};
            const crossings<double> c = scan_model_crossings_sphere(o, deg(e), phi_n, rho);
            INFO("gamma " << g << " sigma " << s << " phi_a " << phi_a << " eta " << e << " phi_n "
                          << phi_n << " status " << conescan::to_string(c.state));
            REQUIRE(c.state == status::ok);
            ++compared;
            check_well_formed(c);
            for (double phi : {c.phi_in, c.phi_out})
              CHECK_WITHIN(angle_to_nadir(o, phi, deg(e), phi_n), static_cast<long double>(rho),
                           1e-13L);
            // The arc between them is the one on the Earth: its middle is closer than rho to
            // the nadir, the middle of the other arc farther.
            CHECK(angle_to_nadir(o, c.phase(), deg(e), phi_n) < rho);
            CHECK(angle_to_nadir(o, c.phase() + conescan::pi<double>(), deg(e), phi_n) > rho);
            CHECK(std::abs(c.phase() - phi_n) < 0.5);  // near the nadir's azimuth
            CHECK(c.iterations <= 2 * 8);              // "a few Newton steps" (MODEL §5)
          }
        }
      }
    }
  }
  CHECK(compared == 2 * 3 * 5 * 3 * 4);
}

TEST_CASE("phi_a = 90 deg: the misalignment shows as a phase error, not a chord error",
          "[scan_model][phase]") {
  // First order in sigma (psi ~ gamma + sigma cos(phi - phi_a), MODEL §4), zero attitude
  // (phi_n = 0), aligned half chord Phi0: a crossing of h(phi, psi) = 0 moves by
  // -h_psi dpsi / h_phi, with h_psi = -sin gamma cos eta + cos gamma sin eta cos Phi0 and
  // h_phi = -+ sin gamma sin eta sin Phi0 at +-Phi0. Averaging and differencing the two moves:
  //   phase      = h_psi sigma sin phi_a / (sin gamma sin eta),
  //   half chord = Phi0 + h_psi sigma cos phi_a cos Phi0 / (sin gamma sin eta sin Phi0).
  // So phi_a = 90 deg gives a phase error and no first-order chord change; phi_a = 0 the
  // reverse. At phi_a = 90 deg, h = sin sigma sin phi: sigma -> -sigma mirrors the scan
  // (phi -> -phi), so the phase is odd in sigma (its first-order term is off by O(sigma^2)
  // relative: tolerance 4 sigma^2) and the half chord even (its change is O(sigma^2): below 5 %
  // of the first-order change at phi_a = 0). At phi_a = 0 the first-order chord term is off by
  // O(sigma) relative: tolerance 20 sigma.
  const double alpha = 0.0, eta = deg(90) - alpha;
  for (double g : {30.0, 45.0}) {
    for (double r_km : {7000.0, 7280.0}) {
      for (double s : {0.02, 0.2}) {
        const double gamma = deg(g), sigma = deg(s), rho = std::asin(6378.137 / r_km);
        const double phi0 = half_chord(gamma, eta, rho).value;
        const double h_psi =
            -std::sin(gamma) * std::cos(eta) + std::cos(gamma) * std::sin(eta) * std::cos(phi0);
        const double phase_first_order = h_psi * sigma / (std::sin(gamma) * std::sin(eta));
        const double chord_first_order =
            h_psi * sigma * std::cos(phi0) / (std::sin(gamma) * std::sin(eta) * std::sin(phi0));
        INFO("gamma " << g << " r " << r_km << " sigma " << s);
        const crossings<double> at_90 =
            scan_model_crossings_sphere(head_optics<double>{gamma, sigma, deg(90)}, eta, 0.0, rho);
        const crossings<double> at_0 =
            scan_model_crossings_sphere(head_optics<double>{gamma, sigma, 0.0}, eta, 0.0, rho);
        REQUIRE(at_90.state == status::ok);
        REQUIRE(at_0.state == status::ok);
        CHECK(at_90.phase() != 0);
        CHECK_WITHIN(at_90.phase(), phase_first_order,
                     4 * sigma * sigma * std::abs(phase_first_order));
        CHECK_WITHIN(at_0.half_chord() - phi0, chord_first_order,
                     20 * sigma * std::abs(chord_first_order));
        CHECK(std::abs(at_0.phase()) < 1e-13);
        CHECK(std::abs(at_90.half_chord() - phi0) < 0.05 * std::abs(at_0.half_chord() - phi0));
        // The bias model (psi frozen at phi = 0) never has a phase error (MODEL §5).
        const crossings<double> bias = conescan::bias_model_crossings(
            head_optics<double>{gamma, sigma, deg(90)}, eta, 0.0, rho);
        CHECK(std::abs(bias.phase()) <= 2 * eps);
      }
    }
  }
}

TEST_CASE("bias model: psi frozen at the reference pulse", "[bias_model]") {
  // Hand-derived psi at phi = 0 (Phi_B = -phi_a): phi_a = 0 gives gamma + sigma, phi_a = 180
  // deg gives gamma - sigma (S, A and the line of sight coplanar). The crossings are then
  // phi_n -+ half_chord(psi, eta, rho), symmetric about the nadir azimuth.
  const double gamma = deg(45), sigma = deg(0.5), eta = deg(80), rho = deg(61);
  for (double phi_n : {0.0, 0.7, -2.0}) {
    for (double phi_a : {0.0, 180.0}) {
      const double psi = phi_a == 0 ? gamma + sigma : gamma - sigma;
      const double phi = half_chord(psi, eta, rho).value;
      const crossings<double> c = conescan::bias_model_crossings(
          head_optics<double>{gamma, sigma, deg(phi_a)}, eta, phi_n, rho);
      INFO("phi_n " << phi_n << " phi_a " << phi_a);
      REQUIRE(c.state == status::ok);
      CHECK(c.iterations == 0);
      CHECK_WITHIN(c.phi_in, phi_n - phi, 8 * eps * (1 + std::abs(phi_n)));
      CHECK_WITHIN(c.phi_out, phi_n + phi, 8 * eps * (1 + std::abs(phi_n)));
      CHECK_WITHIN(c.phase(), phi_n, 2 * eps * (1 + std::abs(phi_n)));
    }
  }
  // Statuses pass through: invalid optics, miss, engulfed.
  CHECK(
      conescan::bias_model_crossings(head_optics<double>{gamma, gamma, 0.0}, eta, 0.0, rho).state ==
      status::invalid);
  CHECK(conescan::bias_model_crossings(head_optics<double>{gamma, sigma, 0.0}, eta,
                                       std::numeric_limits<double>::quiet_NaN(), rho)
            .state == status::invalid);
  CHECK(conescan::bias_model_crossings(head_optics<double>{gamma, sigma, 0.0}, deg(170), 0.0, rho)
            .state == status::miss);
  CHECK(conescan::bias_model_crossings(head_optics<double>{deg(10), sigma, 0.0}, deg(5), 0.0, rho)
            .state == status::engulfed);
}

TEST_CASE("scan model on a sphere: miss and engulfed on both sides of hand-derived boundaries",
          "[scan_model][status]") {
  // phi_n = phi_a = 0: psi(phi) = gamma + sigma at phi = 0 (nearest the nadir when eta > psi),
  // gamma - sigma at phi = pi. Miss boundary (eta > gamma + sigma): rho = eta - gamma - sigma.
  // Engulfed boundary (eta > sigma, the far point at phi = pi): rho = eta + gamma - sigma. Just
  // past them: miss / engulfed; just before: a sliver of chord, i.e. grazing; further: ok.
  const double gamma = deg(30), sigma = deg(1);
  const head_optics<double> o{gamma, sigma, 0.0};
  SECTION("miss") {
    const double eta = deg(50), rho_b = eta - gamma - sigma;
    CHECK(scan_model_crossings_sphere(o, eta, 0.0, rho_b - 1e-9).state == status::miss);
    CHECK(scan_model_crossings_sphere(o, eta, 0.0, rho_b * 0.9).state == status::miss);
    CHECK(scan_model_crossings_sphere(o, eta, 0.0, rho_b + 1e-9).state == status::grazing);
    const crossings<double> c = scan_model_crossings_sphere(o, eta, 0.0, rho_b + deg(1));
    CHECK(c.state == status::ok);
  }
  SECTION("engulfed") {
    const double eta = deg(10), rho_b = eta + gamma - sigma;
    CHECK(scan_model_crossings_sphere(o, eta, 0.0, rho_b + 1e-9).state == status::engulfed);
    CHECK(scan_model_crossings_sphere(o, eta, 0.0, rho_b * 1.1).state == status::engulfed);
    CHECK(scan_model_crossings_sphere(o, eta, 0.0, rho_b - 1e-9).state == status::grazing);
    CHECK(scan_model_crossings_sphere(o, eta, 0.0, rho_b - deg(1)).state == status::ok);
  }
  SECTION("grazing threshold on the scan model's own chord") {
    // By the MODEL §5 identity, the rho for which the symmetric scan's half chord is Phi is
    // acos(cos psi cos eta + sin psi sin eta cos Phi) with psi = psi(Phi).
    const double eta = deg(50), phi_min = conescan::grazing_half_chord_min<double>();
    for (double factor : {1 - 1e-6, 1 + 1e-6}) {
      const double phi = phi_min * factor;
      const double psi = misaligned_cone_angle(gamma, sigma, phi).value;
      const double rho =
          std::acos(std::cos(psi) * std::cos(eta) + std::sin(psi) * std::sin(eta) * std::cos(phi));
      CHECK(scan_model_crossings_sphere(o, eta, 0.0, rho).state ==
            (factor < 1 ? status::grazing : status::ok));
    }
  }
  SECTION("invalid") {
    const double nan_d = std::numeric_limits<double>::quiet_NaN();
    CHECK(scan_model_crossings_sphere(head_optics<double>{gamma, gamma, 0.0}, deg(50), 0.0, 0.5)
              .state == status::invalid);
    CHECK(scan_model_crossings_sphere(head_optics<double>{gamma, -1e-9, 0.0}, deg(50), 0.0, 0.5)
              .state == status::invalid);
    CHECK(scan_model_crossings_sphere(head_optics<double>{gamma, 0.0, nan_d}, deg(50), 0.0, 0.5)
              .state == status::invalid);
    CHECK(scan_model_crossings_sphere(o, deg(50), nan_d, 0.5).state == status::invalid);
    CHECK(scan_model_crossings_sphere(o, -1e-9, 0.0, 0.5).state == status::invalid);
    CHECK(scan_model_crossings_sphere(o, deg(50), 0.0, deg(90) * (1 + 1e-9)).state ==
          status::invalid);
    CHECK(scan_model_crossings_sphere(o, deg(50), 0.0, deg(90)).state != status::invalid);
  }
}

TEST_CASE("ellipsoid with a_eq == b_pol is the sphere", "[scan_model][ellipsoid]") {
  // ECI geometry: satellite at p with velocity v, body attitude from the orbital frame (MODEL
  // §2), head mounting (MODEL §4); the scan frame's axes are rotated into ECI. The sphere sees
  // the nadir at (eta, phi_n) = the angles of -p in that frame and rho = asin(R / |p|).
  // Tolerance 1e-12 rad: the two solvers iterate on different functions with the same zeros.
  int compared = 0;
  const vec3<double> positions[] = {vec3<double>(7280e3, 0, 0), vec3<double>(-3.1e6, 4.4e6, 4.9e6),
                                    vec3<double>(1e5, -2e5, -6.9e6)};
  for (const vec3<double>& p : positions) {
    const vec3<double> v = conescan::cross(vec3<double>(0.3, -0.5, 1), p) * 1e-3;
    for (double alpha : {0.0, 20.0, -30.0}) {
      for (double beta : {90.0, -45.0}) {
        const scan_frame<double> f_body = conescan::scan_frame_from_mounting(deg(alpha), deg(beta));
        for (double roll : {0.0, 2.0}) {
          for (double pitch : {0.0, -1.5}) {
            const scan_frame<double> f_eci = frame_in_eci(f_body, p, v, deg(roll), deg(pitch), 0.3);
            const conescan::scan_angles<double> nadir = conescan::scan_angles_of(f_eci, -p);
            const double rho = std::asin(earth_radius_m / conescan::norm(p));
            for (double phi_a : {0.0, 90.0, 200.0}) {
              const head_optics<double> o{deg(45), deg(0.5), deg(phi_a)};
              const crossings<double> sphere =
                  scan_model_crossings_sphere(o, nadir.polar, nadir.azimuth, rho);
              const crossings<double> ellipsoid =
                  scan_model_crossings_ellipsoid(o, f_eci, p, earth_radius_m, earth_radius_m);
              INFO("p " << p.x << " " << p.y << " " << p.z << " alpha " << alpha << " beta " << beta
                        << " roll " << roll << " pitch " << pitch << " phi_a " << phi_a);
              REQUIRE(ellipsoid.state == sphere.state);
              if (sphere.state != status::ok) continue;
              ++compared;
              CHECK_WITHIN(ellipsoid.phi_in, sphere.phi_in, 1e-12);
              CHECK_WITHIN(ellipsoid.phi_out, sphere.phi_out, 1e-12);
            }
          }
        }
      }
    }
  }
  CHECK(compared > 100);
}

TEST_CASE("ellipsoid crossings are tangent to the inflated WGS84 ellipsoid",
          "[scan_model][ellipsoid]") {
  // MODEL §5: at a crossing the ray is tangent, g = 0 with P.D < 0. |g| / |D|^2 is bounded by
  // 1e-12 (scan_model.hpp's documented accuracy). The arc between the crossings is the one that
  // hits the Earth (g > 0 and P.D < 0 at its middle, not opposite), and "hits the Earth" changes
  // exactly twice around the scan (720 samples).
  const double a = earth_radius_m + 40e3, b = earth_polar_m + 40e3;  // h_h = 40 km
  int compared = 0;
  for (double lat : {0.0, 35.0, 64.0, 89.0}) {
    for (double r : {6.8e6, 7.28e6, 8e6}) {
      const vec3<double> p(r * std::cos(deg(lat)), 0.0, r * std::sin(deg(lat)));
      const vec3<double> v(0.0, 7e3 * std::cos(deg(10)), 7e3 * std::sin(deg(10)));
      for (double alpha : {0.0, 25.0}) {
        const scan_frame<double> f_body = conescan::scan_frame_from_mounting(deg(alpha), deg(90));
        const scan_frame<double> f_eci = frame_in_eci(f_body, p, v, deg(1), deg(-2), 0.0);
        for (double s : {0.0, 0.02, 3.0}) {
          for (double phi_a : {0.0, 120.0}) {
            const head_optics<double> o{deg(45), deg(s), deg(phi_a)};
            const crossings<double> c = scan_model_crossings_ellipsoid(o, f_eci, p, a, b);
            INFO("lat " << lat << " r " << r << " alpha " << alpha << " sigma " << s << " phi_a "
                        << phi_a << " status " << conescan::to_string(c.state));
            REQUIRE(c.state == status::ok);
            ++compared;
            check_well_formed(c);
            for (double phi : {c.phi_in, c.phi_out}) {
              const tangency t = tangency_at(o, f_eci, p, a, b, phi);
              CHECK(std::abs(t.g_normalised) < 1e-12L);
              CHECK(t.p_dot_d < 0);
            }
            const tangency middle = tangency_at(o, f_eci, p, a, b, c.phase());
            CHECK((middle.g_normalised > 0 && middle.p_dot_d < 0));
            // Opposite: off the Earth, i.e. missing the ellipsoid or hitting it behind (g > 0
            // with P.D > 0, which the header's horizon function treats as off).
            const tangency opposite =
                tangency_at(o, f_eci, p, a, b, c.phase() + conescan::pi<double>());
            CHECK_FALSE((opposite.g_normalised > 0 && opposite.p_dot_d < 0));
            int sign_changes = 0;
            bool on_earth_before = false;
            for (int k = 0; k <= 720; ++k) {
              const double phi = c.phi_in + 0.5e-3 + k * (2 * conescan::pi<double>() / 720);
              const tangency t = tangency_at(o, f_eci, p, a, b, phi);
              const bool on_earth = t.g_normalised > 0 && t.p_dot_d < 0;
              if (k > 0 && on_earth != on_earth_before) ++sign_changes;
              on_earth_before = on_earth;
            }
            CHECK(sign_changes == 2);
            CHECK(c.iterations <= 2 * 10);
          }
        }
      }
    }
  }
  CHECK(compared == 4 * 3 * 2 * 3 * 2);
}

TEST_CASE("ellipsoid statuses: miss, engulfed on both sides, and invalid",
          "[scan_model][ellipsoid][status]") {
  // With a_eq == b_pol the hand-derived sphere boundaries apply. Frame: e1, e2, e3 = ECI x, y, z;
  // the satellite at p = -r (sin eta, 0, cos eta) sees the centre at eta from e3, azimuth 0.
  // The disk radius asin(R / r) is moved across the boundary through r.
  const scan_frame<double> f{vec3<double>(1, 0, 0), vec3<double>(0, 1, 0), vec3<double>(0, 0, 1),
                             status::ok};
  const double gamma = deg(30), sigma = deg(1), R = earth_radius_m;
  const head_optics<double> o{gamma, sigma, 0.0};
  auto satellite = [](double eta, double r) {
    return vec3<double>(-r * std::sin(eta), 0.0, -r * std::cos(eta));
  };
  auto radius_for_rho = [&](double rho) { return R / std::sin(rho); };
  SECTION("miss") {
    const double eta = deg(50), rho_b = eta - gamma - sigma;
    CHECK(scan_model_crossings_ellipsoid(o, f, satellite(eta, radius_for_rho(rho_b - 1e-8)), R, R)
              .state == status::miss);
    CHECK(scan_model_crossings_ellipsoid(o, f, satellite(eta, radius_for_rho(rho_b + 1e-8)), R, R)
              .state == status::grazing);
    CHECK(scan_model_crossings_ellipsoid(o, f, satellite(eta, radius_for_rho(rho_b + deg(2))), R, R)
              .state == status::ok);
    // Looking away from the Earth altogether.
    CHECK(scan_model_crossings_ellipsoid(o, f, satellite(deg(180), 7e6), R, R).state ==
          status::miss);
  }
  SECTION("engulfed") {
    const double eta = deg(10), rho_b = eta + gamma - sigma;
    CHECK(scan_model_crossings_ellipsoid(o, f, satellite(eta, radius_for_rho(rho_b + 1e-8)), R, R)
              .state == status::engulfed);
    CHECK(scan_model_crossings_ellipsoid(o, f, satellite(eta, radius_for_rho(rho_b - 1e-8)), R, R)
              .state == status::grazing);
    CHECK(scan_model_crossings_ellipsoid(o, f, satellite(eta, radius_for_rho(rho_b - deg(2))), R, R)
              .state == status::ok);
  }
  SECTION("invalid") {
    const vec3<double> p = satellite(deg(60), 7e6);
    const double nan_d = std::numeric_limits<double>::quiet_NaN();
    // Semi-axes must be positive (whether b_pol > a_eq, a prolate surface, is accepted is the
    // header's documented choice and not pinned here).
    CHECK(scan_model_crossings_ellipsoid(o, f, p, 0.0, R).state == status::invalid);
    CHECK(scan_model_crossings_ellipsoid(o, f, p, -R, R).state == status::invalid);
    CHECK(scan_model_crossings_ellipsoid(o, f, p, R, 0.0).state == status::invalid);
    CHECK(scan_model_crossings_ellipsoid(o, f, p, R, -1.0).state == status::invalid);
    CHECK(scan_model_crossings_ellipsoid(o, f, p, R, 1.0).state != status::invalid);
    CHECK(scan_model_crossings_ellipsoid(o, f, vec3<double>(nan_d, 0, 0), R, R).state ==
          status::invalid);
    // Satellite on or inside the ellipsoid: |P| <= 1.
    CHECK(scan_model_crossings_ellipsoid(o, f, vec3<double>(-R, 0, 0), R, R).state ==
          status::invalid);
    CHECK(scan_model_crossings_ellipsoid(o, f, satellite(deg(60), R * (1 - 1e-9)), R, R).state ==
          status::invalid);
    CHECK(scan_model_crossings_ellipsoid(o, f, satellite(deg(60), R * (1 + 1e-9)), R, R).state !=
          status::invalid);
    CHECK(
        scan_model_crossings_ellipsoid(head_optics<double>{gamma, gamma, 0.0}, f, p, R, R).state ==
        status::invalid);
  }
}

TEST_CASE("scan models stay bounded on nasty inputs", "[scan_model][robustness]") {
  // Each root costs at most bracketed_newton_max_iterations(); every outcome is a status of
  // MODEL §7, never a NaN with status ok. Where ok, the crossings are well formed and on the
  // horizon (looser 1e-9 here: some of these are near-tangent, where the angle is
  // ill-conditioned in phi).
  struct sphere_case {
    double gamma, sigma, phi_a, eta, phi_n, rho;
  };
  const double gamma = deg(30), sigma = deg(1), pi = conescan::pi<double>();
  std::vector<sphere_case> cases;
  for (double d : {1e-15, 1e-12, 1e-9, 1e-6}) {
    cases.push_back({gamma, sigma, 0.0, deg(50), 0.0, deg(50) - gamma - sigma + d});
    cases.push_back({gamma, sigma, 0.0, deg(10), 0.0, deg(10) + gamma - sigma - d});
    cases.push_back({gamma, sigma, 1.0, deg(50), 0.3, deg(50) - gamma - sigma + d});
  }
  for (double phi_a : {0.0, 0.5, 1.5708, 3.0}) {
    cases.push_back({gamma, gamma * 0.999, phi_a, deg(60), 0.0, deg(45)});  // sigma -> gamma
    cases.push_back({gamma, gamma * 0.999, phi_a, deg(40), 2.0, deg(20)});
    cases.push_back({gamma, sigma, phi_a, 0.0, 0.0, gamma});  // nadir on S
    cases.push_back({gamma, sigma, phi_a, 0.0, 0.0, gamma + sigma * 0.5});
    cases.push_back({gamma, sigma, phi_a, pi, 0.0, deg(80)});      // nadir on -S
    cases.push_back({gamma, sigma, phi_a, deg(90), 0.0, pi / 2});  // rho = 90 deg
    cases.push_back({1e-8, 1e-9, phi_a, 1e-8, 0.0, 1e-8});         // tiny cone
    cases.push_back({std::nextafter(pi / 2, 0.0), sigma, phi_a, deg(90), 0.0, deg(60)});
    cases.push_back({gamma, sigma, phi_a + 1e6, deg(50), 1e6, deg(40)});  // huge angles
  }
  for (const sphere_case& k : cases) {
    const head_optics<double> o{k.gamma, k.sigma, k.phi_a};
    const crossings<double> c = scan_model_crossings_sphere(o, k.eta, k.phi_n, k.rho);
    INFO("gamma " << k.gamma << " sigma " << k.sigma << " phi_a " << k.phi_a << " eta " << k.eta
                  << " phi_n " << k.phi_n << " rho " << k.rho << " status "
                  << conescan::to_string(c.state) << " iterations " << c.iterations);
    CHECK(is_status_of_a_forward_model(c.state));
    CHECK(c.iterations >= 0);
    CHECK(c.iterations <= 2 * max_iterations_per_root);
    if (c.state != status::ok) {
      CHECK(std::isnan(c.phi_in));
      continue;
    }
    check_well_formed(c);
    for (double phi : {c.phi_in, c.phi_out})
      CHECK_WITHIN(angle_to_nadir(o, phi, k.eta, k.phi_n), static_cast<long double>(k.rho), 1e-9L);
  }
  // Ellipsoid: strong flattening, a satellite just above the surface, one very far away.
  const scan_frame<double> f{vec3<double>(1, 0, 0), vec3<double>(0, 1, 0), vec3<double>(0, 0, 1),
                             status::ok};
  struct ellipsoid_case {
    vec3<double> p;
    double a, b, sigma, phi_a;
  };
  const double R = earth_radius_m;
  std::vector<ellipsoid_case> e_cases;
  for (double phi_a : {0.0, 2.0}) {
    for (double s : {0.0, 0.02, 25.0}) {
      e_cases.push_back({vec3<double>(-7e6, 0, -2e6), R, 0.05 * R, deg(s), phi_a});
      e_cases.push_back({vec3<double>(-2e6, 0, -7e6), R, 0.05 * R, deg(s), phi_a});
      e_cases.push_back({vec3<double>(-R * (1 + 1e-12), 0, -1), R, R, deg(s), phi_a});
      const double c45 = R / std::sqrt(2.0);  // |P|^2 = 1 + 2e-9: just above the surface
      e_cases.push_back({vec3<double>(-c45, 0, -c45 * (1 + 2e-9)), R, R, deg(s), phi_a});
      e_cases.push_back({vec3<double>(-1e10, 0, -1e10), R, R, deg(s), phi_a});
      e_cases.push_back({vec3<double>(-1e8, 0, -1e8), R, earth_polar_m, deg(s), phi_a});
    }
  }
  for (const ellipsoid_case& k : e_cases) {
    const head_optics<double> o{gamma, k.sigma, k.phi_a};
    const crossings<double> c = scan_model_crossings_ellipsoid(o, f, k.p, k.a, k.b);
    INFO("p " << k.p.x << " " << k.p.z << " a " << k.a << " b " << k.b << " sigma " << k.sigma
              << " status " << conescan::to_string(c.state) << " iterations " << c.iterations);
    CHECK(is_status_of_a_forward_model(c.state));
    CHECK(c.iterations <= 2 * max_iterations_per_root);
    if (c.state != status::ok) continue;
    check_well_formed(c);
    for (double phi : {c.phi_in, c.phi_out})
      CHECK(std::abs(tangency_at(o, f, k.p, k.a, k.b, phi).g_normalised) < 1e-9L);
  }
}
