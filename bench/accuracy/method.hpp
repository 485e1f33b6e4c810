// The head pipelines that the benchmark and the accuracy tests compare (docs/PERFORMANCE.md,
// docs/ACCURACY.md). A method is a forward model plus a processing, end to end for one head.
#pragma once

#include <array>
#include <string_view>

#include "conescan/enum_names.hpp"

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

/// Every method with its name in the CSV files and charts, in the enum's order.
inline constexpr enum_names<method, 7> method_names{
    {{method::paper_quadratic, "paper-quadratic"},
     {method::stable_closed_form, "stable-closed-form"},
     {method::scan_sphere, "scan-sphere"},
     {method::scan_sphere_iterative, "scan-sphere-iterative"},
     {method::scan_ellipsoid, "scan-ellipsoid"},
     {method::scan_ellipsoid_iterative, "scan-ellipsoid-iterative"},
     {method::scan_ellipsoid_quartic, "scan-ellipsoid-quartic"}}};
static_assert(in_enum_order(method_names) &&
                  static_cast<std::size_t>(method::scan_ellipsoid_quartic) + 1 ==
                      method_names.size(),
              "method_names must name every method, in the enum's order");

inline constexpr std::array<method, method_names.size()> all_methods = [] {
  std::array<method, method_names.size()> all{};
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = method_names[i].value;
  return all;
}();

/// The method's name in the CSV files and charts.
constexpr std::string_view method_name(method m) noexcept {
  return name_of(method_names, m, "unknown");
}

}  // namespace conescan::accuracy
