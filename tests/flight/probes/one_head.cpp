// Probe: one head's chord and phase to its roll and pitch (MODEL §6, §2): crossings from the
// telemetry, the chord inverted on the assumed disk (sensor_head::process), the sensed nadir's
// roll and pitch. OH-1 of the paper's pair over paper_samples.h.
#include "flight_loop.hpp"

namespace {

using namespace conescan;

template <class T>
struct one_head_input {
  T chord;
  T phase;
  disk_trig<T> assumed;
};

template <class T>
struct one_head_output {
  head_estimate<T> estimate;
  roll_pitch<T> solution;
};

template <class T>
one_head_output<T> entry(const sensor_head<T>& head, const one_head_input<T>& in) {
  one_head_output<T> out{};
  out.estimate = flight_loop::process_one(head, in.chord, in.phase, in.assumed, out.solution);
  return out;
}

template <class T>
one_head_input<T> input(int i) {
  const flight_loop::sample_input<T> s = flight_loop::sample<T>(i);
  return {s.chord[0], s.phase[0], disk_trig_of(flight_loop::processing_radius_km<T>(), s.r_km)};
}

template <class T>
void run() {
  const flight_loop::head_pair<T> heads = flight_loop::paper_pair<T>();
  for (int i = 0; i < flight_loop::sample_count(); ++i) {
    const one_head_output<T> out = entry(heads.head[0], input<T>(i));
    flight_probe::state("sample", i, "status", out.estimate.state);
    flight_probe::value("sample", i, "eta_s", out.estimate.eta_s);
    flight_probe::value("sample", i, "roll", out.solution.roll);
    flight_probe::value("sample", i, "pitch", out.solution.pitch);
  }
  struct {
    const sensor_head<T>& head;
    one_head_input<T> in;
    one_head_output<T> out;
    void operator()() { out = entry(head, in); }
  } call{heads.head[0], input<T>(1), {}};
  flight_probe::measure("one_head", call);
  flight_probe::keep(call.out);
  for (const char* field : {"eta_s", "roll", "pitch"}) probe_tolerance(field, 1);
}

template <class T>
void size_only() {
  flight_probe::keep(
      entry(flight_probe::opaque<sensor_head<T>>(), flight_probe::opaque<one_head_input<T>>()));
}

}  // namespace

CONESCAN_FLIGHT_PROBE(run, size_only)
