// From options as typed to validated scenes: the one place that turns (option name, value text,
// origin) entries into everything a program runs, whatever the program (conescan-sim's command
// line and scene file, the Python bindings' keyword arguments).
//
//   std::vector<option_value> entries = ...;   // e.g. {"e", "0.05", origin::command_line()}
//   checked<scene_plan> plan = build_scene_plan(entries);
//   if (!plan.ok()) report(plan.error().text());  // "FILE:LINE: --e: e = 2 is outside [0, 1)"
//   for (std::uint64_t j = 0; j < plan.value().scene_count(); ++j) run(plan.value().scene(j));
//
// The steps, each a function of scene_plan.cpp: the command line wins over a scene file (an
// option given on the command line drops the file's option of that name and the option it
// excludes; heads given on the command line replace the file's); an option given twice, or two
// that exclude each other, from one place are refused; each value is read by the option table
// (option_table.hpp); a horizon preset fills in what was not given; the scene is validated and
// an error is pinned on an option the user gave, at its origin; a sweep is counted, checked
// against --max-rows and validated value by value without storing its scenes; the error
// budget's sources are built and validated.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "scene/budget.hpp"
#include "scene/loaded_scene.hpp"
#include "scene/option_table.hpp"
#include "scene/scene_request.hpp"
#include "text/diagnostic.hpp"

namespace conescan::scene {

/// Every scene of a request, all validated. Without a sweep there is one scene; with one, scene
/// j is the request's scene with the swept option set to sweep_value(j), computed when asked
/// (memory does not grow with the sweep's length). The files the request names are loaded once,
/// here (load_scene), and every scene of the plan carries them.
class scene_plan {
 public:
  const scene_request& request() const noexcept { return request_; }
  std::uint64_t scene_count() const noexcept { return scene_count_; }
  /// The swept value of scene j; NaN without a sweep.
  double sweep_value(std::uint64_t j) const;
  /// Scene j (j < scene_count()), validated, with the plan's files.
  loaded_scene scene(std::uint64_t j) const;
  /// Rows of all scenes and runs together (<= --max-rows).
  std::uint64_t total_rows() const noexcept { return total_rows_; }
  /// Some scene repeats with --runs > 1 / some scene has detector noise.
  bool any_runs() const noexcept { return any_runs_; }
  bool any_noise() const noexcept { return any_noise_; }
  /// With --budget: each source's scene, validated (budget.hpp); else empty.
  const std::vector<budget_source>& budget() const noexcept { return budget_; }

 private:
  friend checked<scene_plan> build_scene_plan(std::span<const option_value> entries,
                                              scene_program program);
  scene_request request_;
  std::uint64_t scene_count_ = 1;
  std::uint64_t total_rows_ = 0;
  bool any_runs_ = false;
  bool any_noise_ = false;
  std::vector<budget_source> budget_;
  std::shared_ptr<const source_files> files_;  ///< the request's files, read once
};

/// Scene j's runs (j < scene_count()): --runs, or with --runs swept each scene's own; 1 with
/// --budget.
std::uint64_t runs_of(const scene_plan& plan, std::uint64_t j);

/// The number of units of the plan's campaign (campaign.hpp): the sum of every scene's runs (1
/// for the budget).
std::uint64_t campaign_units(const scene_plan& plan);

/// loaded_scene.hpp's interpolation_tolerance_note over every scene of the plan (they share
/// the epoch; the longest sets the span): printed once by a program, whatever the sweep.
std::optional<std::string> interpolation_tolerance_note(const scene_plan& plan);

/// The scenes of `entries`: later entries of the same origin kind are applied after earlier
/// ones (a program lists a scene file's entries first, then the command line's). The options
/// `program` does not honour are refused, or in a scene file dropped when they ask for nothing
/// (option_table.hpp, scene_program). The error names an option the user gave and where.
checked<scene_plan> build_scene_plan(std::span<const option_value> entries,
                                     scene_program program = scene_program::simulate);

}  // namespace conescan::scene
