// The head pipelines that the benchmark and the accuracy tests compare (docs/PERFORMANCE.md,
// docs/ACCURACY.md). A method is a forward model plus a processing, end to end for one head.
#pragma once

#include <array>
#include <string_view>

namespace conescan::accuracy {

enum class method {
  /// The paper's printed forms: Eq. (1) quadratic for psi, Eq. (3) with acos for the half chord,
  /// Eq. (6) quadratic ('+' root) for eta_s (MODEL §4-§6; square roots restored).
  paper_quadratic,
  /// The stable closed forms: misaligned_cone_angle, half_chord, nadir_angle_from_chord (bias
  /// model, MODEL §5; processing, MODEL §6).
  stable_closed_form,
  /// The scan model on a sphere in closed form (MODEL §5: the scan circle about A meets the
  /// horizon circle) with the stable processing.
  scan_sphere,
  /// The same by bracketed Newton on the scan azimuth (the method before the closed form).
  scan_sphere_iterative,
  /// The scan model on the inflated WGS84 ellipsoid (Newton on the scan circle from the sphere)
  /// with the stable processing on the equatorial sphere (MODEL §5, §6).
  scan_ellipsoid,
  /// The same by bracketed Newton on the scan azimuth.
  scan_ellipsoid_iterative,
  /// The same by solving the quartic in tan(theta / 2) (accuracy/quartic_crossings.hpp).
  scan_ellipsoid_quartic,
};

inline constexpr std::array<method, 7> all_methods{
    method::paper_quadratic,       method::stable_closed_form, method::scan_sphere,
    method::scan_sphere_iterative, method::scan_ellipsoid,     method::scan_ellipsoid_iterative,
    method::scan_ellipsoid_quartic};

/// The method's name in the CSV files and charts.
constexpr std::string_view method_name(method m) noexcept {
  switch (m) {
    case method::paper_quadratic:
      return "paper-quadratic";
    case method::stable_closed_form:
      return "stable-closed-form";
    case method::scan_sphere:
      return "scan-sphere";
    case method::scan_sphere_iterative:
      return "scan-sphere-iterative";
    case method::scan_ellipsoid:
      return "scan-ellipsoid";
    case method::scan_ellipsoid_iterative:
      return "scan-ellipsoid-iterative";
    case method::scan_ellipsoid_quartic:
      return "scan-ellipsoid-quartic";
  }
  return "unknown";
}

}  // namespace conescan::accuracy
