// The text form of a sensor head: "alpha=..,beta=..,gamma=..,sigma=..,phase=.." (degrees; SPEC §9),
// plus the detector's "noise=.." (1 sigma per crossing) and "lsb=.." (telemetry step), issue 7.
#pragma once

#include <string>
#include <string_view>
#include <variant>

#include "scene/scene_config.hpp"

namespace conescan::scene {

/// Parses a head spec. Keys may come in any order and each at most once; a key left out keeps
/// the paper's value (head_config's default). Values are decimal numbers read with
/// std::from_chars (locale-independent, the whole value must be a number). Returns the head or a
/// message naming the offending key or text. Domain checks (alpha, gamma, sigma ranges) are
/// validate()'s, so a scene file and the command line report them alike.
std::variant<head_config, std::string> parse_head_spec(std::string_view spec);

/// True for a key of a head spec (alpha, beta, gamma, sigma, phase, noise, lsb).
bool is_head_key(std::string_view name);

/// The keys, for messages: "alpha, beta, ... (degrees)".
const char* head_keys_text();

/// The canonical text of a head, round-trip exact (the inverse of parse_head_spec).
std::string format_head_spec(const head_config& head);

}  // namespace conescan::scene
