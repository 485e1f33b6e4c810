// The inversion of a half chord to the nadir angle (MODEL §6, corrected Eq. (6)) and the
// processing of one head (MODEL §6), in double.
//
// Expected values come from the forward model: a chord produced by half_chord (itself checked
// against the horizon geometry in test_half_chord.cpp) must invert to the eta it came from. The
// fold is located by hand: the amplification |d eta / d Phi| is derived here by implicit
// differentiation of Eq. (5), independently of the header's amplitude-form expression, and the
// no-real-root boundary follows from cos rho_p = R = hypot(cos gamma, sin gamma cos Phi).
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <vector>

#include "conescan/attitude.hpp"
#include "conescan/bias_model.hpp"
#include "conescan/earth_disk.hpp"
#include "conescan/nadir_angle.hpp"
#include "conescan/processing.hpp"
#include "conescan/scan_frame.hpp"
#include "support/adl_scalar.hpp"
#include "support/approx.hpp"

using conescan::fold_amplification_max;
using conescan::grazing_half_chord_min;
using conescan::half_chord;
using conescan::nadir_angle_from_chord;
using conescan::nadir_angle_from_chord_quadratic;
using conescan::nadir_angle_roots;
using conescan::nadir_angle_roots_from_chord;
using conescan::status;
using conescan_test::deg;
using conescan_test::eps;

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();
constexpr double quiet_nan = std::numeric_limits<double>::quiet_NaN();

/// |d eta / d Phi| on cos rho = cos gamma cos eta + sin gamma sin eta cos Phi (Eq. (5)), by
/// implicit differentiation: (sin gamma cos eta cos Phi - cos gamma sin eta) d eta =
/// sin gamma sin eta sin Phi d Phi. Long double; infinite at the fold.
long double amplification(long double gamma, long double eta, long double phi) {
  const long double denominator =
      std::sin(gamma) * std::cos(eta) * std::cos(phi) - std::cos(gamma) * std::sin(eta);
  return std::abs(std::sin(gamma) * std::sin(eta) * std::sin(phi) / denominator);
}

/// The half chord of Eq. (3) in long double (half-angle form), for building chords at hand-chosen
/// eta to better than double precision.
long double half_chord_ld(long double psi, long double eta, long double rho) {
  const long double p1 = std::sin((rho + psi - eta) / 2) * std::sin((rho - psi + eta) / 2);
  const long double p2 = std::sin((psi + eta + rho) / 2) * std::sin((psi + eta - rho) / 2);
  return 2 * std::atan2(std::sqrt(p1), std::sqrt(p2));
}

}  // namespace

TEST_CASE("half_chord then nadir_angle_from_chord recovers eta on both roots",
          "[nadir_angle][eq6][round_trip]") {
  // Forward with the aligned cone (psi = gamma), then invert on the same Earth. eta must be one
  // of the two roots to 1e-12 rad, and the inversion with eta0 = eta must return it. Where the
  // amplification |d eta / d Phi| (derived above) exceeds fold_amplification_max() (30) the
  // chord is a fold by definition (nadir_angle.hpp); the round trip is required only below 27,
  // and status fold only above 33 (between, rounding of the amplification may decide either
  // way).
  int plus_count = 0, minus_count = 0, fold_count = 0;
  for (int g : {10, 20, 30, 45, 60, 80}) {
    for (int r_tenths : {100, 200, 300, 450, 612, 640, 750, 900}) {
      for (int e_halves = 1; e_halves < 360; e_halves += 5) {  // 0.5 to 178 deg
        const double gamma = deg<double>(g), rho = deg<double>(r_tenths, 10),
                     eta = deg<double>(e_halves, 2);
        const conescan::result<double> phi = half_chord(gamma, eta, rho);
        if (!phi.ok()) continue;
        INFO("gamma " << gamma << " rho " << rho << " eta " << eta << " Phi " << phi.value);
        const long double amp = amplification(gamma, eta, phi.value);
        const nadir_angle_roots<double> roots = nadir_angle_roots_from_chord(gamma, rho, phi.value);
        // Envelope 0: this is the root choice and the fold, not the ambiguity (tested below).
        const conescan::result<double> eta_s =
            nadir_angle_from_chord(gamma, rho, phi.value, eta, 0.0);
        const long double threshold = fold_amplification_max<long double>();
        if (amp > 1.1L * threshold) {
          ++fold_count;
          CHECK(eta_s.state == status::fold);
          continue;
        }
        if (amp > 0.9L * threshold) continue;
        REQUIRE(roots.state == status::ok);
        const double to_plus = std::abs(roots.plus - eta), to_minus = std::abs(roots.minus - eta);
        CHECK(std::min(to_plus, to_minus) <= 1e-12);
        if (to_plus <= to_minus)
          ++plus_count;
        else
          ++minus_count;
        // The roots straddle delta = atan2(k, cos gamma) by half_separation each way.
        CHECK_WITHIN(roots.plus - roots.minus, 2 * roots.half_separation, 4 * eps<double>());
        REQUIRE(eta_s.ok());
        CHECK_WITHIN(eta_s.value, eta, 1e-12);
        // The header's amplification (amplitude form) against the implicit derivative.
        CHECK_WITHIN(
            static_cast<long double>(conescan::chord_inversion_amplification(eta_s.value, roots)),
            amp, 1e-9L * (1 + amp));
      }
    }
  }
  // The grid must cover both roots and the fold.
  CHECK(plus_count > 100);
  CHECK(minus_count > 20);
  CHECK(fold_count > 0);
}

TEST_CASE("corrected Eq. (6): the quadratic form is the '+' root", "[nadir_angle][eq6]") {
  // The quadratic form returns acos(cos eta_s): a rounding e of the cosine moves eta_s by
  // e / sin eta_s; its radicand R^2 - cos^2 rho = R^2 sin^2(half_separation) cancels near the
  // fold, where the sqrt's error grows as 1 / sin(half_separation). Tolerance:
  // 8 eps (1 + 1 / sin eta_plus) (1 + 1 / sin(half_separation)). Compared where the '+' root is
  // in (0, pi) (acos cannot return a negative root).
  int compared = 0;
  for (int g : {10, 30, 45, 60, 80}) {
    for (int r_tenths : {100, 300, 450, 612, 750, 900}) {
      for (int p_halves = 1; p_halves < 360; p_halves += 7) {  // 0.5 to 179 deg
        const double gamma = deg<double>(g), rho = deg<double>(r_tenths, 10),
                     phi = deg<double>(p_halves, 2);
        const nadir_angle_roots<double> roots = nadir_angle_roots_from_chord(gamma, rho, phi);
        const conescan::result<double> quadratic =
            nadir_angle_from_chord_quadratic(gamma, rho, phi);
        INFO("gamma " << gamma << " rho " << rho << " Phi " << phi);
        if (roots.state == status::fold) {
          CHECK(quadratic.state == status::fold);  // no real root: negative radicand
          continue;
        }
        REQUIRE(roots.state == status::ok);
        if (!(roots.plus > 0)) continue;
        REQUIRE(quadratic.ok());
        ++compared;
        const double tol = 8 * eps<double>() * (1 + 1 / std::sin(roots.plus)) *
                           (1 + 1 / std::sin(roots.half_separation));
        CHECK_WITHIN(quadratic.value, roots.plus, tol);
      }
    }
  }
  CHECK(compared > 100);
}

TEST_CASE("nadir_angle_from_chord: fold on both sides of the no-real-root boundary",
          "[nadir_angle][status][fold]") {
  // gamma = 45 deg, rho_p = 30 deg: a real root needs cos rho_p <= R, i.e.
  // cos^2 Phi >= (cos^2 rho_p - cos^2 gamma) / sin^2 gamma = (3/4 - 1/2) / (1/2) = 1/2:
  // the boundary is Phi = 45 deg, where the two roots merge at tan eta = tan gamma cos Phi.
  const double gamma = deg<double>(45), rho = deg<double>(30);
  const double eta_fold = std::atan(std::cos(deg<double>(45)));  // tan gamma = 1
  SECTION("beyond: no real root") {
    for (double phi :
         {deg<double>(45) + 1e-9, deg<double>(60), deg<double>(90), deg<double>(120)}) {
      INFO("Phi " << phi);
      const nadir_angle_roots<double> roots = nadir_angle_roots_from_chord(gamma, rho, phi);
      CHECK(roots.state == status::fold);
      CHECK(std::isnan(roots.plus));
      CHECK(nadir_angle_from_chord(gamma, rho, phi, eta_fold).state == status::fold);
      CHECK(nadir_angle_from_chord_quadratic(gamma, rho, phi).state == status::fold);
    }
  }
  SECTION("before: two real roots, merged beyond use") {
    const double phi = deg<double>(45) - 1e-9;
    const nadir_angle_roots<double> roots = nadir_angle_roots_from_chord(gamma, rho, phi);
    REQUIRE(roots.state == status::ok);
    // Both roots sit at the fold, sqrt(1e-9)-close: half_separation ~ 4.5e-5 rad.
    CHECK_WITHIN(roots.plus, eta_fold, 1e-4);
    CHECK_WITHIN(roots.minus, eta_fold, 1e-4);
    CHECK(roots.half_separation > 0);
    CHECK(nadir_angle_from_chord(gamma, rho, phi, eta_fold).state == status::fold);
    // The quadratic form has no amplification check: it still returns the '+' root.
    CHECK(nadir_angle_from_chord_quadratic(gamma, rho, phi).ok());
  }
}

TEST_CASE("nadir_angle_from_chord: fold on both sides of the amplification threshold",
          "[nadir_angle][status][fold]") {
  CHECK(fold_amplification_max<double>() == 30);  // the documented value (nadir_angle.hpp)
  const long double threshold = fold_amplification_max<long double>();
  // gamma = 45 deg, rho = 30 deg; both branches of the chord curve Phi(eta) leave the fold at
  // eta_f = atan(cos 45 deg) (Phi = 45 deg). On each branch, find eta* with amplification at the
  // threshold by bisection (the derivative above, long double), then step 5 % of eta* - eta_f to
  // either side.
  const long double gamma = deg<double>(45), rho = deg<double>(30);
  const long double eta_f = std::atan(std::cos(gamma));
  for (int branch : {+1, -1}) {
    long double near = eta_f + branch * 1e-9L, far = eta_f + branch * deg<double>(20);
    auto amp_at = [&](long double eta) {
      return amplification(gamma, eta, half_chord_ld(gamma, eta, rho));
    };
    REQUIRE(amp_at(near) > threshold);
    REQUIRE(amp_at(far) < threshold);
    for (int i = 0; i < 100; ++i) {
      const long double mid = (near + far) / 2;
      (amp_at(mid) > threshold ? near : far) = mid;
    }
    const long double eta_star = (near + far) / 2;
    const long double eta_fold_side = eta_f + (eta_star - eta_f) * 0.95L;
    const long double eta_ok_side = eta_f + (eta_star - eta_f) * 1.05L;
    INFO("branch " << branch << " eta* " << static_cast<double>(eta_star));
    REQUIRE(amp_at(eta_fold_side) > threshold * 1.01L);
    REQUIRE(amp_at(eta_ok_side) < threshold * 0.99L);
    const double phi_fold = static_cast<double>(half_chord_ld(gamma, eta_fold_side, rho));
    const double phi_ok = static_cast<double>(half_chord_ld(gamma, eta_ok_side, rho));
    const double g = static_cast<double>(gamma), r = static_cast<double>(rho);
    // Envelope 0: beside the fold both roots are within the default 10 deg (ambiguous).
    CHECK(nadir_angle_from_chord(g, r, phi_fold, static_cast<double>(eta_fold_side), 0.0).state ==
          status::fold);
    const conescan::result<double> ok =
        nadir_angle_from_chord(g, r, phi_ok, static_cast<double>(eta_ok_side), 0.0);
    REQUIRE(ok.ok());
    // The chord was rounded to double (1e-16 rad); amplified up to 30 times: tolerance 1e-12.
    CHECK_WITHIN(ok.value, static_cast<double>(eta_ok_side), 1e-12);
  }
}

TEST_CASE("nadir_angle_from_chord: grazing on both sides of the threshold",
          "[nadir_angle][status][grazing]") {
  // Near Phi = 0: gamma = 45, rho = 30 deg have roots near 75 and 15 deg (cone tangent to the
  // disk from outside and inside); near Phi = pi: gamma = 45, rho = 60 deg, '+' root near 15 deg
  // (psi + eta = rho: the engulfed tangency). Amplification ~ sin Phi: far from the fold.
  const double phi_min = grazing_half_chord_min<double>(), pi = conescan::pi<double>();
  const double gamma = deg<double>(45);
  for (double eta0 : {deg<double>(75), deg<double>(15)}) {
    INFO("eta0 " << eta0);
    CHECK(nadir_angle_from_chord(gamma, deg<double>(30), phi_min * (1 + 1e-9), eta0).ok());
    CHECK(nadir_angle_from_chord(gamma, deg<double>(30), phi_min * (1 - 1e-9), eta0).state ==
          status::grazing);
    CHECK(nadir_angle_from_chord(gamma, deg<double>(30), 0.0, eta0).state == status::grazing);
  }
  CHECK(nadir_angle_from_chord(gamma, deg<double>(60), pi - phi_min * (1 + 1e-9), deg<double>(15))
            .ok());
  CHECK(nadir_angle_from_chord(gamma, deg<double>(60), pi - phi_min * (1 - 1e-9), deg<double>(15))
            .state == status::grazing);
  CHECK(nadir_angle_from_chord(gamma, deg<double>(60), pi, deg<double>(15)).state ==
        status::grazing);
  CHECK(nadir_angle_from_chord_quadratic(gamma, deg<double>(30), phi_min * (1 + 1e-9)).ok());
  CHECK(nadir_angle_from_chord_quadratic(gamma, deg<double>(30), phi_min * (1 - 1e-9)).state ==
        status::grazing);
}

TEST_CASE("nadir_angle_from_chord: invalid on both sides of each domain boundary",
          "[nadir_angle][status]") {
  // Domain: gamma in (0, pi/2), rho_p in (0, pi/2], Phi in [0, pi], all finite; eta0 finite.
  const double pi = conescan::pi<double>();
  const double gamma = deg<double>(45), rho = deg<double>(60), phi = deg<double>(100),
               eta0 = deg<double>(50);
  auto state = [](double g, double r, double p) {
    return nadir_angle_roots_from_chord(g, r, p).state;
  };
  CHECK(state(0.0, rho, phi) == status::invalid);
  CHECK(state(1e-300, rho, phi) != status::invalid);
  CHECK(state(pi / 2, rho, phi) == status::invalid);
  CHECK(state(std::nextafter(pi / 2, 0.0), rho, phi) != status::invalid);
  CHECK(state(gamma, 0.0, phi) == status::invalid);
  CHECK(state(gamma, 1e-300, phi) != status::invalid);
  CHECK(state(gamma, std::nextafter(pi / 2, 4.0), phi) == status::invalid);
  CHECK(state(gamma, pi / 2, phi) != status::invalid);
  CHECK(state(gamma, rho, -1e-300) == status::invalid);
  CHECK(state(gamma, rho, 0.0) != status::invalid);
  CHECK(state(gamma, rho, std::nextafter(pi, 4.0)) == status::invalid);
  CHECK(state(gamma, rho, pi) != status::invalid);
  for (double bad : {quiet_nan, inf, -inf}) {
    CHECK(state(bad, rho, phi) == status::invalid);
    CHECK(state(gamma, bad, phi) == status::invalid);
    CHECK(state(gamma, rho, bad) == status::invalid);
    CHECK(nadir_angle_from_chord(gamma, rho, phi, bad).state == status::invalid);
    CHECK(nadir_angle_from_chord(bad, rho, phi, eta0).state == status::invalid);
    CHECK(nadir_angle_from_chord_quadratic(gamma, bad, phi).state == status::invalid);
    CHECK(std::isnan(nadir_angle_from_chord(gamma, rho, bad, eta0).value));
  }
  CHECK(nadir_angle_from_chord(gamma, rho, phi, eta0).ok());
}

TEST_CASE("sigma = 0: bias model then processing returns the true nadir (MODEL §6)",
          "[processing][bias_model][sigma0]") {
  // With sigma = 0 the line of sight is on the nominal cone (psi = gamma exactly), so the
  // electronics' assumption is right and eta_s = eta, phase = phi_n, n_s = n: zero attitude
  // error. What remains is rounding: a few ulp of Phi and eta, the Phi one amplified by
  // |d eta / d Phi| (derived above). Tolerance for eta: 8 eps (1 + amplification); roll and
  // pitch inherit it through unit vectors of length 1.
  int ok_count = 0, skipped = 0;
  for (int alpha : {-20, 0, 20, 40}) {
    for (int beta : {0, 90, 200}) {
      const conescan::scan_frame<double> frame =
          conescan::scan_frame_from_mounting(deg<double>(alpha), deg<double>(beta));
      REQUIRE(frame.state == status::ok);
      for (int g : {30, 45, 60}) {
        for (double r_km : {6700.0, 7280.0, 8200.0}) {
          const double rho = conescan::disk_angular_radius(6378.137, r_km).value;
          for (int roll_tenths : {-50, -10, 0, 5, 30}) {
            const double roll = deg<double>(roll_tenths, 10);
            for (int pitch : {-4, 0, 2}) {
              const conescan::vec3<double> n = conescan::nadir_in_body(roll, deg<double>(pitch));
              const conescan::scan_angles<double> nadir = conescan::scan_angles_of(frame, n);
              for (int phi_a : {0, 77, 180}) {
                const conescan::head_optics<double> optics{deg<double>(g), 0.0, deg<double>(phi_a)};
                const conescan::crossings<double> c =
                    conescan::bias_model_crossings(optics, nadir.polar, nadir.azimuth, rho);
                INFO("alpha " << alpha << " beta " << beta << " gamma " << g << " r " << r_km
                              << " roll " << roll_tenths / 10.0 << " pitch " << pitch << " phi_a "
                              << phi_a);
                if (c.state != status::ok) {
                  ++skipped;
                  continue;
                }
                const conescan::head_estimate<double> e =
                    conescan::process_head(frame, optics.gamma, rho, c);
                const long double amp = amplification(optics.gamma, nadir.polar, c.half_chord());
                if (amp > 90) {
                  ++skipped;
                  continue;
                }
                REQUIRE(e.state == status::ok);
                ++ok_count;
                const double tol = 8 * eps<double>() * (1 + static_cast<double>(amp));
                CHECK_WITHIN(e.eta_s, nadir.polar, tol);
                CHECK_WITHIN(c.phase(), nadir.azimuth, 4 * eps<double>());
                const conescan::roll_pitch<double> sensed =
                    conescan::roll_pitch_from_nadir(e.nadir);
                CHECK_WITHIN(sensed.roll, roll, 2 * tol);
                CHECK_WITHIN(sensed.pitch, deg<double>(pitch), 2 * tol);
              }
            }
          }
        }
      }
    }
  }
  CHECK(ok_count > 1000);
  CHECK(skipped < ok_count / 4);
}

TEST_CASE("process_head passes on failed crossings and combine_heads averages the ok heads",
          "[processing]") {
  using conescan::head_estimate;
  using conescan::vec3;
  const conescan::scan_frame<double> frame =
      conescan::scan_frame_from_mounting(0.0, deg<double>(90));
  for (status s : {status::miss, status::engulfed, status::grazing, status::invalid}) {
    const head_estimate<double> e = conescan::process_head(frame, deg<double>(45), deg<double>(60),
                                                           conescan::crossings<double>::failed(s));
    CHECK(e.state == s);
    CHECK(std::isnan(e.eta_s));
    CHECK(std::isnan(e.nadir.x));
  }
  // Normalised mean (MODEL §6): (1,0,0) and (0,1,0) give (1,1,0)/sqrt(2); a failed head with a
  // non-NaN nadir must be ignored, not averaged.
  const double nan_d = quiet_nan;
  const head_estimate<double> heads[] = {
      {nan_d, vec3<double>(1, 0, 0), status::ok},
      {nan_d, vec3<double>(0, 0, 1), status::fold},
      {nan_d, vec3<double>(0, 1, 0), status::ok},
  };
  const head_estimate<double> all = conescan::combine_heads<double>(heads, heads + 3);
  CHECK(all.state == status::ok);
  CHECK_WITHIN(all.nadir.x, 1 / std::sqrt(2.0), eps<double>());
  CHECK_WITHIN(all.nadir.y, 1 / std::sqrt(2.0), eps<double>());
  CHECK(all.nadir.z == 0);
  const head_estimate<double> none = conescan::combine_heads<double>(heads + 1, heads + 2);
  CHECK(none.state == status::none);
  CHECK(std::isnan(none.nadir.x));
  CHECK(conescan::combine_heads<double>(heads, heads).state == status::none);  // no heads
}

TEST_CASE("nadir_angle_from_chord: ambiguous on both sides of the attitude envelope",
          "[nadir_angle][status][ambiguous]") {
  // MODEL §7: both roots within the envelope E of eta0 is ambiguous. For a chord made at a true
  // eta (the nearer root, eta0 = eta), the farther root lies D = |other - eta| away, with the
  // roots from nadir_angle_roots_from_chord (two atan2: an independent evaluation of them). An
  // envelope 1e-9 rad above D is ambiguous, 1e-9 rad below it is ok and returns eta.
  int ambiguous = 0;
  for (int g : {30, 45, 60, 80}) {
    for (int r : {20, 30, 45, 62}) {
      for (int e = 5; e < 180; e += 3) {
        const double gamma = deg<double>(g), rho = deg<double>(r), eta = deg<double>(e);
        const conescan::result<double> phi = half_chord(gamma, eta, rho);
        if (!phi.ok()) continue;
        const nadir_angle_roots<double> roots = nadir_angle_roots_from_chord(gamma, rho, phi.value);
        if (roots.state != status::ok) continue;
        const double other =
            std::abs(roots.plus - eta) < std::abs(roots.minus - eta) ? roots.minus : roots.plus;
        const double distance = std::abs(other - eta);
        const conescan::result<double> free =
            nadir_angle_from_chord(gamma, rho, phi.value, eta, 0.0);
        if (!free.ok() || distance > deg<double>(89) || distance < 1e-6) continue;
        INFO("gamma " << g << " rho " << r << " eta " << e << ": other root " << distance
                      << " rad away");
        const conescan::result<double> wide =
            nadir_angle_from_chord(gamma, rho, phi.value, eta, distance + 1e-9);
        const conescan::result<double> narrow =
            nadir_angle_from_chord(gamma, rho, phi.value, eta, distance - 1e-9);
        CHECK(wide.state == status::ambiguous);
        CHECK(std::isnan(wide.value));
        REQUIRE(narrow.ok());
        CHECK(narrow.value == free.value);
        if (distance < conescan::default_attitude_envelope<double>()) {
          CHECK(nadir_angle_from_chord(gamma, rho, phi.value, eta).state == status::ambiguous);
          ++ambiguous;
        }
      }
    }
  }
  CHECK(ambiguous > 10);
  CHECK(conescan::default_attitude_envelope_deg == 10);  // MODEL §7
  // The envelope's domain: [0, pi/2].
  const double gamma = deg<double>(45), rho = deg<double>(60), phi = deg<double>(70);
  const double eta0 = deg<double>(90);
  CHECK(nadir_angle_from_chord(gamma, rho, phi, eta0, 0.0).ok());
  CHECK(nadir_angle_from_chord(gamma, rho, phi, eta0, deg<double>(90)).state != status::invalid);
  CHECK(nadir_angle_from_chord(gamma, rho, phi, eta0, -1e-12).state == status::invalid);
  CHECK(nadir_angle_from_chord(gamma, rho, phi, eta0, deg<double>(90) * (1 + 1e-12)).state ==
        status::invalid);
  CHECK(nadir_angle_from_chord(gamma, rho, phi, eta0, quiet_nan).state == status::invalid);
  // eta0 is a nadir angle, in [0, pi].
  CHECK(nadir_angle_from_chord(gamma, rho, phi, -1e-12).state == status::invalid);
  CHECK(nadir_angle_from_chord(gamma, rho, phi, conescan::pi<double>() + 1e-12).state ==
        status::invalid);
}

TEST_CASE("nadir_angle_from_chord: the nearer root may be the wrong one, which ambiguous says",
          "[nadir_angle][status][ambiguous]") {
  // The case in one head: gamma 80 deg, the true eta a few degrees from eta0 and the
  // other root nearer eta0. Without an envelope the inversion returns the nearer root, wrong by
  // degrees; with MODEL §7's default envelope both roots are within 10 deg: ambiguous.
  const double gamma = deg<double>(80), rho = deg<double>(595, 10), eta0 = deg<double>(70);
  int wrong = 0;
  for (int tenths = -50; tenths <= 50; ++tenths) {
    const double eta = eta0 + deg<double>(tenths, 10);
    const conescan::result<double> phi = half_chord(gamma, eta, rho);
    if (!phi.ok()) continue;
    const conescan::result<double> free = nadir_angle_from_chord(gamma, rho, phi.value, eta0, 0.0);
    if (!free.ok() || std::abs(free.value - eta) < deg<double>(1)) continue;
    ++wrong;  // the nearer root is not the truth
    INFO("true eta " << eta << ", nearer root " << free.value);
    CHECK(nadir_angle_from_chord(gamma, rho, phi.value, eta0).state == status::ambiguous);
  }
  CHECK(wrong > 5);
}

TEST_CASE("sensed_nadir_angle_from_chord: cosine and sine are those of eta_s",
          "[nadir_angle][processing]") {
  // The cosine and sine come from the roots' own terms, without trigonometry: checked against
  // libm's of eta_s, and eta_s against the two-atan2 roots.
  int compared = 0;
  for (int g : {20, 45, 70}) {
    for (int r : {15, 40, 65}) {
      for (int e = 2; e < 180; e += 4) {
        const double gamma = deg<double>(g), rho = deg<double>(r), eta = deg<double>(e);
        const conescan::result<double> phi = half_chord(gamma, eta, rho);
        if (!phi.ok()) continue;
        const conescan::sensed_nadir_angle<double> s =
            conescan::sensed_nadir_angle_from_chord(conescan::head_inversion_of(gamma, eta, 0.0),
                                                    conescan::disk_trig_of_angle(rho), phi.value);
        if (s.state != status::ok) continue;
        ++compared;
        const nadir_angle_roots<double> roots = nadir_angle_roots_from_chord(gamma, rho, phi.value);
        const double nearer =
            std::abs(roots.plus - eta) <= std::abs(roots.minus - eta) ? roots.plus : roots.minus;
        CHECK_WITHIN(s.eta_s, nearer, 1e-14);
        CHECK_WITHIN(s.cos_eta_s, std::cos(s.eta_s), 4 * eps<double>());
        CHECK_WITHIN(s.sin_eta_s, std::sin(s.eta_s), 4 * eps<double>());
      }
    }
  }
  CHECK(compared > 100);
}
