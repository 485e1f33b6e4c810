// Probe: the rest of the core, built freestanding from the umbrella header (every header of
// include/conescan/ compiles for the target; the sensor physics is compiled, not called: its
// function-local statics need the C++ runtime, docs/FLIGHT_SOFTWARE.md). Its entry point is the
// horizon-vector processing of a two-head sample (MODEL §6's alternative: the four crossings'
// horizon vectors, the nadir fitted to them); its cases also call the bias model, the measurement
// errors (noise draws, telemetry steps), the iterative solvers, the Sun's intrusion and the
// orbital frame, in float and double, against the host.
#include "conescan/conescan.hpp"
#include "flight_loop.hpp"

namespace {

using namespace conescan;

template <class T>
struct vector_output {
  horizon_nadir_fit<T> fit;
  roll_pitch<T> solution;
};

/// The horizon-vector processing of one sample: both heads' crossings as horizon vectors, the
/// nadir fitted from body +z.
template <class T>
vector_output<T> entry(const flight_loop::head_pair<T>& heads,
                       const flight_loop::sample_input<T>& in) {
  vec3<T> horizons[4];
  std::size_t used = 0;
  for (int k = 0; k < flight_loop::head_count; ++k) {
    const sensor_head<T>& h = heads.head[k];
    used = append_horizon_vectors(h.frame(), h.optics().gamma,
                                  crossings<T>::from_chord_phase(in.chord[k], in.phase[k]),
                                  horizons, used, 4);
  }
  const disk_trig<T> disk = disk_trig_of(flight_loop::processing_radius_km<T>(), in.r_km);
  vector_output<T> out{
      nadir_from_horizon_vectors(horizons, used, disk.cos_rho, vec3<T>(T(0), T(0), T(1))),
      {not_a_number<T>(), not_a_number<T>()}};
  if (out.fit.state == status::ok) out.solution = roll_pitch_from_nadir(out.fit.nadir);
  return out;
}

template <class T>
void other_functions() {
  const head_optics<T> optics{deg_to_rad(T(45)), deg_to_rad(T(0.02)), deg_to_rad(T(90))};
  const sensor_head<T> head = sensor_head<T>::from_mounting(
      T(0), deg_to_rad(T(90)), optics, {deg_to_rad(T(0.01)), deg_to_rad(T(0.001))});
  for (int i = 0; i < 8; ++i) {
    const T eta = deg_to_rad(static_cast<T>(80 + 2.5 * i)),
            rho = deg_to_rad(static_cast<T>(62 + i));
    const crossings<T> bias = head.bias_crossings(head.bias_cone_angle(), eta, T(0), rho);
    flight_probe::state("bias", i, "status", bias.state);
    flight_probe::value("bias", i, "phi_in", bias.phi_in);
    const crossings<T> noisy = head.measured(bias, static_cast<T>(0.5 - 0.25 * i), T(1.5));
    flight_probe::state("measured", i, "status", noisy.state);
    flight_probe::value("measured", i, "phi_out", noisy.phi_out);
    const crossings<T> iterative = scan_model_crossings_sphere_iterative(optics, eta, T(0), rho);
    flight_probe::state("iterative", i, "status", iterative.state);
    flight_probe::value("iterative", i, "phi_in", iterative.phi_in);
    flight_probe::count("iterative", i, "iterations", iterative.iterations);
  }
  // The Sun 0.3 deg off the cone, near the Earth pulse, then far from it.
  const crossings<T> earth = head.scan_crossings(head.in_scan_frame(nadir_in_body(T(0), T(0))),
                                                 disk_trig_of(T(6378.137), T(7280)));
  for (int i = 0; i < 2; ++i) {
    const T azimuth = earth.phi_out + deg_to_rad(static_cast<T>(1 + 60 * i));
    const T psi = optics.gamma + deg_to_rad(T(0.3));
    const scan_frame<T> scan_axes{vec3<T>(T(1), T(0), T(0)), vec3<T>(T(0), T(1), T(0)),
                                  vec3<T>(T(0), T(0), T(1)), status::ok};
    const vec3<T> sun = direction_in_scan_frame(scan_axes, psi, azimuth);
    const body_intrusion<T> s =
        body_intrusion_of(head.circle(), earth, sun, deg_to_rad(T(0.267)), deg_to_rad(T(1)));
    flight_probe::value("sun", i, "offset", s.cone_offset);
    flight_probe::state("sun", i, "status", intrusion_status(earth, s, false, s, true));
  }
  const mat3<T> c =
      dcm_eci_from_orbit(vec3<T>(T(7000e3), T(1e3), T(0)), vec3<T>(T(0), T(7.5e3), T(1e2)));
  flight_probe::value("frame", 0, "c20", c[2][0]);
  flight_probe::value("frame", 0, "c11", c[1][1]);
}

template <class T>
void run() {
  const flight_loop::head_pair<T> heads = flight_loop::paper_pair<T>();
  for (int i = 0; i < flight_loop::sample_count(); ++i) {
    const vector_output<T> out = entry(heads, flight_loop::sample<T>(i));
    flight_probe::state("vectors", i, "status", out.fit.state);
    flight_probe::value("vectors", i, "roll", out.solution.roll);
    flight_probe::value("vectors", i, "pitch", out.solution.pitch);
  }
  other_functions<T>();
  struct {
    const flight_loop::head_pair<T>& heads;
    flight_loop::sample_input<T> in;
    vector_output<T> out;
    void operator()() { out = entry(heads, in); }
  } call{heads, flight_loop::sample<T>(1), {}};
  flight_probe::measure("horizon_vector_sample", call);
  flight_probe::keep(call.out);
  for (const char* field : {"roll", "pitch", "phi_in", "phi_out", "offset", "c20", "c11"})
    probe_tolerance(field, 4);
}

template <class T>
void size_only() {
  flight_probe::keep(entry(flight_probe::opaque<flight_loop::head_pair<T>>(),
                           flight_probe::opaque<flight_loop::sample_input<T>>()));
}

}  // namespace

CONESCAN_FLIGHT_PROBE(run, size_only)
