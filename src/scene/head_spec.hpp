// The text form of a sensor head: "alpha=..,beta=..,gamma=..,sigma=..,phase=.." (degrees; MODEL
// §9), plus the detector's "noise=.." (1 sigma per crossing) and "lsb=.." (telemetry step), the
// fixed biases a calibration estimates, "dgamma=..", "bias-in=..", "bias-out=.." (MODEL §11), and
// the sensor physics of MODEL §12: "fov=.." (deg), "fov-shape=square|circle", "spin-hz=..",
// "tau-ms=..", "locator=normalised|fixed|slope", "threshold=..".
#pragma once

#include <string>
#include <string_view>
#include <vector>

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

/// The field of head key `key` (a number: alpha, beta, ..., threshold), or nullptr (no such key,
/// or a word: fov-shape, locator).
double* head_key_field(head_config& head, std::string_view key);

/// True for a key of a head spec.
bool is_head_key(std::string_view key);

/// True for a key whose value is a word (fov-shape, locator), not a number.
bool is_head_word_key(std::string_view key);

/// The keys whose value is a number, in order (what a sweep hK.key may name).
std::vector<std::string_view> head_number_keys();

/// The keys, for messages: "alpha, beta, ... bias-out (degrees), fov (degrees), ...".
const char* head_keys_text();

/// Whether `text` is a valid value of head key `key` (a number, or one of its words); the error
/// holds only the message, as parse_head_spec's after "head key 'K': ".
checked<void> check_head_value(std::string_view key, std::string_view text);

/// The canonical text of a head, round-trip exact (the inverse of parse_head_spec): the first ten
/// keys always, the physics keys (fov= ... threshold=) only where they differ from their default.
std::string format_head_spec(const head_config& head);

}  // namespace conescan::scene
