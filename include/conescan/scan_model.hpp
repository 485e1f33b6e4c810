// The exact forward model (MODEL §5, "scan") in closed form: the lines of sight of a misaligned
// head lie on a circle about the optical axis A, so on a sphere the crossings are the two
// intersections of that circle with the horizon circle, and on an ellipsoid the tangency
// function along it is a trigonometric polynomial of degree 2, solved by Newton from the sphere's
// intersections. The bracketed solver on the scan azimuth (scan_model_iterative.hpp) is the
// ellipsoid's fallback and the tests' oracle.
#pragma once

#include "conescan/cone_angle.hpp"
#include "conescan/crossings.hpp"
#include "conescan/earth_disk.hpp"
#include "conescan/ellipsoid_horizon.hpp"
#include "conescan/half_chord.hpp"
#include "conescan/scan_frame.hpp"
#include "conescan/scan_model_iterative.hpp"

namespace conescan {

/// The scan circle of one head (MODEL §4): every true line of sight d makes the angle gamma with
/// the optical axis A, d(theta) = cos gamma A + sin gamma (cos theta u + sin theta v). Components
/// in the head's scan frame (e1, e2, e3 = S). u points from A away from S in the plane of S and A
/// (at phi_A; for sigma = 0, u = e1 rotated by phi_A), v = A x u, so theta grows with the scan
/// azimuth phi (A lies within sigma < gamma of S, inside the circle) and theta = phi - phi_A
/// when sigma = 0. Depends on the optics only: built once per head.
template <class T>
struct scan_circle {
  vec3<T> axis;  ///< A, unit
  vec3<T> u;     ///< unit, normal to A, towards phi_A
  vec3<T> v;     ///< A x u
  T cos_gamma;
  T sin_gamma;
  T versine_gamma;  ///< 1 - cos gamma, without cancellation (tiny cones)
  status state;     ///< ok, or invalid for optics outside cone_in_domain or a non-finite phi_A
};

/// The same circle in scalar U, member by member (the sensor physics' polish reads a double row's
/// exact field mean in long double: sensor_physics/chain.hpp, polish_scalar).
template <class U, class T>
scan_circle<U> scalar_cast(const scan_circle<T>& c) noexcept {
  return {vec3<U>(c.axis), vec3<U>(c.u),       vec3<U>(c.v), U(c.cos_gamma),
          U(c.sin_gamma),  U(c.versine_gamma), c.state};
}

/// The circle of `optics` (rad): A = (sin sigma cos phi_A, sin sigma sin phi_A, cos sigma),
/// u = (cos sigma cos phi_A, cos sigma sin phi_A, -sin sigma), v = (-sin phi_A, cos phi_A, 0).
template <class T>
scan_circle<T> scan_circle_of(const head_optics<T>& optics) noexcept {
  using std::cos;
  using std::sin;
  if (!cone_in_domain(optics.gamma, optics.sigma) || !is_finite(optics.phi_a)) {
    const T nan = not_a_number<T>();
    return {vec3<T>(nan), vec3<T>(nan), vec3<T>(nan), nan, nan, nan, status::invalid};
  }
  const T cos_sigma = cos(optics.sigma), sin_sigma = sin(optics.sigma);
  const T cos_phi_a = cos(optics.phi_a), sin_phi_a = sin(optics.phi_a);
  const T cos_gamma = cos(optics.gamma), sin_gamma = sin(optics.gamma);
  return {vec3<T>(sin_sigma * cos_phi_a, sin_sigma * sin_phi_a, cos_sigma),
          vec3<T>(cos_sigma * cos_phi_a, cos_sigma * sin_phi_a, T(-sin_sigma)),
          vec3<T>(T(-sin_phi_a), cos_phi_a, T(0)),
          cos_gamma,
          sin_gamma,
          T(sin_gamma * sin_gamma / (T(1) + cos_gamma)),
          status::ok};
}

/// The line of sight at theta on the circle, given (cos theta, sin theta): scan-frame components.
template <class T>
vec3<T> scan_circle_direction(const scan_circle<T>& circle, const T& cos_theta,
                              const T& sin_theta) noexcept {
  return scaled(circle.axis, circle.cos_gamma) +
         scaled(scaled(circle.u, cos_theta) + scaled(circle.v, sin_theta), circle.sin_gamma);
}

/// Where the scan circle meets the horizon circle of a sphere: the lines of sight at angle rho
/// from the true nadir n. Directions not normalised (|d| = sin^2 delta, delta the angle from A to
/// n); only their azimuths are wanted.
template <class T>
struct circle_crossings {
  vec3<T> earth_in;   ///< where d.n rises through cos rho as theta grows
  vec3<T> earth_out;  ///< where it falls through cos rho
  status state;       ///< ok, miss, engulfed, invalid (non-finite input)
};

/// The two intersections of the circles d.A = cos gamma and d.n = cos rho on the unit sphere
/// (MODEL §5). With c = A.n = cos delta and w = A x n (|w| = sin delta),
///   d sin^2 delta = (cos gamma - c cos rho) A + (cos rho - c cos gamma) n -+ sqrt(D) w,
///   D = (sin delta sin gamma)^2 - (cos rho - c cos gamma)^2
///     = (cos(delta - gamma) - cos rho) (cos rho - cos(delta + gamma)),
/// the '-' root Earth-in (d/dtheta (d.n) = -d.w > 0 there). The factors decide the statuses
/// exactly as the half-angle form of Eq. (3) does: the nearest line of sight (delta - gamma from
/// n) off the disk is miss, the farthest (delta + gamma) on it engulfed.
/// Written against cancellation: sin delta from n's components across A (not 1 - c^2); every
/// cosine as 1 - versine, v = 1 - cos = sin^2 / (1 + cos), so that
///   cos rho - c cos gamma = v_gamma + v_delta - v_rho - v_delta v_gamma (and its mirror),
/// keeps its digits for small angles (a cone and a disk of 1e-8 rad: cosines of 1 - 1e-16 would
/// leave nothing); and the first two terms regrouped as
///   (cos gamma - c cos rho)(A - n) + (cos gamma + cos rho) v_delta n,
/// because near-concentric circles (n close to A) make both terms O(delta) and their sum
/// O(delta^2): as written in the first line it would lose 1 / delta more digits than the
/// geometry's own conditioning.
///   nadir: unit true nadir, scan-frame components; disk: the sine and cosine of its radius rho.
template <class T>
circle_crossings<T> scan_circle_meets_disk(const scan_circle<T>& circle, const vec3<T>& nadir,
                                           const disk_trig<T>& disk) noexcept {
  using std::sqrt;
  const T nan = not_a_number<T>();
  const T c = dot(circle.axis, nadir);
  const T across_u = dot(circle.u, nadir), across_v = dot(circle.v, nadir);
  const T sin_delta_squared = across_u * across_u + across_v * across_v;
  const T versine_delta = c >= T(0) ? T(sin_delta_squared / (T(1) + c)) : T(T(1) - c);
  const T versine_rho = disk.sin_rho * disk.sin_rho / (T(1) + disk.cos_rho);
  const T& versine_gamma = circle.versine_gamma;
  const T reach = sqrt(sin_delta_squared) * circle.sin_gamma;
  // cos rho - c cos gamma and cos gamma - c cos rho.
  const T towards_n = versine_gamma + versine_delta - versine_rho - versine_delta * versine_gamma;
  const T towards_a = versine_rho + versine_delta - versine_gamma - versine_delta * versine_rho;
  const T near_gap = reach - towards_n;  // cos(delta - gamma) - cos rho
  const T far_gap = reach + towards_n;   // cos rho - cos(delta + gamma)
  if (!is_finite(near_gap) || !is_finite(far_gap))
    return {vec3<T>(nan), vec3<T>(nan), status::invalid};
  if (!(near_gap > T(0))) return {vec3<T>(nan), vec3<T>(nan), status::miss};
  if (!(far_gap > T(0))) return {vec3<T>(nan), vec3<T>(nan), status::engulfed};
  const T root = sqrt(near_gap * far_gap);
  const vec3<T> middle = scaled(circle.axis - nadir, towards_a) +
                         scaled(nadir, T((circle.cos_gamma + disk.cos_rho) * versine_delta));
  const vec3<T> across = scaled(cross(circle.axis, nadir), root);
  return {middle - across, middle + across, status::ok};
}

/// Crossings from the raw azimuths of the Earth-in and Earth-out lines of sight (any branch):
/// phi_in is kept, phi_out = phi_in + W with the chord W in (0, 2 pi]. Status grazing for a half
/// chord within grazing_half_chord_min() of 0 or pi (classify_half_chord).
template <class T>
crossings<T> crossings_from_azimuths(const T& phi_in, const T& phi_out, int iterations) noexcept {
  T chord = phi_out - phi_in;
  if (!(chord > T(0))) chord += T(2) * pi<T>();
  const status s = classify_half_chord(T(chord / T(2)));
  if (s != status::ok) return crossings<T>::failed(s);
  return {phi_in, T(phi_in + chord), status::ok, iterations};
}

/// Scan model on a sphere in closed form (MODEL §5): the circle's intersections with the horizon
/// circle of angular radius rho (`disk`) about the unit true nadir (scan-frame components), at
/// their azimuths about S (two atan2). phi_in is in [-pi, pi], phi_out = phi_in + W. Statuses:
/// miss, engulfed (scan_circle_meets_disk), grazing (crossings_from_azimuths), invalid (circle not
/// ok, non-finite input). `iterations` is 0. Accuracy (double, against cpp_bin_float_50 through the
/// whole head, docs/ACCURACY.md): that of the geometry, a few ulp divided by the sine of the angle
/// at which the circles cross; against scan_model_crossings_sphere_iterative within 1e-13 rad
/// (tests/core/test_scan_model.cpp).
template <class T>
crossings<T> scan_model_crossings_sphere(const scan_circle<T>& circle, const vec3<T>& nadir,
                                         const disk_trig<T>& disk) noexcept {
  using std::atan2;
  if (circle.state != status::ok || disk.state != status::ok)
    return crossings<T>::failed(status::invalid);
  const circle_crossings<T> x = scan_circle_meets_disk(circle, nadir, disk);
  if (x.state != status::ok) return crossings<T>::failed(x.state);
  return crossings_from_azimuths(T(atan2(x.earth_in.y, x.earth_in.x)),
                                 T(atan2(x.earth_out.y, x.earth_out.x)), 0);
}

/// Scan model on a sphere from the angles of the true nadir: eta from S and azimuth phi_n about S
/// (rad), disk radius rho (rad). The crossings are placed about phi_n: their phase lies within pi
/// of it (of phi_n reduced to (-pi, pi] when |phi_n| > 2 pi, whose whole turns would eat the
/// azimuths' digits). Domain: cone_in_domain, finite phi_A and phi_n, and
/// disk_geometry_in_domain(gamma, eta, rho); otherwise invalid. Statuses and accuracy: those of
/// the closed form above.
template <class T>
crossings<T> scan_model_crossings_sphere(const head_optics<T>& optics, const T& eta, const T& phi_n,
                                         const T& rho) noexcept {
  using std::abs;
  using std::cos;
  using std::sin;
  if (!cone_in_domain(optics.gamma, optics.sigma) || !is_finite(optics.phi_a) ||
      !is_finite(phi_n) || !disk_geometry_in_domain(optics.gamma, eta, rho))
    return crossings<T>::failed(status::invalid);
  const T centre = abs(phi_n) <= T(2) * pi<T>() ? phi_n : wrap_pi(phi_n);
  const T sin_eta = sin(eta);
  const vec3<T> nadir(sin_eta * cos(centre), sin_eta * sin(centre), cos(eta));
  crossings<T> c =
      scan_model_crossings_sphere(scan_circle_of(optics), nadir, disk_trig_of_angle(rho));
  if (c.state != status::ok) return c;
  const T offset = c.phase() - centre;
  const T turns = wrap_pi(offset) - offset;  // a whole number of turns, 0 mostly
  c.phi_in += turns;
  c.phi_out += turns;
  return c;
}

/// A point of the scan circle by (cos theta, sin theta), kept without the angle: the Newton
/// steps below rotate it algebraically, so no libm call is needed inside the loop.
template <class T>
struct circle_point {
  T cos_theta;
  T sin_theta;
};

/// a_eq^2 g (ellipsoid_horizon.hpp) along the scan circle: with d(theta) of scan_circle,
///   front(theta) = q.d = f0 + f1 cos theta + f2 sin theta,
///   along(theta) = z.d = z0 + z1 cos theta + z2 sin theta,
///   g(theta) = front^2 - H (1 + kappa along^2),
/// a trigonometric polynomial of degree 2 in theta (MODEL §5): at most four zeros.
template <class T>
struct tangency_on_circle {
  T f0, f1, f2;
  T z0, z1, z2;
  T height;  ///< H
  T kappa;

  /// front, g and dg/dtheta at a point.
  void at(const circle_point<T>& x, T& front, T& g, T& slope) const noexcept {
    front = f0 + f1 * x.cos_theta + f2 * x.sin_theta;
    const T front_slope = f2 * x.cos_theta - f1 * x.sin_theta;
    const T along = z0 + z1 * x.cos_theta + z2 * x.sin_theta;
    const T along_slope = z2 * x.cos_theta - z1 * x.sin_theta;
    const T stretch_along = kappa * along;
    g = front * front - height * (T(1) + stretch_along * along);
    slope = T(2) * (front * front_slope - height * stretch_along * along_slope);
  }
};

template <class T>
tangency_on_circle<T> tangency_on_circle_of(const scan_circle<T>& circle,
                                            const ellipsoid_horizon<T>& surface) noexcept {
  const T f_axis = dot(surface.q, circle.axis), f_u = dot(surface.q, circle.u),
          f_v = dot(surface.q, circle.v);
  const T z_axis = dot(surface.polar, circle.axis), z_u = dot(surface.polar, circle.u),
          z_v = dot(surface.polar, circle.v);
  return {circle.cos_gamma * f_axis,
          circle.sin_gamma * f_u,
          circle.sin_gamma * f_v,
          circle.cos_gamma * z_axis,
          circle.sin_gamma * z_u,
          circle.sin_gamma * z_v,
          surface.height,
          surface.kappa};
}

/// The zeros of g besides in and out (two of its zeros, g rising at in) when they lie in front
/// of the satellite: a second arc on the Earth (MODEL §5, §7). `found` false when there is none.
/// g = F(theta) h(theta) with F = cos(theta - mu) - cos nu zero at in and out (mu their middle,
/// 2 nu the arc from in to out), and h = h0 + h1 cos(theta - mu) + h2 sin(theta - mu) of degree
/// 1: with g = g0 + g1 cos theta + g2 sin theta + g3 cos 2 theta + g4 sin 2 theta, turned by mu to
/// G1, G3, G4, the product gives h1 = 2 G3, h2 = 2 G4, h0 = G1 + 2 cos nu G3. h has real zeros iff
/// h1^2 + h2^2 >= h0^2, at chi +- omega (chi h's phase, cos omega = -h0 / |h|); they are in
/// front iff front < 0 there (both are, or neither: g < 0 where front = 0, so the zeros in front
/// come in pairs). All algebra, two square roots.
template <class T>
struct second_earth_arc {
  bool found = false;
  circle_point<T> first{}, second{};  ///< h's zeros, at chi + omega and chi - omega
};

template <class T>
second_earth_arc<T> second_earth_arc_of(const tangency_on_circle<T>& t, const circle_point<T>& in,
                                        const circle_point<T>& out) noexcept {
  using std::sqrt;
  // Harmonics of g = front^2 - H - H kappa along^2 (products to sums).
  const T hk = t.height * t.kappa;
  const T g1 = T(2) * (t.f0 * t.f1 - hk * t.z0 * t.z1);
  const T g2 = T(2) * (t.f0 * t.f2 - hk * t.z0 * t.z2);
  const T g3 = ((t.f1 * t.f1 - t.f2 * t.f2) - hk * (t.z1 * t.z1 - t.z2 * t.z2)) / T(2);
  const T g4 = t.f1 * t.f2 - hk * t.z1 * t.z2;
  // e^{2 i nu} = e^{i (out - in)}, e^{2 i mu} = e^{i (in + out)}.
  const T cos_2nu = in.cos_theta * out.cos_theta + in.sin_theta * out.sin_theta;
  const T sin_2nu = in.cos_theta * out.sin_theta - in.sin_theta * out.cos_theta;
  const T cos_2mu = in.cos_theta * out.cos_theta - in.sin_theta * out.sin_theta;
  const T sin_2mu = in.sin_theta * out.cos_theta + in.cos_theta * out.sin_theta;
  // e^{i nu} with nu in (0, pi), from whichever half-angle form does not cancel.
  T cos_nu, sin_nu;
  if (cos_2nu <= T(0)) {
    cos_nu = sin_2nu;
    sin_nu = T(1) - cos_2nu;
  } else {
    const T sign = sin_2nu < T(0) ? T(-1) : T(1);
    cos_nu = sign * (T(1) + cos_2nu);
    sin_nu = sign * sin_2nu;
  }
  const T length = sqrt(cos_nu * cos_nu + sin_nu * sin_nu);
  cos_nu /= length;
  sin_nu /= length;
  const T cos_mu = in.cos_theta * cos_nu - in.sin_theta * sin_nu;
  const T sin_mu = in.sin_theta * cos_nu + in.cos_theta * sin_nu;
  const T turned_g1 = g1 * cos_mu + g2 * sin_mu;
  const T turned_g3 = g3 * cos_2mu + g4 * sin_2mu;
  const T turned_g4 = g4 * cos_2mu - g3 * sin_2mu;
  const T h0 = turned_g1 + T(2) * cos_nu * turned_g3;
  const T h1 = T(2) * turned_g3, h2 = T(2) * turned_g4;
  const T amplitude_squared = h1 * h1 + h2 * h2;
  second_earth_arc<T> arc;
  if (!(amplitude_squared >= h0 * h0)) return arc;
  const T amplitude = sqrt(amplitude_squared);
  const T cos_omega = -h0 / amplitude;
  const T sin_omega = sqrt(T(1) - cos_omega * cos_omega);
  // x = chi +- omega, turned back by mu.
  const auto zero = [&](const T& sign) {
    const T cos_x = (h1 * cos_omega - sign * h2 * sin_omega) / amplitude;
    const T sin_x = (h2 * cos_omega + sign * h1 * sin_omega) / amplitude;
    return circle_point<T>{cos_x * cos_mu - sin_x * sin_mu, sin_x * cos_mu + cos_x * sin_mu};
  };
  arc.first = zero(T(1));
  arc.second = zero(T(-1));
  T front, g, slope;
  t.at(arc.first, front, g, slope);
  arc.found = front < T(0);
  return arc;
}

/// Whether g has a second arc on the Earth besides the one from in to out (second_earth_arc_of).
template <class T>
bool has_second_earth_arc(const tangency_on_circle<T>& t, const circle_point<T>& in,
                          const circle_point<T>& out) noexcept {
  return second_earth_arc_of(t, in, out).found;
}

/// The status of a scan from the geometry alone once two of its crossings are known (in, g rising,
/// and out, g falling, whichever pair a root finder found), MODEL §7: with four crossings,
/// multiple, unless both Earth arcs are narrower than the grazing chord (2
/// grazing_half_chord_min(), as azimuths about S), then grazing; ok with two (the caller then
/// classifies the chord of in and out). The four zeros are ordered along the circle from in
/// (g's sign alternates: the arcs on the Earth are [in, next] and [third, fourth]), so the
/// status does not depend on which pair was found, nor on the root finder's path.
template <class T>
status earth_arcs_status(const scan_circle<T>& circle, const tangency_on_circle<T>& t,
                         const circle_point<T>& in, const circle_point<T>& out) noexcept {
  using std::atan2;
  const second_earth_arc<T> arc = second_earth_arc_of(t, in, out);
  if (!arc.found) return status::ok;
  const T two_pi = T(2) * pi<T>();
  // The angle along the circle from in, [0, 2 pi); the azimuth about S of a point.
  const auto from_in = [&](const circle_point<T>& p) {
    const T a = atan2(in.cos_theta * p.sin_theta - in.sin_theta * p.cos_theta,
                      in.cos_theta * p.cos_theta + in.sin_theta * p.sin_theta);
    return a < T(0) ? T(a + two_pi) : a;
  };
  const auto azimuth = [&](const circle_point<T>& p) {
    const vec3<T> d = scan_circle_direction(circle, p.cos_theta, p.sin_theta);
    return T(atan2(d.y, d.x));
  };
  // Without fmod (ceres::Jet has none): azimuth differences lie in (-2 pi, 2 pi).
  const auto width = [&](const circle_point<T>& from, const circle_point<T>& to) {
    const T w = azimuth(to) - azimuth(from);
    return w < T(0) ? T(w + two_pi) : w;
  };
  circle_point<T> z[3] = {out, arc.first, arc.second};
  for (int i = 0; i < 3; ++i)  // three elements: sorted by their angle from in
    for (int j = i + 1; j < 3; ++j)
      if (from_in(z[j]) < from_in(z[i])) {
        const circle_point<T> swap = z[i];
        z[i] = z[j];
        z[j] = swap;
      }
  const T grazing_chord = T(2) * grazing_half_chord_min<T>();
  const bool narrow = width(in, z[0]) < grazing_chord && width(z[1], z[2]) < grazing_chord;
  return narrow ? status::grazing : status::multiple;
}

/// Newton steps on the scan circle from `x` towards a zero of g, rotating (cos theta, sin theta)
/// by atan(tau) for the Newton correction tau = -g / g' (the rotation's own tangent: the step
/// stays quadratic, and no sine or cosine is evaluated). A correction above 1/2 rad leaves the
/// start's basin (a second arc, or no zero near): failed. Converged after a step whose predicted
/// successor, K tau^2 with the convergence constant K ~ |tau| / tau_before^2 of the last two
/// steps, is below eps / 4: the step after a quadratic one of 1e-12 in double is not taken, and
/// a correction at the rounding of g (which may never fall below a few eps) ends the iteration.
template <class T>
struct circle_newton {
  circle_point<T> x;
  T front;               ///< q.d at the last evaluation
  T slope;               ///< dg/dtheta at the last evaluation
  T tau_before = T(-1);  ///< the previous correction's size; < 0 before the first step
  bool converged = false;
  bool failed = false;

  void step(const tangency_on_circle<T>& t) noexcept {
    using std::abs;
    using std::sqrt;
    T g;
    t.at(x, front, g, slope);
    const T tau = -g / slope;
    const T size = abs(tau);
    if (!(size <= T(1) / T(2))) {
      failed = true;
      return;
    }
    const T shrink = T(1) / sqrt(T(1) + tau * tau);
    x = {(x.cos_theta - tau * x.sin_theta) * shrink, (x.sin_theta + tau * x.cos_theta) * shrink};
    const T eps = std::numeric_limits<T>::epsilon();
    converged = size <= T(4) * eps ||
                (tau_before >= T(0) && T(4) * size * size * size <= eps * tau_before * tau_before);
    tau_before = size;
  }
};

/// Cap on the Newton steps per crossing of scan_model_crossings_ellipsoid before the fallback:
/// from the sphere's start (~1e-3 rad off on WGS84) quadratic convergence needs 4 in double and
/// 6 in 50 digits; past the cap the start was not in the zero's basin.
template <class T>
int ellipsoid_newton_max_steps() noexcept {
  return std::numeric_limits<T>::digits / 16 + 6;
}

/// The point of the scan circle whose line of sight is d (scan-frame components, any length).
template <class T>
circle_point<T> circle_point_of(const scan_circle<T>& circle, const vec3<T>& d) noexcept {
  using std::sqrt;
  const T c = dot(d, circle.u), s = dot(d, circle.v);
  const T length = sqrt(c * c + s * s);
  return {c / length, s / length};
}

/// miss or engulfed when the spheres that bound the ellipsoid say so: the ellipsoid lies inside
/// the sphere of radius max(a_eq, b_pol) about its centre and contains the one of radius
/// min(a_eq, b_pol), and so do their horizons as seen from the satellite. A cone missing the
/// larger sphere misses the ellipsoid; one engulfed by the smaller is engulfed by it. `ok` when
/// neither decides (the satellite inside the larger sphere, or a cone between the two).
template <class T>
status bounding_spheres_status(const scan_circle<T>& circle, const ellipsoid_horizon<T>& surface,
                               const vec3<T>& nadir, status start) noexcept {
  using std::sqrt;
  // Radii relative to a_eq: 1 and b_pol / a_eq = 1 / sqrt(1 + kappa).
  const T polar = T(1) / sqrt(T(1) + surface.kappa);
  const T distance = norm(surface.position);
  const T radius =
      start == status::miss ? (polar > T(1) ? polar : T(1)) : (polar < T(1) ? polar : T(1));
  if (!(radius < distance)) return status::ok;
  const T sin_rho = radius / distance;
  const disk_trig<T> sphere{sin_rho, T(sqrt((T(1) - sin_rho) * (T(1) + sin_rho))), status::ok};
  const status bound = scan_circle_meets_disk(circle, nadir, sphere).state;
  return bound == start ? start : status::ok;
}

/// The bracketed solver on the scan azimuth where the Newton iteration did not settle (scan-frame
/// axes, since the surface is expressed in them), its crossings then checked for a second arc
/// as the Newton ones are. `steps`: the Newton steps already spent, added to its iterations.
template <class T>
crossings<T> ellipsoid_crossings_fallback(const scan_circle<T>& circle,
                                          const head_optics<T>& optics,
                                          const ellipsoid_horizon<T>& surface,
                                          const tangency_on_circle<T>& t, int steps) noexcept {
  const scan_frame<T> scan_axes{vec3<T>(T(1), T(0), T(0)), vec3<T>(T(0), T(1), T(0)),
                                vec3<T>(T(0), T(0), T(1)), status::ok};
  crossings<T> c = ellipsoid_crossing_pair(optics, scan_axes, surface);
  c.iterations += steps;
  if (c.state != status::ok) return c;
  auto point_at = [&](const T& phi) {
    const T psi = misaligned_cone_angle(optics.gamma, optics.sigma, T(phi - optics.phi_a)).value;
    return circle_point_of(circle, direction_in_scan_frame(scan_axes, psi, phi));
  };
  status s = earth_arcs_status(circle, t, point_at(c.phi_in), point_at(c.phi_out));
  if (s == status::ok) s = classify_half_chord(c.half_chord());
  if (s != status::ok) {
    const int iterations = c.iterations;
    c = crossings<T>::failed(s);
    c.iterations = iterations;
  }
  return c;
}

/// The closed-form part of scan_model_crossings_ellipsoid: the crossings when the Newton
/// iteration from the sphere settles (or the bounding spheres decide miss or engulfed); otherwise
/// `settled` is false and the bracketed fallback must decide. Used alone where the fallback cannot
/// run (ceres::Jet has no fmod; the calibration then drops the measurement).
template <class T>
struct ellipsoid_newton_crossings {
  crossings<T> result;
  bool settled;
  tangency_on_circle<T> tangency;
  int steps;
};

template <class T>
ellipsoid_newton_crossings<T> scan_model_crossings_ellipsoid_newton(
    const scan_circle<T>& circle, const ellipsoid_horizon<T>& surface) noexcept {
  using std::atan2;
  using std::sqrt;
  const tangency_on_circle<T> t = tangency_on_circle_of(circle, surface);
  // The sphere's start: the nadir towards the centre, sin rho = 1 / |P|.
  const vec3<T> nadir = unit(scaled(surface.position, T(-1)));
  const T sin_rho = surface.inverse_norm_p_scaled;
  const disk_trig<T> sphere{sin_rho, T(sqrt((T(1) - sin_rho) * (T(1) + sin_rho))), status::ok};
  const circle_crossings<T> start = scan_circle_meets_disk(circle, nadir, sphere);
  if (start.state == status::miss || start.state == status::engulfed) {
    // Most scans that do not reach the sphere do not reach the ellipsoid either: decided without
    // the fallback's search of the whole scan circle where the bounding spheres agree.
    const status bound = bounding_spheres_status(circle, surface, nadir, start.state);
    if (bound != status::ok) return {crossings<T>::failed(bound), true, t, 0};
  }
  circle_newton<T> in{}, out{};
  int steps = 0;
  if (start.state == status::ok) {
    in.x = circle_point_of(circle, start.earth_in);
    out.x = circle_point_of(circle, start.earth_out);
    const int max_steps = ellipsoid_newton_max_steps<T>();
    for (int i = 0; i < max_steps && !in.failed && !out.failed; ++i) {
      if (in.converged && out.converged) break;
      if (!in.converged) {
        in.step(t);
        ++steps;
      }
      if (!out.converged) {
        out.step(t);
        ++steps;
      }
    }
  }
  const bool settled = start.state == status::ok && in.converged && out.converged &&
                       in.front < T(0) && out.front < T(0) && in.slope > T(0) && out.slope < T(0);
  if (!settled) return {crossings<T>::failed(status::invalid), false, t, steps};
  if (const status arcs = earth_arcs_status(circle, t, in.x, out.x); arcs != status::ok)
    return {crossings<T>::failed(arcs), true, t, steps};
  const vec3<T> d_in = scan_circle_direction(circle, in.x.cos_theta, in.x.sin_theta);
  const vec3<T> d_out = scan_circle_direction(circle, out.x.cos_theta, out.x.sin_theta);
  return {crossings_from_azimuths(T(atan2(d_in.y, d_in.x)), T(atan2(d_out.y, d_out.x)), steps),
          true, t, steps};
}

/// Scan model on an ellipsoid of revolution (MODEL §3, §5) with the surface expressed in the
/// head's scan frame (ellipsoid_horizon_of with p and the polar axis in scan-frame components).
/// Along the scan circle g is a trigonometric polynomial of degree 2 (tangency_on_circle); each
/// crossing is its zero found by Newton from the sphere through the ellipsoid's radius along p
/// (scan_circle_meets_disk), with no libm call in the loop, then placed at its azimuth about S
/// (one atan2 each). Where that does not settle on two crossings of the right orientation in
/// front of the satellite (near miss, engulfed or grazing, or a strongly non-spherical surface),
/// the bracketed solver on the scan azimuth decides (scan_model_crossings_ellipsoid_iterative),
/// so the result never diverges; a miss or engulfed start that the ellipsoid's bounding spheres
/// confirm (bounding_spheres_status) is final without it. Either way the two crossings found are
/// then checked for a second arc on the Earth (has_second_earth_arc): status multiple. `iterations`
/// counts the Newton steps of both crossings (plus the fallback's). Statuses: invalid (circle or
/// surface not ok, optics), miss, engulfed, grazing, multiple. Accuracy: the tangency residual |g|
/// / |D|^2 below 1e-12 in double; against the iterative solver within 1e-12 rad
/// (tests/apps/test_scan_model_closed_form.cpp); docs/ACCURACY.md.
template <class T>
crossings<T> scan_model_crossings_ellipsoid(const scan_circle<T>& circle,
                                            const head_optics<T>& optics,
                                            const ellipsoid_horizon<T>& surface) noexcept {
  if (circle.state != status::ok || surface.state != status::ok)
    return crossings<T>::failed(status::invalid);
  const ellipsoid_newton_crossings<T> newton =
      scan_model_crossings_ellipsoid_newton(circle, surface);
  if (newton.settled) return newton.result;
  return ellipsoid_crossings_fallback(circle, optics, surface, newton.tangency, newton.steps);
}

/// The same with the head's scan frame and the satellite position in ECI (m, from the
/// ellipsoid's centre) and the polar axis along ECI z; semi-axes a_eq, b_pol (m, oblate or
/// prolate). Domain: cone_in_domain, finite phi_A and p, a_eq, b_pol > 0, the satellite outside
/// the ellipsoid; otherwise invalid. `frame_eci` itself is not checked: pass a valid frame.
template <class T>
crossings<T> scan_model_crossings_ellipsoid(const head_optics<T>& optics,
                                            const scan_frame<T>& frame_eci, const vec3<T>& p_eci,
                                            const T& a_eq, const T& b_pol) noexcept {
  const vec3<T> p(dot(frame_eci.e1, p_eci), dot(frame_eci.e2, p_eci), dot(frame_eci.e3, p_eci));
  const vec3<T> polar(frame_eci.e1.z, frame_eci.e2.z, frame_eci.e3.z);
  return scan_model_crossings_ellipsoid(scan_circle_of(optics), optics,
                                        ellipsoid_horizon_of(p, polar, a_eq, b_pol));
}

}  // namespace conescan
