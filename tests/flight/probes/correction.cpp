// Probe: the calibration on board (conescan/head_calibration.hpp: calibrated_crossings, what
// conescan-sim --apply subtracts): a head's measured crossings corrected by its calibrated
// misalignment, cone-angle and crossing biases at the nadir the flight loop estimated, on the
// sphere of the fitted horizon.
#include "conescan/head_calibration.hpp"
#include "flight_loop.hpp"

namespace {

using namespace conescan;

template <class T>
struct correction_input {
  crossings<T> measured;
  vec3<T> nadir_body;
  disk_trig<T> disk;
};

template <class T>
head_calibration<T> calibration() {
  return {{T(0.025), T(0.0433), T(0.01)}, T(0.002), T(-0.003)};
}

template <class T>
crossings<T> entry(const sensor_head<T>& head, const head_calibration<T>& c,
                   const correction_input<T>& in) {
  return calibrated_crossings(in.measured, head.optics().gamma, c,
                              head.in_scan_frame(in.nadir_body), in.disk);
}

template <class T>
correction_input<T> input(int i) {
  const flight_loop::sample_input<T> s = flight_loop::sample<T>(i);
  return {crossings<T>::from_chord_phase(s.chord[0], s.phase[0]),
          nadir_in_body(deg_to_rad(static_cast<T>(-2 + 0.25 * i)),
                        deg_to_rad(static_cast<T>(1 - 0.1 * i))),
          disk_trig_of(T(6378.137 + 40), s.r_km)};
}

template <class T>
void run() {
  const flight_loop::head_pair<T> heads = flight_loop::paper_pair<T>();
  const head_calibration<T> c = calibration<T>();
  for (int i = 0; i < flight_loop::sample_count(); ++i) {
    const crossings<T> out = entry(heads.head[0], c, input<T>(i));
    flight_probe::state("sample", i, "status", out.state);
    flight_probe::value("sample", i, "phi_in", out.phi_in);
    flight_probe::value("sample", i, "phi_out", out.phi_out);
  }
  struct {
    const sensor_head<T>& head;
    head_calibration<T> c;
    correction_input<T> in;
    crossings<T> out;
    void operator()() { out = entry(head, c, in); }
  } call{heads.head[0], c, input<T>(1), {}};
  flight_probe::measure("correction", call);
  flight_probe::keep(call.out);
  // The correction is a difference of predicted chords (and phases) of ~2 rad: their libm's
  // last bits, a few ulps of 1 rad.
  probe_tolerance("phi_in", 4);
  probe_tolerance("phi_out", 4);
}

template <class T>
void size_only() {
  flight_probe::keep(entry(flight_probe::opaque<sensor_head<T>>(),
                           flight_probe::opaque<head_calibration<T>>(),
                           flight_probe::opaque<correction_input<T>>()));
}

}  // namespace

CONESCAN_FLIGHT_PROBE(run, size_only)
