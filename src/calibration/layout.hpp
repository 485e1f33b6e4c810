// How a fit carries the parameters: the estimated coordinates, and the conversions between them
// and the named parameters of parameters.hpp.
//
// The values live in one array of slots laid out as the parameters are numbered (head k's seven
// at 7 k, the Earth's five after the heads), so that a measurement depends on 12 slots (its
// head's seven and the Earth's five: the 12 derivatives of a parameter_jet). The estimated
// coordinates are the free slots, a drifting slot (--free NAME@SECONDS) being one coordinate per
// segment of the telemetry; `coordinate(slot, t_s)` says which carries a slot for a measurement.
// Only a head's first two slots change meaning with the free set:
//   - sigma and phase both free: (x, y) = (sigma cos phi_A, sigma sin phi_A), "cartesian": the
//     misalignment is estimated as its two components, smooth at sigma = 0 where phi_A is
//     undefined (MODEL §11);
//   - otherwise (sigma, phi_A) themselves, "polar": only sigma free estimates a signed sigma
//     along the held phi_A (a negative estimate says the data prefer phi_A + 180 deg; it is not
//     clamped, which would bias it); only phase free estimates phi_A at the held sigma (with
//     sigma = 0 held, phi_A changes nothing and is reported unobservable).
// A held value stays where the parameter set put it.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "calibration/forward_model.hpp"
#include "calibration/parameters.hpp"

namespace conescan::calibration {

enum class misalignment_form : unsigned char { cartesian, polar };

struct estimation_layout {
  std::size_t head_count = 0;
  std::vector<misalignment_form> forms;  ///< per head
  std::vector<bool> free;                ///< per slot (= per parameter index)
  /// Per slot: 0 for a global value, else the length (s) of a drifting slot's segments; segment
  /// k covers [t0 + k L, t0 + (k + 1) L), t0 the first measurement's time, the last also
  /// everything after it.
  std::vector<double> segment_s;
  double t0_s = 0;
  std::vector<std::size_t> segments;  ///< per slot: its number of values (1 unless drifting)
  /// The estimated coordinates, in order: each free slot's value, or each segment's value of a
  /// drifting one (a drifting cartesian pair interleaved: x and y of segment 0, of segment 1,
  /// ..., so that a segment's x and y are neighbours as a global pair's are).
  std::vector<std::size_t> coordinates;          ///< the slot of each
  std::vector<std::size_t> coordinate_segment;   ///< its segment (0 for a global slot)
  std::vector<std::ptrdiff_t> first_coordinate;  ///< per slot: its first coordinate, -1 if held
  std::vector<std::size_t> stride;  ///< per slot: from one segment's coordinate to the next

  /// The number of segments of segment_s seconds that cover [t_first_s, t_last_s]: at least one,
  /// the last closed at t_last_s (a span of exactly n segments is n, not n and a segment of
  /// one row). In double: a fit refuses counts beyond its bound before making them.
  static double segment_count(double t_first_s, double t_last_s, double segment_s) noexcept {
    return std::max(1.0, std::ceil((t_last_s - t_first_s) / segment_s));
  }
  double t_last_s = 0;  ///< the end of the last segment (the last measurement's time)

  /// The layout of a parameter set for measurements at times in [t_first_s, t_last_s]:
  /// cartesian for a head whose sigma and phase are both free.
  static estimation_layout of(const parameter_set& parameters, double t_first_s = 0,
                              double t_last_s = 0);
  /// Where head k's block starts; the Earth's block starts at earth_block().
  static constexpr std::size_t head_block(std::size_t head) noexcept {
    return head_parameter_count * head;
  }
  std::size_t earth_block() const noexcept { return head_parameter_count * head_count; }
  bool drifts(std::size_t slot) const noexcept { return segment_s[slot] > 0; }

  /// The segment of a drifting slot that holds t_s.
  std::size_t segment_of(std::size_t slot, double t_s) const noexcept {
    const double k = std::floor((t_s - t0_s) / segment_s[slot]);
    if (!(k > 0)) return 0;
    return std::min(segments[slot] - 1, static_cast<std::size_t>(std::min(k, 1e18)));
  }
  /// The coordinate that carries `slot` for a measurement at t_s, or -1 when the slot is held.
  std::ptrdiff_t coordinate(std::size_t slot, double t_s) const noexcept {
    const std::ptrdiff_t first = first_coordinate[slot];
    if (first < 0 || !drifts(slot)) return first;
    return first + static_cast<std::ptrdiff_t>(stride[slot] * segment_of(slot, t_s));
  }
};

/// The name of coordinate slot `slot`: the parameter's name, or for a cartesian head's first two
/// slots "hK.misalign-x" (sigma cos phi_A) and "hK.misalign-y" (sigma sin phi_A).
std::string slot_name(const estimation_layout& layout, std::size_t slot);

/// The slot values of a parameter set (x, y from sigma, phi_A for a cartesian head).
std::vector<double> slots_from_parameters(const estimation_layout& layout,
                                          const parameter_set& parameters);
/// The name of coordinate i: slot_name, and "[k]" after it for segment k of a drifting slot.
std::string coordinate_name(const estimation_layout& layout, std::size_t i);

/// What a coordinate estimates, addressed by (head, parameter) rather than by its name: the slot
/// it carries (a parameter index, parameters.hpp: head k's parameter p at parameter_index(k, p),
/// the Earth's after every head's), its segment when the slot drifts, and whether it is a
/// cartesian head's misalignment component (x in the sigma slot, y in the phase slot).
struct coordinate_key {
  std::size_t slot = 0;
  std::optional<std::size_t> segment;  ///< a drifting slot's segment; none for a global value
  bool cartesian = false;
  friend bool operator==(const coordinate_key&, const coordinate_key&) = default;
};

/// The key of coordinate i.
coordinate_key coordinate_key_of(const estimation_layout& layout, std::size_t i);

/// The coordinates' values of slot values (every segment at its slot's value), and the slot
/// values with the coordinates put in (a drifting slot takes its first segment's value).
std::vector<double> coordinates_from_slots(const estimation_layout& layout,
                                           const std::vector<double>& slots);
std::vector<double> slots_with_coordinates(const estimation_layout& layout,
                                           std::vector<double> slots,
                                           const std::vector<double>& coordinates);

/// The parameter values of slot values: sigma = hypot(x, y), phi_A = atan2(y, x) for a cartesian
/// head (phi_A = 0 at sigma = 0); a free phi_A wrapped into (-180, 180] deg, a held one as given.
std::vector<double> parameters_from_slots(const estimation_layout& layout,
                                          const std::vector<double>& slots);

/// An angle in degrees wrapped into (-180, 180].
double wrap_deg(double angle_deg);

inline constexpr double radians_per_degree = std::numbers::pi / 180;

/// The model parameters of a head from its block of slot values (head_parameter's order).
template <class T>
head_geometry<T> head_geometry_of(const T* block, misalignment_form form) {
  using std::cos;
  using std::sin;
  constexpr auto tau = static_cast<std::size_t>(head_parameter::tau_ms);
  constexpr auto threshold = static_cast<std::size_t>(head_parameter::threshold);
  if (form == misalignment_form::cartesian)
    return {{block[0], block[1], block[2]}, block[tau], block[threshold]};
  const T phase_rad = block[1] * radians_per_degree;
  return {{T(block[0] * cos(phase_rad)), T(block[0] * sin(phase_rad)), block[2]},
          block[tau],
          block[threshold]};
}

/// The Earth's parameters from its block of slot values (earth_parameter's order).
template <class T>
earth_geometry<T> earth_geometry_of(const T* block) {
  return {block[0], block[1], block[2], block[3], block[4]};
}

}  // namespace conescan::calibration

namespace conescan::calibration {

/// Head k's geometry parameters from named parameter values (sigma, phi_A to components): what
/// a model is given for a parameter set, e.g. to simulate or to correct with a fit's estimates.
inline head_geometry<double> head_geometry_of(const parameter_set& parameters, std::size_t head) {
  const double sigma = parameters.values[parameter_index(head, head_parameter::sigma)];
  const double phase_rad =
      parameters.values[parameter_index(head, head_parameter::phase)] * radians_per_degree;
  return {{sigma * std::cos(phase_rad), sigma * std::sin(phase_rad),
           parameters.values[parameter_index(head, head_parameter::dgamma)]},
          parameters.values[parameter_index(head, head_parameter::tau_ms)],
          parameters.values[parameter_index(head, head_parameter::threshold)]};
}

/// The Earth's geometry parameters from named parameter values.
inline earth_geometry<double> earth_geometry_of(const parameter_set& parameters) {
  return earth_geometry_of(
      &parameters.values[parameter_index(parameters.head_count, earth_parameter::horizon)]);
}

}  // namespace conescan::calibration
