// conescan-sim --calendar DIR: the scene's blinding calendar (simulation/blinding_calendar.hpp)
// into DIR as the CSV tables of simulation/calendar_csv.hpp, every file whole or none of them.
#pragma once

#include "scene/scene_plan.hpp"

namespace conescan::cli {

/// Computes and writes the calendar of the plan's one scene; a line on standard error says what
/// it wrote. The exit status: 0, or 1 with the error printed (DIR cannot be made or written).
int run_calendar(const scene::scene_plan& plan);

}  // namespace conescan::cli
