// The text form of a sensor head: "alpha=..,beta=..,gamma=..,sigma=..,phase=.." (degrees; MODEL
// §9), plus the detector's "noise=.." (1 sigma per crossing) and "lsb=.." (telemetry step), and the
// fixed biases a calibration estimates, "dgamma=..", "bias-in=..", "bias-out=.." (issue 15).
#pragma once

#include <string>
#include <string_view>

#include "scene/scene_config.hpp"
#include "text/diagnostic.hpp"

namespace conescan::scene {

/// Parses a head spec: key=value items separated by commas (blanks around ',' and '=' are
/// allowed). Keys may come in any order and each at most once; a key left out keeps the
/// paper's value (head_config's default). Values go through text::parse_real (number_text.hpp), the
/// parser of every number. Domain checks (alpha, gamma, sigma ranges) are validate()'s, so a
/// scene file and the command line report them alike; but a gamma given at or below the
/// default sigma (0.02) that was not given is refused here, naming gamma, which the user typed.
/// On failure the error holds only the message (the caller names the option and origin).
checked<head_config> parse_head_spec(std::string_view spec);

/// The field of head key `key` (alpha, beta, ..., bias-out), or nullptr.
double* head_key_field(head_config& head, std::string_view key);

/// True for a key of a head spec.
bool is_head_key(std::string_view key);

/// The keys, for messages: "alpha, beta, ... (degrees)".
const char* head_keys_text();

/// The canonical text of a head, every key, round-trip exact (the inverse of parse_head_spec).
std::string format_head_spec(const head_config& head);

}  // namespace conescan::scene
