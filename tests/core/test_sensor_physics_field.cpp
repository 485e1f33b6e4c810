// The field of view (include/conescan/sensor_physics/field.hpp), MODEL §12:
//  - the straight-limb mean as a 1-D quadrature over the height offset with the field's exact
//    weight (a trapezoid for the square, the chord sqrt(1 - x^2) for the circle) against a dense
//    2-D quadrature of the definition, with and without the surface's jump inside the field;
//  - a symmetric field on a straight step edge moves nothing: its mean at the step is 1/2;
//  - on the profile the field's 50 % point moves up towards delta50 + 0.2107 H (the Gumbel
//    distribution's mean, gamma + ln ln 2), its limit for fields many H tall.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "conescan/sensor_physics/field.hpp"
#include "support/approx.hpp"

#define CHECK_CLOSE(actual, expected, tolerance)                                     \
  CHECK_WITHIN(static_cast<long double>(actual), static_cast<long double>(expected), \
               static_cast<long double>(tolerance))

using conescan::field_of_view;
using conescan::field_shape;

namespace {

/// The mean over the field by a 2-D tensor Gauss quadrature of the definition: strips across
/// the direction in which the height changes most (v), each cut exactly where the height crosses
/// 0 (it is linear), so that the surface's jump never sits inside a cell, and the strips broken
/// where that line leaves the field (there the inner integral has a kink in v); 64 strips between
/// breaks, 48 x 48 nodes.
long double dense_mean(const conescan::radiance_profile<double>& p, double centre, double gx,
                       double gy, const field_of_view<double>& f) {
  const auto rule = conescan::gauss_legendre_rule_of<long double, 48>();
  const long double half = f.fov_rad / 2.0L;
  const bool swap = std::abs(gy) > std::abs(gx);
  const long double gu = swap ? gy : gx, gv = swap ? gx : gy;
  const bool circle = f.shape == field_shape::circle;
  // Where the surface's line centre + gu u + gv v = 0 meets the field's boundary, in v.
  std::vector<long double> breaks{-half, half};
  if (!circle && gv != 0) {
    for (int sign = -1; sign <= 1; sign += 2) breaks.push_back((-centre - sign * gu * half) / gv);
  } else if (circle) {
    const long double g = std::sqrt(gu * gu + gv * gv), nu = gu / g, nv = gv / g;
    const long double foot = -centre / g;
    if (std::abs(foot) < half) {
      const long double t = std::sqrt(half * half - foot * foot);
      breaks.push_back(foot * nv + t * nu);
      breaks.push_back(foot * nv - t * nu);
    }
  }
  // The circle's strips in theta, v = half sin(theta): its chord's square root then has no end
  // singularity.
  for (long double& b : breaks) {
    b = std::max(-half, std::min(half, b));
    if (circle) b = std::asin(b / half);
  }
  std::sort(breaks.begin(), breaks.end());
  long double sum = 0, area = 0;
  for (std::size_t b = 0; b + 1 < breaks.size(); ++b) {
    const long double lo = breaks[b], hi = breaks[b + 1];
    if (!(hi > lo)) continue;
    const int strips = 64;
    for (int i = 0; i < strips; ++i)
      for (int q = 0; q < 48; ++q) {
        const long double t = lo + (hi - lo) * (i + (rule.nodes[q] + 1) / 2) / strips;
        const long double v = circle ? half * std::sin(t) : t;
        const long double wv =
            rule.weights[q] * (hi - lo) / 2 / strips * (circle ? half * std::cos(t) : 1.0L);
        const long double ends = circle ? half * std::cos(t) : half;
        long double cuts[3] = {-ends, ends, ends};
        int n = 2;
        const long double u0 = -(centre + gv * v) / gu;
        if (u0 > -ends && u0 < ends) {
          cuts[1] = u0;
          cuts[2] = ends;
          n = 3;
        }
        for (int c = 0; c + 1 < n; ++c)
          for (int k = 0; k < 48; ++k) {
            const long double u = cuts[c] + (rule.nodes[k] + 1) * (cuts[c + 1] - cuts[c]) / 2;
            const long double w = rule.weights[k] * (cuts[c + 1] - cuts[c]) / 2 * wv;
            const double height = static_cast<double>(centre + gu * u + gv * v);
            sum += w * conescan::radiance(p, 1.0, height);
            area += w;
          }
      }
  }
  return sum / area;
}

}  // namespace

TEST_CASE("the straight-limb mean against a dense 2-D quadrature", "[physics]") {
  // Heights across a 1.5 deg field at the paper's orbit: ~3500 km per rad normal to the limb,
  // split between along and across by the crossing angle.
  for (field_shape shape : {field_shape::square, field_shape::circle})
    for (double offset : {40000.0, 0.0})
      for (double disk : {1.0, 1.3})
        for (double angle_deg : {0.0, 34.0, 90.0})
          for (double centre : {-15000.0, 5000.0, 45000.0}) {
            const auto p = conescan::radiance_profile_of(7000.0, offset, disk);
            const double g = 3.5e6, a = conescan::deg_to_rad(angle_deg);
            const double gx = g * std::cos(a), gy = g * std::sin(a);
            const field_of_view<double> f{conescan::deg_to_rad(1.5), shape};
            const double fast = conescan::straight_limb_field_mean(p, 1.0, centre, gx, gy, f);
            const long double dense = dense_mean(p, centre, gx, gy, f);
            INFO("circle " << (shape == field_shape::circle) << " delta50 " << offset << " disk "
                           << disk << " angle " << angle_deg << " centre " << centre);
            CHECK_CLOSE(fast, dense, 2e-13);
          }
}

TEST_CASE("a symmetric field on a straight step edge moves nothing", "[physics]") {
  // MODEL §12: at the step the field holds as much above as below, for any orientation of the
  // limb and either shape.
  const auto step = conescan::radiance_profile_of(0.0, 40000.0, 1.0);
  for (field_shape shape : {field_shape::square, field_shape::circle})
    for (double angle_deg : {0.0, 17.0, 45.0, 90.0})
      for (double fov_deg : {0.5, 1.0, 1.5}) {
        const double a = conescan::deg_to_rad(angle_deg);
        const field_of_view<double> f{conescan::deg_to_rad(fov_deg), shape};
        const double mean = conescan::straight_limb_field_mean(
            step, 1.0, 40000.0, 3.5e5 * std::cos(a), 3.5e5 * std::sin(a), f);
        CHECK(mean == Approx(0.5).epsilon(1e-14));
      }
}

TEST_CASE("the field's 50 % point moves up to delta50 + 0.2107 H", "[physics]") {
  // The mean of l over a field many H tall is 1/2 where the field's centre sits at the
  // profile's own mean height delta50 + H (gamma + ln ln 2) = delta50 + 0.2107 H.
  const double mean_offset = 0.57721566490153286 + std::log(std::log(2.0));
  CHECK(mean_offset == Approx(0.21070).epsilon(1e-4));
  const auto p = conescan::radiance_profile_of(7000.0, 40000.0, 1.0);
  double previous = 0;
  for (double fov_deg : {0.05, 0.2, 0.5, 1.0, 2.0, 4.0, 8.0}) {
    const field_of_view<double> f{conescan::deg_to_rad(fov_deg), field_shape::square};
    double lo = 20000, hi = 60000;
    for (int i = 0; i < 80; ++i) {
      const double m = (lo + hi) / 2;
      if (conescan::straight_limb_field_mean(p, 1.0, m, 3.5e6, 0.0, f) > 0.5)
        lo = m;
      else
        hi = m;
    }
    const double shift = ((lo + hi) / 2 - 40000) / 7000;
    INFO("fov " << fov_deg << " deg: the 50 % point at delta50 + " << shift << " H");
    CHECK(shift >= previous - 1e-12);
    CHECK(shift <= mean_offset + 1e-9);
    previous = shift;
    // An 8 deg field is 70 H tall: within 1 % of the limit.
    if (fov_deg == 8.0) CHECK(shift == Approx(mean_offset).epsilon(0.01));
  }
}
