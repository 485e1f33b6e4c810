// The core as a consumer compiles it: GLM's default vec3, with x/r/s in anonymous unions. This is
// its own program because the project's other targets define GLM_FORCE_XYZW_ONLY (the root
// CMakeLists.txt), and one program must not define glm::vec two ways (the one-definition rule).
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstddef>
#include <type_traits>

#include "conescan/conescan.hpp"
#include "support/adl_scalar.hpp"
#include "support/approx.hpp"

#ifdef GLM_FORCE_XYZW_ONLY
#error "this test is about GLM's default vec3: build it without GLM_FORCE_XYZW_ONLY"
#endif

using conescan::status;
using conescan::vec3;
using conescan_test::deg;
using conescan_test::eps;

TEST_CASE("horizon-vector fit with a scalar whose vec3 GLM cannot copy",
          "[scalar][horizon_vector]") {
  // Without GLM_FORCE_XYZW_ONLY, GLM's vec3 of a scalar with non-trivial special members, such
  // as Boost.Multiprecision's, has no copy constructor or copy assignment (its x, y, z live in
  // anonymous unions). horizon_vector.hpp must not need them. Expected values as in
  // test_horizon_vector.cpp's "several heads with exact crossings": the true nadir to 64 eps,
  // condition below 3.
  using Q = boost::multiprecision::cpp_bin_float_quad;
  static_assert(!std::is_copy_constructible_v<vec3<Q>>);
  static_assert(!std::is_copy_assignable_v<vec3<Q>>);
  const Q gamma = deg<Q>(45), rho = deg<Q>(61);
  const vec3<Q> truth = conescan::nadir_in_body(deg<Q>(3, 2), deg<Q>(-2));
  vec3<Q> h[4] = {vec3<Q>(Q(0)), vec3<Q>(Q(0)), vec3<Q>(Q(0)), vec3<Q>(Q(0))};
  std::size_t count = 0;
  for (int beta : {90, -90}) {
    const conescan::scan_frame<Q> frame = conescan::scan_frame_from_mounting(Q(0), deg<Q>(beta));
    const conescan::scan_angles<Q> angles = conescan::scan_angles_of(frame, truth);
    const conescan::crossings<Q> c = conescan::bias_model_crossings(
        conescan::head_optics<Q>{gamma, Q(0), Q(0)}, angles.polar, angles.azimuth, rho);
    REQUIRE(c.state == status::ok);
    count = conescan::append_horizon_vectors(frame, gamma, c, h, count, 4);
  }
  REQUIRE(count == 4);
  using std::cos;
  const Q cos_rho = cos(rho);
  const conescan::horizon_nadir_fit<Q> fit =
      conescan::nadir_from_horizon_vectors(h, count, cos_rho, vec3<Q>(Q(0), Q(0), Q(1)));
  REQUIRE(fit.ok());
  CHECK_WITHIN(conescan::angle_between(fit.nadir, truth), Q(0), Q(eps<Q>() * 64));
  CHECK(fit.condition < Q(3));
  CHECK_WITHIN(conescan::horizon_condition(h, count, truth), fit.condition,
               Q(eps<Q>() * 64 * fit.condition));
  // The failure paths return through horizon_nadir_fit::failed: invalid, and fold for coincident
  // crossings (J^T J exactly singular).
  CHECK(conescan::nadir_from_horizon_vectors(h, 1, cos_rho, truth).state == status::invalid);
  const vec3<Q> same[2] = {vec3<Q>(h[0].x, h[0].y, h[0].z), vec3<Q>(h[0].x, h[0].y, h[0].z)};
  const conescan::horizon_nadir_fit<Q> fold =
      conescan::nadir_from_horizon_vectors(same, 2, cos_rho, truth);
  CHECK(fold.state == status::fold);
  CHECK(fold.nadir.x != fold.nadir.x);  // NaN
}
