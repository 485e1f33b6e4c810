// Flight-software-style attitude processing with the conescan core.
//
// Turns what a conical Earth sensor's telemetry gives, per head and per scan — the Earth width
// (chord W) and the phase m of its centre from the reference pulse, in degrees — plus the orbit
// radius into the sensed roll and pitch, with a status at every step (MODEL §6, §7).
// Written as flight code is written: float only, no heap (fixed-size arrays), no exceptions or
// RTTI (built with -fno-exceptions -fno-rtti), no GeographicLib; only <conescan/conescan.hpp>.
//
// The heads are conescan::sensor_head objects, built once at start-up from their mounting and
// nominal cone (everything that depends on the head alone is computed then). The pipeline for
// one telemetry sample (each step one core function):
//   orbit radius r            -> disk_trig_of             -> assumed Earth disk (sin, cos rho_p)
//   chord W, phase m (head k) -> crossings phi_in = m - W/2, phi_out = m + W/2
//   crossings, disk           -> sensor_head::process     -> sensed nadir n_s (body axes)
//   n_s of the heads          -> combine_heads            -> system nadir (heads with status ok)
//   system nadir              -> roll_pitch_from_nadir    -> roll, pitch
//
// The telemetry below replays conescan-sim rows of the paper's orbit (a = 7280 km, e = 0.1) for
// the two-head pair of data/scenes/paper-fig2b.toml, then corrupts some of it as a real link
// would. The program checks every status and value against its expectation and exits 1 on a
// mismatch, so ctest can run it (tests/find_package/run_example.cmake).
#include <conescan/conescan.hpp>

#include <array>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <new>

// Ground check of the no-heap rule: any C++ allocation in this program stops it here.
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

namespace {

using conescan::deg_to_rad;
using conescan::rad_to_deg;
using conescan::status;

constexpr std::size_t head_count = 2;

/// A head's fixed configuration, deg: mounting alpha (elevation of the spin axis towards
/// nadir), beta (azimuth from +x towards +y), and the nominal half-apex cone angle gamma.
struct head_config {
  float alpha_deg;
  float beta_deg;
  float gamma_deg;
};

/// OH-1 on the +pitch side of the orbit plane, OH-2 its mirror image (paper-fig2b.toml).
constexpr std::array<head_config, head_count> heads_config{{{0.f, 90.f, 45.f}, {0.f, -90.f, 45.f}}};

/// Radius of the sphere the processing assumes, km: WGS84 a plus the IR horizon height. The
/// paper's scene puts the horizon on the surface; a 14-16 um sensor would add about 40 km.
constexpr float processing_radius_km = 6378.137f;

/// One scan of one head as telemetry gives it, deg. NaN marks a dropped word.
struct head_telemetry {
  float chord_deg;  ///< Earth width W = phi_out - phi_in, (0, 360)
  float phase_deg;  ///< m = (phi_in + phi_out) / 2 from the reference pulse
};

struct telemetry_sample {
  const char* what;
  float t_s;   ///< time since t = 0, s
  float r_km;  ///< orbit radius from the navigation solution, km
  std::array<head_telemetry, head_count> heads;
};

/// The processing's output for one sample.
struct attitude_solution {
  std::array<status, head_count> head_state;
  std::array<float, head_count> head_roll_deg;   ///< NaN unless the head's status is ok
  std::array<float, head_count> head_pitch_deg;  ///< NaN unless the head's status is ok
  float roll_deg;                                ///< system solution; NaN unless ok
  float pitch_deg;
  status state;  ///< ok, or none when no head is ok
};

using heads_array = std::array<conescan::sensor_head<float>, head_count>;

/// The head with configuration k: the nominal cone (the electronics know of no misalignment).
conescan::sensor_head<float> make_head(std::size_t k) {
  return conescan::sensor_head<float>::from_mounting(
      deg_to_rad(heads_config[k].alpha_deg), deg_to_rad(heads_config[k].beta_deg),
      {deg_to_rad(heads_config[k].gamma_deg), 0.f, 0.f});
}

/// The pipeline of one telemetry sample. Every failure is a status; nothing throws, nothing
/// allocates, no NaN leaves without a status saying why.
attitude_solution process_sample(const telemetry_sample& sample, const heads_array& heads) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  attitude_solution out{};

  // Earth disk the processing assumes, from the orbit radius (MODEL §6). A radius inside the
  // assumed sphere (a corrupt navigation word) makes the disk, and so every head, invalid.
  const conescan::disk_trig<float> assumed =
      conescan::disk_trig_of(processing_radius_km, sample.r_km);

  std::array<conescan::head_estimate<float>, head_count> estimates{};
  for (std::size_t k = 0; k < head_count; ++k) {
    // The measured crossings from the telemetry: the chord is centred on the phase. Their range
    // (chord in (0, 360) deg, finite) is checked by the inversion, which says invalid.
    const float phase = deg_to_rad(sample.heads[k].phase_deg);
    const float half_chord = deg_to_rad(sample.heads[k].chord_deg) / 2.f;
    const float phi_in = phase - half_chord, phi_out = phase + half_chord;
    const conescan::crossings<float> measured{phi_in, phi_out, status::ok, 0};
    estimates[k] = heads[k].process(measured, assumed);
    out.head_state[k] = estimates[k].state;
    out.head_roll_deg[k] = nan;
    out.head_pitch_deg[k] = nan;
    if (estimates[k].state == status::ok) {
      // Per-head roll/pitch: diagnostics for the ground (a head drifting from its partner).
      const conescan::roll_pitch<float> rp = conescan::roll_pitch_from_nadir(estimates[k].nadir);
      out.head_roll_deg[k] = rad_to_deg(rp.roll);
      out.head_pitch_deg[k] = rad_to_deg(rp.pitch);
    }
  }

  // System solution: the normalised mean nadir of the heads that are ok.
  const conescan::head_estimate<float> system =
      conescan::combine_heads<float>(estimates.begin(), estimates.end());
  out.state = system.state;
  out.roll_deg = nan;
  out.pitch_deg = nan;
  if (system.state == status::ok) {
    const conescan::roll_pitch<float> rp = conescan::roll_pitch_from_nadir(system.nadir);
    out.roll_deg = rad_to_deg(rp.roll);
    out.pitch_deg = rad_to_deg(rp.pitch);
  }
  return out;
}

/// What each sample must give (from conescan-sim in double: true attitude + its error).
struct expectation {
  std::array<status, head_count> head_state;
  status state;
  float roll_deg;
  float pitch_deg;
};

/// Float's share: ~1e-7 relative in the angles, amplified by the chord inversion (<= 100, the
/// fold limit, and ~1 to 10 on these rows); 5e-4 deg still resolves the 6e-3 deg misalignment.
constexpr float tolerance_deg = 5e-4f;

bool near(float a, float b) {
  const float d = a - b;
  return d <= tolerance_deg && -d <= tolerance_deg;
}

}  // namespace

int main() {
  // The heads, built once. A mounting or cone outside the domain (|alpha| >= 90 deg, gamma
  // outside (0, 90) deg) makes a head invalid: the software must then not start.
  const heads_array heads{make_head(0), make_head(1)};
  for (const conescan::sensor_head<float>& head : heads)
    if (head.state() != status::ok) {
      std::printf("flight_software: a head is outside its domain; not starting\n");
      return 1;
    }

  const float nan = std::numeric_limits<float>::quiet_NaN();
  // Telemetry: orbit radius, then {chord, phase} of OH-1 and OH-2, deg. The first three rows are
  // conescan-sim's paper-fig2b.toml scene at t = 0, 1500 and 3000 s, the last two with
  // --roll-deg 0.5 --pitch-deg -0.3; at 3000 s OH-2's chord is replaced by a grazing one. The
  // rest are corrupted on purpose.
  // clang-format off
  const std::array<telemetry_sample, 6> telemetry{{
      {"perigee, zero attitude", 0.f, 6552.f,
       {{{142.248712f, 0.f}, {142.248712f, 0.f}}}},
      {"roll 0.5, pitch -0.3", 1500.f, 7319.06373f,
       {{{93.5705660f, 0.300011423f}, {90.7963646f, -0.300011423f}}}},
      {"OH-2 grazes (chord 0.05 deg)", 3000.f, 8005.43578f,
       {{{64.5100683f, 0.300011423f}, {0.05f, 0.f}}}},
      {"OH-1 word lost, OH-2 near 360", 3010.f, 8007.6f,
       {{{nan, 0.3f}, {359.98f, 0.f}}}},
      {"radius below the horizon sphere", 3020.f, 6000.f,
       {{{64.5f, 0.3f}, {60.7f, -0.3f}}}},
      {"chord out of range", 3030.f, 8012.f,
       {{{-4.f, 0.3f}, {400.f, -0.3f}}}},
  }};
  const std::array<expectation, telemetry.size()> expected{{
      // {OH-1, OH-2} status               system        roll_deg                 pitch_deg
      // Mirrored heads: +/-0.00647 deg of roll each, cancelling in the system solution.
      {{status::ok, status::ok},           status::ok,   0.f,                     0.f},
      {{status::ok, status::ok},           status::ok,   0.5f - 0.000265069f,     -0.3f},
      // OH-2 is dropped; the system falls back on OH-1 alone, bias and all.
      {{status::ok, status::grazing},      status::ok,   0.5f + 0.0168629f,       -0.3f + 7.8e-7f},
      {{status::invalid, status::grazing}, status::none, nan,                     nan},
      {{status::invalid, status::invalid}, status::none, nan,                     nan},
      {{status::invalid, status::invalid}, status::none, nan,                     nan},
  }};
  // clang-format on

  std::printf("%-32s %7s  %-8s %9s %9s  %-8s %9s %9s  %-6s %9s %9s\n", "sample", "t_s", "OH-1",
              "roll_deg", "pitch_deg", "OH-2", "roll_deg", "pitch_deg", "system", "roll_deg",
              "pitch_deg");
  int failures = 0;
  for (std::size_t i = 0; i < telemetry.size(); ++i) {
    const attitude_solution a = process_sample(telemetry[i], heads);
    std::printf("%-32s %7.0f  %-8s %9.5f %9.5f  %-8s %9.5f %9.5f  %-6s %9.5f %9.5f\n",
                telemetry[i].what, static_cast<double>(telemetry[i].t_s),
                conescan::to_string(a.head_state[0]), static_cast<double>(a.head_roll_deg[0]),
                static_cast<double>(a.head_pitch_deg[0]), conescan::to_string(a.head_state[1]),
                static_cast<double>(a.head_roll_deg[1]), static_cast<double>(a.head_pitch_deg[1]),
                conescan::to_string(a.state), static_cast<double>(a.roll_deg),
                static_cast<double>(a.pitch_deg));
    // What the attitude controller does with it: use an ok solution, hold otherwise.
    if (a.state != status::ok)
      std::printf("%-32s -> no valid solution (%s): hold the last attitude estimate\n", "",
                  conescan::to_string(a.state));

    const expectation& e = expected[i];
    bool good = a.state == e.state && a.head_state == e.head_state;
    if (e.state == status::ok)
      good = good && near(a.roll_deg, e.roll_deg) && near(a.pitch_deg, e.pitch_deg);
    else
      good = good && a.roll_deg != a.roll_deg && a.pitch_deg != a.pitch_deg;  // NaN
    if (!good) {
      std::printf("%-32s -> MISMATCH: expected system %s, roll %.5f, pitch %.5f\n", "",
                  conescan::to_string(e.state), static_cast<double>(e.roll_deg),
                  static_cast<double>(e.pitch_deg));
      ++failures;
    }
  }
  std::printf("%d of %zu samples as expected\n", static_cast<int>(telemetry.size()) - failures,
              telemetry.size());
  return failures == 0 ? 0 : 1;
}
