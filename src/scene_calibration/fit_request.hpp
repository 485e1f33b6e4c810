// conescan-fit's own options, which are also conescan.fit's and conescan.predict's keywords: one
// table with their checks, read from (option name, text, origin) entries exactly as the scene
// options are (src/scene/scene_plan.hpp). conescan-fit's command line registers the table on
// CLI11 (src/cli/fit_options.hpp) and the Python module passes its keywords as entries
// (python/src/fit.cpp), so both read every value through the checks below, word for word.
//
//   std::vector<scene::option_value> entries = ...;  // scene options and fit options together
//   checked<fit_plan> plan = build_fit_plan(entries, telemetry_input::file_option);
//   if (!plan.ok()) report(plan.error().text());     // "--max-iterations: '0' is not a count ..."
//
// The scene options go to build_scene_plan for scene_program::fit (the options a fit does not
// honour, such as --sweep, --runs, --write-oem, --threads, are refused there); then the fit's own
// options are checked in this order: none given twice, --max-iterations a count in [1, 10000],
// --free given, --loss a known word, --telemetry given exactly when the telemetry is neither
// planned (--predict) nor in memory, --residuals not with --predict; then --free's names
// (global or drifting, parse_free_selection) against the scene's heads.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "calibration/estimator.hpp"
#include "calibration/parameters.hpp"
#include "scene/loaded_scene.hpp"
#include "scene/scene_config.hpp"
#include "scene/scene_request.hpp"
#include "text/diagnostic.hpp"

namespace conescan::calibration {

/// What a fit option's value is: a text (a file, a list), a count, one of a list of words, or a
/// flag (no value on the command line; "true" or "false" as an entry).
enum class fit_option_kind { text, count, choice, flag };

/// One of conescan-fit's own options.
struct fit_option_spec {
  std::string_view name;  ///< long name without dashes, also the Python keyword ('-' as '_')
  fit_option_kind kind;
  std::string_view value_name;  ///< what --help shows for its value: FILE, LIST, WORD, COUNT
  std::string_view help;
  bool python = true;  ///< a keyword of conescan.fit / conescan.predict (--json and --predict
                       ///< are the functions' choice there, --residuals a file Python does not
                       ///< write: not offered)
};

/// Every fit option, in --help's order.
std::span<const fit_option_spec> fit_option_table();

/// The fit option named `name`, or nullptr.
const fit_option_spec* find_fit_option(std::string_view name);

/// What conescan-fit's own options hold once checked.
struct fit_request {
  std::optional<std::string> telemetry;               ///< --telemetry FILE
  std::string free;                                   ///< --free LIST
  bool json = false;                                  ///< --json
  bool predict = false;                               ///< --predict
  robust_loss loss = robust_loss::huber;              ///< --loss huber|none
  int max_iterations = fit_options{}.max_iterations;  ///< --max-iterations
  std::optional<std::string> residuals;               ///< --residuals FILE
};

/// Where the telemetry comes from: the --telemetry file, or the caller's memory (conescan.fit's
/// arrays; --telemetry is then neither needed nor allowed).
enum class telemetry_input { file_option, in_memory };

/// The fit options among `entries` (the others are skipped), checked as the top of this file
/// says. The error names the option and, for an entry from a file, where.
checked<fit_request> read_fit_request(std::span<const scene::option_value> entries,
                                      telemetry_input input = telemetry_input::file_option);

/// checked<void> success when the scene request is one scene for one fit, else the refusal naming
/// the option (--sweep, --budget, --summary, --runs, --apply): what the scene_program::fit
/// filter of build_scene_plan leaves to check, such as a value given through a sweep.
checked<void> single_scene_problem(const scene::scene_request& request);

/// A fit's input, checked: the scene, the fit's own options and the free parameters.
struct fit_plan {
  scene::loaded_scene scene;  ///< the plan's scene, its files loaded
  fit_request request;
  std::vector<free_parameter> free;  ///< parse_free_selection of request.free
  /// --threads: the fit's worker threads; without it every core the process may use, as
  /// conescan-sim's (text::available_cores): every count gives the same fit to the bit
  /// (passes.hpp).
  int threads = 1;
};

/// The scene options and the fit options of `entries`, checked in the order the top of this file
/// says (the scene's first, as conescan-fit always has).
checked<fit_plan> build_fit_plan(std::span<const scene::option_value> entries,
                                 telemetry_input input = telemetry_input::file_option);

}  // namespace conescan::calibration
