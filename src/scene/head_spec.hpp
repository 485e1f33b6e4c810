// A sensor head as text, "key=value,..." (docs/CLI.md, "Heads"), and its keys: one table,
// head_keys(), of the mounting (MODEL §9), the measurement's errors, the fixed biases (MODEL §11)
// and the sensor physics (MODEL §12), from which the parser, the messages and --help are made.
#pragma once

#include <set>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene_config.hpp"
#include "text/diagnostic.hpp"

namespace conescan::scene {

/// The groups of a head's keys: the mounting and optics (MODEL §9: alpha, beta, gamma, sigma,
/// phase), the measurement's errors (noise, lsb), the fixed biases a calibration estimates
/// (MODEL §11: dgamma, bias-in, bias-out), and the sensor physics (MODEL §12: fov ... threshold).
enum class head_key_group { mounting, errors, biases, physics };

/// The step of MODEL §12's chain a physics key sets: the field of view (fov, fov-shape), the
/// detector (spin-hz, tau-ms), the locator (locator, threshold); none for the other groups.
enum class physics_step { none, field, detector, locator };

/// The words of a key whose value is one of the core's enumerators (fov-shape: field_shape,
/// locator: locator_kind), read and written through that enum's name table.
struct head_key_words {
  /// Sets the head's value to the enumerator named `word`; false when no enumerator is.
  bool (*set)(head_config& head, std::string_view word);
  /// The name of the head's value.
  const char* (*get)(const head_config& head);
  /// The names, in the enum's order, joined by `separator`.
  std::string (*list)(std::string_view separator);
};

/// One key of a head spec: its name, group, unit ("deg", "rev/s", "ms"; "" for a pure number
/// or a word), and either the head_config field a number sets or the words of an enum. Its
/// default is head_config's.
struct head_key {
  const char* name;
  head_key_group group;
  physics_step step = physics_step::none;
  const char* unit = "";
  double head_config::*field = nullptr;  ///< a number's field; nullptr for a word
  head_key_words words = {};             ///< a word's; unset for a number
  const char* help = nullptr;            ///< what --head's help says of it beyond its name

  /// True when `head` holds the same value of this key as `other`.
  bool same(const head_config& head, const head_config& other) const;
  /// Sets this key of `head` to its value in `from`.
  void copy(head_config& head, const head_config& from) const;
  /// The value's text, as format_head_spec writes it.
  std::string text(const head_config& head) const;
};

/// Every head key, group by group (mounting, errors, biases, physics), in the order a spec is
/// printed: the one list the parser, the messages, --help, the checks and the budget read.
std::span<const head_key> head_keys();

/// The key named `name`, or nullptr.
const head_key* find_head_key(std::string_view name);

/// Copies the keys of physics step `step` from `from` into `head`.
void copy_physics_step(head_config& head, const head_config& from, physics_step step);

/// The --head help of conescan-sim (fit: false) or conescan-fit (fit: true), with the keys,
/// their words and the default head from the table.
std::string_view head_help(bool fit);

/// The physics keys as a refusal names them: "fov=, fov-shape=, spin-hz=, ...".
std::string physics_keys_text();

/// Parses a head spec: key=value items separated by commas (blanks around ',' and '=' are
/// allowed). Keys may come in any order and each at most once; a key left out keeps the
/// paper's value (head_config's default). Values go through text::parse_real (number_text.hpp), the
/// parser of every number. Domain checks (alpha, gamma, sigma ranges) are validate()'s, so a
/// scene file and the command line report them alike; but a gamma given at or below the
/// default sigma (0.02) that was not given is refused here, naming gamma, which the user typed.
/// On failure the error holds only the message (the caller names the option and origin).
checked<head_config> parse_head_spec(std::string_view spec);

/// The keys a head spec gives ("beta=90, fov=1" -> beta, fov), valid or not, split as
/// parse_head_spec splits it: what a sensor preset leaves to the user (sensor_preset.hpp).
std::set<std::string> head_spec_keys(std::string_view spec);

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
