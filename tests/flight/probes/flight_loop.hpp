// What the probes of the flight loop share: the paper's two-head pair (data/scenes/
// paper-fig2b.toml: pitch-axis heads at beta = +-90 deg, gamma 45 deg, processed on the sphere of
// WGS84's a), its telemetry samples and one sample's processing (MODEL §6).
//
// The samples: paper_samples.h.
#pragma once

#include <cstddef>

#include "conescan/attitude.hpp"
#include "conescan/processing.hpp"
#include "conescan/sensor_head.hpp"
#include "flight_probe.hpp"
#include "paper_samples.h"

namespace flight_loop {

using namespace conescan;

inline constexpr int head_count = 2;

template <class T>
struct head_pair {
  sensor_head<T> head[head_count];
};

/// The pair of paper-fig2b.toml: alpha 0, beta +90 and -90 deg, gamma 45 deg, no misalignment.
template <class T>
head_pair<T> paper_pair() {
  const T gamma = deg_to_rad(T(45));
  return {{sensor_head<T>::from_mounting(T(0), deg_to_rad(T(90)), {gamma, T(0), T(0)}),
           sensor_head<T>::from_mounting(T(0), deg_to_rad(T(-90)), {gamma, T(0), T(0)})}};
}

/// One sample of telemetry: the orbit radius (km), each head's chord and phase (rad).
template <class T>
struct sample_input {
  T r_km;
  T chord[head_count];
  T phase[head_count];
};

template <class T>
struct sample_output {
  status head_state[head_count];
  roll_pitch<T> head[head_count];  ///< each head's own solution (NaN unless ok)
  status state;                    ///< ok, or none when no head is ok
  roll_pitch<T> system;            ///< the heads' combined solution
};

/// Radius of the sphere the processing assumes, km (WGS84 a; the paper's horizon at 0 km).
template <class T>
T processing_radius_km() {
  return T(6378.137);
}

inline int sample_count() {
  return paper_sample_count;
}

template <class T>
sample_input<T> sample(int i) {
  const double* row = paper_samples[i];
  sample_input<T> in{static_cast<T>(row[0]), {}, {}};
  for (int k = 0; k < head_count; ++k) {
    in.chord[k] =
        row[1 + 2 * k] == -1 ? not_a_number<T>() : deg_to_rad(static_cast<T>(row[1 + 2 * k]));
    in.phase[k] = deg_to_rad(static_cast<T>(row[2 + 2 * k]));
  }
  return in;
}

/// One head's chord and phase to its sensed nadir and roll/pitch.
template <class T>
head_estimate<T> process_one(const sensor_head<T>& head, const T& chord, const T& phase,
                             const disk_trig<T>& assumed, roll_pitch<T>& solution) {
  const head_estimate<T> e = head.process(crossings<T>::from_chord_phase(chord, phase), assumed);
  solution = e.state == status::ok ? roll_pitch_from_nadir(e.nadir)
                                   : roll_pitch<T>{not_a_number<T>(), not_a_number<T>()};
  return e;
}

/// The whole sample: every failure a status, nothing allocated.
template <class T>
sample_output<T> process_sample(const head_pair<T>& heads, const sample_input<T>& in) {
  sample_output<T> out{};
  const disk_trig<T> assumed = disk_trig_of(processing_radius_km<T>(), in.r_km);
  head_estimate<T> estimates[head_count];
  for (int k = 0; k < head_count; ++k) {
    estimates[k] = process_one(heads.head[k], in.chord[k], in.phase[k], assumed, out.head[k]);
    out.head_state[k] = estimates[k].state;
  }
  const head_estimate<T> system = combine_heads<T>(estimates, estimates + head_count);
  out.state = system.state;
  out.system = system.state == status::ok ? roll_pitch_from_nadir(system.nadir)
                                          : roll_pitch<T>{not_a_number<T>(), not_a_number<T>()};
  return out;
}

}  // namespace flight_loop
