// Whether a loaded scene can be simulated (MODEL §7, §10 and the CLI contract): the user's values
// and what the files say, checked in one pass in a fixed order, so that the first failing check
// names the option at fault. scene_plan validates every scene it plans (each sweep value, each
// budget source); the simulation validates the scene it is given.
#pragma once

#include "scene/loaded_scene.hpp"
#include "text/diagnostic.hpp"

namespace conescan::scene {

/// Every check of MODEL §7 and of the CLI contract, on the user's values and on what the files
/// say (the perigee of a file orbit, the files' spans): success when the scene can be simulated,
/// or an error naming the option at fault (its long name without dashes; "head" with the head's
/// index for a head) and stating the value and the allowed range. No origin: the caller knows
/// where the option was typed (scene_plan.hpp).
checked<void> validate(const loaded_scene& scene);

}  // namespace conescan::scene
