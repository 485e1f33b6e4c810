// The parameters a calibration estimates or holds (MODEL §11), their names and units, and the
// --free list that chooses them.
//
// Per head K (1-based in names): hK.sigma (the misalignment sigma, deg), hK.phase (its azimuth
// phi_A, deg), hK.dgamma (a cone-angle bias: the true half-apex angle is gamma + dgamma, deg),
// hK.bias-in and hK.bias-out (crossing-angle biases: each measured crossing azimuth is the true
// one plus its bias, deg), and the sensor physics of MODEL §12: hK.tau-ms (the detector's time
// constant, ms) and hK.threshold (the locator's threshold: a fixed locator's level in units of the
// limb's plateau L0, a normalised one's fraction of the peak). For the Earth: horizon-km (the
// horizon height h0), horizon-pole-km (the apparent horizon's pole term) and horizon-shift-km (its
// season term), radiance-offset-km (the limb's 50 % height above the horizon surface) and
// radiance-scale-km (its scale height H), as the scene options and head keys of the same names
// define them. One table below holds the names and units; parsing, reports and the fit's files
// all read it.
//
// The physics parameters exist where the scene runs MODEL §12's chain: a head's tau-ms and
// threshold when that head does, the limb's when any head does (scene_physics.hpp's physics_on).
// Elsewhere their value is NaN (physics_absent), they are held, and reports and the fit's JSON
// leave them out: a fit without the physics reads and writes as before.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "text/diagnostic.hpp"

namespace conescan::calibration {

/// A head's parameters, in the order of names, reports and a head's block of estimated values.
enum class head_parameter : unsigned char {
  sigma,
  phase,
  dgamma,
  bias_in,
  bias_out,
  tau_ms,
  threshold
};
/// The Earth's parameters, after every head's.
enum class earth_parameter : unsigned char {
  horizon,
  horizon_pole,
  horizon_shift,
  radiance_offset,
  radiance_scale
};

inline constexpr std::size_t head_parameter_count = 7;
inline constexpr std::size_t earth_parameter_count = 5;

/// A parameter's name (without "hK." for a head's) and unit ("deg" or "km").
struct parameter_spec {
  std::string_view key;
  std::string_view unit;
};

/// The table of names and units, in enum order.
inline constexpr std::array<parameter_spec, head_parameter_count> head_parameter_specs{{
    {"sigma", "deg"},
    {"phase", "deg"},
    {"dgamma", "deg"},
    {"bias-in", "deg"},
    {"bias-out", "deg"},
    {"tau-ms", "ms"},
    {"threshold", "1"},
}};
inline constexpr std::array<parameter_spec, earth_parameter_count> earth_parameter_specs{{
    {"horizon-km", "km"},
    {"horizon-pole-km", "km"},
    {"horizon-shift-km", "km"},
    {"radiance-offset-km", "km"},
    {"radiance-scale-km", "km"},
}};

/// Parameters are numbered 0 .. 7 K + 4: head k's (0-based) at 7 k + its head_parameter, then
/// the Earth's at 7 K + its earth_parameter.
constexpr std::size_t parameter_count(std::size_t head_count) noexcept {
  return head_parameter_count * head_count + earth_parameter_count;
}
constexpr std::size_t parameter_index(std::size_t head, head_parameter p) noexcept {
  return head_parameter_count * head + static_cast<std::size_t>(p);
}
constexpr std::size_t parameter_index(std::size_t head_count, earth_parameter p) noexcept {
  return head_parameter_count * head_count + static_cast<std::size_t>(p);
}

/// "h2.dgamma", "horizon-km": the name of parameter `index` of a scene with head_count heads.
std::string parameter_name(std::size_t index, std::size_t head_count);
/// "deg", "km", "ms" or "1".
std::string_view parameter_unit(std::size_t index, std::size_t head_count);

/// True for the sensor physics' parameters (hK.tau-ms, hK.threshold, radiance-offset-km,
/// radiance-scale-km).
bool is_physics_parameter(std::size_t index, std::size_t head_count);

/// True when a physics parameter does not exist in the scene (its value NaN: the file comment).
bool physics_absent(std::size_t index, std::size_t head_count, double value);

/// Every parameter's value (in its unit) and whether the fit frees it: the start of a fit (the
/// scene's nominal values) and the values of those it holds.
struct parameter_set {
  std::size_t head_count = 0;
  std::vector<double> values;  ///< parameter_count(head_count), by parameter_index
  std::vector<bool> free;      ///< the same length
  /// The same length: 0 for a global parameter (one value for the whole telemetry), else the
  /// length (s) of the segments a drifting parameter takes one value in (parse_free_selection).
  std::vector<double> segment_s;

  /// All values 0 and held.
  static parameter_set nominal(std::size_t head_count);
  double& value(std::size_t head, head_parameter p) { return values[parameter_index(head, p)]; }
  double& value(earth_parameter p) { return values[parameter_index(head_count, p)]; }
  bool any_free() const;
};

/// A parameter name read without knowing the scene: a head's (0-based head, key) or the Earth's.
struct parsed_name {
  bool is_head = false;
  std::size_t head = 0;  ///< 0-based; meaningful when is_head
  head_parameter head_key = head_parameter::sigma;
  earth_parameter earth_key = earth_parameter::horizon;
};

/// Reads one parameter name ("h1.sigma", "horizon-km"). Heads are numbered from 1, in decimal
/// digits without a leading zero. The error holds only the message (the caller names the option
/// or file): an unknown name, with the names allowed.
checked<parsed_name> parse_parameter_name(std::string_view name);

/// A parameter of --free: its index, and for a drifting one the length of its segments (s).
struct free_parameter {
  std::size_t index = 0;
  double segment_s = 0;  ///< 0: global
};

/// The parameters --free LIST names, in the list's order: comma-separated items, no spaces,
/// each a name or NAME@SECONDS (a drifting parameter: one value per SECONDS of telemetry from its
/// first time, the others global; any parameter, any length). Errors (option "free", quoting the
/// token): an empty list, an empty item, an unknown name, a head beyond the scene's head_count,
/// a name given twice, a segment length that is not a number > 0 (at most 1e12 s), a head whose
/// sigma and phase are both free but drift differently (they are estimated as one pair of
/// components: both @ the same SECONDS, or neither).
checked<std::vector<free_parameter>> parse_free_selection(std::string_view list,
                                                          std::size_t head_count);

/// The parameters --free LIST names, as indices, without drifting ones (a NAME@SECONDS item is
/// refused: "drifting parameters are conescan-fit's"); otherwise as parse_free_selection.
checked<std::vector<std::size_t>> parse_free_list(std::string_view list, std::size_t head_count);

/// The parameter set with `free` freed (and their segment lengths set).
void free_parameters(parameter_set& parameters, const std::vector<free_parameter>& free);

/// Every allowed name, for messages: "hK.sigma, hK.phase, ... (K = 1..N), horizon-km, ...".
std::string allowed_parameter_names(std::size_t head_count);

}  // namespace conescan::calibration
