// The C++ side of probe.h: what a probe of the core writes, in its scalar (float or double, the
// build's CONESCAN_PROBE_SCALAR), and the macro that makes a probe's entry.
//
// A probe is one source file of tests/flight/probes/: a template run<T>() that writes its cases
// (values, statuses) and measures its entry point on a typical input, and a template
// size_only<T>() that calls the same entry point once on inputs read through opaque(), so that
// the compiler keeps all of its code. CONESCAN_FLIGHT_PROBE(run, size_only) defines probe_main.
#pragma once

#include "conescan/status.hpp"
#include "probe.h"

namespace flight_probe {

using scalar = CONESCAN_PROBE_SCALAR;

inline void value(const char* case_name, int index, const char* field, float x) {
  probe_value_f(case_name, index, field, x);
}
inline void value(const char* case_name, int index, const char* field, double x) {
  probe_value_d(case_name, index, field, x);
}
inline void state(const char* case_name, int index, const char* field, conescan::status s) {
  probe_status(case_name, index, field, static_cast<int>(s));
}
inline void count(const char* case_name, int index, const char* field, int n) {
  probe_count(case_name, index, field, n);
}

/// Measures `call()` (probe_measure): it runs 101 times on the target, once on the host.
template <class Call>
void measure(const char* entry, Call& call) {
  probe_measure(
      entry, [](void* context) { (*static_cast<Call*>(context))(); }, &call);
}

/// An input the compiler cannot see (the size-only build's: never run for its values).
template <class Input>
const Input& opaque() {
  static_assert(sizeof(Input) <= sizeof(probe_opaque_bytes), "the input exceeds the bytes");
  const unsigned char* bytes = probe_opaque_bytes;
  __asm__ volatile("" : "+r"(bytes));
  return *reinterpret_cast<const Input*>(bytes);
}

/// An output the compiler must compute.
template <class Output>
void keep(const Output& out) {
  __asm__ volatile("" : : "r"(&out) : "memory");
}

}  // namespace flight_probe

#ifdef CONESCAN_PROBE_SIZE_ONLY
#define CONESCAN_FLIGHT_PROBE(run, size_only) \
  extern "C" void probe_main(void) {          \
    size_only<flight_probe::scalar>();        \
  }
#else
#define CONESCAN_FLIGHT_PROBE(run, size_only) \
  extern "C" void probe_main(void) {          \
    run<flight_probe::scalar>();              \
  }
#endif
