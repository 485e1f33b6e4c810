// The forward half chord Phi of a cone on a spherical Earth disk: MODEL §5, paper Eq. (3), and the
// disk's angular radius (MODEL §3). In double.
//
// Expected values come from the definition: the line of sight at polar angle psi from S and
// azimuth Phi (from the nadir's azimuth) is on the horizon, i.e. its angle to the nadir (at eta
// from S) is rho. That is measured with vectors in long double; the statuses are set up at
// boundaries derived by hand (tangencies |psi - eta| = rho, psi + eta = rho, psi + eta + rho =
// 2 pi, and the rho at which Phi equals the grazing threshold, from Eq. (3) solved for rho).
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <vector>

#include "conescan/earth_disk.hpp"
#include "conescan/half_chord.hpp"
#include "conescan/vector.hpp"
#include "support/adl_scalar.hpp"
#include "support/approx.hpp"

using conescan::classify_half_chord;
using conescan::grazing_half_chord_min;
using conescan::half_chord;
using conescan::half_chord_acos;
using conescan::status;
using conescan_test::deg;
using conescan_test::eps;

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();
constexpr double quiet_nan = std::numeric_limits<double>::quiet_NaN();

struct disk_case {
  double psi, eta, rho;
};

std::vector<disk_case> disk_grid() {
  // Tenths of a degree.
  const int psis[] = {5, 10, 100, 300, 450, 600, 800, 900, 1000, 1500, 1790};
  const int etas[] = {5, 50, 150, 300, 450, 600, 750, 900, 1050, 1350, 1700, 1795};
  const int rhos[] = {10, 100, 300, 450, 612, 640, 800, 900};
  std::vector<disk_case> grid;
  for (int p : psis)
    for (int e : etas)
      for (int r : rhos)
        grid.push_back({deg<double>(p, 10), deg<double>(e, 10), deg<double>(r, 10)});
  return grid;
}

/// Angle between the line of sight (psi from S, azimuth phi) and the nadir (eta from S, azimuth
/// 0), with vectors in long double: the horizon condition of MODEL §5 says it is rho.
long double angle_to_nadir(double psi, double phi, double eta) {
  const long double p = psi, f = phi, e = eta;
  const conescan::vec3<long double> l(std::sin(p) * std::cos(f), std::sin(p) * std::sin(f),
                                      std::cos(p));
  const conescan::vec3<long double> n(std::sin(e), 0.0L, std::cos(e));
  return conescan::angle_between(l, n);
}

/// rho for which the half chord is exactly phi: Eq. (3) solved for rho, in long double.
long double rho_for_half_chord(long double psi, long double eta, long double phi) {
  return std::acos(std::cos(psi) * std::cos(eta) + std::sin(psi) * std::sin(eta) * std::cos(phi));
}

}  // namespace

TEST_CASE("half_chord puts the crossing on the horizon", "[half_chord][eq3]") {
  // Backward-error check: the computed Phi is exact for inputs perturbed by a few ulp, so the
  // angle from the crossing's line of sight to the nadir is rho to within 8 eps (psi + eta +
  // rho) (each input's rounding moves that angle by at most its own size times eps). Also
  // rho -> rho and Phi in [grazing_min, pi - grazing_min] when ok.
  int ok_count = 0;
  for (const disk_case& c : disk_grid()) {
    const conescan::result<double> phi = half_chord(c.psi, c.eta, c.rho);
    INFO("psi " << c.psi << " eta " << c.eta << " rho " << c.rho << " status "
                << conescan::to_string(phi.state));
    if (!phi.ok()) {
      CHECK(std::isnan(phi.value));
      continue;
    }
    ++ok_count;
    CHECK(phi.value >= grazing_half_chord_min<double>());
    CHECK(phi.value <= conescan::pi<double>() - grazing_half_chord_min<double>());
    const double tol = 8 * eps<double>() * (c.psi + c.eta + c.rho);
    CHECK_WITHIN(angle_to_nadir(c.psi, phi.value, c.eta), static_cast<long double>(c.rho),
                 static_cast<long double>(tol));
    // The crossing at -Phi is the mirror image.
    CHECK_WITHIN(angle_to_nadir(c.psi, -phi.value, c.eta), static_cast<long double>(c.rho),
                 static_cast<long double>(tol));
  }
  CHECK(ok_count > 200);  // the grid must exercise the ok path, not only the statuses
}

TEST_CASE("half_chord equals the paper's Eq. (3) away from its ill-conditioned places",
          "[half_chord][eq3]") {
  // half_chord_acos evaluates acos((cos rho - cos psi cos eta) / (sin psi sin eta)): its
  // argument carries ~4 eps (1 + |cos rho| + |cos psi cos eta|) / (sin psi sin eta) of rounding,
  // which acos turns into that divided by sin Phi. Tolerance: twice that, plus 4 eps Phi for
  // the stable form's own error. Statuses must agree wherever the two are not near a boundary.
  int compared = 0;
  for (const disk_case& c : disk_grid()) {
    const conescan::result<double> stable = half_chord(c.psi, c.eta, c.rho);
    const conescan::result<double> printed = half_chord_acos(c.psi, c.eta, c.rho);
    INFO("psi " << c.psi << " eta " << c.eta << " rho " << c.rho);
    if (!stable.ok()) {
      // A boundary case may fall on either side in the two forms only within rounding of it.
      const double p1 =
          std::sin((c.rho + c.psi - c.eta) / 2) * std::sin((c.rho - c.psi + c.eta) / 2);
      const double p2 =
          std::sin((c.psi + c.eta + c.rho) / 2) * std::sin((c.psi + c.eta - c.rho) / 2);
      if (std::abs(p1) > 1e-12 && std::abs(p2) > 1e-12) CHECK(printed.state == stable.state);
      continue;
    }
    REQUIRE(printed.ok());
    ++compared;
    const double argument_error =
        4 * eps<double>() *
        (1 + std::abs(std::cos(c.rho)) + std::abs(std::cos(c.psi) * std::cos(c.eta))) /
        (std::sin(c.psi) * std::sin(c.eta));
    const double tol =
        2 * argument_error / std::sin(stable.value) + 4 * eps<double>() * stable.value;
    CHECK_WITHIN(printed.value, stable.value, tol);
  }
  CHECK(compared > 200);
}

TEST_CASE("half_chord: hand-derived values", "[half_chord][eq3]") {
  // psi = eta = 90 deg: the scan circle is the great circle normal to S and passes through the
  // nadir, and the azimuth along it is the arc from the nadir: Phi = rho (Eq. (3) with
  // cos psi = cos eta = 0 gives cos Phi = cos rho).
  for (int r : {1, 10, 45, 80}) {
    const double rho = deg<double>(r);
    CHECK_WITHIN(half_chord(deg<double>(90), deg<double>(90), rho).value, rho, 4 * eps<double>());
  }
  // psi = eta: cos rho = cos^2 psi + sin^2 psi cos Phi, i.e. sin(rho/2) = sin psi sin(Phi/2).
  // psi = eta = 30 deg: sin(Phi/2) = 2 sin(rho/2); rho = 2 asin(1/4) gives Phi = 2 asin(1/2) =
  // 60 deg exactly.
  CHECK_WITHIN(half_chord(deg<double>(30), deg<double>(30), 2 * std::asin(0.25)).value,
               deg<double>(60), 8 * eps<double>());
}

TEST_CASE("half_chord statuses: miss on both sides of the cone", "[half_chord][status]") {
  // miss <=> |psi - eta| >= rho (MODEL §7): the disk lies wholly outside (eta >= psi + rho) or
  // wholly inside (eta <= psi - rho) the scan circle. 0.5 + 0.25 = 0.75 exactly in binary, so
  // the tangencies themselves are tested exactly; there the chord is 0: miss. Just inside the
  // boundary the chord is ~sqrt(delta), far below the grazing threshold: grazing. Further in, ok.
  const double psi = 0.5, rho = 0.25;
  // half_chord decides by the signs of its products, so the tangencies are exactly miss; the
  // printed form's cos rho - cos psi cos eta vs sin psi sin eta is decided by rounding there.
  CHECK(half_chord(psi, 0.75, rho).state == status::miss);  // outer tangency
  CHECK(half_chord(psi, 0.25, rho).state == status::miss);  // inner tangency
  CHECK(half_chord_acos(psi, 0.75, rho).state != status::ok);
  CHECK(half_chord_acos(psi, 0.25, rho).state != status::ok);
  for (auto f : {&half_chord<double>, &half_chord_acos<double>}) {
    CHECK(f(psi, 0.75 + 1e-9, rho).state == status::miss);     // outside
    CHECK(f(psi, 0.25 - 1e-9, rho).state == status::miss);     // inside the circle
    CHECK(f(psi, 0.75 - 1e-9, rho).state == status::grazing);  // a sliver crossed
    CHECK(f(psi, 0.25 + 1e-9, rho).state == status::grazing);
    CHECK(f(psi, 0.5, rho).state == status::ok);
    CHECK(std::isnan(f(psi, 0.75 + 1e-9, rho).value));
  }
  // eta = 0: the nadir on the spin axis; the circle is at psi from it everywhere.
  CHECK(half_chord(0.5, 0.0, 0.25).state == status::miss);
  CHECK(half_chord_acos(0.5, 0.0, 0.25).state == status::miss);
}

TEST_CASE("half_chord statuses: engulfed on both sides", "[half_chord][status]") {
  // engulfed <=> the farthest point of the circle is on the disk: psi + eta <= rho, or (the far
  // side wraps past -S) psi + eta + rho >= 2 pi. 0.5 + 0.5 = 1 exactly: tangency tested exactly.
  CHECK(half_chord(0.5, 0.5, 1.0).state == status::engulfed);  // exact, as for miss
  CHECK(half_chord_acos(0.5, 0.5, 1.0).state != status::ok);
  for (auto f : {&half_chord<double>, &half_chord_acos<double>}) {
    CHECK(f(0.5, 0.5 - 1e-9, 1.0).state == status::engulfed);
    CHECK(f(0.5, 0.5 + 1e-9, 1.0).state == status::grazing);  // a sliver off the Earth
    CHECK(f(0.5, 0.8, 1.0).state == status::ok);
    // Wrapping branch: psi = eta = 3, nadir and cone near -S; boundary rho = 2 pi - 6.
    const double rho_b = 2 * conescan::pi<double>() - 6.0;
    CHECK(f(3.0, 3.0, rho_b + 1e-9).state == status::engulfed);
    CHECK(f(3.0, 3.0, rho_b - 1e-9).state == status::grazing);
    CHECK(f(3.0, 3.0, rho_b - 0.1).state == status::ok);
  }
  // eta = 0 and eta = pi: the circle is psi (resp. pi - psi) from the nadir everywhere.
  CHECK(half_chord(0.5, 0.0, 0.75).state == status::engulfed);
  CHECK(half_chord_acos(0.5, 0.0, 0.75).state == status::engulfed);
  const double pi = conescan::pi<double>();
  CHECK(half_chord(3.0, pi, 0.25).state == status::engulfed);  // pi - 3 = 0.14 < 0.25
  CHECK(half_chord(2.0, pi, 0.25).state == status::miss);      // pi - 2 = 1.14 > 0.25
  CHECK(half_chord_acos(2.0, pi, 0.25).state == status::miss);
}

TEST_CASE("half_chord statuses: grazing on both sides of its threshold", "[half_chord][status]") {
  // The threshold is the documented 0.1 deg (half_chord.hpp).
  CHECK_WITHIN(grazing_half_chord_min<double>(), conescan::pi<double>() / 1800, eps<double>());
  const double phi_min = grazing_half_chord_min<double>();
  const double pi = conescan::pi<double>();
  // rho at which Phi is 1 +- 1e-6 times the threshold (near 0) or pi minus it (near pi), from
  // Eq. (3) solved for rho in long double. The rounding of rho to double moves Phi by ~1e-13,
  // far less than the 1e-9 margin.
  for (double psi : {deg<double>(20), deg<double>(45), deg<double>(70)}) {
    for (double eta : {deg<double>(30), deg<double>(60), deg<double>(90)}) {
      INFO("psi " << psi << " eta " << eta);
      for (auto f : {&half_chord<double>, &half_chord_acos<double>}) {
        const double below =
            static_cast<double>(rho_for_half_chord(psi, eta, phi_min * (1 - 1e-6)));
        const double above =
            static_cast<double>(rho_for_half_chord(psi, eta, phi_min * (1 + 1e-6)));
        CHECK(f(psi, eta, below).state == status::grazing);
        CHECK(f(psi, eta, above).state == status::ok);
        const double near_pi_in =
            static_cast<double>(rho_for_half_chord(psi, eta, pi - phi_min * (1 + 1e-6)));
        const double near_pi_out =
            static_cast<double>(rho_for_half_chord(psi, eta, pi - phi_min * (1 - 1e-6)));
        if (near_pi_out <= pi / 2) {  // rho beyond 90 deg is outside the domain
          CHECK(f(psi, eta, near_pi_in).state == status::ok);
          CHECK(f(psi, eta, near_pi_out).state == status::grazing);
        }
      }
    }
  }
  CHECK(classify_half_chord(phi_min) == status::ok);
  CHECK(classify_half_chord(std::nextafter(phi_min, 0.0)) == status::grazing);
  CHECK(classify_half_chord(pi - phi_min) == status::ok);
  CHECK(classify_half_chord(std::nextafter(pi - phi_min, 4.0)) == status::grazing);
  CHECK(classify_half_chord(0.0) == status::grazing);
  CHECK(classify_half_chord(quiet_nan) == status::invalid);
}

TEST_CASE("half_chord statuses: invalid outside the domain, on both sides",
          "[half_chord][status]") {
  // Domain: psi in (0, pi), eta in [0, pi], rho in (0, pi/2], finite (half_chord.hpp).
  const double pi = conescan::pi<double>();
  for (auto f : {&half_chord<double>, &half_chord_acos<double>}) {
    CHECK(f(0.0, 0.5, 0.3).state == status::invalid);
    CHECK(f(1e-300, 0.5, 0.3).state != status::invalid);
    CHECK(f(pi, 0.5, 0.3).state == status::invalid);
    CHECK(f(std::nextafter(pi, 0.0), 0.5, 0.3).state != status::invalid);
    CHECK(f(0.5, -1e-300, 0.3).state == status::invalid);
    CHECK(f(0.5, 0.0, 0.3).state != status::invalid);
    CHECK(f(0.5, std::nextafter(pi, 4.0), 0.3).state == status::invalid);
    CHECK(f(0.5, pi, 0.3).state != status::invalid);
    CHECK(f(0.5, 0.5, 0.0).state == status::invalid);
    CHECK(f(0.5, 0.5, 1e-300).state != status::invalid);
    CHECK(f(0.5, 0.5, std::nextafter(pi / 2, 4.0)).state == status::invalid);
    CHECK(f(0.5, 0.5, pi / 2).state != status::invalid);
    for (double bad : {quiet_nan, inf, -inf}) {
      CHECK(f(bad, 0.5, 0.3).state == status::invalid);
      CHECK(f(0.5, bad, 0.3).state == status::invalid);
      CHECK(f(0.5, 0.5, bad).state == status::invalid);
      CHECK(std::isnan(f(0.5, 0.5, bad).value));
    }
  }
}

TEST_CASE("disk_angular_radius: sin rho = radius / r", "[earth_disk]") {
  // Hand-derived: radius / r = 1/2 gives 30 deg, 1/sqrt(2) gives 45 deg.
  CHECK_WITHIN(conescan::disk_angular_radius(1.0, 2.0).value, deg<double>(30), 2 * eps<double>());
  CHECK_WITHIN(conescan::disk_angular_radius(6378137.0, 6378137.0 * std::sqrt(2.0)).value,
               deg<double>(45), 4 * eps<double>());
  // Domain 0 < radius < r, finite: both sides of each boundary.
  CHECK(conescan::disk_angular_radius(0.0, 2.0).state == status::invalid);
  CHECK(conescan::disk_angular_radius(1e-300, 2.0).ok());
  CHECK(conescan::disk_angular_radius(2.0, 2.0).state == status::invalid);
  CHECK(conescan::disk_angular_radius(std::nextafter(2.0, 0.0), 2.0).ok());
  CHECK(conescan::disk_angular_radius(3.0, 2.0).state == status::invalid);
  for (double bad : {quiet_nan, inf, -inf}) {
    CHECK(conescan::disk_angular_radius(bad, 2.0).state == status::invalid);
    CHECK(conescan::disk_angular_radius(1.0, bad).state == status::invalid);
  }
}
