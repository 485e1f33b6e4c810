// What a user asks of conescan: a scene (scene_config) and how to run it (a sweep, the error
// budget, a summary, a trace). The option table (option_table.hpp) reads options into it;
// scene_plan.hpp turns it into validated scenes.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "scene/scene_config.hpp"
#include "scene/sweep.hpp"
#include "text/diagnostic.hpp"

namespace conescan::scene {

/// An option as a user typed it: its long name without dashes ("e", "a-km", "head"), its value
/// as text ("true" for a flag given on the command line), and where it was typed. A scene is
/// built from a list of these (scene_plan.hpp), whatever the program: the CLI's command line and
/// scene file, or the Python bindings' keyword arguments.
struct option_value {
  std::string name;
  std::string text;
  origin where;
};

/// --shard K/N: part `index` (1-based) of `count` parts of a campaign's runs (campaign.hpp).
struct shard_spec {
  std::uint64_t index = 1;
  std::uint64_t count = 1;
};

/// Most worker threads --threads accepts (more is a typing error, not a machine).
inline constexpr std::uint64_t max_threads = 1024;

/// Figures of an apparent IR horizon, filled in for the options the user did not give.
enum class horizon_preset { none, co2_15um };

/// A real sensor's scene, filled in for the options the user did not give (sensor_preset.hpp).
enum class sensor_preset { none, conical_15um };

struct scene_request {
  scene_config scene;
  horizon_preset preset = horizon_preset::none;
  sensor_preset sensor = sensor_preset::none;
  std::optional<sweep_spec> sweep;  ///< one option run over a range of values
  bool budget = false;              ///< once per error source alone, and with all (budget.hpp)
  bool summary = false;             ///< statistics instead of rows
  /// Instead of rows: the blinding calendar, written into this directory (--calendar;
  /// blinding_calendar.hpp); "": none.
  std::string calendar_dir;
  bool trace = false;  ///< the scan model's root-finder iterations on standard error
  /// A fit's JSON whose modelled errors are subtracted before the processing (--apply;
  /// fit_correction.hpp). The option checks that the file can be opened; its content is read
  /// when the scene runs.
  std::optional<std::string> apply_fit;
  // How the campaign runs (campaign.hpp), not what it computes:
  std::uint64_t threads = 0;        ///< worker threads; 0: every core the process may use
  std::optional<shard_spec> shard;  ///< this process's part of the runs (or sweep values)
  std::string summary_state;        ///< file for the mergeable summary; "": none
  std::string write_oem_file;   ///< also write the scene's orbit as an OEM (ephemeris_writer.hpp)
  std::string write_aem_file;   ///< also write the scene's true attitude as an AEM
  std::size_t heads_given = 0;  ///< head options read so far (the first replaces the default)
};

}  // namespace conescan::scene
