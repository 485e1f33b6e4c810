// conescan-sim's options (SPEC §9) on CLI11, and their translation to a scene.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "scene/scene_config.hpp"

namespace conescan::cli {

/// What the command line (and a --config scene file) holds, as typed.
struct options {
  scene::scene_config scene;
  double radius_km = 0;   // scene.radius_km when given
  double duration_s = 0;  // scene.duration_s when given
  std::string earth = "sphere";
  std::string model = "bias";
  std::string processing_radius;   // equatorial | local | <km>; empty: the model's default
  std::vector<std::string> heads;  // head specs; empty: the paper's head
  std::string sweep;               // NAME=FROM:TO:STEP; empty: no sweep
  std::string processing = "chord-phase";
  std::string horizon_preset = "none";
  std::string date;                // YYYY-MM-DD: the Sun's declination
  double sun_declination_deg = 0;  // scene.sun_declination_deg when given
  double processing_horizon_km = 0;
  bool summary = false;
  bool budget = false;
  bool trace = false;
};

/// Declares every option on `app`, bound to `opts`, and the --config scene-file reader.
void declare_options(CLI::App& app, options& opts);

/// One scene of a run: the swept value (NaN without a sweep) and the scene for it.
struct scene_run {
  double sweep_value;
  scene::scene_config scene;
};

/// After parsing: every scene the options describe (one, or one per sweep value), all
/// validated, or the first error naming the option at fault.
std::variant<std::vector<scene_run>, scene::config_error> to_scene_runs(const CLI::App& app,
                                                                        const options& opts);

/// After parsing: the scene the options describe, or the error naming the option at fault.
/// Values are checked by scene::validate(); this adds the checks of the text forms (--earth,
/// --model, --processing-radius, --head).
std::variant<scene::scene_config, scene::config_error> to_scene(const CLI::App& app,
                                                                const options& opts);

}  // namespace conescan::cli
