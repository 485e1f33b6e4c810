// The half chord Phi: half the scan azimuth that a cone of half-angle psi about the spin axis
// spends on a spherical Earth disk of angular radius rho whose centre (the nadir) lies eta from
// the spin axis. MODEL §5; paper Eqs. (3) and (5).
#pragma once

#include "conescan/status.hpp"

namespace conescan {

/// Smallest half chord accepted as a measurement: 0.1 deg (a chord of 0.2 deg). Below it (or
/// above pi minus it) the crossing azimuths lose their conditioning: an error e in cos Phi moves
/// Phi by e / sin Phi, so at 0.1 deg double keeps ~13 digits and float ~2. A chord this short
/// or this close to a full turn is status grazing (MODEL §7).
template <class T>
T grazing_half_chord_min() noexcept {
  return deg_to_rad(T(1) / T(10));
}

/// ok, or grazing for a half chord within grazing_half_chord_min() of 0 or pi.
template <class T>
status classify_half_chord(const T& half_chord) noexcept {
  if (!is_finite(half_chord)) return status::invalid;
  if (half_chord < grazing_half_chord_min<T>() ||
      half_chord > pi<T>() - grazing_half_chord_min<T>())
    return status::grazing;
  return status::ok;
}

/// Domain of the forward geometry: psi in (0, pi), eta in [0, pi], rho in (0, pi/2], all finite.
template <class T>
bool disk_geometry_in_domain(const T& psi, const T& eta, const T& rho) noexcept {
  return is_finite(psi) && is_finite(eta) && is_finite(rho) && psi > T(0) && psi < pi<T>() &&
         eta >= T(0) && eta <= pi<T>() && rho > T(0) && rho <= pi<T>() / T(2);
}

/// Phi from the half-angle form of Eq. (3) (MODEL §5):
///   sin^2(Phi/2) = sin((rho+psi-eta)/2) sin((rho-psi+eta)/2) / (sin psi sin eta)
///   cos^2(Phi/2) = sin((psi+eta+rho)/2) sin((psi+eta-rho)/2) / (sin psi sin eta)
/// so Phi = 2 atan2(sqrt(P1), sqrt(P2)) with the common denominator cancelled. Unlike
/// acos((cos rho - cos psi cos eta) / (sin psi sin eta)) it has no cancellation near Phi = 0 or
/// pi and no division by sin eta, and the signs of P1, P2 decide the statuses exactly:
///   P1 <= 0: the nearest point of the cone is off the disk (|psi - eta| >= rho): miss;
///   P2 <= 0: the farthest point is on the disk: engulfed;
///   Phi within grazing_half_chord_min() of 0 or pi: grazing.
/// Domain: disk_geometry_in_domain; otherwise invalid. Accuracy: a few ulp of Phi on the domain
/// (measured: docs/ACCURACY.md).
template <class T>
result<T> half_chord(const T& psi, const T& eta, const T& rho) noexcept {
  using std::atan2;
  using std::sin;
  using std::sqrt;
  if (!disk_geometry_in_domain(psi, eta, rho)) return result<T>::bad(status::invalid);
  T p1 = sin((rho + psi - eta) / T(2)) * sin((rho - psi + eta) / T(2));
  T p2 = sin((psi + eta + rho) / T(2)) * sin((psi + eta - rho) / T(2));
  if (p1 <= T(0)) return result<T>::bad(status::miss);
  if (p2 <= T(0)) return result<T>::bad(status::engulfed);
  T phi = T(2) * atan2(sqrt(p1), sqrt(p2));
  status s = classify_half_chord(phi);
  return s == status::ok ? result<T>::good(phi) : result<T>::bad(s);
}

/// Phi from the paper's Eq. (3) as printed: acos((cos rho - cos psi cos eta) / (sin psi sin eta)).
/// Kept to measure against half_chord(): it loses digits near Phi = 0 and pi (acos near +-1) and
/// as eta -> 0. Same domain and statuses.
template <class T>
result<T> half_chord_acos(const T& psi, const T& eta, const T& rho) noexcept {
  using std::acos;
  using std::cos;
  using std::sin;
  if (!disk_geometry_in_domain(psi, eta, rho)) return result<T>::bad(status::invalid);
  T numerator = cos(rho) - cos(psi) * cos(eta);
  T denominator = sin(psi) * sin(eta);
  if (numerator >= denominator) return result<T>::bad(status::miss);
  if (numerator <= -denominator) return result<T>::bad(status::engulfed);
  T phi = acos(numerator / denominator);
  status s = classify_half_chord(phi);
  return s == status::ok ? result<T>::good(phi) : result<T>::bad(s);
}

}  // namespace conescan
