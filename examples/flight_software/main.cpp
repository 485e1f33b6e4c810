// Flight-software-style attitude processing with the conescan core, calibrated on board.
//
// Turns what a conical Earth sensor's telemetry gives, per head and per scan — the Earth width
// (chord W) and the phase m of its centre from the reference pulse, in degrees — plus the orbit
// radius into the sensed roll and pitch, with a status at every step (MODEL §6, §7), and corrects
// each head's crossings by its calibration from the ground (conescan-fit's estimates, as
// calibration.h from scripts/fit-header.py) exactly as conescan-sim --apply does (MODEL §11).
// Written as flight code is written: float only, no heap, no exceptions or RTTI, no printf (the
// platform writes lines: output.hpp), no GeographicLib; only <conescan/conescan.hpp>. It runs on
// the host (ctest package.flight_software_example) and on a Cortex-M7 under QEMU (ctest
// flight.example, docs/FLIGHT_SOFTWARE.md), where nothing that allocates would even link.
//
// The heads are conescan::sensor_head objects, built once at start-up from their mounting and
// nominal cone. The pipeline for one telemetry sample (each step one core function):
//   orbit radius r             -> disk_trig_of          -> assumed Earth disk (sin, cos rho)
//   chord W, phase m (head k)  -> crossings::from_chord_phase
//   crossings, disk            -> sensor_head::process  -> sensed nadir of each head
//   the heads' nadirs          -> combine_heads         -> system nadir, the geometry at which
//   crossings, calibration     -> calibrated_crossings  -> crossings less the modelled errors
//   corrected crossings        -> process, combine_heads, roll_pitch_from_nadir -> roll, pitch
//
// The telemetry (telemetry.hpp) is the README's calibrated scene with the true attitude zero, so
// the roll and pitch it prints are the errors: before and after the correction, then the
// statuses of corrupted samples. It exits 1 when the corrected errors are not below the bound.
#include <conescan/conescan.hpp>

#include <cstddef>

#include "output.hpp"
#include "telemetry.hpp"
#define CONESCAN_FIT_SCALAR float
#include "calibration.h"

#if __STDC_HOSTED__
#include <cstdlib>
#include <new>

// Ground check of the no-heap rule on a hosted build: any C++ allocation stops the program here.
// (On the bare-metal target there is no operator new at all: an allocation would not link.)
void* operator new(std::size_t) {
  std::abort();
}
void* operator new[](std::size_t) {
  std::abort();
}
void operator delete(void*) noexcept {}
void operator delete[](void*) noexcept {}
void operator delete(void*, std::size_t) noexcept {}
void operator delete[](void*, std::size_t) noexcept {}
#endif

namespace {

using conescan::deg_to_rad;
using conescan::rad_to_deg;
using conescan::status;

constexpr int head_count = 2;
static_assert(CONESCAN_FIT_HEAD_COUNT == head_count, "calibration.h is for another pair");

/// OH-1 on the +pitch side of the orbit plane, OH-2 its mirror image: alpha 0, beta +-90 deg,
/// the nominal cone gamma 45 deg (the electronics know of no misalignment).
conescan::sensor_head<float> make_head(int k) {
  return conescan::sensor_head<float>::from_mounting(0.f, deg_to_rad(k == 0 ? 90.f : -90.f),
                                                     {deg_to_rad(45.f), 0.f, 0.f});
}

/// The sphere the processing assumes (km): WGS84 a plus the horizon the scene declares.
constexpr float earth_radius_km = 6378.137f;
constexpr float processing_horizon_km = 42.f;

/// The calibration from the ground (calibration.h), per head.
constexpr conescan::head_calibration<float> calibration[head_count] = CONESCAN_FIT_CALIBRATION;

/// Bound on the corrected errors, deg: the README's double-precision --apply leaves 4.7e-5 deg;
/// float adds ~1e-5 deg (its 6e-6 deg per radian's ulp through the chord inversion).
constexpr float corrected_bound_deg = 1e-4f;

/// One telemetry sample: the orbit radius (km), each head's chord and phase (rad); a negative
/// chord marks a lost word.
struct sample {
  float r_km;
  float chord[head_count];
  float phase[head_count];
};

struct solution {
  status head_state[head_count];
  status state;  ///< ok, or none when no head is ok
  float roll_deg;
  float pitch_deg;
};

using heads_array = conescan::sensor_head<float>[head_count];

/// The system nadir of the heads' crossings on the assumed disk.
conescan::head_estimate<float> system_nadir(
    const heads_array& heads, const conescan::crossings<float> (&measured)[head_count],
    const conescan::disk_trig<float>& assumed, status (&states)[head_count]) {
  conescan::head_estimate<float> estimates[head_count];
  for (int k = 0; k < head_count; ++k) {
    estimates[k] = heads[k].process(measured[k], assumed);
    states[k] = estimates[k].state;
  }
  return conescan::combine_heads<float>(estimates, estimates + head_count);
}

/// The pipeline of one sample, with the calibration on board or without. Every failure is a
/// status; nothing throws, nothing allocates.
solution process_sample(const sample& s, const heads_array& heads, bool calibrated) {
  const conescan::disk_trig<float> assumed =
      conescan::disk_trig_of(earth_radius_km + processing_horizon_km, s.r_km);
  conescan::crossings<float> measured[head_count];
  for (int k = 0; k < head_count; ++k)
    measured[k] = s.chord[k] < 0.f
                      ? conescan::crossings<float>::failed(status::invalid)
                      : conescan::crossings<float>::from_chord_phase(s.chord[k], s.phase[k]);
  solution out{};
  conescan::head_estimate<float> system = system_nadir(heads, measured, assumed, out.head_state);
  if (calibrated && system.state == status::ok) {
    // The modelled errors at the first estimate's nadir, on the sphere of the fitted horizon.
    const conescan::disk_trig<float> fitted =
        conescan::disk_trig_of(earth_radius_km + CONESCAN_FIT_HORIZON_KM, s.r_km);
    for (int k = 0; k < head_count; ++k)
      measured[k] =
          conescan::calibrated_crossings(measured[k], heads[k].optics().gamma, calibration[k],
                                         heads[k].in_scan_frame(system.nadir), fitted);
    system = system_nadir(heads, measured, assumed, out.head_state);
  }
  out.state = system.state;
  out.roll_deg = out.pitch_deg = conescan::not_a_number<float>();
  if (system.state == status::ok) {
    const conescan::roll_pitch<float> rp = conescan::roll_pitch_from_nadir(system.nadir);
    out.roll_deg = rad_to_deg(rp.roll);
    out.pitch_deg = rad_to_deg(rp.pitch);
  }
  return out;
}

sample telemetry_sample(int i) {
  const double* row = telemetry_rows[i];
  sample s{static_cast<float>(row[0]), {}, {}};
  for (int k = 0; k < head_count; ++k) {
    s.chord[k] = deg_to_rad(static_cast<float>(row[1 + 2 * k]));
    s.phase[k] = deg_to_rad(static_cast<float>(row[2 + 2 * k]));
  }
  return s;
}

float magnitude(float x) {
  return x < 0.f ? -x : x;
}

/// The largest |roll| and |pitch| over the telemetry (deg), or -1 when a sample is not ok.
void largest_errors(const heads_array& heads, bool calibrated, float& roll, float& pitch) {
  roll = pitch = 0.f;
  const int rows = static_cast<int>(sizeof telemetry_rows / sizeof telemetry_rows[0]);
  for (int i = 0; i < rows; ++i) {
    const solution a = process_sample(telemetry_sample(i), heads, calibrated);
    if (a.state != status::ok) {
      roll = pitch = -1.f;
      return;
    }
    if (magnitude(a.roll_deg) > roll) roll = magnitude(a.roll_deg);
    if (magnitude(a.pitch_deg) > pitch) pitch = magnitude(a.pitch_deg);
  }
}

/// Corrupted samples, as a link makes them, and the statuses they must give.
struct corrupted {
  const char* what;
  sample s;
  status head_state[head_count];
  status state;
};

bool check_corrupted(const heads_array& heads) {
  const float deg = deg_to_rad(1.f);
  const corrupted cases[] = {
      {"OH-2 grazes (chord 0.05 deg)",
       {8005.f, {64.5f * deg, 0.05f * deg}, {0.3f * deg, 0.f}},
       {status::ok, status::grazing},
       status::ok},
      {"OH-1 word lost",
       {8007.f, {-1.f, 359.98f * deg}, {0.3f * deg, 0.f}},
       {status::invalid, status::grazing},
       status::none},
      {"radius below the horizon sphere",
       {6000.f, {64.5f * deg, 60.7f * deg}, {0.3f * deg, -0.3f * deg}},
       {status::invalid, status::invalid},
       status::none},
  };
  bool good = true;
  for (const corrupted& c : cases) {
    const solution a = process_sample(c.s, heads, true);
    const bool expected = a.state == c.state && a.head_state[0] == c.head_state[0] &&
                          a.head_state[1] == c.head_state[1];
    line l;
    l << c.what << ": OH-1 " << conescan::to_string(a.head_state[0]) << ", OH-2 "
      << conescan::to_string(a.head_state[1]) << ", system " << conescan::to_string(a.state)
      << (a.state == status::ok ? "" : ": hold the last attitude estimate")
      << (expected ? "" : "  MISMATCH");
    l.write();
    good = good && expected;
  }
  return good;
}

}  // namespace

int main() {
  // The heads, built once. A mounting or cone outside the domain makes a head invalid: the
  // software must then not start.
  const heads_array heads = {make_head(0), make_head(1)};
  for (const conescan::sensor_head<float>& head : heads)
    if (head.state() != status::ok) {
      line l;
      l << "flight_software: a head is outside its domain; not starting";
      l.write();
      return 1;
    }
  float roll_raw, pitch_raw, roll, pitch;
  largest_errors(heads, false, roll_raw, pitch_raw);
  largest_errors(heads, true, roll, pitch);
  const int rows = static_cast<int>(sizeof telemetry_rows / sizeof telemetry_rows[0]);
  line summary;
  summary << "flight_software: " << rows << " samples of the calibrated scene, float";
  summary.write();
  line raw;
  raw << "  without the calibration: max |roll| ";
  raw.scientific(roll_raw) << " deg, max |pitch| ";
  raw.scientific(pitch_raw) << " deg";
  raw.write();
  line corrected;
  corrected << "  corrected on board:      max |roll| ";
  corrected.scientific(roll) << " deg, max |pitch| ";
  corrected.scientific(pitch) << " deg";
  corrected.write();
  const bool below =
      roll >= 0.f && pitch >= 0.f && roll < corrected_bound_deg && pitch < corrected_bound_deg;
  if (!below) {
    line l;
    l << "  MISMATCH: the corrected errors exceed ";
    l.scientific(corrected_bound_deg) << " deg";
    l.write();
  }
  const bool statuses = check_corrupted(heads);
  return below && statuses ? 0 : 1;
}
