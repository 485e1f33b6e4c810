// Sensor presets (--sensor-preset NAME, scene-file key sensor-preset): a real sensor's scene in one
// word, every value filled in unless the user gave it, so each can be overridden and
// --print-config writes them all. The one preset:
//
// conical-15um: a two-head 14-16 um conical scanner at typical values (docs/STUDY.md, "The sensor
// preset": the table of every value and where it comes from):
//   earth wgs84, model scan                       the Earth's figure, the exact scan model
//   horizon-preset co2-15um                       the CO2 horizon fitted to flight data (SeaWiFS)
//   processing-radius local                       a flight processor's sphere (full-budget.toml)
//   two heads beta = +90, -90 (gamma 45, sigma    the paper's pair (OH-1, OH-2) and misalignment,
//     0.02 at phases 60, 200), noise 0.01         full-budget.toml's phases and detector noise
//   head keys fov=1.5, spin-hz=1, tau-ms=1        the project's reference field and lag (flight
//                                                 heads' are not published)
// and keeps conescan's defaults for the rest of the physics: the limb profile's scale height
// 7 km and its 50 % point at the horizon surface, a square field, the normalised locator at 1/2.
// Heads the user gives replace the preset's pair, and take the preset's head keys they do not
// give themselves.
#pragma once

#include <functional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene_request.hpp"

namespace conescan::scene {

/// The presets' names, in order ("none" first).
inline constexpr std::string_view sensor_preset_words[] = {"none", "conical-15um"};

/// Fills in `r.sensor`'s values (top of file) that the user did not give: `given(name)` is true
/// for an option given (on the command line or in a scene file), `head_keys[k]` the keys head k's
/// spec gave (r.heads_given of them; none given: the preset's heads).
void fill_in_sensor_preset(scene_request& r, const std::function<bool(std::string_view)>& given,
                           const std::vector<std::set<std::string>>& head_keys);

}  // namespace conescan::scene
