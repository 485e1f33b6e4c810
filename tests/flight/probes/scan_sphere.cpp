// Probe: the closed-form scan model on a sphere (MODEL §5; sensor_head::scan_crossings), what an
// on-board model of the sensor (or a simulator on the target) calls: a misaligned head's true
// crossings for the true attitude and the orbit radius. Attitudes from nadir to beyond the
// Earth's edge (statuses ok, grazing, miss, engulfed), radii from perigee to apogee.
#include "flight_loop.hpp"

namespace {

using namespace conescan;

template <class T>
struct scan_input {
  T roll, pitch, r_km;
};

template <class T>
crossings<T> entry(const sensor_head<T>& head, const scan_input<T>& in) {
  return head.scan_crossings(head.in_scan_frame(nadir_in_body(in.roll, in.pitch)),
                             disk_trig_of(flight_loop::processing_radius_km<T>(), in.r_km));
}

/// Case i: roll from -40 to 60 deg, pitch within 3 deg, and a radius (all arithmetic on
/// literals: the same inputs on both sides).
template <class T>
scan_input<T> input(int i) {
  return {deg_to_rad(static_cast<T>(-40 + 2.5 * i)),
          deg_to_rad(static_cast<T>(-3 + 0.15 * (i % 41))), static_cast<T>(6552 + 36.4 * (i % 41))};
}

template <class T>
sensor_head<T> misaligned_head() {
  return sensor_head<T>::from_mounting(T(0), deg_to_rad(T(90)),
                                       {deg_to_rad(T(45)), deg_to_rad(T(0.05)), deg_to_rad(T(60))});
}

template <class T>
void run() {
  const sensor_head<T> head = misaligned_head<T>();
  for (int i = 0; i < 41; ++i) {
    const crossings<T> c = entry(head, input<T>(i));
    flight_probe::state("scan", i, "status", c.state);
    flight_probe::value("scan", i, "phi_in", c.phi_in);
    flight_probe::value("scan", i, "phi_out", c.phi_out);
  }
  struct {
    const sensor_head<T>& head;
    scan_input<T> in;
    crossings<T> out;
    void operator()() { out = entry(head, in); }
  } call{head, {T(0), T(0), T(7280)}, {}};
  flight_probe::measure("scan_sphere", call);
  flight_probe::keep(call.out);
  // Double: libm's last bits grow towards grazing (the crossing's angle with the horizon).
  const unsigned ulps = sizeof(T) == sizeof(float) ? 1 : 4;
  probe_tolerance("phi_in", ulps);
  probe_tolerance("phi_out", ulps);
}

template <class T>
void size_only() {
  flight_probe::keep(
      entry(flight_probe::opaque<sensor_head<T>>(), flight_probe::opaque<scan_input<T>>()));
}

}  // namespace

CONESCAN_FLIGHT_PROBE(run, size_only)
