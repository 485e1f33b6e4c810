// Statuses of MODEL §7 and the result type that carries them.
#pragma once

#include <array>
#include <cstddef>

#include "conescan/enum_names.hpp"
#include "conescan/scalar.hpp"

namespace conescan {

/// Why a method could (not) produce a value. MODEL §7. The values are 0, 1, ... in this order,
/// which all_statuses repeats (a table indexed by a status has status_count entries).
enum class status : unsigned char {
  ok,         ///< the value is valid
  miss,       ///< the scan cone does not reach the Earth (no crossing)
  engulfed,   ///< the whole scan cone lies on the Earth (no crossing)
  grazing,    ///< chord near 0 or 360 deg: crossing azimuths are ill-conditioned
  multiple,   ///< the scan cuts the horizon four times (two arcs on the Earth): no one chord
  fold,       ///< the chord inversion's two roots merge: the chord no longer determines eta
  ambiguous,  ///< both inversion roots lie within the attitude envelope of eta0
  gimbal,     ///< true pitch within 1.91 deg of +-90 deg: roll undefined (MODEL §7)
  sun,        ///< the Sun's pulse meets the Earth pulse: the crossings are lost (MODEL §13)
  moon,       ///< the Moon's pulse meets the Earth pulse (MODEL §13)
  invalid,    ///< an input lies outside the model's domain
  none,       ///< system solution: no head is ok
};

/// Every status with its CSV spelling (MODEL §9), in the enum's order: status_names[i] names
/// status(i). A new status goes before `none` (the enum's last) and here, in order.
inline constexpr enum_names<status, 12> status_names{{{status::ok, "ok"},
                                                      {status::miss, "miss"},
                                                      {status::engulfed, "engulfed"},
                                                      {status::grazing, "grazing"},
                                                      {status::multiple, "multiple"},
                                                      {status::fold, "fold"},
                                                      {status::ambiguous, "ambiguous"},
                                                      {status::gimbal, "gimbal"},
                                                      {status::sun, "sun"},
                                                      {status::moon, "moon"},
                                                      {status::invalid, "invalid"},
                                                      {status::none, "none"}}};
static_assert(in_enum_order(status_names) &&
                  static_cast<std::size_t>(status::none) + 1 == status_names.size(),
              "status_names must name every status, in the enum's order");

/// Number of statuses: the size of any table indexed by one (status_index).
inline constexpr std::size_t status_count = status_names.size();

/// Every status, in the enum's order: all_statuses[i] is status(i).
inline constexpr std::array<status, status_count> all_statuses = [] {
  std::array<status, status_count> all{};
  for (std::size_t i = 0; i < status_count; ++i) all[i] = status_names[i].value;
  return all;
}();

/// A status as a table index in [0, status_count).
constexpr std::size_t status_index(status s) noexcept {
  return static_cast<std::size_t>(s);
}

/// The CSV spelling of a status (MODEL §9); nullptr for a value outside the enum.
constexpr const char* to_string(status s) noexcept {
  return name_of(status_names, s);
}

/// A value with its status. On any status but ok the value is NaN.
template <class T>
struct [[nodiscard]] result {
  T value;
  status state;

  bool ok() const noexcept { return state == status::ok; }

  static result good(const T& v) noexcept { return {v, status::ok}; }
  static result bad(status s) noexcept { return {not_a_number<T>(), s}; }
};

}  // namespace conescan
