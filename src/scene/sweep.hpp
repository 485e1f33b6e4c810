// Sweeps: one scene option run over a range of values (MODEL §9, --sweep NAME=FROM:TO:STEP).
//
// The values are counted when the sweep is read, and computed one at a time when they are used:
// a sweep's work and memory are known before any is spent (scene_plan checks the count and the
// rows against --max-rows, then validates every value without storing the scenes).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "text/diagnostic.hpp"

namespace conescan::scene {

struct sweep_spec {
  std::string text;  ///< NAME=FROM:TO:STEP as typed (--print-config writes it back)
  std::string name;  ///< the swept option's long name (e.g. "e", "a-km") or "hK.key"
  double from = 0;
  double to = 0;
  double step = 0;
  int decimals = -1;        ///< decimals of FROM and STEP as typed: the values are rounded to
                            ///< them; -1: not rounded (more than 30 decimals)
  std::uint64_t count = 0;  ///< number of values, >= 1
};

/// Most values a sweep may have, whatever --max-rows allows: j STEP must stay exact in a double.
inline constexpr std::uint64_t max_sweep_values = std::uint64_t(1) << 53;

/// Parses NAME=FROM:TO:STEP: FROM, TO, STEP by text::parse_real (number_text.hpp), STEP > 0,
/// TO >= FROM, and counts the values: FROM + j STEP for j = 0, 1, ... while it does not exceed
/// TO by more than 1e-9 STEP, at most max_sweep_values. The NAME is checked against the option
/// table by the caller. On failure the error holds only the message.
checked<sweep_spec> parse_sweep(std::string_view text);

/// Value j (0-based, j < count): FROM + j STEP rounded to the typed decimals, so 0:0.1:0.025
/// gives 0, 0.025, 0.05, 0.075, 0.1 exactly as typed, not 0.07500000000000001.
double sweep_value(const sweep_spec& spec, std::uint64_t j);

}  // namespace conescan::scene
