// A scene once its files are read: what the user wrote (scene_config, a pure value) beside what
// was loaded from the files it names (source_files: the orbit and attitude files, the epoch),
// made in one place, load_scene:
//
//   checked<loaded_scene> scene = load_scene(config);   // the files read and checked once
//   if (scene.ok() && validate(scene.value()).ok()) run(simulation::of(scene.value()));
//
// scene_plan loads a request's scene once and hands every scene of it (each sweep value, each
// budget source, each campaign part) the same files; the simulation, the budget, campaigns and
// the fit take a loaded_scene. What needs the loaded orbit (the two-body period of a file orbit,
// the rows, the perigee and the checks of the files' spans) is asked of it, never of the config.
#pragma once

#include <cstdint>
#include <memory>

#include "scene/scene_config.hpp"
#include "text/diagnostic.hpp"

namespace conescan::scene {

struct source_files;  // truth_source.hpp: the files a scene names, once read

/// A scene and its files: `files` is set (load_scene: at least the epoch), immutable and shared by
/// every scene made from the same request (a sweep's values, the budget's sources).
struct loaded_scene {
  scene_config config;
  std::shared_ptr<const source_files> files;
};

/// Reads and checks the files `config` names and its epoch (MODEL §10). Errors name the option
/// (epoch, tle, omm, oem, aem, attitude-csv, ...) and in the message the file, line and keyword
/// or value. An OEM is read whole (at most sources::oem_max_states states) unless --epoch and
/// --duration-s fix the scene's span before it is read; an AEM for the scene's span unless
/// span_may_change (a sweep of the step or duration: then whole).
checked<loaded_scene> load_scene(scene_config config, bool span_may_change = false);

/// Every check of MODEL §7 and of the CLI contract, on the user's values and on what the files
/// say (the perigee of a file orbit, the files' spans): success when the scene can be simulated,
/// or an error naming the option at fault (its long name without dashes; "head" with the head's
/// index for a head) and stating the value and the allowed range. No origin: the caller knows
/// where the option was typed (scene_plan.hpp).
checked<void> validate(const loaded_scene& scene);

/// The satellite's two-body period for this scene, s (from a TLE or OEM: of the osculating orbit
/// at the epoch, MODEL §10).
double orbital_period_s(const loaded_scene& scene);

/// The scene's duration, s: duration_s, or orbits two-body periods.
double scene_duration_s(const loaded_scene& scene);

/// Number of rows: t = k step for k = 0, 1, ... while k step <= duration (MODEL §3; the test is
/// done on the product k * step, never on an accumulated time).
std::uint64_t row_count(const loaded_scene& scene);

/// The time of the scene's last row, s from the epoch: (row_count - 1) step.
double last_row_t_s(const loaded_scene& scene);

}  // namespace conescan::scene
