// Probe: the statuses at their boundaries (MODEL §7), each on both sides, on the target as on
// the host: the inversion's (a chord swept through a turn: invalid, grazing near 0 and 360 deg,
// fold, ambiguous; the grazing limit itself), the disk's (a radius at the orbit's), the system
// solution's (none, invalid for nadirs that cancel), the true pitch's (gimbal at acos(1/30)) and
// a head's (the scan model's miss and engulfed as the roll grows). A boundary the two platforms
// placed differently would show as unequal statuses.
#include "flight_loop.hpp"

namespace {

using namespace conescan;

/// Chords (deg) from `first` by `step`, `count` of them, then the grazing limit's four sides.
template <class T>
void chord_sweep(const char* name, const sensor_head<T>& head, const T& r_km, double first = -2.5,
                 double step = 5, int count = 73) {
  const disk_trig<T> assumed = disk_trig_of(flight_loop::processing_radius_km<T>(), r_km);
  for (int i = 0; i < count; ++i) {
    const T chord = deg_to_rad(static_cast<T>(first + step * i));
    const head_estimate<T> e = head.process(crossings<T>::from_chord_phase(chord, T(0)), assumed);
    flight_probe::state(name, i, "status", e.state);
    flight_probe::value(name, i, "eta_s", e.eta_s);
  }
  // The grazing limit: a half chord a thousandth inside and outside it, at both ends.
  const T limit = grazing_half_chord_min<T>();
  const T half_chords[] = {limit * T(0.999), limit * T(1.001), pi<T>() - limit * T(0.999),
                           pi<T>() - limit * T(1.001)};
  for (int i = 0; i < 4; ++i) {
    const crossings<T> c = crossings<T>::from_chord_phase(T(2) * half_chords[i], T(0));
    flight_probe::state(name, 100 + i, "status", head.process(c, assumed).state);
  }
}

template <class T>
void disk_boundary() {
  const T radius = flight_loop::processing_radius_km<T>();
  const T ratios[] = {T(0.999), T(1), T(1.001), T(1000), not_a_number<T>()};
  for (int i = 0; i < 5; ++i) {
    const disk_trig<T> d = disk_trig_of(radius, T(radius * ratios[i]));
    flight_probe::state("disk", i, "status", d.state);
    flight_probe::value("disk", i, "sin_rho", d.sin_rho);
    flight_probe::value("disk", i, "cos_rho", d.cos_rho);
  }
}

template <class T>
void system_boundary() {
  const T nan = not_a_number<T>();
  const head_estimate<T> none[2] = {{nan, vec3<T>(nan), status::grazing},
                                    {nan, vec3<T>(nan), status::fold}};
  const head_estimate<T> cancel[2] = {{T(1), vec3<T>(T(0), T(0), T(1)), status::ok},
                                      {T(1), vec3<T>(T(0), T(0), T(-1)), status::ok}};
  const head_estimate<T> one[2] = {{T(1), vec3<T>(T(0), T(0.6), T(0.8)), status::ok},
                                   {nan, vec3<T>(nan), status::ambiguous}};
  flight_probe::state("system", 0, "status", combine_heads<T>(none, none + 2).state);
  flight_probe::state("system", 1, "status", combine_heads<T>(cancel, cancel + 2).state);
  const head_estimate<T> e = combine_heads<T>(one, one + 2);
  flight_probe::state("system", 2, "status", e.state);
  flight_probe::value("system", 2, "nadir_y", e.nadir.y);
}

template <class T>
void gimbal_boundary() {
  using std::acos;
  const T edge = acos(T(1) / T(30));
  const T pitches[] = {edge * T(0.9999),  edge * T(1.0001), -edge * T(0.9999),
                       -edge * T(1.0001), pi<T>() / T(2),   not_a_number<T>()};
  for (int i = 0; i < 6; ++i)
    flight_probe::state("gimbal", i, "status", classify_true_pitch(pitches[i]));
}

template <class T>
void scan_boundary() {
  const sensor_head<T> head =
      sensor_head<T>::from_mounting(T(0), deg_to_rad(T(90)), {deg_to_rad(T(45)), T(0), T(0)});
  // Roll moves the nadir towards the +y head's spin axis: engulfed past ~58 deg at perigee (the
  // nadir within rho - gamma of it); the other way, miss past ~-32 deg.
  for (int i = 0; i <= 40; ++i) {
    const T roll = deg_to_rad(static_cast<T>(-60 + 3.25 * i));
    const crossings<T> c =
        head.scan_crossings(head.in_scan_frame(nadir_in_body(roll, T(0))),
                            disk_trig_of(flight_loop::processing_radius_km<T>(), T(6552)));
    flight_probe::state("scan", i, "status", c.state);
  }
}

template <class T>
void run() {
  const flight_loop::head_pair<T> pair = flight_loop::paper_pair<T>();
  chord_sweep("chord_perigee", pair.head[0], T(6552));
  chord_sweep("chord_apogee", pair.head[0], T(8008));
  // A narrow cone (20 deg) whose spin axis is 10 deg from nadir, at 20 000 km: ambiguous from a
  // chord of ~112.8 deg (both roots within the envelope), fold from ~137.7 deg (no root).
  const sensor_head<T> narrow =
      sensor_head<T>::from_mounting(deg_to_rad(T(80)), T(0), {deg_to_rad(T(20)), T(0), T(0)});
  chord_sweep("chord_narrow", narrow, T(20000));
  chord_sweep("chord_narrow_edges", narrow, T(20000), 110, 0.25, 121);
  disk_boundary<T>();
  system_boundary<T>();
  gimbal_boundary<T>();
  scan_boundary<T>();
  // The inversion amplifies libm's last bits by up to fold_amplification_max() (30) near a fold.
  probe_tolerance("eta_s", 8);
  probe_tolerance("sin_rho", 1);
  probe_tolerance("cos_rho", 1);
}

template <class T>
void size_only() {}

}  // namespace

CONESCAN_FLIGHT_PROBE(run, size_only)
