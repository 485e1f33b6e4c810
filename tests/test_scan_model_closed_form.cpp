// The scan model's closed forms (scan_model.hpp) against the bracketed solver on the scan azimuth
// (scan_model_iterative.hpp), which is derived independently (a root of the horizon function in
// phi, with psi(phi) from Eq. (1)), and against the geometry itself:
//  - on a sphere, the two-circle intersection agrees with the bracketed solver over a grid of
//    attitude, mounting, gamma, sigma up to 1 deg, phi_A and altitude, status for status;
//  - the statuses change where the hand-derived geometry says, on both sides.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <vector>

#include "conescan/attitude.hpp"
#include "conescan/scan_model.hpp"
#include "support/approx.hpp"

using conescan::crossings;
using conescan::head_optics;
using conescan::scan_frame;
using conescan::status;
using conescan::vec3;

namespace {

constexpr double earth_a_m = 6378137.0;

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

