/* conescan's core for flight code written in C: plain structs and functions over the C++ core,
 * in float (suffix _f) and double (suffix _d). A C or C++ program includes this header; exactly
 * one of its C++ files defines the functions by including conescan/c_interface.hpp (the core's
 * templates instantiated for float and double: C++17, -fno-exceptions -fno-rtti, no heap).
 *
 * What a flight loop calls, per head and per scan (MODEL §6, §7):
 *   at start-up   conescan_head_init_*      a head from its mounting and optics, in the caller's
 *                                           storage (a static conescan_head_* object)
 *   per sample    conescan_disk_of_*       the assumed Earth disk from the orbit radius
 *                 conescan_crossings_of_*   a telemetry's chord and phase as crossings
 *                 conescan_correct_*        the crossings corrected by the head's calibration
 *                                           (conescan-fit's estimates; optional)
 *                 conescan_process_*        crossings -> the head's sensed nadir
 *                 conescan_combine_*        the system nadir of the heads that are ok
 *                 conescan_roll_pitch_*     roll and pitch of a nadir
 * Angles in rad unless a name says deg; lengths in any one unit. Every result carries a
 * conescan_status; on any status but CONESCAN_OK its values are NaN. Nothing allocates, nothing
 * prints, nothing keeps state between calls. docs/FLIGHT_SOFTWARE.md shows a loop and its costs
 * on a Cortex-M7.
 */
#ifndef CONESCAN_CONESCAN_H
#define CONESCAN_CONESCAN_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Why a value could (not) be computed: MODEL §7, the values of conescan::status. */
typedef enum conescan_status {
  CONESCAN_OK = 0,    /* the value is valid */
  CONESCAN_MISS,      /* the scan cone does not reach the Earth */
  CONESCAN_ENGULFED,  /* the whole scan cone lies on the Earth */
  CONESCAN_GRAZING,   /* chord near 0 or 360 deg */
  CONESCAN_MULTIPLE,  /* four crossings: no one chord */
  CONESCAN_FOLD,      /* the chord no longer determines the nadir angle */
  CONESCAN_AMBIGUOUS, /* both inversion roots lie within the attitude envelope */
  CONESCAN_GIMBAL,    /* pitch within 1.91 deg of +-90 deg */
  CONESCAN_SUN,       /* the Sun's pulse meets the Earth pulse */
  CONESCAN_MOON,      /* the Moon's pulse meets the Earth pulse */
  CONESCAN_INVALID,   /* an input lies outside the model's domain */
  CONESCAN_NONE       /* system solution: no head is ok */
} conescan_status;

/* The status's name as the CSV spells it ("ok", "miss", ...); NULL for a value outside the enum. */
const char* conescan_status_name(conescan_status status);

/* Declares the structs and functions of one scalar (float or double) and suffix (f or d). */
#define CONESCAN_C_INTERFACE(scalar, s)                                                         \
  /* A head's fixed configuration (rad): mounting alpha (elevation of the spin axis towards     \
   * nadir) and beta (azimuth from +x towards +y), MODEL §4; the nominal half-apex cone angle  \
   * gamma; the misalignment sigma at azimuth phi_a known on board (usually 0: the calibration  \
   * corrects it); the attitude envelope of MODEL §7 (0.17453 = 10 deg). */                    \
  typedef struct conescan_head_config_##s {                                                     \
    scalar alpha_rad, beta_rad, gamma_rad, sigma_rad, phi_a_rad, envelope_rad;                  \
  } conescan_head_config_##s;                                                                   \
  /* A head built by conescan_head_init_*: opaque, copyable, in the caller's storage. */        \
  typedef struct conescan_head_##s {                                                            \
    double storage[sizeof(scalar) == sizeof(float) ? 19 : 37];                                  \
  } conescan_head_##s;                                                                          \
  /* The Earth disk by the sine and cosine of its angular radius. */                            \
  typedef struct conescan_disk_##s {                                                            \
    scalar sin_rho, cos_rho;                                                                    \
    conescan_status status;                                                                     \
  } conescan_disk_##s;                                                                          \
  /* Earth-in and Earth-out scan azimuths (rad). */                                             \
  typedef struct conescan_crossings_##s {                                                       \
    scalar phi_in_rad, phi_out_rad;                                                             \
    conescan_status status;                                                                     \
  } conescan_crossings_##s;                                                                     \
  /* A sensed nadir (unit, body axes) and, for one head, its nadir angle from the spin axis. */ \
  typedef struct conescan_estimate_##s {                                                        \
    scalar nadir[3];                                                                            \
    scalar eta_rad;                                                                             \
    conescan_status status;                                                                     \
  } conescan_estimate_##s;                                                                      \
  typedef struct conescan_attitude_##s {                                                        \
    scalar roll_rad, pitch_rad;                                                                 \
    conescan_status status;                                                                     \
  } conescan_attitude_##s;                                                                      \
  /* A head's calibrated parameters as conescan-fit --json estimates them (deg; MODEL §11):    \
   * misalignment components sigma cos phi_A and sigma sin phi_A, cone-angle bias, crossing     \
   * biases. scripts/fit-header.py writes them from a fit. */                                   \
  typedef struct conescan_calibration_##s {                                                     \
    scalar misalignment_x_deg, misalignment_y_deg, dgamma_deg, bias_in_deg, bias_out_deg;       \
  } conescan_calibration_##s;                                                                   \
  /* Builds the head in *head; CONESCAN_OK, or CONESCAN_INVALID for a configuration outside the \
   * domain (|alpha| >= 90 deg, gamma outside (0, 90) deg, sigma >= gamma, a non-finite value,  \
   * an envelope outside [0, 90] deg), after which every call with it says invalid. */          \
  conescan_status conescan_head_init_##s(conescan_head_##s* head,                               \
                                         const conescan_head_config_##s* config);               \
  /* The disk of a sphere of `radius` seen from orbit radius r (same unit): invalid unless      \
   * 0 < radius < r, finite. */                                                                 \
  conescan_disk_##s conescan_disk_of_##s(scalar radius, scalar r);                              \
  /* A telemetry's chord W and phase m (rad) as crossings m -+ W/2 (range checked later). */    \
  conescan_crossings_##s conescan_crossings_of_##s(scalar chord_rad, scalar phase_rad);         \
  /* MODEL §6: the measured chord inverted on the assumed disk (the root nearest the head's    \
   * nominal nadir angle), the sensed nadir. Statuses: the crossings' own, invalid, fold,       \
   * grazing, ambiguous. */                                                                     \
  conescan_estimate_##s conescan_process_##s(const conescan_head_##s* head,                     \
                                             const conescan_crossings_##s* measured,            \
                                             const conescan_disk_##s* assumed);                 \
  /* The normalised mean nadir of the estimates that are ok; CONESCAN_NONE when none is. */     \
  conescan_estimate_##s conescan_combine_##s(const conescan_estimate_##s* estimates,            \
                                             size_t count);                                     \
  /* Roll and pitch of an estimate's nadir (MODEL §2); its status passes through. */           \
  conescan_attitude_##s conescan_roll_pitch_##s(const conescan_estimate_##s* estimate);         \
  /* The measured crossings less the modelled errors of the head's calibration (what            \
   * conescan-sim --apply subtracts, bit for bit), at the geometry given: the unit nadir in     \
   * body axes (the sample's first estimate) and the disk of the fitted horizon (R + horizon-km \
   * from r). Statuses: the crossings' own, the scan model's (miss, engulfed, grazing,          \
   * invalid), grazing when the correction closes the chord. */                                 \
  conescan_crossings_##s conescan_correct_##s(                                                  \
      const conescan_head_##s* head, const conescan_calibration_##s* calibration,               \
      const conescan_crossings_##s* measured, const scalar nadir_body[3],                       \
      const conescan_disk_##s* disk);

CONESCAN_C_INTERFACE(float, f)
CONESCAN_C_INTERFACE(double, d)

#ifdef __cplusplus
}
#endif

#endif
