// The core's result types as Python sees them: each a named tuple of arrays, one per field, named
// as the C++ members (state is spelled status). A new core result type needs one entry here.
#pragma once

#include <tuple>

#include "conescan/conescan.hpp"
#include "vectorize.hpp"

namespace conescan::python {

/// Rows e1, e2, e3 of a scan frame.
inline matrix3 rows_of(const scan_frame<double>& f) noexcept {
  return {{{f.e1.x, f.e1.y, f.e1.z}, {f.e2.x, f.e2.y, f.e2.z}, {f.e3.x, f.e3.y, f.e3.z}}};
}

/// A column-major GLM matrix (c[col][row]) as NumPy's row-major m[row][col], so that m @ v in
/// NumPy is apply(c, v) in C++.
inline matrix3 rows_of(const mat3<double>& c) noexcept {
  return {{{c[0][0], c[1][0], c[2][0]}, {c[0][1], c[1][1], c[2][1]}, {c[0][2], c[1][2], c[2][2]}}};
}

template <>
struct result_fields<result<double>> {
  static constexpr const char* type_name = "result";
  static auto fields() {
    return std::make_tuple(field{"value", &result<double>::value},
                           field{"status", &result<double>::state});
  }
};

template <>
struct result_fields<crossings<double>> {
  static constexpr const char* type_name = "crossings";
  static auto fields() {
    return std::make_tuple(field{"phi_in", &crossings<double>::phi_in},
                           field{"phi_out", &crossings<double>::phi_out},
                           field{"status", &crossings<double>::state},
                           field{"iterations", &crossings<double>::iterations});
  }
};

template <>
struct result_fields<nadir_angle_roots<double>> {
  static constexpr const char* type_name = "nadir_angle_roots";
  static auto fields() {
    using roots = nadir_angle_roots<double>;
    return std::make_tuple(field{"plus", &roots::plus}, field{"minus", &roots::minus},
                           field{"half_separation", &roots::half_separation},
                           field{"status", &roots::state});
  }
};

template <>
struct result_fields<scan_frame<double>> {
  static constexpr const char* type_name = "scan_frame";
  static auto fields() {
    return std::make_tuple(field{"frame", [](const scan_frame<double>& f) { return rows_of(f); }},
                           field{"status", &scan_frame<double>::state});
  }
};

template <>
struct result_fields<scan_angles<double>> {
  static constexpr const char* type_name = "scan_angles";
  static auto fields() {
    return std::make_tuple(field{"polar", &scan_angles<double>::polar},
                           field{"azimuth", &scan_angles<double>::azimuth});
  }
};

template <>
struct result_fields<head_estimate<double>> {
  static constexpr const char* type_name = "head_estimate";
  static auto fields() {
    return std::make_tuple(field{"eta_s", &head_estimate<double>::eta_s},
                           field{"nadir", &head_estimate<double>::nadir},
                           field{"status", &head_estimate<double>::state});
  }
};

template <>
struct result_fields<roll_pitch<double>> {
  static constexpr const char* type_name = "roll_pitch";
  static auto fields() {
    return std::make_tuple(field{"roll", &roll_pitch<double>::roll},
                           field{"pitch", &roll_pitch<double>::pitch});
  }
};

}  // namespace conescan::python
