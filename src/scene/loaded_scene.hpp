// A scene once its files are read: what the user wrote (scene_config, a pure value) beside what
// was loaded from the files it names (source_files: the orbit and attitude files, the epoch),
// made in one place, load_scene:
//
//   checked<loaded_scene> scene = load_scene(config);   // the files read and checked once
//   if (scene.ok() && validate(scene.value()).ok()) run(simulation::of(scene.value()));
//
// (validate: scene_validation.hpp.)
//
// scene_plan loads a request's scene once and hands every scene of it (each sweep value, each
// budget source, each campaign part) the same files; the simulation, the budget, campaigns and
// the fit take a loaded_scene. What needs the loaded orbit (the two-body period of a file orbit,
// the rows, the perigee and the checks of the files' spans) is asked of it, never of the config.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "scene/scene_config.hpp"
#include "scene/source_files.hpp"
#include "text/diagnostic.hpp"

namespace conescan::scene {

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

/// Before any row (validate() calls it): the scene's span [epoch, epoch + last row] lies within
/// ERFA's UTC table and each file's usable span (an OEM also with its interpolation error
/// estimate at most 1e-6 deg: sources::default_max_interpolation_angle_rad), and SGP4 gives a
/// state at the first and last rows and at least every tenth of an orbit between (a decay or an
/// eccentricity out of range is refused, naming the time). Errors as load_scene's.
checked<void> check_source_coverage(const loaded_scene& scene);

/// With --interpolation-tolerance-deg above its default and an OEM whose interpolation error
/// estimate over [epoch, epoch + last_t_s] exceeds the default: what a program prints once on
/// standard error, the worst estimate and the bound it puts on each row's truth, (1 + tan rho)
/// times it (the Earth's angular radius rho at the epoch: SOURCES.md). nullopt otherwise.
std::optional<std::string> interpolation_tolerance_note(const loaded_scene& scene, double last_t_s);
/// The same over the scene's rows.
std::optional<std::string> interpolation_tolerance_note(const loaded_scene& scene);

}  // namespace conescan::scene
