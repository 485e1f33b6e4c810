// Statuses of SPEC §7 and the result type that carries them.
#pragma once

#include "conescan/scalar.hpp"

namespace conescan {

/// Why a method could (not) produce a value. SPEC §7.
enum class status : unsigned char {
  ok,        ///< the value is valid
  miss,      ///< the scan cone does not reach the Earth (no crossing)
  engulfed,  ///< the whole scan cone lies on the Earth (no crossing)
  grazing,   ///< chord near 0 or 360 deg: crossing azimuths are ill-conditioned
  fold,      ///< the chord inversion's two roots merge: the chord no longer determines eta
  invalid,   ///< an input lies outside the model's domain
  none,      ///< system solution: no head is ok
};

/// The CSV spelling of a status (SPEC §9).
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
    case status::fold:
      return "fold";
    case status::invalid:
      return "invalid";
    case status::none:
      return "none";
  }
  return "invalid";
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
