// The blinding calendar of a scene (MODEL §13, conescan-sim --calendar): over the scene's span,
// every interval in which the Sun or the Moon takes a head's crossings (its status `sun` or
// `moon`) and every interval in which the body is on the head's cone, found from the geometry
// instead of row by row: samples as far apart as rate bounds on two necessary conditions (the body
// on the cone, near the Earth's outline) allow, at most calendar_max_step_s; where both hold,
// samples the scene's step apart, each asking the scene's own rule (simulation::sky_check_at);
// every change of state between two samples bisected to calendar_edge_tolerance_s.
//
// Accuracy: an interval's edges within calendar_edge_tolerance_s / 2 of the rule's; every interval
// longer than the resolution is found (a shorter one may be missed, as rows that far apart would
// miss it), while the attitude's rate stays within twice its sampled value over each step (any
// orbit-pointing scene; tables and AEMs sampled finer than 60 s). The conditions, their bounds and
// the checks against the rows (tests/apps/test_blinding_calendar.cpp): docs/SUN_MOON.md, "A
// calendar for any orbit".
#pragma once

#include <cstdint>
#include <vector>

#include "conescan/vector.hpp"
#include "scene/calendar_span.hpp"
#include "scene/loaded_scene.hpp"
#include "scene/scene_config.hpp"
#include "sources/time_scales.hpp"
#include "text/diagnostic.hpp"

namespace conescan::scene {

/// The bodies of the calendar, in this order (names: "sun", "moon").
inline constexpr std::size_t calendar_bodies = 2;
const char* calendar_body_name(std::size_t body) noexcept;

/// Edges are refined by bisection to this (s).
inline constexpr double calendar_edge_tolerance_s = 1e-3;
/// The longest step between samples (s), and the step over which an attitude's rate is taken.
inline constexpr double calendar_max_step_s = 60;
inline constexpr double calendar_rate_probe_s = 1;

/// One interval of a head and a body.
struct calendar_interval {
  std::size_t head = 0;  ///< 0-based
  std::size_t body = 0;  ///< 0 the Sun, 1 the Moon
  double start_s = 0;    ///< from the epoch
  double end_s = 0;
  /// Where in the orbit it starts: the argument of latitude (deg, [0, 360): the angle from the
  /// ascending node along the orbit; the true longitude on an equatorial orbit).
  double start_orbit_deg = 0;
};

struct blinding_calendar {
  sources::instant epoch{};
  double span_s = 0;        ///< the calendar covers [0, span_s]
  double resolution_s = 0;  ///< candidate windows sampled this far apart (the scene's step)
  std::size_t heads = 0;
  /// The intervals in which the head's status is the body's (its crossings lost), by start time.
  std::vector<calendar_interval> lost;
  /// The intervals in which the body is on the head's cone (|angle(A, X) - gamma| <= eps).
  std::vector<calendar_interval> on_cone;
  std::uint64_t samples = 0;  ///< the scene's rule asked this many times
};

/// The calendar of `scene` (validated, with --intrusions) over its rows' span, [0, (rows - 1)
/// step], at the resolution of its step. Errors: the simulation's (simulation::of).
checked<blinding_calendar> blinding_calendar_of(const loaded_scene& scene);

/// The argument of latitude of a state (deg, [0, 360); top): for the calendar's picture.
double argument_of_latitude_deg(const vec3<double>& r_m, const vec3<double>& v_m_s) noexcept;

}  // namespace conescan::scene
