/* Probe: the C interface (include/conescan/conescan.h) from C, compiled by the C compiler: the
 * paper's two-head pair built in static storage, each sample of paper_samples.h through
 * disk -> crossings -> correction by a calibration -> processing -> combination -> roll/pitch,
 * as a flight loop in C runs it. Built twice, in float (the _f functions) and in double (_d). */
#include "conescan/conescan.h"
#include "paper_samples.h"
#include "probe.h"

#if CONESCAN_PROBE_DOUBLE
typedef double real;
#define C(name) name##_d
#define VALUE probe_value_d
#else
typedef float real;
#define C(name) name##_f
#define VALUE probe_value_f
#endif

typedef C(conescan_head) head;
typedef C(conescan_estimate) estimate;

enum { head_count = 2 };

#define degree ((real)(3.14159265358979323846 / 180))
/* WGS84's a (km), the sphere the processing assumes. */
static const real processing_radius_km = (real)6378.137;
/* A calibration as conescan-fit writes it (deg): OH-1 misaligned by 0.05 deg at 60 deg with a
 * cone-angle bias, OH-2 with crossing biases. */
static const C(conescan_calibration) calibration[head_count] = {
    {(real)0.025, (real)0.0433, (real)0.01, 0, 0}, {0, 0, 0, (real)0.002, (real)-0.003}};

typedef struct {
  real r_km;
  real chord[head_count], phase[head_count];
} sample;

typedef struct {
  C(conescan_crossings) corrected[head_count];
  estimate estimates[head_count];
  estimate system;
  C(conescan_attitude) attitude;
} result;

#ifndef CONESCAN_PROBE_SIZE_ONLY
static sample sample_at(int i) {
  const double* row = paper_samples[i];
  sample s;
  s.r_km = (real)row[0];
  for (int k = 0; k < head_count; ++k) {
    s.chord[k] = row[1 + 2 * k] == -1 ? (real)0 / (real)0 : (real)row[1 + 2 * k] * degree;
    s.phase[k] = (real)row[2 + 2 * k] * degree;
  }
  return s;
}
#endif

/* One sample: a first pass gives the nadir at which each head's calibration is evaluated, the
 * second processes the corrected crossings. */
static result process(const head* heads_in, const sample* s) {
  result out;
  const C(conescan_disk) disk = C(conescan_disk_of)(processing_radius_km, s->r_km);
  C(conescan_crossings) measured[head_count];
  estimate first[head_count];
  for (int k = 0; k < head_count; ++k) {
    measured[k] = C(conescan_crossings_of)(s->chord[k], s->phase[k]);
    first[k] = C(conescan_process)(&heads_in[k], &measured[k], &disk);
  }
  const estimate nadir = C(conescan_combine)(first, head_count);
  for (int k = 0; k < head_count; ++k) {
    out.corrected[k] =
        C(conescan_correct)(&heads_in[k], &calibration[k], &measured[k], nadir.nadir, &disk);
    out.estimates[k] = C(conescan_process)(&heads_in[k], &out.corrected[k], &disk);
  }
  out.system = C(conescan_combine)(out.estimates, head_count);
  out.attitude = C(conescan_roll_pitch)(&out.system);
  return out;
}

typedef struct {
  const head* heads;
  sample in;
  result out;
} measured_call;

static void call(void* context) {
  measured_call* c = (measured_call*)context;
  c->out = process(c->heads, &c->in);
}

#ifndef CONESCAN_PROBE_SIZE_ONLY
static void write(int i, const result* r) {
  static const char* const in_field[head_count] = {"h1.phi_in", "h2.phi_in"};
  static const char* const out_field[head_count] = {"h1.phi_out", "h2.phi_out"};
  static const char* const status_field[head_count] = {"h1.status", "h2.status"};
  for (int k = 0; k < head_count; ++k) {
    VALUE("sample", i, in_field[k], r->corrected[k].phi_in_rad);
    VALUE("sample", i, out_field[k], r->corrected[k].phi_out_rad);
    probe_status("sample", i, status_field[k], (int)r->estimates[k].status);
  }
  probe_status("sample", i, "status", (int)r->attitude.status);
  VALUE("sample", i, "roll", r->attitude.roll_rad);
  VALUE("sample", i, "pitch", r->attitude.pitch_rad);
}
#endif

#ifndef CONESCAN_PROBE_SIZE_ONLY
/* Static storage, as flight code keeps its heads. */
static head heads[head_count];

static void build_heads(void) {
  for (int k = 0; k < head_count; ++k) {
    const C(conescan_head_config)
        config = {0, (k == 0 ? 90 : -90) * degree, 45 * degree, 0, 0, 10 * degree};
    probe_status("head", k, "status", (int)C(conescan_head_init)(&heads[k], &config));
  }
}
#endif

#ifdef CONESCAN_PROBE_SIZE_ONLY
/* The entry point alone: one sample processed by heads the compiler cannot see. */
void probe_main(void) {
  measured_call c;
  c.heads = (const head*)(const void*)probe_opaque_bytes;
  c.in = *(const sample*)(const void*)(probe_opaque_bytes + head_count * sizeof(head));
  call(&c);
  probe_status("size", 0, "status", (int)c.out.attitude.status);
}
#else
void probe_main(void) {
  build_heads();
  for (int i = 0; i < paper_sample_count; ++i) {
    const sample s = sample_at(i);
    const result r = process(heads, &s);
    write(i, &r);
  }
  /* The statuses by name, as the C enum spells them. */
  for (int s = CONESCAN_OK; s <= CONESCAN_NONE; ++s)
    probe_text(conescan_status_name((conescan_status)s));
  measured_call c;
  c.heads = heads;
  c.in = sample_at(1);
  probe_measure("c_corrected_sample", call, &c);
  probe_limit("c_corrected_sample", "stack", sizeof(real) == sizeof(float) ? 1024 : 2048);
  /* The correction is the difference of two predicted chords (and phases) of ~2 rad: their
   * libm's last bits, a few ulps of 1 rad. */
  probe_tolerance("h1.phi_in", 4);
  probe_tolerance("h1.phi_out", 4);
  probe_tolerance("h2.phi_in", 4);
  probe_tolerance("h2.phi_out", 4);
  probe_tolerance("roll", 4);
  probe_tolerance("pitch", 4);
}
#endif
