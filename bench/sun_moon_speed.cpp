// conescan-sun-moon-speed: what the scene frame and the Sun and Moon cost a row (docs/SUN_MOON.md).
//
// Times per call or per row (median of 15 runs, bench/timing.hpp):
//  - the exact ERFA calls: all rotations into TOD at one instant (scene_rotations_at), the Sun
//    and Moon at one instant with their rotation (sun_moon_at);
//  - the tracks' nodes (one ERFA evaluation each, every 6 h of scene) and their per-row lookups;
//  - a two-head WGS84 scan row of the core (Kepler state, orbital frame, inflated ellipsoid in
//    body axes, per head the closed-form crossings and the processing), which is what the
//    scene's ~1 us row spends on geometry, and the same row with the intrusion rule added the way
//    a scene would (bodies once per row from the track, seen from the satellite, hidden or not
//    once per row, per head the cone offset and, on the cone, the pulses);
//  - the same with the Sun and Moon from ERFA at every row (what the track avoids).
//
// Usage: conescan-sun-moon-speed (no arguments). Never a pass/fail criterion.
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "conescan/intrusion.hpp"
#include "conescan/orbital_frame.hpp"
#include "conescan/sensor_head.hpp"
#include "orbit/kepler.hpp"
#include "orbit/wgs84.hpp"
#include "sources/scene_frame.hpp"
#include "sources/sun_moon.hpp"
#include "timing.hpp"

namespace {

using namespace conescan;
using conescan::bench::keep;
using conescan::bench::time_per_sample;
constexpr double deg = std::numbers::pi / 180;

sources::instant utc(const char* text) {
  return (sources::parse_epoch(text, sources::time_scale::utc)).value();
}

/// The scene of the row benchmark: the paper's orbit (a = 7280 km, e = 0.1, i = 97.7 deg), two
/// heads at beta = +-90 deg, gamma = 45 deg, sigma = 0.02 deg, a 1 deg field, the inflated WGS84
/// ellipsoid with a 40 km horizon, one row every 10 s over a day.
struct scene {
  orbit::kepler_orbit path;
  std::vector<sensor_head<double>> heads;
  double a_eq, b_pol;
  disk_trig<double> assumed{0, 0, status::invalid};
  sources::instant epoch;
  std::vector<double> times;
  double fov = 1 * deg;
};

scene make_scene() {
  const orbit::earth_constants& w = orbit::wgs84();
  const orbit::elements el{7280e3, 0.1, 97.7 * deg, 0.5, 0.3, 0.0};
  scene s{orbit::kepler_orbit(el, orbit::two_body_rates(el, w.gm_m3_s2), w.gm_m3_s2),
          {},
          w.a_m + 40e3,
          w.b_m + 40e3,
          {},
          utc("2026-06-01T00:00:00"),
          {}};
  for (double beta : {90 * deg, -90 * deg})
    s.heads.push_back(sensor_head<double>::from_mounting(0.0, beta, {45 * deg, 0.02 * deg, 0.0}));
  for (int k = 0; k <= 8640; ++k) s.times.push_back(10.0 * k);
  return s;
}

/// The geometry of one row that the intrusion rule reuses: the state, the orbital frame (body =
/// orbital, zero attitude), the surface in body axes, each head's crossings.
struct row_geometry {
  orbit::orbit_state state;
  mat3<double> eci_from_body;
  ellipsoid_horizon<double> surface_body;
  crossings<double> earth[2];
};

row_geometry scan_row(const scene& s, double t, double& sink) {
  row_geometry g{s.path.state_at(t), mat3<double>(1.0), {}, {}};
  g.eci_from_body = dcm_eci_from_orbit(g.state.r_eci_m, g.state.v_eci_m_s);
  g.surface_body = ellipsoid_horizon_of(apply_transpose(g.eci_from_body, g.state.r_eci_m),
                                        apply_transpose(g.eci_from_body, vec3<double>(0, 0, 1)),
                                        s.a_eq, s.b_pol);
  const disk_trig<double> assumed = disk_trig_of(s.a_eq, norm(g.state.r_eci_m));
  for (std::size_t h = 0; h < 2; ++h) {
    const sensor_head<double>& head = s.heads[h];
    g.earth[h] = head.scan_crossings(head.in_scan_frame(g.surface_body));
    const head_estimate<double> e = head.process(head.measured(g.earth[h], 0.0, 0.0), assumed);
    sink += e.nadir.x;
  }
  return g;
}

/// The intrusion rule on a row: bodies seen from the satellite, hidden or not, per head.
void intrusions(const scene& s, const row_geometry& g, const sources::sun_moon_positions& sky,
                double& sink) {
  const sources::body_view sun =
      sources::view_from(sky.sun_tod_m, sources::sun_radius_m, g.state.r_eci_m);
  const sources::body_view moon =
      sources::view_from(sky.moon_tod_m, sources::moon_radius_m, g.state.r_eci_m);
  const vec3<double> sun_body = apply_transpose(g.eci_from_body, sun.direction_tod);
  const vec3<double> moon_body = apply_transpose(g.eci_from_body, moon.direction_tod);
  const bool sun_hidden =
      body_hidden_by_ellipsoid(g.surface_body, s.a_eq, sun_body * sun.distance_m).hidden;
  const bool moon_hidden =
      body_hidden_by_ellipsoid(g.surface_body, s.a_eq, moon_body * moon.distance_m).hidden;
  for (std::size_t h = 0; h < 2; ++h) {
    const sensor_head<double>& head = s.heads[h];
    const body_intrusion<double> x = body_intrusion_of(
        head.circle(), g.earth[h], head.in_scan_frame(sun_body), sun.angular_radius_rad, s.fov);
    const body_intrusion<double> y = body_intrusion_of(
        head.circle(), g.earth[h], head.in_scan_frame(moon_body), moon.angular_radius_rad, s.fov);
    sink += x.cone_offset + y.cone_offset +
            static_cast<double>(intrusion_status(g.earth[h], x, sun_hidden, y, moon_hidden));
  }
}

void report(const char* what, const bench::sample_time& t) {
  std::printf("%-58s %10.1f ns  (min %.1f, max %.1f)\n", what, t.median_ns, t.min_ns, t.max_ns);
}

/// The exact calls, at the instants `few`, and the tracks' builds over [t0, t1].
void time_exact_calls(const std::vector<sources::instant>& few, const sources::instant& t0,
                      const sources::instant& t1, double& sink) {
  report("scene_rotations_at (all frames, one nutation series)", time_per_sample(few.size(), [&] {
           for (const sources::instant& t : few) sink += sources::scene_rotations_at(t).gast_rad;
         }));
  report("sun_moon_at (eraEpv00, eraMoon98, their rotation)", time_per_sample(few.size(), [&] {
           for (const sources::instant& t : few)
             sink += (sources::sun_moon_at(t)).value().sun_tod_m.x;
         }));
  report("frame_track::over, per node (a day: 8 nodes)",
         time_per_sample(8, [&] { keep(sources::frame_track::over(t0, t1)); }));
  report("sun_moon_track::over, per node (a day: 8 nodes)",
         time_per_sample(8, [&] { keep(sources::sun_moon_track::over(t0, t1)); }));
}

/// The tracks' values per row: each frame's rotation to TOD, the Sun and Moon.
void time_track_rows(const sources::frame_track& frames, const sources::sun_moon_track& sky,
                     const std::vector<sources::instant>& rows, double& sink) {
  for (sources::reference_frame f : {sources::reference_frame::teme, sources::reference_frame::gcrf,
                                     sources::reference_frame::itrf}) {
    const std::string label =
        "frame_track::at + to_tod, per row (" + std::string(sources::to_string(f)) + ")";
    report(label.c_str(), time_per_sample(rows.size(), [&] {
             const sources::cartesian_state state{vec3<double>(7e6, 1e5, 2e5),
                                                  vec3<double>(10, 7000, 1000)};
             for (const sources::instant& t : rows)
               sink += sources::to_tod(frames.at(f, t), state).r_m.x;
           }));
  }
  report("sun_moon_track::at, per row", time_per_sample(rows.size(), [&] {
           for (const sources::instant& t : rows) sink += sky.at(t).moon_tod_m.x;
         }));
}

/// The scene's rows: the core row, with the intrusions from the track, with a TEME state turned
/// into TOD as well, and with the Sun and Moon from ERFA at every row; and their ratios.
void time_scene_rows(const scene& s, const sources::frame_track& frames,
                     const sources::sun_moon_track& sky, const std::vector<sources::instant>& rows,
                     const std::vector<sources::instant>& few, double& sink) {
  const bench::sample_time row = time_per_sample(s.times.size(), [&] {
    for (double t : s.times) keep(scan_row(s, t, sink));
  });
  const bench::sample_time with = time_per_sample(s.times.size(), [&] {
    for (std::size_t k = 0; k < s.times.size(); ++k) {
      const row_geometry g = scan_row(s, s.times[k], sink);
      intrusions(s, g, sky.at(rows[k]), sink);
    }
  });
  const bench::sample_time with_teme = time_per_sample(s.times.size(), [&] {
    for (std::size_t k = 0; k < s.times.size(); ++k) {
      const row_geometry g = scan_row(s, s.times[k], sink);
      sink += sources::to_tod(frames.at(sources::reference_frame::teme, rows[k]),
                              {g.state.r_eci_m, g.state.v_eci_m_s})
                  .r_m.y;
      intrusions(s, g, sky.at(rows[k]), sink);
    }
  });
  const bench::sample_time exact = time_per_sample(few.size(), [&] {
    for (std::size_t k = 0; k < few.size(); ++k) {
      const double t = 890.0 * static_cast<double>(k);
      const row_geometry g = scan_row(s, t, sink);
      intrusions(s, g, (sources::sun_moon_at(few[k])).value(), sink);
    }
  });
  report("two-head WGS84 scan row (core geometry and processing)", row);
  report("  + Sun and Moon from the track, the rule for both heads", with);
  report("  + a TEME state turned into TOD from the frame track", with_teme);
  report("  the same with the Sun and Moon from ERFA at every row", exact);
  std::printf(
      "intrusions add %.0f %% to the core row (%.0f %% with the TEME rotation); with "
      "ERFA per row x%.0f\n",
      100 * (with.median_ns / row.median_ns - 1), 100 * (with_teme.median_ns / row.median_ns - 1),
      exact.median_ns / row.median_ns);
}

}  // namespace

int main() {
  const scene s = make_scene();
  const sources::instant t0 = s.epoch;
  const sources::instant t1 = sources::add_seconds(t0, s.times.back());
  double sink = 0;
  // Exact calls, at 97 instants over the day.
  std::vector<sources::instant> few;
  for (int k = 0; k < 97; ++k) few.push_back(sources::add_seconds(t0, 890.0 * k));
  time_exact_calls(few, t0, t1, sink);
  const auto frames = (sources::frame_track::over(t0, t1)).value();
  const auto sky = (sources::sun_moon_track::over(t0, t1)).value();
  std::vector<sources::instant> rows;
  for (double t : s.times) rows.push_back(sources::add_seconds(t0, t));
  time_track_rows(frames, sky, rows, sink);
  time_scene_rows(s, frames, sky, rows, few, sink);
  std::printf("(sink %g)\n", sink);
  return 0;
}
