// Sweeps: one scene option run over a range of values (SPEC §9, --sweep NAME=FROM:TO:STEP).
#pragma once

#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "scene/scene_config.hpp"

namespace conescan::scene {

struct sweep_spec {
  std::string name;  ///< a numeric scene option's long name (e.g. "e", "a-km") or "hK.key"
  double from;
  double to;
  double step;
  int decimals;  ///< decimals of FROM and STEP as typed: the values are rounded to them
};

/// Parses NAME=FROM:TO:STEP (STEP > 0, TO >= FROM, all finite). The NAME is checked by
/// apply_sweep_value. Returns the spec or a message saying what is wrong.
std::variant<sweep_spec, std::string> parse_sweep(std::string_view text);

/// FROM + j STEP for j = 0, 1, ... while it does not exceed TO by more than 1e-9 STEP; each value
/// rounded to the typed decimals, so 0:0.1:0.025 gives 0, 0.025, 0.05, 0.075, 0.1 exactly as
/// typed, not 0.07500000000000001.
std::vector<double> sweep_values(const sweep_spec& spec);

/// Sets option `name` of the scene to `value`. Names: a-km, e, i-deg, raan-deg, argp-deg, m0-deg,
/// step-s, orbits, duration-s, radius-km, horizon-km, processing-radius (km), roll-deg,
/// pitch-deg, yaw-deg, and hK.alpha|beta|gamma|sigma|phase for head K (1-based). Returns an
/// empty string, or a message naming the allowed names.
std::string apply_sweep_value(scene_config& scene, const std::string& name, double value);

}  // namespace conescan::scene
