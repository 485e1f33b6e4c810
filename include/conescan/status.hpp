// Statuses of MODEL §7 and the result type that carries them.
#pragma once

#include <array>
#include <cstddef>

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

/// Every status, in the enum's order: all_statuses[i] is status(i).
inline constexpr std::array<status, 12> all_statuses{
    status::ok,       status::miss, status::engulfed,  status::grazing,
    status::multiple, status::fold, status::ambiguous, status::gimbal,
    status::sun,      status::moon, status::invalid,   status::none};

/// Number of statuses: the size of any table indexed by one (status_index).
inline constexpr std::size_t status_count = all_statuses.size();

/// A status as a table index in [0, status_count).
constexpr std::size_t status_index(status s) noexcept {
  return static_cast<std::size_t>(s);
}

/// The CSV spelling of a status (MODEL §9); nullptr for a value outside the enum.
constexpr const char* to_string(status s) noexcept {
  switch (s) {
    case status::ok:
      return "ok";
    case status::miss:
      return "miss";
    case status::engulfed:
      return "engulfed";
    case status::grazing:
      return "grazing";
    case status::multiple:
      return "multiple";
    case status::fold:
      return "fold";
    case status::ambiguous:
      return "ambiguous";
    case status::gimbal:
      return "gimbal";
    case status::sun:
      return "sun";
    case status::moon:
      return "moon";
    case status::invalid:
      return "invalid";
    case status::none:
      return "none";
  }
  return nullptr;
}

// The switch above names every enumerator (-Wswitch, an error in the project's builds), so a new
// status needs its spelling there; these checks then need it in all_statuses, in order.
namespace status_layout {
constexpr bool all_in_order() noexcept {
  for (std::size_t i = 0; i < status_count; ++i)
    if (status_index(all_statuses[i]) != i || to_string(all_statuses[i]) == nullptr) return false;
  return true;
}
static_assert(all_in_order(), "all_statuses must list the statuses in the enum's order");
static_assert(to_string(static_cast<status>(status_count)) == nullptr,
              "a status is missing from all_statuses");
}  // namespace status_layout

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
