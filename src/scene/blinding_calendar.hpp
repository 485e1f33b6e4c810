// The blinding calendar of a scene (MODEL §13, conescan-sim --calendar): over the scene's span,
// every interval in which the Sun or the Moon takes a head's crossings (its status `sun` or
// `moon`) and every interval in which the body is on the head's cone, found from the geometry
// instead of row by row, with their edges refined.
//
// How. A head loses its crossings to a body only when both of these hold:
//   on the cone     g1 = |angle(A, X) - gamma| - eps <= 0          (eps = fov/2 + r_X)
//   at the limb     g2 = max(rho_in - theta, theta - rho_out - 2 eps - fov/2) <= 0
// theta the body's angle from the Earth's centre as the satellite sees it, rho_in and rho_out the
// angular radii of spheres inside and about the horizon surface. The second is necessary since a
// visible body is outside the surface's outline (theta >= rho_in), and a body pulse (the scan
// arc within eps of X: the nearest line of sight at |g1 + eps| <= eps, the arc's ends within eps
// more) that meets the Earth pulse (the scan arc inside the outline, widened by fov/2) puts X
// within 2 eps + fov/2 of the outline (theta <= rho_out + 2 eps + fov/2). Each margin moves no
// faster than a rate bound: g1 at |dA/dt| + |dX/dt| (the optical axis's turn in the scene frame,
// taken over rate_probe_s at the sample, and the body's own motion and parallax, v/distance),
// g2 at |dX/dt| + (v / |r - c|)(1 + tan rho_out) (the centre's direction and the outline's size);
// each bound is doubled (rate_safety) to hold over a step of at most max_step_s. From a sample,
// the next is as far as neither the on-cone state nor the pair of conditions can change, at
// least `resolution_s` (the scene's step) and at most max_step_s; where both conditions hold
// (a candidate window: tens of seconds around each limb passage of a body on the cone), samples
// are `resolution_s` apart and each asks the scene's own rule (simulation::sky_check_at). Every
// change of state between two samples is bisected to edge_tolerance_s.
//
// Accuracy: an interval's edges within edge_tolerance_s / 2 of the rule's; every interval
// longer than the resolution is found (one shorter may be missed, as rows that far apart would
// miss it: grazing passages at the ends of a season); outside candidate windows nothing is
// sampled, and the bounds make that safe while the attitude's rate stays within twice its
// sampled value over each step (60 s at most; smooth attitudes: any orbit-pointing scene,
// tables and AEMs sampled finer than that). Tests: tests/test_blinding_calendar.cpp against the
// rows at the resolution.
#pragma once

#include <cstdint>
#include <vector>

#include "conescan/vector.hpp"
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

/// The finest resolution the calendar takes (s): the edges' tolerance.
inline constexpr double calendar_least_step_s = 1e-3;

/// The calendar's default span from `epoch` (s): to the same UTC date and time a year later (from
/// a 29 February, to the 28th).
double calendar_year_s(const sources::instant& epoch);

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
checked<blinding_calendar> blinding_calendar_of(const scene_config& scene);

/// The argument of latitude of a state (deg, [0, 360); top): for the calendar's picture.
double argument_of_latitude_deg(const vec3<double>& r_m, const vec3<double>& v_m_s) noexcept;

}  // namespace conescan::scene
