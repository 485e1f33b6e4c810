// The one table of every scene option: its name, help, kind of value, the scene field it sets,
// whether it can be swept and how --print-config writes it. The command line (its parser only
// collects the texts; its --help is made from this table), scene files, --sweep, head specs,
// --print-config and the Python bindings all go through it, and every number through the one
// parser of number_text.hpp.
//
// Adding an option: one entry in option_table.cpp's table plus its field in scene_config (or
// scene_request), and its range check in validate(). A real, count or flag bound to a field
// needs nothing else: parsing, the file key, --print-config, sweeping (when sweepable) and the
// help's default come from the kind and the field. For example, a count:
//
//   {.name = "repeats",  .group = G::time,  .kind = K::count,
//    .help = "repetitions, >= 1",  .binding = scene_field(&scene_config::repeats)},
//
// The tests then walk it with hostile values (tests/apps/test_cli_options.cpp) and require the
// --print-config round trip to draw it (tests/apps/test_cli_config.cpp: teach its drawer the
// option). A free-text field (a file name) needs a field_ref<std::string> alternative in
// option_binding, read and printed like a choice's word (no quotes, no control characters: the
// scene file has no escapes); until then text options are custom_bindings.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>

#include "scene/scene_request.hpp"
#include "text/diagnostic.hpp"

namespace conescan::scene {

enum class option_group { orbit, time, earth, model, attitude, scenes };

/// The programs that read scene options, as bits of option_spec::honoured_by. Each honours a part
/// of the option table: an option a program does not honour is not offered by it (its --help, its
/// keyword arguments); given to it on its command line or as a keyword it is refused, and in a
/// scene file it is refused when it asks for anything (a value other than the one the scene has
/// without it, e.g. runs = 3) and dropped when it does not (runs = 1, as --print-config writes
/// it), so that one scene file serves every program.
enum class scene_program : std::uint8_t {
  simulate = 1,        ///< conescan-sim
  python_rows = 2,     ///< conescan.simulate
  python_summary = 4,  ///< conescan.summary
  fit = 8,             ///< conescan-fit, conescan.fit, conescan.predict
};
inline constexpr std::uint8_t every_program = 15;

/// The program's name in messages: "conescan-sim", "conescan.simulate", ...
std::string_view program_name(scene_program program);

/// The title of a group, as --help shows it.
std::string_view group_title(option_group group);

/// What an option's value is: a finite real (text::parse_real), a count (text::parse_count), a flag
/// (true | false; no value on the command line), one of a list of words, free text, or a head spec.
enum class value_kind { real, count, flag, choice, text, head };

/// A kind's name, as conescan.options() gives it: "real", "count", "flag", "choice", "text",
/// "head".
std::string_view value_kind_name(value_kind kind);

/// What --help shows for a value of the kind where the option names none: "REAL", "COUNT",
/// "WORD", "TEXT", "SPEC"; "" for a flag, which takes none.
std::string_view value_kind_placeholder(value_kind kind);

/// A field of scene_request that an option sets: a member of its scene_config or of the request
/// itself (exactly one is non-null).
template <class V>
struct field_ref {
  V scene_config::*in_scene = nullptr;
  V scene_request::*in_request = nullptr;

  V& of(scene_request& r) const { return in_scene ? r.scene.*in_scene : r.*in_request; }
  const V& of(const scene_request& r) const { return in_scene ? r.scene.*in_scene : r.*in_request; }
};

/// One of a list of words; `set` and `get` map the word's index to the request.
struct choice_binding {
  std::span<const std::string_view> words;
  void (*set)(scene_request&, std::size_t word);
  std::size_t (*get)(const scene_request&);
};

/// An option with its own reading and writing. `apply`'s error holds only the message.
/// `print` gives the value as a scene file writes it (already quoted when text), or nullopt
/// when it is not written. `sweep` sets a swept value (nullptr: not sweepable).
struct custom_binding {
  checked<void> (*apply)(scene_request&, std::string_view text);
  std::optional<std::string> (*print)(const scene_request&);
  void (*sweep)(scene_request&, double value) = nullptr;
};

using option_binding =
    std::variant<field_ref<double>, field_ref<std::optional<double>>, field_ref<std::uint64_t>,
                 field_ref<bool>, choice_binding, custom_binding>;

struct option_spec {
  std::string_view name;  ///< long name without dashes, also the scene-file key
  option_group group;
  value_kind kind;
  /// What --help shows for a text option's value (FILE, K/N...); "": the kind's name.
  std::string_view value_name = {};
  std::string_view help;  ///< meaning, unit and domain; the default is added by option_help
  option_binding binding;
  bool sweepable = false;
  /// The options this one conflicts with, space-separated (given together from one place:
  /// refused; from the command line and a file: the command line's wins).
  std::string_view excludes = {};
  /// The default as help states it, when the printed default would not say it ("" : printed).
  std::string_view default_text = {};
  /// When validate() blames this option and the user did not give it: blame the first of
  /// these (space-separated) that the user gave.
  std::string_view blame_instead = {};
  /// Not written by --print-config when this returns true (its value is not used).
  bool (*omitted)(const scene_request&) = nullptr;
  /// Why the option has no effect in this scene (a sweep of it is refused), or nullptr.
  const char* (*ignored)(const scene_request&) = nullptr;
  /// The programs that honour it (scene_program bits).
  std::uint8_t honoured_by = every_program;
  /// What it is for, said when a program that does not honour it refuses it.
  std::string_view not_honoured = {};
  /// conescan-fit's help where the option means less there ("": help as it is).
  std::string_view fit_help = {};
};

/// Whether `program` honours `option` (scene_program).
bool honours(scene_program program, const option_spec& option) noexcept;

/// The refusal of an option `program` does not honour: "not an option of conescan-fit: ...".
diagnostic not_honoured(scene_program program, const option_spec& option, const origin& where);

/// Every scene option, in the order of --help and --print-config.
std::span<const option_spec> option_table();

/// The option named `name` (long name without dashes), or nullptr.
const option_spec* find_option(std::string_view name);

/// The option's help line in `program`'s --help: help (conescan-fit's fit_help where it has
/// one), the words of a choice, and "(default X)".
std::string option_help(const option_spec& option, scene_program program = scene_program::simulate);

/// Reads `value` (named as `option`) into the request. The error names the option and the
/// value's origin.
checked<void> apply_option(const option_spec& option, scene_request& request,
                           const option_value& value);

/// The option's value as a scene file writes it, or nullopt when --print-config leaves it out.
std::optional<std::string> print_option(const option_spec& option, const scene_request& request);

/// Sets the swept option `name` (a sweepable option, or hK.key for head K's key) to `value`.
/// The error (option "sweep", no origin) says why the name cannot be swept.
checked<void> apply_sweep_value(scene_request& request, const std::string& name, double value);

/// True when `option` excludes the option named `other` (option_spec::excludes).
bool excludes(const option_spec& option, std::string_view other);

/// The file source (tle, omm, oem, aem, attitude-csv) that replaces option `name` in this request
/// (the classical elements with an orbit file, the constant angles with an attitude file:
/// MODEL §10's one source each), or "" when none does. Such an option is refused when given,
/// swept or printed.
std::string_view replaced_by_source(const scene_request& request, std::string_view name);

/// Every option's name, "a-km, e, ...", for messages.
std::string option_names();

/// The names a sweep accepts, for messages.
std::string sweepable_names();

}  // namespace conescan::scene
