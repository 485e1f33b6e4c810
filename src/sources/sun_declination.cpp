#include "sources/sun_declination.hpp"

#include <algorithm>
#include <cmath>

#include "sources/scene_frame.hpp"
#include "sources/sun_moon.hpp"

namespace conescan::sources {

double apparent_sun_declination_rad(const julian_date& tt) noexcept {
  // The one Sun (sun_moon.hpp's apparent Sun) in the true equator of date. Only the matrix
  // N P B of the rotations is used, so UT1 (GAST's time) may be any: TT is passed.
  const vec3<double> sun = apparent_sun_tod_m(tt, scene_rotations_at(tt, tt).tod_from_gcrf);
  return std::atan2(sun.z, std::hypot(sun.x, sun.y));
}

double sun_declination_rad(const instant& t) noexcept {
  return apparent_sun_declination_rad(tt_julian_date(t));
}

checked<sun_declination_track> sun_declination_track::over(const instant& t0, const instant& t1) {
  if (checked<void> e = check_in_utc_table(t0, t1); !e.ok()) return e.error();
  sun_declination_track track;
  track.first_node_ = add_seconds(t0, -sun_track_node_spacing_s);
  const double span_s = std::max(0.0, seconds_between(t0, t1));
  // One node before t0, enough to pass t1 by one, and at least the four the cubic takes (a span
  // of length 0 would otherwise get three: found by AddressSanitizer).
  const auto nodes = std::max<std::size_t>(
      4, static_cast<std::size_t>(std::ceil(span_s / sun_track_node_spacing_s)) + 3);
  track.declination_rad_.reserve(nodes);
  for (std::size_t k = 0; k < nodes; ++k) {
    const instant node =
        add_seconds(track.first_node_, static_cast<double>(k) * sun_track_node_spacing_s);
    track.declination_rad_.push_back(sun_declination_rad(node));
  }
  return track;
}

double sun_declination_track::at(const instant& t) const noexcept {
  // Four nodes around t: k-1, k, k+1, k+2 with t in [node k, node k+1], clamped to the table.
  const double x = seconds_between(first_node_, t) / sun_track_node_spacing_s;
  const auto last_start = static_cast<double>(declination_rad_.size() - 4);
  const double start = std::clamp(std::floor(x) - 1.0, 0.0, last_start);
  const auto k = static_cast<std::size_t>(start);
  const double u = x - start;  // in node units from node k: nodes at 0, 1, 2, 3
  const double* d = declination_rad_.data() + k;
  return -d[0] * (u - 1) * (u - 2) * (u - 3) / 6 + d[1] * u * (u - 2) * (u - 3) / 2 -
         d[2] * u * (u - 1) * (u - 3) / 2 + d[3] * u * (u - 1) * (u - 2) / 6;
}

}  // namespace conescan::sources
