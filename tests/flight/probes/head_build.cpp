// Probe: a head built at start-up (sensor_head::from_mounting: its scan frame, scan circle and
// the inversion's cosines), in place in static storage as flight code keeps it. Mountings and
// optics inside the domain and on both sides of its edges (|alpha| < 90 deg, gamma in
// (0, 90) deg, sigma < gamma, the envelope in [0, 90] deg).
#include <new>

#include "flight_loop.hpp"

namespace {

using namespace conescan;

template <class T>
struct head_config {
  T alpha, beta, gamma, sigma, phi_a, envelope;
};

// deg: alpha, beta, gamma, sigma, phi_a, envelope.
constexpr double configs[][6] = {
    {0, 90, 45, 0, 0, 10},        {0, -90, 45, 0.02, 90, 10}, {30, 45, 60, 0.5, 200, 10},
    {-60, 180, 20, 1, -30, 5},    {89.9, 0, 45, 0, 0, 10},    {90, 0, 45, 0, 0, 10},
    {0, 90, 0, 0, 0, 10},         {0, 90, 0.001, 0, 0, 10},   {0, 90, 89.999, 0, 0, 10},
    {0, 90, 90, 0, 0, 10},        {0, 90, 45, 44.99, 0, 10},  {0, 90, 45, 45, 0, 10},
    {0, 90, 45, 0, 0, 90},        {0, 90, 45, 0, 0, 90.01},   {0, 90, 45, 0, 0, -0.01},
    {0, 720.5, 45, 0.1, -1e4, 0},
};

template <class T>
head_config<T> config(int i) {
  const double* c = configs[i];
  return {deg_to_rad(static_cast<T>(c[0])), deg_to_rad(static_cast<T>(c[1])),
          deg_to_rad(static_cast<T>(c[2])), deg_to_rad(static_cast<T>(c[3])),
          deg_to_rad(static_cast<T>(c[4])), deg_to_rad(static_cast<T>(c[5]))};
}

template <class T>
sensor_head<T> entry(const head_config<T>& c) {
  return sensor_head<T>::from_mounting(c.alpha, c.beta, {c.gamma, c.sigma, c.phi_a}, {T(0), T(0)},
                                       c.envelope);
}

template <class T>
alignas(sensor_head<T>) unsigned char storage[sizeof(sensor_head<T>)];

template <class T>
void write_vector(int i, const char* field, const vec3<T>& v) {
  flight_probe::value("head", i, field, v.x);
  flight_probe::value("head", i, field, v.y);
  flight_probe::value("head", i, field, v.z);
}

template <class T>
void run() {
  const int count = static_cast<int>(sizeof configs / sizeof configs[0]);
  for (int i = 0; i < count; ++i) {
    const sensor_head<T> h = entry(config<T>(i));
    flight_probe::state("head", i, "status", h.state());
    if (h.state() != status::ok) continue;
    write_vector(i, "e1", h.frame().e1);
    write_vector(i, "e3", h.frame().e3);
    write_vector(i, "axis", h.circle().axis);
    write_vector(i, "u", h.circle().u);
    flight_probe::value("head", i, "cos_eta0", h.inversion().cos_eta0);
    flight_probe::value("head", i, "sin_eta0", h.inversion().sin_eta0);
    flight_probe::value("head", i, "cos_envelope", h.inversion().cos_envelope);
  }
  // In place, in the static storage a flight program keeps its heads in (no function-local
  // static: its guard would need the C++ runtime).
  struct {
    head_config<T> c;
    void operator()() { ::new (static_cast<void*>(storage<T>)) sensor_head<T>(entry(c)); }
  } call{config<T>(2)};
  flight_probe::measure("head_build", call);
  for (const char* field : {"e1", "e3", "axis", "u", "cos_eta0", "sin_eta0", "cos_envelope"})
    probe_tolerance(field, 1);
}

template <class T>
void size_only() {
  flight_probe::keep(entry(flight_probe::opaque<head_config<T>>()));
}

}  // namespace

CONESCAN_FLIGHT_PROBE(run, size_only)
