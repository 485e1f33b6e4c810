// The tangent height of a line of sight above the horizon surface (MODEL §12, "Height above the
// horizon"), on the sphere R + h_h and on the ellipsoid of MODEL §5 (inflated, or the apparent
// horizon surface with its pole and season terms folded into its semi-axes and centre), and the
// geodetic latitude of the tangent point (the season term of the radiance needs it).
//
// The surfaces are expressed in a head's scan frame, as the scan models use them
// (scan_model.hpp): every direction below is a unit vector in scan-frame components, the satellite
// at the origin.
#pragma once

#include <cmath>
#include <limits>

#include "conescan/earth_disk.hpp"
#include "conescan/ellipsoid_horizon.hpp"
#include "conescan/scan_model.hpp"
#include "conescan/sensor_physics/geodetic_latitude.hpp"
#include "conescan/status.hpp"
#include "conescan/vector.hpp"

namespace conescan {

/// A line of sight's height above the horizon surface and the latitude of its tangent point.
/// `height_m` is signed: the height of the line's closest approach to the surface (in the scaled
/// space of MODEL §5 on the ellipsoid), negative when the line meets the surface. MODEL §12 gives
/// such a line the height -inf; the signed value is kept because it is a smooth function of the
/// direction (the crossing solvers and the field quadrature need that), and spec_height() returns
/// MODEL §12's value. height_m = 0 is exactly the geometric crossing of MODEL §5.
template <class T>
struct tangent_height {
  T height_m;      ///< signed tangent height (m); < 0: the line meets the surface
  T sin_latitude;  ///< sine of the WGS84 geodetic latitude of the tangent point (MODEL §12)
  status state;    ///< ok, or invalid (non-finite direction, surface not ok)

  bool meets_surface() const noexcept { return height_m < T(0); }
  /// MODEL §12's delta: height_m above the surface, -inf for a line that meets it.
  T spec_height() const noexcept {
    return height_m < T(0) ? T(-std::numeric_limits<T>::infinity()) : height_m;
  }
};

/// The horizon sphere (radius R + h_h) seen from the satellite, in scan-frame components.
template <class T>
struct sphere_surface {
  vec3<T> nadir;  ///< unit, from the satellite towards the sphere's centre
  vec3<T> polar;  ///< unit polar axis (only the latitude reads it)
  T radius_m;     ///< R + h_h
  T distance_m;   ///< |p|, the satellite's distance from the centre
  status state;   ///< ok, or invalid
};

/// The same sphere in scalar U, member by member.
template <class U, class T>
sphere_surface<U> scalar_cast(const sphere_surface<T>& s) noexcept {
  return {vec3<U>(s.nadir), vec3<U>(s.polar), U(s.radius_m), U(s.distance_m), s.state};
}

/// The sphere from the unit true nadir, its radius and the satellite's distance (m). invalid
/// unless 0 < radius < distance, all finite, and nadir and polar of unit length (to 1e-6).
template <class T>
sphere_surface<T> sphere_surface_of(const vec3<T>& nadir, const T& radius_m, const T& distance_m,
                                    const vec3<T>& polar) noexcept {
  using std::abs;
  const T nan = not_a_number<T>();
  sphere_surface<T> s{nadir, polar, radius_m, distance_m, status::invalid};
  const T tolerance = T(1) / T(1000000);
  const bool units =
      abs(dot(nadir, nadir) - T(1)) <= tolerance && abs(dot(polar, polar) - T(1)) <= tolerance;
  if (!is_finite(radius_m) || !is_finite(distance_m) || !(radius_m > T(0)) ||
      !(radius_m < distance_m) || !units) {
    s.radius_m = s.distance_m = nan;
    return s;
  }
  s.state = status::ok;
  return s;
}

/// The same from the disk of MODEL §5 (disk_trig: sin rho = radius / distance) and the radius.
template <class T>
sphere_surface<T> sphere_surface_of(const vec3<T>& nadir, const disk_trig<T>& disk,
                                    const T& radius_m, const vec3<T>& polar) noexcept {
  if (disk.state != status::ok)
    return sphere_surface_of(nadir, not_a_number<T>(), not_a_number<T>(), polar);
  return sphere_surface_of(nadir, radius_m, T(radius_m / disk.sin_rho), polar);
}

/// The WGS84 geodetic latitude's sine of the sphere's point at geocentric latitude sine z (MODEL
/// §12: geodetic on every Earth model; on a sphere of WGS84's radius 45 deg geocentric is 45.19
/// deg geodetic).
template <class T>
T sphere_point_latitude(const sphere_surface<T>& s, const T& z) noexcept {
  using std::sqrt;
  const T z_clamped = z > T(1) ? T(1) : z < T(-1) ? T(-1) : z;
  return wgs84_sin_geodetic_latitude(T(s.radius_m * sqrt((T(1) - z_clamped) * (T(1) + z_clamped))),
                                     T(s.radius_m * z_clamped));
}

/// Height on the sphere from c = d.n (the cosine of the line's angle beta from the nadir) and
/// the polar components pd = polar.d, pn = polar.n; the caller's fast path (the field
/// quadrature builds c, pd from two dot products per scan azimuth). MODEL §12:
///   delta = |p| sin beta - (R + h_h) for d.p < 0 (c > 0); the line's closest approach to the
///   centre is then the point at distance |p| c along it;
///   delta = |p| - (R + h_h) for c <= 0: the line leaves the satellite away from the sphere, and
///   its nearest point is the satellite itself (continuous at c = 0).
/// The tangent point is the closest approach seen from the centre, on the sphere: the unit vector
/// (c d - n) / sin beta, whose polar component is (c pd - pn) / sin beta (-pn, the sub-satellite
/// point, for c <= 0 or a line through the centre); its latitude is WGS84's geodetic one.
/// sin beta = sqrt((1 - c)(1 + c)) keeps its digits near the limb, where c is far from 1.
/// with_latitude false skips the latitude (0 is returned for it): it costs as much as the height.
template <class T>
tangent_height<T> sphere_tangent_height(const sphere_surface<T>& s, const T& c, const T& pd,
                                        const T& pn, bool with_latitude = true) noexcept {
  using std::sqrt;
  if (!(c > T(0)))
    return {T(s.distance_m - s.radius_m), with_latitude ? sphere_point_latitude(s, T(-pn)) : T(0),
            status::ok};
  const T c_clamped = c < T(1) ? c : T(1);
  const T sin_beta = sqrt((T(1) - c_clamped) * (T(1) + c_clamped));
  const T height = s.distance_m * sin_beta - s.radius_m;
  const T sin_geocentric = sin_beta > T(0) ? T((c_clamped * pd - pn) / sin_beta) : T(-pn);
  return {height, with_latitude ? sphere_point_latitude(s, sin_geocentric) : T(0), status::ok};
}

/// The tangent height of the unit line of sight d (scan-frame components) above the sphere,
/// and the WGS84 geodetic latitude of its tangent point. Domain: s
/// ok, d finite; otherwise invalid. Accuracy: the subtraction |p| sin beta - R leaves an
/// absolute error of a few ulp of R (1e-9 m in double, 0.5 m in float); the latitude's sine
/// ~1e-16 (tests/core/test_sensor_physics.cpp against long double).
template <class T>
tangent_height<T> tangent_height_of(const sphere_surface<T>& s, const vec3<T>& d) noexcept {
  const T nan = not_a_number<T>();
  if (s.state != status::ok || !is_finite(d.x) || !is_finite(d.y) || !is_finite(d.z))
    return {nan, nan, status::invalid};
  return sphere_tangent_height(s, T(dot(d, s.nadir)), T(dot(d, s.polar)), T(dot(s.nadir, s.polar)));
}

/// The ellipsoid of MODEL §5 as seen from the satellite (ellipsoid_horizon_of in scan-frame
/// components), with its equatorial semi-axis a_eq (m) to map heights back to metres, and the
/// scaled-space quantities the heights need: P = N p / a_eq, s = a_eq / b_pol.
template <class T>
struct ellipsoid_surface {
  ellipsoid_horizon<T> horizon;  ///< position, q = N^2 p / a_eq, polar, kappa, height H
  T a_eq_m;                      ///< equatorial semi-axis (m)
  vec3<T> scaled_position;       ///< P = N p / a_eq
  T stretch;                     ///< s = a_eq / b_pol = sqrt(1 + kappa)
  T norm_scaled_position;        ///< |P| = sqrt(1 + H)
  status state;                  ///< ok, or invalid
};

/// The same ellipsoid in scalar U, member by member (its derived members as they are, so that it
/// is the double row's surface to the last bit, not one recomputed from rounder inputs).
template <class U, class T>
ellipsoid_surface<U> scalar_cast(const ellipsoid_surface<T>& s) noexcept {
  return {scalar_cast<U>(s.horizon), U(s.a_eq_m), vec3<U>(s.scaled_position), U(s.stretch),
          U(s.norm_scaled_position), s.state};
}

/// From an ellipsoid_horizon (scan-frame components) and its equatorial semi-axis (m). invalid
/// unless the horizon is ok and a_eq > 0 finite.
template <class T>
ellipsoid_surface<T> ellipsoid_surface_of(const ellipsoid_horizon<T>& e, const T& a_eq_m) noexcept {
  using std::sqrt;
  const T nan = not_a_number<T>();
  ellipsoid_surface<T> s{e, a_eq_m, vec3<T>(nan), nan, nan, status::invalid};
  if (e.state != status::ok || !is_finite(a_eq_m) || !(a_eq_m > T(0))) return s;
  s.stretch = sqrt(T(1) + e.kappa);
  // N p / a = p / a + (s - 1)(z . p / a) z, with s - 1 = kappa / (1 + s) (no cancellation).
  const T along = dot(e.position, e.polar);
  s.scaled_position = e.position + scaled(e.polar, T(e.kappa / (T(1) + s.stretch) * along));
  s.norm_scaled_position = sqrt(T(1) + e.height);
  s.state = status::ok;
  return s;
}

/// The WGS84 geodetic latitude's sine of the ellipsoid's point a N^-1 X^ with zeta = z . X^ (X^ a
/// unit vector of the scaled space): a_eq sqrt(1 - zeta^2) from the axis, b_pol zeta along it,
/// from the surface's centre (the Earth's, unless --horizon-shift-km moves the surface).
template <class T>
T ellipsoid_point_latitude(const ellipsoid_surface<T>& s, const T& zeta) noexcept {
  using std::sqrt;
  const T z = zeta > T(1) ? T(1) : zeta < T(-1) ? T(-1) : zeta;
  return wgs84_sin_geodetic_latitude(T(s.a_eq_m * sqrt((T(1) - z) * (T(1) + z))),
                                     T(s.a_eq_m * z / s.stretch));
}

/// Height on the ellipsoid from front = q.d, along = z.d and zp = z.P (the caller's fast path;
/// all three are linear in d). In the scaled space of MODEL §5 the line is P + t D, D = N d, and
/// the unit sphere is the surface; its closest approach to the centre is X = P + t* D, t* =
/// -front / |D|^2, |D|^2 = 1 + kappa along^2, with
///   |X|^2 - 1 = H - front^2 / |D|^2 = -g / |D|^2    (g of ellipsoid_horizon.hpp),
/// so |X| = 1 exactly where g = 0: the geometric crossing. Its scaled height eps = |X| - 1 maps
/// back along the surface normal at the tangent point a N^-1 X/|X|, where the real normal is
/// N X/|X N X| and the real offset a N^-1 (eps X/|X|): their product is
///   delta = a_eq eps / sqrt(1 + kappa zeta^2),  zeta = z . X / |X|;
/// the tangent point's latitude is WGS84's geodetic one (ellipsoid_point_latitude). front >= 0 (the
/// closest approach behind the satellite): X = P. A line through the centre (X = 0) takes the
/// sub-satellite point's direction P / |P|.
template <class T>
tangent_height<T> ellipsoid_tangent_height(const ellipsoid_surface<T>& s, const T& front,
                                           const T& along, const T& zp,
                                           bool with_latitude = true) noexcept {
  using std::sqrt;
  const ellipsoid_horizon<T>& e = s.horizon;
  T norm_x, zeta;
  if (front < T(0)) {
    const T d_squared = T(1) + e.kappa * along * along;
    const T t = -front / d_squared;
    // |X|^2 = 1 + H - front^2 / |D|^2, written as its parts to keep the digits near 1.
    const T excess = e.height - front * front / d_squared;
    const T norm_x_squared = T(1) + excess;
    norm_x = norm_x_squared > T(0) ? T(sqrt(norm_x_squared)) : T(0);
    const T z_x = zp + t * s.stretch * along;  // z . X, with z . D = s (z . d)
    zeta = norm_x > T(0) ? T(z_x / norm_x) : T(zp / s.norm_scaled_position);
    const T eps = norm_x > T(0) ? T(excess / (norm_x + T(1))) : T(-1);
    const T normal = sqrt(T(1) + e.kappa * zeta * zeta);
    return {T(s.a_eq_m * eps / normal), with_latitude ? ellipsoid_point_latitude(s, zeta) : T(0),
            status::ok};
  }
  norm_x = s.norm_scaled_position;
  zeta = zp / norm_x;
  const T eps = e.height / (norm_x + T(1));
  const T normal = sqrt(T(1) + e.kappa * zeta * zeta);
  return {T(s.a_eq_m * eps / normal), with_latitude ? ellipsoid_point_latitude(s, zeta) : T(0),
          status::ok};
}

/// The tangent height of the unit line of sight d (scan-frame components) above the ellipsoid,
/// MODEL §12, and the WGS84 geodetic latitude of its tangent point. Domain: s
/// ok, d finite; otherwise invalid. Accuracy: a few ulp of a_eq absolute near the limb (the
/// subtraction H - front^2/|D|^2); tests/core/test_sensor_physics.cpp checks it against a long
/// double evaluation of the definition and against the sphere for kappa = 0.
template <class T>
tangent_height<T> tangent_height_of(const ellipsoid_surface<T>& s, const vec3<T>& d) noexcept {
  const T nan = not_a_number<T>();
  if (s.state != status::ok || !is_finite(d.x) || !is_finite(d.y) || !is_finite(d.z))
    return {nan, nan, status::invalid};
  return ellipsoid_tangent_height(s, T(dot(s.horizon.q, d)), T(dot(s.horizon.polar, d)),
                                  T(dot(s.horizon.polar, s.scaled_position)));
}

/// The true line of sight at scan azimuth phi (MODEL §4) by the cosine and sine of phi and of its
/// angle psi from S, from the scan circle: with h = A . (cos phi, sin phi, 0) = sin sigma cos(phi -
/// phi_A), p = sin sigma sin(phi - phi_A), a = cos sigma, the corrected Eq. (1) gives
///   cos psi = (a cos gamma - h r) / (a^2 + h^2),  sin psi = (h cos gamma + a r) / (a^2 + h^2),
///   r = sqrt((sin gamma - |p|)(sin gamma + |p|))   (= sqrt(a^2 + h^2 - cos^2 gamma)).
template <class T>
struct scan_point {
  T cos_phi, sin_phi, cos_psi, sin_psi;
};

template <class T>
scan_point<T> scan_point_at(const scan_circle<T>& c, const T& phi) noexcept {
  using std::abs;
  using std::cos;
  using std::sin;
  using std::sqrt;
  const T cp = cos(phi), sp = sin(phi);
  const T h = c.axis.x * cp + c.axis.y * sp;
  const T p = abs(c.axis.y * cp - c.axis.x * sp);
  const T a = c.axis.z;
  T radicand = (c.sin_gamma - p) * (c.sin_gamma + p);
  if (radicand < T(0)) radicand = T(0);
  const T r = sqrt(radicand);
  const T r2 = a * a + h * h;
  return {cp, sp, T((a * c.cos_gamma - h * r) / r2), T((h * c.cos_gamma + a * r) / r2)};
}

/// v . d for the line of sight d at polar angle psi and azimuth phi (scan_point).
template <class T>
T line_of_sight_dot(const scan_point<T>& q, const vec3<T>& v) noexcept {
  const T h = v.x * q.cos_phi + v.y * q.sin_phi;
  return q.sin_psi * h + q.cos_psi * v.z;
}

/// The two directions a surface's height needs dot products with, and its constant term.
template <class T>
struct surface_probe {
  vec3<T> first, second;
  T constant;
};

template <class T>
surface_probe<T> probe_of(const sphere_surface<T>& s) noexcept {
  return {s.nadir, s.polar, T(dot(s.nadir, s.polar))};
}
template <class T>
surface_probe<T> probe_of(const ellipsoid_surface<T>& s) noexcept {
  return {s.horizon.q, s.horizon.polar, T(dot(s.horizon.polar, s.scaled_position))};
}
/// The unit direction from the satellite through the surface's centre: the one line whose
/// closest approach is the centre itself, where the tangent point's direction (and its latitude)
/// turns about the line (decision 2 of docs/SENSOR_PHYSICS.md: singular there, smooth in polar
/// coordinates about it).
template <class T>
vec3<T> centre_direction(const sphere_surface<T>& s) noexcept {
  return s.nadir;
}
template <class T>
vec3<T> centre_direction(const ellipsoid_surface<T>& s) noexcept {
  // X = P + t N d is 0 where N d is parallel to N p: d along -p, in the real space as well.
  return scaled(s.horizon.position, T(T(-1) / norm(s.horizon.position)));
}
template <class T>
tangent_height<T> height_from(const sphere_surface<T>& s, const T& a, const T& b, const T& k,
                              bool with_latitude = true) noexcept {
  return sphere_tangent_height(s, a, b, k, with_latitude);
}
template <class T>
tangent_height<T> height_from(const ellipsoid_surface<T>& s, const T& a, const T& b, const T& k,
                              bool with_latitude = true) noexcept {
  return ellipsoid_tangent_height(s, a, b, k, with_latitude);
}

/// The sign that makes a line's dot product with the surface's first probe positive where its
/// closest approach lies ahead of the satellite (the height's formula) and not positive where it
/// lies behind (the satellite's own height, flat in the direction: docs/SENSOR_PHYSICS.md,
/// decision 5): the sphere's c = d.n, the ellipsoid's -front = -q.d.
template <class T>
T ahead_sign(const sphere_surface<T>&) noexcept {
  return T(1);
}
template <class T>
T ahead_sign(const ellipsoid_surface<T>&) noexcept {
  return T(-1);
}

/// The exact height (and latitude, unless with_latitude is false: 0 then, as height_from) of the
/// true line of sight at scan azimuth phi.
template <class T, class Surface>
tangent_height<T> exact_height(const scan_circle<T>& circle, const Surface& surface,
                               const surface_probe<T>& probe, const T& phi,
                               bool with_latitude = true) noexcept {
  const scan_point<T> q = scan_point_at(circle, phi);
  return height_from(surface, line_of_sight_dot(q, probe.first), line_of_sight_dot(q, probe.second),
                     probe.constant, with_latitude);
}

}  // namespace conescan
