// A scene: everything conescan-sim simulates, as a user writes it (km, s, degrees; MODEL §9).
//
// The scene is kept in the user's units because it is what scene files and options hold, and
// every validation message must quote the value the user typed. The simulation converts to SI
// and radians once, at construction. A pure value: what its files hold is a loaded_scene's
// (loaded_scene.hpp), and its checks (validate) are scene_validation.hpp's.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "conescan/nadir_angle.hpp"
#include "conescan/sensor_physics/field.hpp"
#include "conescan/sensor_physics/locator.hpp"
#include "text/diagnostic.hpp"

namespace conescan::scene {

enum class earth_model { sphere, wgs84 };
enum class forward_model { bias, scan };
/// The sphere the processing assumes (MODEL §6): `truth` is the truth sphere's R on --earth
/// sphere and WGS84 a on --earth wgs84 (the defaults MODEL §6 names); `equatorial` is WGS84 a;
/// `local` the WGS84 radius along r; `value` processing_radius_km.
enum class processing_radius_kind { truth, equatorial, local, value };

/// How the system solution is formed: MODEL §6's normalised mean of the per-head
/// sensed nadirs, or one least-squares nadir from the horizon vectors of all crossings.
enum class processing_method { chord_phase, horizon_vector };

/// One sensor head (degrees). Defaults: the paper's head (MODEL §8).
struct head_config {
  double alpha_deg = 0;     ///< spin-axis elevation from the roll-pitch plane towards nadir
  double beta_deg = 90;     ///< azimuth of its projection from +x towards +y
  double gamma_deg = 45;    ///< half-apex cone angle
  double sigma_deg = 0.02;  ///< misalignment of the optical axis from the spin axis
  double phase_deg = 0;     ///< azimuth phi_A of the misalignment about the spin axis
  double noise_deg = 0;     ///< detector noise, 1 sigma, on each crossing azimuth, [0, 10]
  double lsb_deg = 0;       ///< telemetry step of the chord and the phase: 0, or [1e-9, 10]
  // Fixed biases (MODEL §11: what conescan-fit estimates, hK.dgamma, hK.bias-in,
  // hK.bias-out): the true half-apex angle is gamma + dgamma (the electronics assume gamma), each
  // measured crossing azimuth the true one plus its bias.
  double dgamma_deg = 0;    ///< cone-angle bias, gamma + dgamma in (0, 90) and above sigma
  double bias_in_deg = 0;   ///< Earth-in crossing bias, [-10, 10]
  double bias_out_deg = 0;  ///< Earth-out crossing bias, [-10, 10]
  // Sensor physics (MODEL §12; scene_physics.hpp): at their defaults the crossings are MODEL §5's.
  double fov_deg = 0;  ///< field of view's full width, 0 (a pencil beam) or [0.001, 90)
  field_shape shape = field_shape::square;  ///< the field's shape (head key fov-shape=)
  double spin_hz = 0;                       ///< scan rate, rev/s, 0 or [0.001, 1000]
  double tau_ms = 0;  ///< detector time constant, ms, 0 or [1e-6, 1000]; > 0 needs spin_hz
  /// Where the electronics place a crossing on the detector's output (head key locator=).
  locator_kind locator = locator_kind::normalised;
  double threshold = 0.5;  ///< normalised: k in (0, 1); fixed: T > 0 (units of L0)

  /// The field of view's full width, deg, that MODEL §13's intrusion rule widens the pulses by
  /// (0, a pencil beam: only the body's own radius counts).
  double field_of_view_deg() const noexcept { return fov_deg; }
};

/// Most heads a scene may have (the pipeline keeps them on the stack).
inline constexpr std::size_t max_heads = 16;

/// The direction accuracy an OEM's interpolation must reach by default (its error estimate,
/// sources/oem.hpp), deg; --interpolation-tolerance-deg raises it for a coarse ephemeris.
inline constexpr double default_interpolation_tolerance_deg = 1e-6;
/// The largest tolerance --interpolation-tolerance-deg accepts, deg.
inline constexpr double max_interpolation_tolerance_deg = 1;

/// Default maximum number of rows; --max-rows raises it.
inline constexpr std::uint64_t default_max_rows = 10'000'000;

/// Defaults: the paper's scene (MODEL §8).
struct scene_config {
  // time and sources (MODEL §10): file paths as given ("" = not given), read by load_scene into
  // the scene's source_files (loaded_scene.hpp, source_files.hpp)
  std::string epoch_utc;  ///< ISO 8601 UTC; "" = the source's epoch (MODEL §10)
  std::string tle_file;   ///< orbit from a two-line element set (SGP4/SDP4)
  std::string omm_file;   ///< orbit from an OMM (KVN, XML, CSV, JSON; SGP4/SDP4)
  /// The element set of a catalogue tle_file or omm_file: its NORAD catalogue number,
  /// international designator or name (orbit/catalogue.hpp); "" = the file's only set.
  std::string object;
  std::string oem_file;           ///< orbit from a CCSDS OEM
  std::string eop_file;           ///< IERS Earth orientation (finals2000A) for an ITRF OEM
  std::string aem_file;           ///< true attitude from a CCSDS AEM
  std::string attitude_csv_file;  ///< true attitude from a table of angles or quaternions
  /// The inertial frame of an attitude table's quaternions (CCSDS name: EME2000, GCRF, ICRF,
  /// TEME, TOD); star trackers give J2000, which is EME2000.
  std::string attitude_frame = "EME2000";
  /// An OEM interval whose interpolation error estimate exceeds this is refused (deg).
  double interpolation_tolerance_deg = default_interpolation_tolerance_deg;
  // orbit
  double a_km = 7280;
  double e = 0.1;
  double i_deg = 97.7;
  double raan_deg = 0;
  double argp_deg = 0;
  double m0_deg = 0;
  bool sun_sync = false;  ///< derive i from a, e (i_deg is ignored)
  bool j2 = false;        ///< J2 secular drift of Omega, omega, M
  // time
  double step_s = 10;
  double orbits = 1;                 ///< duration in two-body periods, unless duration_s
  std::optional<double> duration_s;  ///< overrides orbits
  std::uint64_t max_rows = default_max_rows;
  // Earth
  earth_model earth = earth_model::sphere;
  std::optional<double> radius_km;  ///< truth sphere radius; default WGS84 a
  double horizon_km = 0;            ///< horizon height h_h (h0) above the surface
  // Apparent horizon surface (wgs84 only): polar radius b + h0 + horizon_pole_km,
  // centre moved along +z by horizon_shift_km * sin(sun declination).
  double horizon_pole_km = 0;
  double horizon_shift_km = 0;
  std::optional<double> sun_declination_deg;
  /// false: the truth ellipsoid starts from a sphere of radius a instead of WGS84 (a, b). Not an
  /// option: the error budget uses it to isolate the horizon's latitude and season terms.
  bool geodetic_flattening = true;
  /// Horizon height the processing assumes (default: horizon_km, i.e. known exactly).
  std::optional<double> processing_horizon_km;
  processing_radius_kind processing_radius = processing_radius_kind::truth;
  double processing_radius_km = 0;  ///< used when processing_radius == value
  // model
  forward_model model = forward_model::bias;
  processing_method processing = processing_method::chord_phase;
  std::vector<head_config> heads = std::vector<head_config>(1);  // the paper's head
  // true attitude (3-2-1: yaw, pitch, roll from orbital to body)
  double roll_deg = 0;
  double pitch_deg = 0;
  double yaw_deg = 0;
  /// Largest excursion of the true nadir angle from nominal (MODEL §7): a chord whose inversion
  /// roots both lie within it of eta0 is `ambiguous`.
  double attitude_envelope_deg = default_attitude_envelope_deg;
  /// The Sun and the Moon in each head's scan (MODEL §13, --intrusions; scene_sky.hpp).
  bool intrusions = false;
  // The limb's radiance (MODEL §12; scene_physics.hpp): L(delta) = L0 [1 - exp(-ln 2
  // e^{-(delta - delta50)/H})], L_disk L0 on the disk, L0 = 1 + A sin(lat) sin(dec) / sin 23.44.
  double radiance_scale_km = 7;   ///< H, [0, 1000] km (0: a step edge)
  double radiance_offset_km = 0;  ///< delta50 above the horizon surface, [-1000, 1000] km
  double radiance_disk = 1;       ///< L_disk / L0, [0, 100]
  double radiance_season = 0;     ///< A, (-1, 1)
  // detector noise draws
  std::uint64_t seed = 1;  ///< with the run, row, head and crossing, defines every noise draw
  std::uint64_t runs = 1;  ///< independent repetitions of the scene (different noise)
};

/// True when any head has detector noise.
bool has_noise(const scene_config& scene);

/// The inclination that the scene uses, deg: i_deg, or the sun-synchronous one.
double effective_inclination_deg(const scene_config& scene);
/// cos i of the sun-synchronous orbit of the scene's a and e (WGS84 J2); |cos i| > 1 when none
/// exists (validate() refuses sun_sync then).
double sun_synchronous_cos_inclination(const scene_config& scene);

/// A file a run reads, and the option that named it.
struct input_file {
  std::string_view option;
  std::string path;
};

/// The source files a scene reads (--tle, --omm, --oem, --aem, --attitude-csv), those given.
std::vector<input_file> scene_input_files(const scene_config& scene);

/// Success unless the output `path` of `option` is one of `inputs` (the same file: the same
/// inode, or the same resolved path): a run never writes over what it reads.
checked<void> output_apart_from_inputs(std::string_view option, const std::string& path,
                                       std::span<const input_file> inputs);

}  // namespace conescan::scene
