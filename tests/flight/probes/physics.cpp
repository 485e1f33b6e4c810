// Probe: the sensor physics (MODEL §12; sensor_physics_crossings) on the target: a head built in
// place in static storage (sensor_physics_head_build), the workspace in static storage too, as
// a flight computer would keep them; a pencil with 1 ms of lag at 1 rev/s and a 1 deg square
// field without lag, on the paper's sphere at three radii. Not measured over 101 calls (a row
// with a field costs millions of instructions): the values and statuses against the host's.
#include "conescan/sensor_physics.hpp"
#include "flight_loop.hpp"

namespace {

using namespace conescan;

template <class T>
sensor_physics_head<T> pencil_head;
template <class T>
sensor_physics_head<T> field_head;
template <class T>
sensor_physics_workspace<T> workspace;

template <class T>
crossings<T> entry(const sensor_physics_head<T>& physics, const T& r_m) {
  const sensor_head<T> head = sensor_head<T>::from_mounting(
      T(0), deg_to_rad(T(90)), {deg_to_rad(T(45)), deg_to_rad(T(0.02)), deg_to_rad(T(30))});
  const vec3<T> nadir = head.in_scan_frame(nadir_in_body(T(0), T(0)));
  const T radius_m = T(6378137) + T(40000);
  const disk_trig<T> disk = disk_trig_of(T(radius_m / T(1000)), T(r_m / T(1000)));
  const crossings<T> geometric = head.scan_crossings(nadir, disk);
  const sphere_surface<T> sphere = sphere_surface_of(nadir, disk, radius_m, nadir);
  return sensor_physics_crossings(physics, head.circle(), sphere, T(0), geometric, workspace<T>);
}

template <class T>
void build_heads() {
  sensor_physics_settings<T> s;
  s.offset_m = T(40000);
  s.spin_hz = T(1);
  s.tau_s = T(1) / T(1000);
  sensor_physics_head_build(pencil_head<T>, s);
  s.tau_s = T(0);
  s.field = {deg_to_rad(T(1)), field_shape::square};
  sensor_physics_head_build(field_head<T>, s);
}

template <class T>
void run() {
  build_heads<T>();
  const T radii[3] = {T(6552000), T(7280000), T(8008000)};
  for (int i = 0; i < 3; ++i) {
    const crossings<T> pencil = entry(pencil_head<T>, radii[i]);
    flight_probe::state("pencil", i, "status", pencil.state);
    flight_probe::value("pencil", i, "phi_in", pencil.phi_in);
    flight_probe::value("pencil", i, "phi_out", pencil.phi_out);
    const crossings<T> field = entry(field_head<T>, radii[i]);
    flight_probe::state("field", i, "status", field.state);
    flight_probe::value("field", i, "phi_in", field.phi_in);
    flight_probe::value("field", i, "phi_out", field.phi_out);
  }
  // libm's last bits on either side move the windows' roots and pieces: measured bit for bit in
  // float and 1 ulp in double (newlib against glibc); 16 ulps leave room for another libm.
  const unsigned ulps = 16;
  probe_tolerance("phi_in", ulps);
  probe_tolerance("phi_out", ulps);
}

template <class T>
void size_only() {
  build_heads<T>();
  flight_probe::keep(entry(field_head<T>, flight_probe::opaque<T>()));
}

}  // namespace

CONESCAN_FLIGHT_PROBE(run, size_only)
