// Probe: one telemetry sample of a two-head pair, as a flight loop processes it (MODEL §6):
// the assumed disk from the orbit radius, each head's chord and phase -> crossings -> sensed
// nadir (sensor_head::process), the system nadir of the heads that are ok (combine_heads), its
// roll and pitch. The budget in float: 2 000 instructions, 512 bytes of stack, 16 KiB of
// code for this whole path.
#include <initializer_list>

#include "flight_loop.hpp"

namespace {

using namespace conescan;
using flight_loop::sample_input;
using flight_loop::sample_output;

template <class T>
void write(int index, const sample_output<T>& out) {
  for (int k = 0; k < flight_loop::head_count; ++k) {
    flight_probe::state("sample", index, k == 0 ? "h1.status" : "h2.status", out.head_state[k]);
    flight_probe::value("sample", index, k == 0 ? "h1.roll" : "h2.roll", out.head[k].roll);
    flight_probe::value("sample", index, k == 0 ? "h1.pitch" : "h2.pitch", out.head[k].pitch);
  }
  flight_probe::state("sample", index, "status", out.state);
  flight_probe::value("sample", index, "roll", out.system.roll);
  flight_probe::value("sample", index, "pitch", out.system.pitch);
}

template <class T>
void run() {
  const flight_loop::head_pair<T> heads = flight_loop::paper_pair<T>();
  const int count = flight_loop::sample_count();
  for (int i = 0; i < count; ++i)
    write(i, flight_loop::process_sample(heads, flight_loop::sample<T>(i)));
  struct {
    const flight_loop::head_pair<T>& heads;
    sample_input<T> in;
    sample_output<T> out;
    void operator()() { out = flight_loop::process_sample(heads, in); }
  } call{heads, flight_loop::sample<T>(1), {}};
  flight_probe::measure("two_head_sample", call);
  flight_probe::keep(call.out);
  // Float: the budget. Double: the same path on the FPU's double precision.
  const bool single = sizeof(T) == sizeof(float);
  probe_limit("two_head_sample", "instructions", single ? 2000 : 3000);
  probe_limit("two_head_sample", "stack", single ? 512 : 1024);
  probe_limit("two_head_sample", "code", 16384);
  // libm's last bits (newlib's against glibc's), through the chord inversion.
  for (const char* field : {"h1.roll", "h2.roll", "h1.pitch", "h2.pitch", "roll", "pitch"})
    probe_tolerance(field, 1);
}

template <class T>
void size_only() {
  flight_probe::keep(flight_loop::process_sample(flight_probe::opaque<flight_loop::head_pair<T>>(),
                                                 flight_probe::opaque<sample_input<T>>()));
}

}  // namespace

CONESCAN_FLIGHT_PROBE(run, size_only)
