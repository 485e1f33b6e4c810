// The sensor physics of a scene (MODEL §12): which heads run the signal chain, the chain's
// settings in SI from the scene's keys (km, ms, degrees), and their checks. The simulation's
// physics step (simulation.cpp), the validation (loaded_scene.cpp), the error budget (budget.cpp)
// and the fit (scene_calibration) ask these functions.
//
// Off means off: a head runs the chain only when one of its physics keys (fov=, fov-shape=,
// spin-hz=, tau-ms=, locator=, threshold=) or one of the scene's radiance options differs from
// its default; otherwise its crossings are MODEL §5's, byte for byte.
#pragma once

#include "conescan/sensor_physics.hpp"
#include "scene/scene_config.hpp"
#include "text/diagnostic.hpp"

namespace conescan::scene {

/// True when one of the scene's radiance options (--radiance-scale-km, --radiance-offset-km,
/// --radiance-disk, --radiance-season) differs from its default.
bool radiance_given(const scene_config& scene);

/// The first radiance option (its long name) that differs from its default, or nullptr.
const char* radiance_option_given(const scene_config& scene);

/// True when one of the head's physics keys differs from its default.
bool head_physics_given(const head_config& head);

/// True when head `head` runs MODEL §12's chain: radiance_given or head_physics_given.
bool physics_on(const scene_config& scene, const head_config& head);

/// True when any head runs the chain.
bool any_physics(const scene_config& scene);

/// True when the scene's truth needs the Sun's declination per row: the horizon's season term
/// (--horizon-shift-km) or the radiance's (--radiance-season).
bool has_season_terms(const scene_config& scene);

/// The head's chain settings, SI and radians (sensor_physics.hpp).
sensor_physics_settings<double> physics_settings_of(const scene_config& scene,
                                                    const head_config& head);

/// MODEL §7 and §12's checks of the physics keys and options: each finite and in its range
/// (scene_config.hpp), tau-ms > 0 only with spin-hz, a normalised threshold in (0, 1), a fixed
/// one > 0, no threshold for the slope locator, a field narrower than twice the true cone's
/// distance from the spin axis (gamma + dgamma - sigma), and the scan model (the chain traces the
/// true scan cone). The error names the option, or "head" with the head's index.
checked<void> check_physics(const scene_config& scene);

}  // namespace conescan::scene
