// What --calendar asks of a scene's time (blinding_calendar.hpp computes the calendar): its finest
// resolution and its default span, a year from the epoch. The plan sets the scene's step and
// duration from them (scene_plan.cpp) before any calendar is computed.
#pragma once

#include "sources/time_scales.hpp"

namespace conescan::scene {

/// The finest resolution the calendar takes (s): the edges' tolerance.
inline constexpr double calendar_least_step_s = 1e-3;

/// The calendar's default span from `epoch` (s): to the same UTC date and time a year later (from
/// a 29 February, to the 28th).
double calendar_year_s(const sources::instant& epoch);

}  // namespace conescan::scene
