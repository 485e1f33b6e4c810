// The scan model's closed forms (scan_model.hpp) against the bracketed solver on the scan azimuth
// (scan_model_iterative.hpp), which is derived independently (a root of the horizon function in
// phi, with psi(phi) from Eq. (1)), and against the geometry itself:
//  - on a sphere, the two-circle intersection agrees with the bracketed solver over a grid of
//    attitude, mounting, gamma, sigma up to 1 deg, phi_A and altitude, status for status;
//  - the statuses change where the hand-derived geometry says, on both sides;
//  - on ellipsoids (inflated WGS84, the apparent horizon surface oblate or prolate, a shifted
//    centre) the Newton solve agrees with the bracketed solver, and each crossing is tangent;
//  - a scan that cuts a strongly prolate horizon four times is `multiple`, on one side of a
//    boundary found by bisection, and counting the Earth arcs by dense sampling of the tangency
//    function agrees with the status over many random surfaces.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "conescan/attitude.hpp"
#include "conescan/orbital_frame.hpp"
#include "conescan/scan_model.hpp"
#include "support/approx.hpp"
#include "support/cli.hpp"

using conescan::crossings;
using conescan::head_optics;
using conescan::scan_frame;
using conescan::status;
using conescan::vec3;

namespace {

constexpr double earth_a_m = 6378137.0;
constexpr double earth_b_m = 6378137.0 * (1 - 1 / 298.257223563);

double deg(double d) {
  return conescan::deg_to_rad(d);
}

/// Components of a body-axes vector in a scan frame given in body axes.
vec3<double> in_scan_frame(const scan_frame<double>& f, const vec3<double>& v) {
  return vec3<double>(conescan::dot(f.e1, v), conescan::dot(f.e2, v), conescan::dot(f.e3, v));
}

/// The difference of two crossings: of phi_in modulo 2 pi, and of the chords.
double crossing_difference(const crossings<double>& a, const crossings<double>& b) {
  return std::max(std::abs(conescan::wrap_pi(a.phi_in - b.phi_in)),
                  std::abs(a.chord() - b.chord()));
}

/// Long double a_eq^2 g at the azimuth phi (psi(phi) from Eq. (1)), the surface in `frame`'s
/// axes: (q.d)^2 - H (1 + kappa (z.d)^2) and q.d (ellipsoid_horizon.hpp), normalised by
/// 1 + kappa (z.d)^2 (|D|^2 a_eq^2).
struct tangency {
  long double g_normalised;
  long double front;
};
tangency tangency_at(const head_optics<double>& o, const vec3<double>& p, const vec3<double>& polar,
                     double a, double b, double phi) {
  const long double psi =
      conescan::misaligned_cone_angle<long double>(o.gamma, o.sigma, phi - o.phi_a).value;
  const long double f = phi;
  const vec3<long double> d(std::sin(psi) * std::cos(f), std::sin(psi) * std::sin(f),
                            std::cos(psi));
  const vec3<long double> pl(p.x, p.y, p.z), zl(polar.x, polar.y, polar.z);
  const long double al = a, bl = b;
  const long double kappa = (al - bl) * (al + bl) / (bl * bl);
  const vec3<long double> q = (pl + zl * (kappa * conescan::dot(pl, zl))) / al;
  const long double height =
      (conescan::dot(pl, pl) + kappa * conescan::dot(pl, zl) * conescan::dot(pl, zl)) / (al * al) -
      1;
  const long double front = conescan::dot(q, d), along = conescan::dot(zl, d);
  const long double stretch = 1 + kappa * along * along;
  return {(front * front - height * stretch) / stretch, front};
}

/// A head's view of an ellipsoid in its scan frame: the satellite at latitude lat_deg and radius
/// r_m (plus a centre shift along z), the head mounted at (alpha, beta) on a body with the given
/// roll and pitch in the orbital frame of a polar orbit.
struct ellipsoid_scene {
  vec3<double> p_scan;      ///< satellite from the ellipsoid's centre, scan-frame components
  vec3<double> polar_scan;  ///< polar axis, scan-frame components
  scan_frame<double> frame_eci;
  vec3<double> p_eci;
};
ellipsoid_scene ellipsoid_scene_of(double lat_deg, double r_m, double shift_m, double alpha_deg,
                                   double beta_deg, double roll_deg, double pitch_deg) {
  const double lat = deg(lat_deg);
  const vec3<double> r(r_m * std::cos(lat), 0.0, r_m * std::sin(lat));
  const vec3<double> v(-std::sin(lat), 0.0, std::cos(lat));
  const conescan::mat3<double> eci_from_orbit = conescan::dcm_eci_from_orbit(r, v);
  const conescan::mat3<double> body_from_orbit =
      conescan::dcm_body_from_orbit(deg(roll_deg), deg(pitch_deg), 0.0);
  const scan_frame<double> f_body =
      conescan::scan_frame_from_mounting(deg(alpha_deg), deg(beta_deg));
  auto to_eci = [&](const vec3<double>& e) {
    return conescan::apply(eci_from_orbit, conescan::apply_transpose(body_from_orbit, e));
  };
  const scan_frame<double> f{to_eci(f_body.e1), to_eci(f_body.e2), to_eci(f_body.e3), status::ok};
  const vec3<double> p = r - vec3<double>(0, 0, shift_m);
  return {vec3<double>(conescan::dot(f.e1, p), conescan::dot(f.e2, p), conescan::dot(f.e3, p)),
          vec3<double>(f.e1.z, f.e2.z, f.e3.z), f, p};
}

/// Earth arcs along the scan by sampling the tangency function at n azimuths (on the Earth:
/// g > 0 in front), and the smallest |g| seen (samples near a tangency cannot count reliably).
struct arc_count {
  int arcs;
  long double smallest_g;
};
arc_count count_earth_arcs(const head_optics<double>& o, const vec3<double>& p,
                           const vec3<double>& polar, double a, double b, int n) {
  int changes = 0;
  long double smallest = std::numeric_limits<long double>::infinity();
  bool first_on = false, before = false;
  for (int k = 0; k <= n; ++k) {
    const double phi = 2 * conescan::pi<double>() * k / n;
    const tangency t = tangency_at(o, p, polar, a, b, phi);
    smallest = std::min(smallest, std::abs(t.g_normalised));
    const bool on = t.g_normalised > 0 && t.front < 0;
    if (k == 0) first_on = on;
    if (k > 0 && on != before) ++changes;
    before = on;
  }
  (void)first_on;
  return {changes / 2, smallest};
}

}  // namespace

TEST_CASE("scan model on a sphere: the closed form agrees with the bracketed solver",
          "[scan_model][closed_form]") {
  // The nadir of the true attitude seen from the head (scan-frame components for the closed
  // form, its angles for the bracketed solver). Where both are ok the crossings agree to 1e-13
  // rad; the statuses agree everywhere on this grid.
  int compared = 0, refused = 0;
  for (double roll : {0.0, 3.0, -7.0}) {
    for (double pitch : {0.0, 2.0, -5.0}) {
      const vec3<double> nadir_body = conescan::nadir_in_body(deg(roll), deg(pitch));
      for (double alpha : {-30.0, 0.0, 20.0, 45.0, 70.0}) {
        for (double beta : {90.0, -45.0, 180.0}) {
          const scan_frame<double> f = conescan::scan_frame_from_mounting(deg(alpha), deg(beta));
          const vec3<double> nadir = in_scan_frame(f, nadir_body);
          const conescan::scan_angles<double> angles = conescan::scan_angles_of(f, nadir_body);
          for (double alt_km : {300.0, 800.0, 6000.0, 35786.0}) {
            const double r_m = earth_a_m + alt_km * 1000;
            const conescan::disk_trig<double> disk = conescan::disk_trig_of(earth_a_m, r_m);
            const double rho = conescan::disk_angular_radius(earth_a_m, r_m).value;
            for (double gamma : {10.0, 30.0, 45.0, 60.0, 80.0}) {
              for (double sigma : {0.0, 0.02, 0.3, 1.0}) {
                for (double phi_a : {0.0, 60.0, 180.0, 270.0}) {
                  const head_optics<double> o{deg(gamma), deg(sigma), deg(phi_a)};
                  const crossings<double> closed = conescan::scan_model_crossings_sphere(
                      conescan::scan_circle_of(o), nadir, disk);
                  const crossings<double> oracle = conescan::scan_model_crossings_sphere_iterative(
                      o, angles.polar, angles.azimuth, rho);
                  INFO("roll " << roll << " pitch " << pitch << " alpha " << alpha << " beta "
                               << beta << " alt " << alt_km << " gamma " << gamma << " sigma "
                               << sigma << " phi_a " << phi_a << ": "
                               << conescan::to_string(closed.state) << " vs "
                               << conescan::to_string(oracle.state));
                  CHECK(closed.state == oracle.state);
                  CHECK(closed.iterations == 0);
                  if (closed.state != status::ok || oracle.state != status::ok) {
                    ++refused;
                    continue;
                  }
                  ++compared;
                  CHECK(crossing_difference(closed, oracle) <= 1e-13);
                  CHECK(closed.chord() > 0);
                  CHECK(closed.chord() < 2 * conescan::pi<double>());
                }
              }
            }
          }
        }
      }
    }
  }
  CHECK(compared > 10000);
  CHECK(refused > 1000);  // miss, engulfed and grazing scenes are in the grid too
}

TEST_CASE("scan model on a sphere: every status on both sides of its boundary",
          "[scan_model][closed_form][status]") {
  // A cone of gamma = 30 deg about S, the nadir eta = 2 deg from S (sigma = 0, so A = S): the
  // circles cross iff |gamma - eta| < rho < gamma + eta. Below 28 deg the disk lies inside the
  // scan cone (miss, the second kind), above 32 deg the cone inside the disk (engulfed); just
  // inside either, a chord near 0 or 360 deg (grazing); in the middle, ok.
  const scan_frame<double> axes{vec3<double>(1, 0, 0), vec3<double>(0, 1, 0), vec3<double>(0, 0, 1),
                                status::ok};
  const head_optics<double> o{deg(30), 0.0, 0.0};
  const conescan::scan_circle<double> circle = conescan::scan_circle_of(o);
  const vec3<double> nadir = conescan::direction_in_scan_frame(axes, deg(2), 0.4);
  auto at = [&](double rho) {
    return conescan::scan_model_crossings_sphere(circle, nadir, conescan::disk_trig_of_angle(rho))
        .state;
  };
  // (At a penetration d the arc on the disk is ~sqrt(2 d / (cot 28 deg - cot 30 deg)) wide: below
  // the grazing chord up to d ~ 1e-7.)
  for (double d : {1e-9, 1e-10}) {
    CHECK(at(deg(28) - d) == status::miss);
    CHECK(at(deg(28) + d) == status::grazing);
    CHECK(at(deg(32) + d) == status::engulfed);
    CHECK(at(deg(32) - d) == status::grazing);
  }
  CHECK(at(deg(27)) == status::miss);
  CHECK(at(deg(30)) == status::ok);
  CHECK(at(deg(33)) == status::engulfed);
  // The far miss (the cone beside the disk) and the concentric limits.
  const vec3<double> far = conescan::direction_in_scan_frame(axes, deg(70), 0.4);
  CHECK(conescan::scan_model_crossings_sphere(circle, far,
                                              conescan::disk_trig_of_angle(deg(40) - 1e-9))
            .state == status::miss);
  CHECK(conescan::scan_model_crossings_sphere(circle, far,
                                              conescan::disk_trig_of_angle(deg(40) + 1e-9))
            .state == status::grazing);
  const vec3<double> on_s(0, 0, 1);
  CHECK(conescan::scan_model_crossings_sphere(circle, on_s, conescan::disk_trig_of_angle(deg(29)))
            .state == status::miss);
  CHECK(conescan::scan_model_crossings_sphere(circle, on_s, conescan::disk_trig_of_angle(deg(31)))
            .state == status::engulfed);
  const vec3<double> anti_s(0, 0, -1);
  CHECK(conescan::scan_model_crossings_sphere(circle, anti_s, conescan::disk_trig_of_angle(deg(80)))
            .state == status::miss);
  // Invalid inputs.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK(conescan::scan_model_crossings_sphere(circle, vec3<double>(nan, 0, 1),
                                              conescan::disk_trig_of_angle(deg(30)))
            .state == status::invalid);
  CHECK(conescan::scan_model_crossings_sphere(circle, nadir, conescan::disk_trig_of_angle(0.0))
            .state == status::invalid);
  CHECK(conescan::scan_model_crossings_sphere(
            conescan::scan_circle_of(head_optics<double>{deg(30), deg(30), 0.0}), nadir,
            conescan::disk_trig_of_angle(deg(30)))
            .state == status::invalid);
}

TEST_CASE("scan model on ellipsoids: Newton from the sphere agrees with the bracketed solver",
          "[scan_model][closed_form][ellipsoid]") {
  // Surfaces: MODEL §3's inflated WGS84 (h = 40 km), the apparent horizon surface with its pole
  // lowered by 13 km and its centre shifted 11.5 km north (the co2-15um figures), and a
  // prolate one (pole raised 60 km above the equator's 40). Where both are ok the crossings
  // agree to 1e-12 rad and are tangent (|g| / |D|^2 < 1e-12 in long double, in front); the
  // statuses agree everywhere on the grid. Almost every scene settles by Newton: at most 4
  // steps per crossing (the fallback is counted, and rare).
  struct surface {
    double a, b, shift;
  };
  const surface surfaces[] = {{earth_a_m + 40e3, earth_b_m + 40e3, 0.0},
                              {earth_a_m + 40e3, earth_b_m + 27e3, 11.5e3},
                              {earth_a_m + 40e3, earth_a_m + 100e3, -20e3}};
  int compared = 0, settled = 0;
  for (const surface& s : surfaces) {
    for (double lat : {0.0, 35.0, 64.0, -89.0}) {
      for (double alt_km : {300.0, 800.0, 6000.0, 35786.0}) {
        for (double alpha : {0.0, 25.0, -40.0}) {
          for (double beta : {90.0, -90.0, 30.0}) {
            const ellipsoid_scene e =
                ellipsoid_scene_of(lat, earth_a_m + alt_km * 1000, s.shift, alpha, beta, 2, -3);
            const conescan::ellipsoid_horizon<double> horizon =
                conescan::ellipsoid_horizon_of(e.p_scan, e.polar_scan, s.a, s.b);
            for (double gamma : {20.0, 45.0, 70.0}) {
              for (double sigma : {0.0, 0.3, 1.0}) {
                for (double phi_a : {0.0, 100.0}) {
                  const head_optics<double> o{deg(gamma), deg(sigma), deg(phi_a)};
                  const crossings<double> newton = conescan::scan_model_crossings_ellipsoid(
                      conescan::scan_circle_of(o), o, horizon);
                  const crossings<double> oracle =
                      conescan::scan_model_crossings_ellipsoid_iterative(o, e.frame_eci, e.p_eci,
                                                                         s.a, s.b);
                  INFO("a " << s.a << " b " << s.b << " shift " << s.shift << " lat " << lat
                            << " alt " << alt_km << " alpha " << alpha << " beta " << beta
                            << " gamma " << gamma << " sigma " << sigma << " phi_a " << phi_a
                            << ": " << conescan::to_string(newton.state) << " vs "
                            << conescan::to_string(oracle.state) << ", " << newton.iterations
                            << " iterations");
                  CHECK(newton.state == oracle.state);
                  if (newton.state != status::ok || oracle.state != status::ok) continue;
                  ++compared;
                  if (newton.iterations <= 8) ++settled;
                  CHECK(crossing_difference(newton, oracle) <= 1e-12);
                  for (double phi : {newton.phi_in, newton.phi_out}) {
                    const tangency t = tangency_at(o, e.p_scan, e.polar_scan, s.a, s.b, phi);
                    CHECK(std::abs(t.g_normalised) < 1e-12L);
                    CHECK(t.front < 0);
                  }
                }
              }
            }
          }
        }
      }
    }
  }
  INFO(settled << " of " << compared << " settled by Newton in at most 4 steps per crossing");
  CHECK(compared > 1000);
  CHECK(settled >= compared * 99 / 100);
}

TEST_CASE("scan model on an ellipsoid: flattening 0 and no shift is the sphere",
          "[scan_model][closed_form][ellipsoid]") {
  // a_eq = b_pol: the sphere's closed form (radius a, nadir towards the centre) must come out of
  // the Newton solve, which then starts at the answer: one step per crossing settles it.
  int compared = 0;
  for (double lat : {0.0, 50.0}) {
    for (double alt_km : {500.0, 20000.0}) {
      for (double alpha : {0.0, 30.0}) {
        const ellipsoid_scene e =
            ellipsoid_scene_of(lat, earth_a_m + alt_km * 1000, 0.0, alpha, 90, 1.5, -0.5);
        const conescan::ellipsoid_horizon<double> horizon =
            conescan::ellipsoid_horizon_of(e.p_scan, e.polar_scan, earth_a_m, earth_a_m);
        const vec3<double> nadir = conescan::unit(-e.p_scan);
        const conescan::disk_trig<double> disk =
            conescan::disk_trig_of(earth_a_m, conescan::norm(e.p_scan));
        for (double sigma : {0.0, 0.5}) {
          for (double phi_a : {0.0, 200.0}) {
            const head_optics<double> o{deg(50), deg(sigma), deg(phi_a)};
            const conescan::scan_circle<double> circle = conescan::scan_circle_of(o);
            const crossings<double> sphere =
                conescan::scan_model_crossings_sphere(circle, nadir, disk);
            const crossings<double> ellipsoid =
                conescan::scan_model_crossings_ellipsoid(circle, o, horizon);
            INFO("lat " << lat << " alt " << alt_km << " alpha " << alpha << " sigma " << sigma
                        << " phi_a " << phi_a);
            REQUIRE(ellipsoid.state == sphere.state);
            if (sphere.state != status::ok) continue;
            ++compared;
            CHECK(crossing_difference(sphere, ellipsoid) <= 1e-14);
            CHECK(ellipsoid.iterations <= 4);
          }
        }
      }
    }
  }
  CHECK(compared >= 16);
}

TEST_CASE("scan model on an ellipsoid: four crossings are `multiple`",
          "[scan_model][closed_form][ellipsoid][multiple]") {
  // A prolate surface (b = 1.5 a) seen from the equator at r = 2 a, the head looking straight
  // down (S on the nadir, sigma = 0): the horizon spans asin(1/2) = 30 deg across the equator
  // and atan(1.5 / sqrt(3)) = 40.9 deg towards the poles. A scan cone between the two cuts it
  // four times (multiple); narrower it lies inside (engulfed), wider it encloses the horizon
  // (miss). Just above 30 deg the two Earth arcs are nearly half turns each: multiple up to the
  // boundary. Just below 40.9 deg they shrink to slivers near the poles' directions, shorter
  // than the grazing chord: grazing, then miss. Each boundary is found by bisection on gamma.
  const double a = earth_a_m, b = 1.5 * earth_a_m, r = 2 * earth_a_m;
  const scan_frame<double> axes{vec3<double>(0, 1, 0), vec3<double>(0, 0, 1),
                                vec3<double>(-1, 0, 0), status::ok};
  const vec3<double> p(r, 0, 0);
  const vec3<double> p_scan(conescan::dot(axes.e1, p), conescan::dot(axes.e2, p),
                            conescan::dot(axes.e3, p));
  const vec3<double> polar(axes.e1.z, axes.e2.z, axes.e3.z);
  const conescan::ellipsoid_horizon<double> horizon =
      conescan::ellipsoid_horizon_of(p_scan, polar, a, b);
  auto status_at = [&](double gamma, double sigma) {
    const head_optics<double> o{gamma, sigma, 0.3};
    return conescan::scan_model_crossings_ellipsoid(conescan::scan_circle_of(o), o, horizon).state;
  };
  CHECK(status_at(deg(35), 0.0) == status::multiple);
  CHECK(status_at(deg(29), 0.0) == status::engulfed);
  CHECK(status_at(deg(42), 0.0) == status::miss);
  // The wrapper (ECI frame, polar axis along z) agrees.
  const head_optics<double> o35{deg(35), 0.0, 0.3};
  CHECK(conescan::scan_model_crossings_ellipsoid(o35, axes, p, a, b).state == status::multiple);
  // The gamma where the status stops being `multiple`, between inside and outside.
  auto boundary = [&](double inside, double outside) {
    while (std::abs(outside - inside) > 1e-13) {
      const double mid = (inside + outside) / 2;
      (status_at(mid, 0.0) == status::multiple ? inside : outside) = mid;
    }
    return inside;
  };
  const double rho_equator = std::asin(0.5), rho_pole = std::atan(1.5 / std::sqrt(3.0));
  const double low = boundary(deg(35), deg(29));
  CHECK_WITHIN(low, rho_equator, 1e-12);
  CHECK(status_at(rho_equator - 1e-9, 0.0) == status::engulfed);
  CHECK(status_at(rho_equator + 1e-9, 0.0) == status::multiple);
  const double high = boundary(deg(35), deg(42));
  CHECK(high < rho_pole - 1e-7);
  CHECK(high > rho_pole - 1e-5);
  CHECK(status_at(high - 1e-9, 0.0) == status::multiple);
  CHECK(status_at(high + 1e-9, 0.0) == status::grazing);
  CHECK(status_at(rho_pole - 1e-9, 0.0) == status::grazing);
  CHECK(status_at(rho_pole + 1e-9, 0.0) == status::miss);
  // Tilting the cone (sigma) moves it off centre: two crossings again, on one side of a
  // boundary in sigma found the same way.
  CHECK(status_at(deg(35), deg(12)) == status::ok);
  double multiple_sigma = 0, two_sigma = deg(12);
  while (two_sigma - multiple_sigma > 1e-12) {
    const double mid = (multiple_sigma + two_sigma) / 2;
    (status_at(deg(35), mid) == status::multiple ? multiple_sigma : two_sigma) = mid;
  }
  CHECK(status_at(deg(35), multiple_sigma - 1e-7) == status::multiple);
  CHECK(status_at(deg(35), two_sigma + 1e-7) == status::ok);
}

TEST_CASE("scan model on an ellipsoid: `multiple` exactly where the scan finds two Earth arcs",
          "[scan_model][closed_form][ellipsoid][multiple]") {
  // Random strongly non-spherical surfaces (b / a from 0.5 to 2), positions, mountings and
  // optics. Ground truth: the Earth arcs counted by sampling the tangency function at 4000
  // azimuths, where no sample is near a tangency. Two arcs <=> multiple; one arc <=> ok or
  // grazing, with the crossings tangent; none <=> miss or engulfed.
  std::uint64_t state = 12345;
  auto uniform = [&] {  // splitmix64 to [0, 1)
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return static_cast<double>((z ^ (z >> 31)) >> 11) * 0x1p-53;
  };
  // Half the scenes look near the nadir with a cone about as wide as the horizon (between the
  // angular radii of spheres of radius a and b), where the cone can lie across an elongated
  // horizon.
  int counted[3] = {0, 0, 0};
  for (int i = 0; i < 4000; ++i) {
    const double a = earth_a_m, b = earth_a_m * (0.5 + 1.5 * uniform());
    const double r = std::max(a, b) * (1.1 + 2 * uniform());
    const bool across = i % 2 == 1;
    const double alpha = across ? 80 + 9.9 * uniform() : 140 * uniform() - 70;
    const double tilt = across ? 2 : 10;
    const ellipsoid_scene e =
        ellipsoid_scene_of(180 * uniform() - 90, r, 0.0, alpha, 360 * uniform(),
                           2 * tilt * uniform() - tilt, 2 * tilt * uniform() - tilt);
    const double rho_a = std::asin(a / r), rho_b = std::asin(b / r);
    const double gamma =
        across ? std::min(rho_a, rho_b) + (std::abs(rho_a - rho_b) + deg(4)) * uniform() - deg(2)
               : deg(10 + 70 * uniform());
    const head_optics<double> o{gamma, deg(across ? 1 : 5) * uniform(), deg(360 * uniform())};
    const conescan::ellipsoid_horizon<double> horizon =
        conescan::ellipsoid_horizon_of(e.p_scan, e.polar_scan, a, b);
    REQUIRE(horizon.state == status::ok);  // outside: r > 1.1 max(a, b)
    const arc_count truth = count_earth_arcs(o, e.p_scan, e.polar_scan, a, b, 4000);
    if (truth.smallest_g < 1e-4L || truth.arcs > 2) continue;
    const crossings<double> c =
        conescan::scan_model_crossings_ellipsoid(conescan::scan_circle_of(o), o, horizon);
    INFO("b/a " << b / a << " gamma " << o.gamma << " sigma " << o.sigma << ": " << truth.arcs
                << " arcs, status " << conescan::to_string(c.state));
    ++counted[truth.arcs];
    if (truth.arcs == 2) {
      CHECK(c.state == status::multiple);
    } else if (truth.arcs == 1) {
      CHECK((c.state == status::ok || c.state == status::grazing));
      if (c.state != status::ok) continue;
      for (double phi : {c.phi_in, c.phi_out})
        CHECK(std::abs(tangency_at(o, e.p_scan, e.polar_scan, a, b, phi).g_normalised) < 1e-12L);
    } else {
      CHECK((c.state == status::miss || c.state == status::engulfed));
    }
  }
  INFO("scenes with 0, 1, 2 Earth arcs: " << counted[0] << ", " << counted[1] << ", "
                                          << counted[2]);
  CHECK(counted[0] > 100);
  CHECK(counted[1] > 100);
  CHECK(counted[2] > 10);
}

TEST_CASE("scan model: --trace reports the solver's steps per head and row", "[scan_model][cli]") {
  // The sphere's closed form takes no step; the ellipsoid's Newton solve 2 x 3 in double on the
  // WGS84 scene (at most 2 x ellipsoid_newton_max_steps() without the fallback).
  const auto sphere = conescan_test::run_sim("--model scan --duration-s 20 --trace");
  REQUIRE(sphere.exit_status == 0);
  CHECK(sphere.err.find("trace: t_s=0 head=1 iterations=0 status=ok") != std::string::npos);
  const auto wgs84 = conescan_test::run_sim(
      "--model scan --earth wgs84 --horizon-km 40 --head beta=90 --head beta=-90 --duration-s 600 "
      "--trace");
  REQUIRE(wgs84.exit_status == 0);
  int lines = 0;
  std::size_t at = 0;
  const std::string key = "iterations=";
  while ((at = wgs84.err.find(key, at)) != std::string::npos) {
    const int steps = std::stoi(wgs84.err.substr(at + key.size()));
    CHECK(steps >= 2);
    CHECK(steps <= 2 * conescan::ellipsoid_newton_max_steps<double>());
    ++lines;
    at += key.size();
  }
  CHECK(lines == 2 * 61);
}
