// Probe: the scan model on an ellipsoid (MODEL §3, §5; sensor_head::scan_crossings of the
// surface): Newton on the scan circle from the sphere's crossings, the bracketed solver where it
// does not settle, the check for a second Earth arc. WGS84 with the horizon 40 km up, seen from
// the paper's orbit at latitudes from the equator to the pole and attitudes out to the Earth's
// edge (statuses ok, grazing, miss, engulfed, multiple where they occur).
#include "flight_loop.hpp"

namespace {

using namespace conescan;

template <class T>
struct scan_input {
  T roll, pitch, r_m, latitude;
};

template <class T>
crossings<T> entry(const sensor_head<T>& head, const scan_input<T>& in) {
  using std::cos;
  using std::sin;
  // The orbital frame's axes in body axes (zero yaw): the satellite at -r along the nadir, the
  // polar axis in the orbit plane (x, z) at the latitude.
  const vec3<T> nadir = nadir_in_body(in.roll, in.pitch);
  const vec3<T> polar(T(cos(in.latitude)), T(0), T(-sin(in.latitude)));
  const ellipsoid_horizon<T> surface = ellipsoid_horizon_of(
      scaled(nadir, T(-in.r_m)), polar, T(6378137 + 40000), T(6356752.314245 + 40000));
  return head.scan_crossings(head.in_scan_frame(surface));
}

template <class T>
scan_input<T> input(int i) {
  return {deg_to_rad(static_cast<T>(-44 + 2.5 * i)),
          deg_to_rad(static_cast<T>(-3 + 0.15 * (i % 41))),
          static_cast<T>(6552000 + 36400 * (i % 41)), deg_to_rad(static_cast<T>(2.25 * (i % 41)))};
}

template <class T>
void run() {
  const sensor_head<T> head = sensor_head<T>::from_mounting(
      T(0), deg_to_rad(T(90)), {deg_to_rad(T(45)), deg_to_rad(T(0.05)), deg_to_rad(T(60))});
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
  } call{head, {T(0), T(0), T(7280000), deg_to_rad(T(30))}, {}};
  flight_probe::measure("scan_ellipsoid", call);
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
