#include "scene/option_table.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>

#include "conescan/enum_names.hpp"
#include "conescan/scalar.hpp"
#include "scene/head_spec.hpp"
#include "scene/scene_physics.hpp"
#include "scene/sensor_preset.hpp"
#include "sources/sun_declination.hpp"
#include "sources/time_scales.hpp"
#include "text/number_text.hpp"
#include "text/text_lines.hpp"

namespace conescan::scene {

namespace {

template <class V>
constexpr field_ref<V> scene_field(V scene_config::*member) {
  return {member, nullptr};
}
template <class V>
constexpr field_ref<V> request_field(V scene_request::*member) {
  return {nullptr, member};
}

// A TOML basic string (scene files are TOML, scene_file.hpp): a backslash escaped; quotes and
// control characters never reach here (check_text refuses them).
std::string in_quotes(std::string_view text) {
  std::string out = "\"";
  for (char c : text) out += c == '\\' ? std::string("\\\\") : std::string(1, c);
  return out + "\"";
}

// True when the field is at scene_config's default (--print-config then leaves it out).
template <double scene_config::*Field>
bool at_default(const scene_request& r) {
  static const scene_config defaults;
  return r.scene.*Field == defaults.*Field;
}

// --- Choices -------------------------------------------------------------------------------

constexpr std::array<std::string_view, 2> earth_words{"sphere", "wgs84"};
constexpr std::array<std::string_view, 2> model_words{"bias", "scan"};
constexpr std::array<std::string_view, 2> processing_words{"chord-phase", "horizon-vector"};
constexpr std::array<std::string_view, 2> preset_words{"none", "co2-15um"};
constexpr std::array<std::string_view, 5> attitude_frame_words{"EME2000", "GCRF", "ICRF", "TEME",
                                                               "TOD"};

constexpr choice_binding earth_choice{
    earth_words, [](scene_request& r, std::size_t k) { r.scene.earth = earth_model(k); },
    [](const scene_request& r) { return static_cast<std::size_t>(r.scene.earth); }};
constexpr choice_binding model_choice{
    model_words, [](scene_request& r, std::size_t k) { r.scene.model = forward_model(k); },
    [](const scene_request& r) { return static_cast<std::size_t>(r.scene.model); }};
constexpr choice_binding processing_choice{
    processing_words,
    [](scene_request& r, std::size_t k) { r.scene.processing = processing_method(k); },
    [](const scene_request& r) { return static_cast<std::size_t>(r.scene.processing); }};
constexpr choice_binding attitude_frame_choice{
    attitude_frame_words,
    [](scene_request& r, std::size_t k) {
      r.scene.attitude_frame = std::string(attitude_frame_words[k]);
    },
    [](const scene_request& r) {
      return static_cast<std::size_t>(std::find(attitude_frame_words.begin(),
                                                attitude_frame_words.end(),
                                                r.scene.attitude_frame) -
                                      attitude_frame_words.begin());
    }};
constexpr choice_binding sensor_preset_choice{
    sensor_preset_words, [](scene_request& r, std::size_t k) { r.sensor = sensor_preset(k); },
    [](const scene_request& r) { return static_cast<std::size_t>(r.sensor); }};
constexpr choice_binding preset_choice{
    preset_words, [](scene_request& r, std::size_t k) { r.preset = horizon_preset(k); },
    [](const scene_request& r) { return static_cast<std::size_t>(r.preset); }};

// Why a sweep of the season term changes nothing: docs/SENSOR_PHYSICS.md's reduction. With the
// profile's 50 % point on the surface (radiance-offset-km 0) the radiance jumps there from
// L0 / 2 to L_disk L0, and a pencil without lag located at 1/2 of the pulse's peak stays on that
// jump whatever the season factor makes of L0 (a disk at least as bright as the limb, and L0
// within a factor 2 along the scan: |A| < 1/3): every row the same.
const char* season_hidden(const scene_request& r) {
  const scene_config& s = r.scene;
  if (s.radiance_offset_km != 0 || !(s.radiance_disk >= 1)) return nullptr;
  for (const head_config& h : s.heads)
    if (h.fov_deg != 0 || h.tau_ms != 0 || h.locator != locator_kind::normalised ||
        h.threshold != 0.5)
      return nullptr;
  const double largest = r.sweep && r.sweep->name == "radiance-season"
                             ? std::max(std::abs(r.sweep->from), std::abs(r.sweep->to))
                             : std::abs(s.radiance_season);
  if (!(largest < 1.0 / 3)) return nullptr;
  return "at --radiance-offset-km 0 a pencil beam without lag, located at half the pulse's peak, "
         "stays on the radiance's jump at the horizon whatever the season does to L0 "
         "(docs/SENSOR_PHYSICS.md): give the profile's height, e.g. --radiance-offset-km 40";
}

// --- Options with their own reading --------------------------------------------------------

checked<void> apply_processing_radius(scene_request& r, std::string_view text) {
  scene_config& s = r.scene;
  if (text == "equatorial") {
    s.processing_radius = processing_radius_kind::equatorial;
  } else if (text == "local") {
    s.processing_radius = processing_radius_kind::local;
  } else {
    const checked<double> km = text::parse_real(text);
    if (!km.ok())
      return diagnostic::saying(quote(text) +
                                " is not one of: equatorial, local, a radius in km (a finite "
                                "decimal number)");
    s.processing_radius = processing_radius_kind::value;
    s.processing_radius_km = km.value();
  }
  return success();
}

std::optional<std::string> print_processing_radius(const scene_request& r) {
  switch (r.scene.processing_radius) {
    case processing_radius_kind::truth:
      return std::nullopt;
    case processing_radius_kind::equatorial:
      return in_quotes("equatorial");
    case processing_radius_kind::local:
      return in_quotes("local");
    case processing_radius_kind::value:
      return text::shortest_text(r.scene.processing_radius_km);
  }
  return std::nullopt;
}

void sweep_processing_radius(scene_request& r, double km) {
  r.scene.processing_radius = processing_radius_kind::value;
  r.scene.processing_radius_km = km;
}

// --sun-sync derives the inclination from a and e, and a scene's i-deg is then not read:
// --print-config writes the inclination the run uses, saying where it comes from, instead of
// an i-deg that is ignored.
checked<void> apply_inclination(scene_request& r, std::string_view text) {
  const checked<double> deg = text::parse_real(text);
  if (!deg.ok()) return deg.error();
  r.scene.i_deg = deg.value();
  return success();
}

std::optional<std::string> print_inclination(const scene_request& r) {
  if (!r.scene.sun_sync) return text::shortest_text(r.scene.i_deg);
  return text::shortest_text(effective_inclination_deg(r.scene)) +
         "  # the inclination --sun-sync derives from a-km and e (i-deg is not read with it)";
}

void sweep_inclination(scene_request& r, double deg) {
  r.scene.i_deg = deg;
}

// --date sets the Sun's declination: the one Sun's (ERFA, sun_declination.hpp) at 12:00 UTC of
// the date; --print-config writes the declination instead.
checked<void> apply_date(scene_request& r, std::string_view text) {
  const std::string refused = quote(text) + " is not a valid YYYY-MM-DD date in 1960-2099";
  bool form = text.size() == 10 && text[4] == '-' && text[7] == '-';
  for (std::size_t i = 0; form && i < text.size(); ++i)
    form = i == 4 || i == 7 || (text[i] >= '0' && text[i] <= '9');
  if (!form) return diagnostic::saying(refused);
  const checked<sources::instant> noon =
      sources::parse_epoch(std::string(text) + "T12:00:00", sources::time_scale::utc);
  if (!noon.ok()) return diagnostic::saying(refused);
  r.scene.sun_declination_deg = rad_to_deg(sources::sun_declination_rad(noon.value()));
  return success();
}

checked<void> apply_head(scene_request& r, std::string_view text) {
  const std::size_t number = r.heads_given + 1;
  if (r.heads_given == max_heads)
    return diagnostic::saying("head " + std::to_string(number) + ": a scene has at most " +
                              std::to_string(max_heads) + " heads");
  checked<head_config> head = parse_head_spec(text);
  if (!head.ok())
    return diagnostic::saying("head " + std::to_string(number) + " " + quote(text) + ": " +
                              head.error().message);
  if (r.heads_given == 0) r.scene.heads.clear();  // the first head replaces the default one
  r.scene.heads.push_back(head.value());
  ++r.heads_given;
  return success();
}

checked<void> apply_sweep(scene_request& r, std::string_view text) {
  checked<sweep_spec> spec = parse_sweep(text);
  if (!spec.ok()) return spec.error();
  r.sweep = std::move(spec).value();
  return success();
}

std::optional<std::string> print_sweep(const scene_request& r) {
  if (!r.sweep) return std::nullopt;
  return in_quotes(r.sweep->text);
}

// --apply FILE: a path the scene file can hold (no quote, no control character) of a
// file that opens; the fit's JSON itself is read by fit_correction when the scene runs.
// A text kept as typed. A scene file writes it as a TOML string: no quote, no control character
// (a backslash is escaped).
checked<void> check_text(std::string_view text, const char* what) {
  if (text.empty()) return diagnostic::saying(std::string("empty value: give ") + what);
  for (const unsigned char c : text)
    if (c < 0x20 || c == 0x7f || c == '"')
      return diagnostic::saying(quote(text) +
                                " holds a quote or a control character (a scene file could "
                                "not write it)");
  return success();
}

checked<void> apply_fit_file(scene_request& r, std::string_view text) {
  if (checked<void> ok = check_text(text, "a fit's JSON file"); !ok.ok()) return ok;
  std::ifstream probe;
  if (checked<void> opened = text::open_for_reading(std::string(text), probe); !opened.ok())
    return diagnostic::saying(std::string(text) + ": " + opened.error().message);
  r.apply_fit = std::string(text);
  return success();
}

std::optional<std::string> print_fit_file(const scene_request& r) {
  if (!r.apply_fit) return std::nullopt;
  return in_quotes(*r.apply_fit);
}

std::optional<std::string> print_nothing(const scene_request&) {
  return std::nullopt;
}

// --- Campaign options -------------------------------------------------------------

checked<void> apply_threads(scene_request& r, std::string_view text) {
  const checked<std::uint64_t> count = text::parse_count(text);
  if (!count.ok()) return count.error();
  if (count.value() < 1 || count.value() > max_threads)
    return diagnostic::saying(std::string(text) + " threads is outside [1, " +
                              std::to_string(max_threads) + "]");
  r.threads = count.value();
  return success();
}

std::optional<std::string> print_threads(const scene_request& r) {
  if (r.threads == 0) return std::nullopt;
  return std::to_string(r.threads);
}

checked<void> apply_shard(scene_request& r, std::string_view text) {
  const std::size_t slash = text.find('/');
  const std::string form = quote(text) + " is not K/N (shard K of N, 1 <= K <= N, e.g. 2/4)";
  if (slash == std::string_view::npos) return diagnostic::saying(form);
  const checked<std::uint64_t> index = text::parse_count(text.substr(0, slash));
  const checked<std::uint64_t> count = text::parse_count(text.substr(slash + 1));
  if (!index.ok() || !count.ok()) return diagnostic::saying(form);
  if (count.value() == 0) return diagnostic::saying(quote(text) + ": N must be at least 1");
  if (index.value() < 1 || index.value() > count.value())
    return diagnostic::saying(quote(text) + ": K must be in [1, N]");
  r.shard = shard_spec{index.value(), count.value()};
  return success();
}

std::optional<std::string> print_shard(const scene_request& r) {
  if (!r.shard) return std::nullopt;
  return in_quotes(std::to_string(r.shard->index) + "/" + std::to_string(r.shard->count));
}

// --- File names and the epoch (MODEL §10; truth_source.hpp reads them) ----------------------

template <std::string scene_config::*Field>
checked<void> apply_file(scene_request& r, std::string_view text) {
  if (checked<void> ok = check_text(text, "a file name"); !ok.ok()) return ok;
  r.scene.*Field = std::string(text);
  return success();
}

template <std::string scene_config::*Field>
std::optional<std::string> print_file(const scene_request& r) {
  const std::string& text = r.scene.*Field;
  if (text.empty()) return std::nullopt;
  return in_quotes(text);
}

// --object KEY: a catalogue's set (orbit/catalogue.hpp), kept as typed; blanks alone name none.
checked<void> apply_object(scene_request& r, std::string_view text) {
  constexpr const char* what = "a NORAD catalogue number, international designator or name";
  if (checked<void> ok = check_text(text, what); !ok.ok()) return ok;
  if (text::trim_blanks(text).empty())
    return diagnostic::saying(quote(text) + " is blank: give " + what);
  r.scene.object = std::string(text);
  return success();
}

checked<void> apply_epoch(scene_request& r, std::string_view text) {
  if (checked<void> ok = check_text(text, "an ISO 8601 UTC time"); !ok.ok()) return ok;
  const auto t = sources::parse_epoch(text, sources::time_scale::utc);
  if (!t.ok()) return diagnostic::saying(t.error().message);
  r.scene.epoch_utc = std::string(text);
  return success();
}

template <std::string scene_request::*Field>
checked<void> apply_output(scene_request& r, std::string_view text) {
  if (checked<void> ok = check_text(text, "a file name"); !ok.ok()) return ok;
  r.*Field = std::string(text);
  return success();
}

template <std::string scene_request::*Field>
std::optional<std::string> print_output(const scene_request& r) {
  if ((r.*Field).empty()) return std::nullopt;
  return in_quotes(r.*Field);
}

// --- The table -----------------------------------------------------------------------------

using G = option_group;
using K = value_kind;

constexpr auto program_bit(scene_program p) {
  return static_cast<std::uint8_t>(p);
}
// Who honours what (option_spec::honoured_by).
constexpr std::uint8_t sim_only = program_bit(scene_program::simulate);
constexpr std::uint8_t sim_and_summary =
    program_bit(scene_program::simulate) | program_bit(scene_program::python_summary);
constexpr std::uint8_t simulations = program_bit(scene_program::simulate) |
                                     program_bit(scene_program::python_rows) |
                                     program_bit(scene_program::python_summary);
constexpr std::string_view processing_only =
    "the processing of simulated rows (the nadir from the chords); a fit models the chords and "
    "phases it reads";

// Each entry names only what differs from option_spec's defaults (designated initializers, in
// the member order of option_spec).
const option_spec table[] = {
    // Orbit
    {.name = "a-km",
     .group = G::orbit,
     .kind = K::real,
     .help = "semi-major axis, km, [1, 1e9]",
     .binding = scene_field(&scene_config::a_km),
     .sweepable = true},
    {.name = "e",
     .group = G::orbit,
     .kind = K::real,
     .help = "eccentricity, [0, 1)",
     .binding = scene_field(&scene_config::e),
     .sweepable = true,
     .blame_instead = "a-km radius-km horizon-km horizon-preset earth"},
    {.name = "i-deg",
     .group = G::orbit,
     .kind = K::real,
     .help = "inclination, deg, [0, 180]",
     .binding = custom_binding{apply_inclination, print_inclination, sweep_inclination},
     .sweepable = true,
     .ignored = [](const scene_request& r) -> const char* {
       return r.scene.sun_sync ? "--sun-sync derives the inclination" : nullptr;
     }},
    {.name = "raan-deg",
     .group = G::orbit,
     .kind = K::real,
     .help = "right ascension of the ascending node, deg",
     .binding = scene_field(&scene_config::raan_deg),
     .sweepable = true},
    {.name = "argp-deg",
     .group = G::orbit,
     .kind = K::real,
     .help = "argument of perigee, deg",
     .binding = scene_field(&scene_config::argp_deg),
     .sweepable = true},
    {.name = "m0-deg",
     .group = G::orbit,
     .kind = K::real,
     .help = "mean anomaly at t = 0, deg",
     .binding = scene_field(&scene_config::m0_deg),
     .sweepable = true},
    {.name = "sun-sync",
     .group = G::orbit,
     .kind = K::flag,
     .help = "derive i from a and e for a sun-synchronous node rate (ignores --i-deg)",
     .binding = scene_field(&scene_config::sun_sync),
     .blame_instead = "a-km e"},
    {.name = "j2",
     .group = G::orbit,
     .kind = K::flag,
     .help = "J2 secular drift of the node, perigee and mean anomaly (default: two-body)",
     .binding = scene_field(&scene_config::j2)},
    // Orbit from a file and the epoch (MODEL §10): one orbit source; elements then refused
    {.name = "epoch",
     .group = G::orbit,
     .kind = K::text,
     .value_name = "UTC",
     .help = "the scene's t = 0, ISO 8601 UTC YYYY-MM-DDThh:mm:ss[.f][Z] (1960-2099; TAI - UTC "
             "= 37 s assumed after ERFA's table)",
     .binding = custom_binding{apply_epoch, print_file<&scene_config::epoch_utc>},
     .default_text = "the TLE's epoch, the OEM's first usable time, else 2000-01-01T12:00:00"},
    {.name = "tle",
     .group = G::orbit,
     .kind = K::text,
     .value_name = "FILE",
     .help = "orbit from FILE: a two- or three-line element set (of a catalogue: the one "
             "--object names), SGP4/SDP4, TEME rotated into the scene frame (TOD) (instead of "
             "the elements above)",
     .binding =
         custom_binding{apply_file<&scene_config::tle_file>, print_file<&scene_config::tle_file>},
     .excludes = "oem omm",
     .default_text = "none"},
    {.name = "omm",
     .group = G::orbit,
     .kind = K::text,
     .value_name = "FILE",
     .help = "orbit from FILE: an element set as a CCSDS OMM (KVN or XML) or CelesTrak's CSV or "
             "JSON (of a catalogue: the one --object names), SGP4/SDP4 as --tle (instead of the "
             "elements above)",
     .binding =
         custom_binding{apply_file<&scene_config::omm_file>, print_file<&scene_config::omm_file>},
     .excludes = "tle oem",
     .default_text = "none"},
    {.name = "object",
     .group = G::orbit,
     .kind = K::text,
     .value_name = "KEY",
     .help = "the element set of a catalogue --tle or --omm (a file of many, as CelesTrak's GP "
             "files) whose NORAD catalogue number (25544), international designator (1998-067A "
             "or 98067A) or name (any case) is KEY: exactly one set must match",
     .binding = custom_binding{apply_object, print_file<&scene_config::object>},
     .default_text = "none: the file must hold one set"},
    {.name = "oem",
     .group = G::orbit,
     .kind = K::text,
     .value_name = "FILE",
     .help = "orbit from FILE: a CCSDS OEM (KVN; EME2000, GCRF, ICRF, TEME, TOD or ITRF, rotated "
             "into TOD), interpolated as it says, refused where its interpolation error estimate "
             "exceeds 1e-6 deg (instead of the elements above)",
     .binding =
         custom_binding{apply_file<&scene_config::oem_file>, print_file<&scene_config::oem_file>},
     .excludes = "tle omm",
     .default_text = "none"},
    {.name = "eop",
     .group = G::orbit,
     .kind = K::text,
     .value_name = "FILE",
     .help = "Earth orientation from FILE, an IERS finals2000A file (finals2000A.all, .data, "
             ".daily): an ITRF --oem's states are turned with each day's UT1 - UTC and pole "
             "instead of UT1 = UTC and the pole at the CIP (up to 0.46 km and 17 m at 7000 km); "
             "it must cover the OEM's states",
     .binding =
         custom_binding{apply_file<&scene_config::eop_file>, print_file<&scene_config::eop_file>},
     .default_text = "none"},
    {.name = "interpolation-tolerance-deg",
     .group = G::orbit,
     .kind = K::real,
     .help = "the largest interpolation error estimate an OEM may have over the scene, deg, "
             "(0, 1]: raise it for a coarse ephemeris; the bound that then holds for the rows' "
             "truth is printed once on stderr",
     .binding = scene_field(&scene_config::interpolation_tolerance_deg)},
    {.name = "write-oem",
     .group = G::orbit,
     .kind = K::text,
     .value_name = "FILE",
     .help =
         "also write the scene's orbit at its rows' times to FILE as a CCSDS OEM (KVN, "
         "REF_FRAME TOD = the scene frame, UTC, HERMITE 7; LAGRANGE 7 from a TLE or OMM or with "
         "--j2), all or nothing",
     .binding = custom_binding{apply_output<&scene_request::write_oem_file>,
                               print_output<&scene_request::write_oem_file>},
     .default_text = "none",
     .honoured_by = sim_only,
     .not_honoured = "conescan-sim writes the scene's orbit as an OEM"},
    // Time
    {.name = "step-s",
     .group = G::time,
     .kind = K::real,
     .help = "time step, s, > 0",
     .binding = scene_field(&scene_config::step_s),
     .sweepable = true},
    {.name = "orbits",
     .group = G::time,
     .kind = K::real,
     .help = "duration in two-body orbital periods, >= 0",
     .binding = scene_field(&scene_config::orbits),
     .sweepable = true,
     .excludes = "duration-s",
     .omitted = [](const scene_request& r) { return r.scene.duration_s.has_value(); },
     .ignored = [](const scene_request& r) -> const char* {
       return r.scene.duration_s ? "--duration-s sets the duration" : nullptr;
     }},
    {.name = "duration-s",
     .group = G::time,
     .kind = K::real,
     .help = "duration, s, >= 0 (instead of --orbits)",
     .binding = scene_field(&scene_config::duration_s),
     .sweepable = true,
     .excludes = "orbits",
     .default_text = "--orbits"},
    {.name = "max-rows",
     .group = G::time,
     .kind = K::count,
     .help = "refuse scenes (all sweep values and runs together) with more rows than this",
     .binding = scene_field(&scene_config::max_rows),
     .blame_instead = "step-s duration-s orbits runs sweep a-km",
     .fit_help = "refuse a scene with more rows (its duration over its step) than this"},
    // Earth
    {.name = "earth",
     .group = G::earth,
     .kind = K::choice,
     .help = "truth Earth: sphere, or wgs84 (the inflated WGS84 ellipsoid)",
     .binding = earth_choice},
    {.name = "radius-km",
     .group = G::earth,
     .kind = K::real,
     .help = "sphere radius, km, [1, 1e6]",
     .binding = scene_field(&scene_config::radius_km),
     .sweepable = true,
     .default_text = "WGS84 a = 6378.137",
     .blame_instead = "earth"},
    {.name = "horizon-km",
     .group = G::earth,
     .kind = K::real,
     .help = "IR horizon height above the surface, km, [0, 1e4] (about 40 for a 14-16 um sensor)",
     .binding = scene_field(&scene_config::horizon_km),
     .sweepable = true,
     .blame_instead = "horizon-preset"},
    {.name = "horizon-pole-km",
     .group = G::earth,
     .kind = K::real,
     .help = "apparent horizon: polar radius b + horizon-km + this, km (wgs84 only)",
     .binding = scene_field(&scene_config::horizon_pole_km),
     .sweepable = true,
     .blame_instead = "horizon-preset horizon-km"},
    {.name = "horizon-shift-km",
     .group = G::earth,
     .kind = K::real,
     .help = "apparent horizon: centre moved along the polar axis by this times sin(Sun's "
             "declination), km (wgs84 only; the declination of each row's time unless --date or "
             "--sun-declination-deg)",
     .binding = scene_field(&scene_config::horizon_shift_km),
     .sweepable = true,
     .blame_instead = "horizon-preset"},
    {.name = "horizon-preset",
     .group = G::earth,
     .kind = K::choice,
     .help = "co2-15um: the 14-16 um CO2 horizon fitted to flight data (SeaWiFS Earth sensor "
             "navigation): horizon-km 40, horizon-pole-km -13, horizon-shift-km 11.5, each "
             "unless given (wgs84 only)",
     .binding = preset_choice},
    {.name = "sensor-preset",
     .group = G::earth,
     .kind = K::choice,
     .help = "conical-15um: a two-head 14-16 um conical scanner at typical values, each unless "
             "given (docs/STUDY.md, \"The sensor preset\"): earth wgs84, model scan, "
             "horizon-preset co2-15um, processing-radius local, heads beta=90,phase=60 and "
             "beta=-90,phase=200 with noise=0.01 (heads given replace them), and on every head "
             "fov=1.5, spin-hz=1, "
             "tau-ms=1 unless its spec gives them",
     .binding = sensor_preset_choice,
     .honoured_by = simulations,
     .not_honoured = "a real sensor's physics (MODEL §12), which a fit's forward model does not "
                     "have; give its geometry's options instead"},
    {.name = "date",
     .group = G::earth,
     .kind = K::text,
     .value_name = "DATE",
     .help = "date YYYY-MM-DD (1960-2099): the Sun's declination (ERFA's) at its noon UTC for "
             "every row (--print-config writes the declination)",
     .binding = custom_binding{apply_date, print_nothing},
     .excludes = "sun-declination-deg",
     .default_text = "none"},
    {.name = "sun-declination-deg",
     .group = G::earth,
     .kind = K::real,
     .help = "the Sun's declination for every row, deg, [-90, 90] (instead of --date)",
     .binding = scene_field(&scene_config::sun_declination_deg),
     .sweepable = true,
     .excludes = "date",
     .default_text = "ERFA's at each row's time",
     .blame_instead = "date horizon-preset",
     .ignored = [](const scene_request& r) -> const char* {
       return has_season_terms(r.scene)
                  ? nullptr
                  : "only the season terms (--horizon-shift-km, --radiance-season) use the Sun's "
                    "declination";
     }},
    {.name = "processing-horizon-km",
     .group = G::earth,
     .kind = K::real,
     .help = "horizon height the processing assumes, km, [0, 1e4]",
     .binding = scene_field(&scene_config::processing_horizon_km),
     .sweepable = true,
     .default_text = "--horizon-km",
     .honoured_by = simulations,
     .not_honoured = processing_only},
    {.name = "processing-radius",
     .group = G::earth,
     .kind = K::text,
     .value_name = "RADIUS",
     .help = "Earth radius the processing assumes: equatorial (WGS84 a), local (WGS84 radius "
             "under the satellite), or a radius in km",
     .binding =
         custom_binding{apply_processing_radius, print_processing_radius, sweep_processing_radius},
     .sweepable = true,
     .default_text = "the sphere's radius, or equatorial on wgs84",
     .blame_instead = "processing-horizon-km horizon-km horizon-preset radius-km a-km e earth",
     .honoured_by = simulations,
     .not_honoured = processing_only},
    // The limb's radiance (MODEL §12, sensor physics; scene_physics.hpp): given, every head runs
    // the signal chain (in conescan-fit's forward model too). Written by --print-config only
    // where not at the default.
    {.name = "radiance-scale-km",
     .group = G::earth,
     .kind = K::real,
     .help = "sensor physics (MODEL §12, model scan): the limb radiance profile's scale height H, "
             "km, 0 (a step edge) or [1e-06, 1000]",
     .binding = scene_field(&scene_config::radiance_scale_km),
     .sweepable = true,
     .default_text = "7",
     .omitted = at_default<&scene_config::radiance_scale_km>},
    {.name = "radiance-offset-km",
     .group = G::earth,
     .kind = K::real,
     .help = "sensor physics: the height of the profile's 50 % point above the horizon surface "
             "(--horizon-km), km, [-1000, 1000]",
     .binding = scene_field(&scene_config::radiance_offset_km),
     .sweepable = true,
     .default_text = "0",
     .omitted = at_default<&scene_config::radiance_offset_km>},
    {.name = "radiance-disk",
     .group = G::earth,
     .kind = K::real,
     .help = "sensor physics: the disk's radiance in units of the limb's plateau L0, [0, 100]",
     .binding = scene_field(&scene_config::radiance_disk),
     .sweepable = true,
     .default_text = "1",
     .omitted = at_default<&scene_config::radiance_disk>},
    {.name = "radiance-season",
     .group = G::earth,
     .kind = K::real,
     .help = "sensor physics: the season term A, (-1, 1): the plateau L0 = 1 + A sin(tangent "
             "latitude) sin(Sun's declination) / sin 23.44 deg (0.2: the 1.5 pole-to-pole ratio "
             "at solstice)",
     .binding = scene_field(&scene_config::radiance_season),
     .sweepable = true,
     .default_text = "0",
     .omitted = at_default<&scene_config::radiance_season>,
     .ignored = season_hidden},
    // Model
    {.name = "model",
     .group = G::model,
     .kind = K::choice,
     .help = "forward model: bias (the paper's fixed cone-angle bias, sphere only), or scan "
             "(exact per-crossing geometry)",
     .binding = model_choice,
     .blame_instead = "earth",
     .fit_help = "forward model: give scan (exact per-crossing geometry), the one a fit models; "
                 "bias (the paper's fixed cone-angle bias) has no true scan cone to fit"},
    {.name = "head",
     .group = G::model,
     .kind = K::head,
     .help = head_help(false),
     .binding = custom_binding{apply_head, print_nothing},
     .fit_help = head_help(true)},
    {.name = "processing",
     .group = G::model,
     .kind = K::choice,
     .help = "system solution: chord-phase (MODEL §6: mean of the per-head nadirs), or "
             "horizon-vector (least squares over every crossing's horizon vector)",
     .binding = processing_choice,
     .honoured_by = simulations,
     .not_honoured = processing_only},
    // MODEL §13: the Sun and the Moon in the scan (src/scene/scene_sky.hpp)
    {.name = "intrusions",
     .group = G::model,
     .kind = K::flag,
     .help = "the Sun and the Moon (ERFA, at each row's time) in each head's scan: a head whose "
             "Earth pulse a visible body's pulse meets has status sun or moon (its numbers nan; "
             "the system uses the other heads); per head the columns hK_sun_deg and hK_moon_deg "
             "(the body's angle from the true cone, deg); with --summary each head's fraction of "
             "rows lost to each body (model scan, the Sun of the rows' times: not with --date or "
             "--sun-declination-deg)",
     .binding = scene_field(&scene_config::intrusions),
     .omitted = [](const scene_request& r) { return !r.scene.intrusions; },
     .fit_help = "the Sun and the Moon (ERFA, at each row's time) in each head's scan: the "
                 "telemetry's rows a body blinds are left out of the fit (model scan, not with "
                 "--date or --sun-declination-deg)"},
    // subtract a fit's modelled errors (src/scene_calibration/fit_correction.hpp)
    {.name = "apply",
     .group = G::model,
     .kind = K::text,
     .value_name = "FILE",
     .help =
         "a fit's JSON (conescan-fit --json): its modelled head errors (misalignment, cone-angle "
         "and crossing biases) are subtracted from each measurement before the processing, so "
         "the errors printed are what remains after calibration (model scan)",
     .binding = custom_binding{apply_fit_file, print_fit_file},
     .default_text = "none",
     .honoured_by = simulations,
     .not_honoured = "conescan-sim corrects with a fit; conescan-fit makes one"},
    {.name = "seed",
     .group = G::model,
     .kind = K::count,
     .help = "seed of the detector noise draws (head key noise=)",
     .binding = scene_field(&scene_config::seed),
     .sweepable = true,
     .ignored = [](const scene_request& r) -> const char* {
       return has_noise(r.scene) ? nullptr : "no head has noise= (the seed draws the noise)";
     },
     .honoured_by = simulations,
     .not_honoured = "draws the noise of simulated rows; a fit weighs by the heads' noise= alone"},
    {.name = "runs",
     .group = G::model,
     .kind = K::count,
     .help = "repeat the scene with independent noise, >= 1",
     .binding = scene_field(&scene_config::runs),
     .sweepable = true,
     .honoured_by = simulations,
     .not_honoured = "repeats the scene with new noise; a fit is of one telemetry"},
    {.name = "trace",
     .group = G::model,
     .kind = K::flag,
     .help = "write the scan model's root-finder iterations per row and head to stderr",
     .binding = request_field(&scene_request::trace),
     .honoured_by = sim_only,
     .not_honoured = "writes the root finder's iterations to conescan-sim's standard error"},
    // True attitude
    {.name = "roll-deg",
     .group = G::attitude,
     .kind = K::real,
     .help = "roll, deg",
     .binding = scene_field(&scene_config::roll_deg),
     .sweepable = true},
    {.name = "pitch-deg",
     .group = G::attitude,
     .kind = K::real,
     .help = "pitch, deg, [-90, 90] (within 1.91 deg of +-90 every row is 'gimbal': roll "
             "undefined, MODEL §7)",
     .binding = scene_field(&scene_config::pitch_deg),
     .sweepable = true},
    {.name = "yaw-deg",
     .group = G::attitude,
     .kind = K::real,
     .help = "yaw, deg",
     .binding = scene_field(&scene_config::yaw_deg),
     .sweepable = true},
    // True attitude from a file (MODEL §10): one attitude source; the angles above then refused
    {.name = "aem",
     .group = G::attitude,
     .kind = K::text,
     .value_name = "FILE",
     .help = "true attitude from FILE: a CCSDS AEM (KVN, QUATERNION; its inertial frame rotated "
             "into TOD), interpolated on the rotation group; must cover the scene",
     .binding =
         custom_binding{apply_file<&scene_config::aem_file>, print_file<&scene_config::aem_file>},
     .excludes = "attitude-csv",
     .default_text = "none"},
    {.name = "attitude-csv",
     .group = G::attitude,
     .kind = K::text,
     .value_name = "FILE",
     .help = "true attitude from FILE: a CSV of a time (t_s from the epoch, utc, or gps_week and "
             "gps_s) and 3-2-1 angles roll_deg,pitch_deg,yaw_deg orbital to body or a star "
             "tracker's quaternion q_w,q_x,q_y,q_z inertial to body (--attitude-frame), "
             "interpolated (angles linearly, quaternions on the geodesic); must cover the scene",
     .binding = custom_binding{apply_file<&scene_config::attitude_csv_file>,
                               print_file<&scene_config::attitude_csv_file>},
     .excludes = "aem",
     .default_text = "none"},
    {.name = "attitude-frame",
     .group = G::attitude,
     .kind = K::choice,
     .help = "the inertial frame of --attitude-csv's quaternions (star trackers' J2000 is "
             "EME2000); angle tables are orbital to body and do not use it",
     .binding = attitude_frame_choice,
     .default_text = "\"EME2000\"",
     .omitted = [](const scene_request& r) { return r.scene.attitude_csv_file.empty(); }},
    {.name = "write-aem",
     .group = G::attitude,
     .kind = K::text,
     .value_name = "FILE",
     .help = "also write the scene's true attitude at its rows' times to FILE as a CCSDS AEM "
             "(KVN, body <- TOD = the scene frame, A2B, scalar last, LAGRANGE 7), all or nothing",
     .binding = custom_binding{apply_output<&scene_request::write_aem_file>,
                               print_output<&scene_request::write_aem_file>},
     .default_text = "none",
     .honoured_by = sim_only,
     .not_honoured = "conescan-sim writes the scene's true attitude as an AEM"},
    {.name = "attitude-envelope-deg",
     .group = G::attitude,
     .kind = K::real,
     .help = "largest excursion of the true nadir angle from nominal, deg, [0, 90]: a head whose "
             "chord has both inversion roots within it is 'ambiguous' (MODEL §7); 0 switches the "
             "check off",
     .binding = scene_field(&scene_config::attitude_envelope_deg),
     .sweepable = true,
     .honoured_by = simulations,
     .not_honoured = processing_only},
    // Scenes and output
    {.name = "sweep",
     .group = G::scenes,
     .kind = K::text,
     .value_name = "NAME=FROM:TO:STEP",
     .help = "run the scene for each value of an option (e.g. "
             "e=0:0.1:0.025, h1.alpha=0:25:5); the value becomes the first column",
     .binding = custom_binding{apply_sweep, print_sweep},
     .default_text = "none",
     .honoured_by = simulations,
     .not_honoured = "runs many scenes; a fit is of one scene"},
    {.name = "budget",
     .group = G::scenes,
     .kind = K::flag,
     .help = "run the scene once per error source alone (misalignment, head biases, "
             "oblateness, horizon height with the limb's radiance and the locator, pole and "
             "season terms, field of view and detector lag on that limb, noise, quantisation) "
             "and with all, each with the scan model, then their sum and the interaction (all "
             "- sum): per row, or with --summary per source",
     .binding = request_field(&scene_request::budget),
     .honoured_by = simulations,
     .not_honoured = "runs a scene per error source; a fit is of one scene"},
    {.name = "summary",
     .group = G::scenes,
     .kind = K::flag,
     .help = "instead of rows: per head and system (and sweep value, budget source) the count "
             "of each status and min, max, mean, RMS, 1 sigma and 3 sigma of the roll and "
             "pitch errors (deg)",
     .binding = request_field(&scene_request::summary),
     .honoured_by = sim_and_summary,
     .not_honoured = "statistics instead of rows: conescan-sim --summary, conescan.summary()"},
    {.name = "calendar",
     .group = G::scenes,
     .kind = K::text,
     .value_name = "DIR",
     .help = "instead of rows: the Sun's and the Moon's blinding calendar (MODEL §13; implies "
             "--intrusions) over a year from the epoch unless --duration-s or --orbits is "
             "given, written into DIR (lost.csv, on-cone.csv, days.csv, seasons.csv); events "
             "found from the geometry, sampled --step-s apart where a body can blind a head "
             "(default 1 s with it, >= 0.001), edges to 1 ms",
     .binding = custom_binding{apply_output<&scene_request::calendar_dir>,
                               print_output<&scene_request::calendar_dir>},
     .default_text = "none",
     .honoured_by = sim_only,
     .not_honoured = "conescan-sim writes the blinding calendar (--calendar DIR)"},
    // Campaigns over threads, processes and clusters (src/scene/campaign.hpp)
    {.name = "threads",
     .group = G::scenes,
     .kind = K::count,
     .help = "worker threads computing runs, sweep values, budget sources, blocks of rows and "
             "a physics table's build, [1, 1024]; the output is byte for byte that of one thread",
     .binding = custom_binding{apply_threads, print_threads},
     .default_text = "every core this process may use",
     .honoured_by = sim_only | program_bit(scene_program::fit),
     .not_honoured = "conescan-sim's worker threads (from Python, run scenes in Python "
                     "threads: the GIL is released)",
     .fit_help = "worker threads of every pass over the telemetry, [1, 1024]: the sums are "
                 "taken over parts that do not depend on the threads, so every count gives the "
                 "same fit to the bit (default every core this process may use)"},
    {.name = "shard",
     .group = G::scenes,
     .kind = K::text,
     .value_name = "K/N",
     .help = "only part K of N of the campaign's runs (sweep values x runs, in order), "
             "with the seeds and run numbers of the whole campaign; N <= the number of runs",
     .binding = custom_binding{apply_shard, print_shard},
     .default_text = "none",
     .honoured_by = sim_only,
     .not_honoured = "a campaign's shard is conescan-sim's (--shard, --summary-state, --merge)"},
    {.name = "summary-state",
     .group = G::scenes,
     .kind = K::text,
     .value_name = "FILE",
     .help = "also write the summary as a mergeable state (conescan-sim --merge FILE... "
             "prints the campaign's summary from its shards' states)",
     .binding = custom_binding{apply_output<&scene_request::summary_state>,
                               print_output<&scene_request::summary_state>},
     .default_text = "none",
     .honoured_by = sim_only,
     .not_honoured = "a campaign's state file is conescan-sim's"},
};

template <class... F>
struct overloaded : F... {
  using F::operator()...;
};
template <class... F>
overloaded(F...) -> overloaded<F...>;

}  // namespace

std::string_view group_title(option_group group) {
  static constexpr enum_names<option_group, 6> titles{{
      {option_group::orbit, "Orbit (classical elements at t = 0, or a file)"},
      {option_group::time, "Time (rows at t = k * step while t <= duration)"},
      {option_group::earth, "Earth"},
      {option_group::model, "Model"},
      {option_group::attitude, "True attitude (3-2-1 Euler, orbital to body, or a file)"},
      {option_group::scenes, "Scenes and output"},
  }};
  return name_of(titles, group, "Options");
}

std::string_view program_name(scene_program program) {
  static constexpr enum_names<scene_program, 4> names{
      {{scene_program::simulate, "conescan-sim"},
       {scene_program::python_rows, "conescan.simulate"},
       {scene_program::python_summary, "conescan.summary"},
       {scene_program::fit, "conescan-fit"}}};
  return name_of(names, program, "conescan");
}

std::string_view value_kind_name(value_kind kind) {
  static constexpr enum_names<value_kind, 6> names{{{value_kind::real, "real"},
                                                    {value_kind::count, "count"},
                                                    {value_kind::flag, "flag"},
                                                    {value_kind::choice, "choice"},
                                                    {value_kind::text, "text"},
                                                    {value_kind::head, "head"}}};
  return name_of(names, kind, "");
}

std::string_view value_kind_placeholder(value_kind kind) {
  static constexpr enum_names<value_kind, 6> placeholders{{{value_kind::real, "REAL"},
                                                           {value_kind::count, "COUNT"},
                                                           {value_kind::flag, ""},
                                                           {value_kind::choice, "WORD"},
                                                           {value_kind::text, "TEXT"},
                                                           {value_kind::head, "SPEC"}}};
  return name_of(placeholders, kind, "");
}

bool honours(scene_program program, const option_spec& option) noexcept {
  return (option.honoured_by & program_bit(program)) != 0;
}

diagnostic not_honoured(scene_program program, const option_spec& option, const origin& where) {
  return diagnostic{std::string(option.name),
                    "not an option of " + std::string(program_name(program)) + ": " +
                        std::string(option.not_honoured),
                    where};
}

std::span<const option_spec> option_table() {
  return table;
}

const option_spec* find_option(std::string_view name) {
  for (const option_spec& o : table)
    if (o.name == name) return &o;
  return nullptr;
}

std::string option_help(const option_spec& option, scene_program program) {
  std::string help(program == scene_program::fit && !option.fit_help.empty() ? option.fit_help
                                                                             : option.help);
  if (const auto* choice = std::get_if<choice_binding>(&option.binding)) {
    std::string words;
    for (std::string_view w : choice->words) words += (words.empty() ? "" : " | ") + std::string(w);
    help = words + ": " + help;
  }
  if (option.kind == value_kind::flag || option.kind == value_kind::head) return help;
  if (help.find("(default ") != std::string::npos) return help;  // a fit_help with its own
  if (!option.default_text.empty())
    return help + " (default " + std::string(option.default_text) + ")";
  if (const std::optional<std::string> text = print_option(option, scene_request{}))
    return help + " (default " + *text + ")";
  return help;
}

checked<void> apply_option(const option_spec& option, scene_request& r, const option_value& v) {
  const auto parsed = [&](const auto& value, auto&& store) -> checked<void> {
    if (!value.ok()) return value.error();
    store(value.value());
    return success();
  };
  checked<void> outcome = std::visit(
      overloaded{
          [&](const field_ref<double>& f) {
            return parsed(text::parse_real(v.text), [&](double x) { f.of(r) = x; });
          },
          [&](const field_ref<std::optional<double>>& f) {
            return parsed(text::parse_real(v.text), [&](double x) { f.of(r) = x; });
          },
          [&](const field_ref<std::uint64_t>& f) {
            return parsed(text::parse_count(v.text), [&](std::uint64_t x) { f.of(r) = x; });
          },
          [&](const field_ref<bool>& f) {
            return parsed(text::parse_flag(v.text), [&](bool x) { f.of(r) = x; });
          },
          [&](const choice_binding& c) -> checked<void> {
            for (std::size_t k = 0; k < c.words.size(); ++k)
              if (v.text == c.words[k]) {
                c.set(r, k);
                return success();
              }
            std::string words;
            for (std::string_view w : c.words)
              words += (words.empty() ? "" : ", ") + std::string(w);
            return diagnostic::saying(quote(v.text) + " is not one of: " + words);
          },
          [&](const custom_binding& c) { return c.apply(r, v.text); },
      },
      option.binding);
  if (outcome.ok()) return outcome;
  diagnostic error = std::move(outcome).error();
  error.option = std::string(option.name);
  error.where = v.where;
  if (option.kind == value_kind::head) error.head = r.heads_given + 1;
  return error;
}

bool excludes(const option_spec& option, std::string_view other) {
  std::string_view list = option.excludes;
  while (!list.empty()) {
    const std::size_t space = list.find(' ');
    if (list.substr(0, space) == other) return true;
    list = space == std::string_view::npos ? std::string_view() : list.substr(space + 1);
  }
  return false;
}

std::string_view replaced_by_source(const scene_request& r, std::string_view name) {
  static constexpr std::string_view orbit_elements[] = {
      "a-km", "e", "i-deg", "raan-deg", "argp-deg", "m0-deg", "sun-sync", "j2"};
  static constexpr std::string_view attitude_angles[] = {"roll-deg", "pitch-deg", "yaw-deg"};
  const scene_config& s = r.scene;
  for (std::string_view o : orbit_elements)
    if (o == name)
      return !s.tle_file.empty()   ? "tle"
             : !s.omm_file.empty() ? "omm"
             : !s.oem_file.empty() ? "oem"
                                   : "";
  for (std::string_view o : attitude_angles)
    if (o == name)
      return !s.aem_file.empty() ? "aem" : !s.attitude_csv_file.empty() ? "attitude-csv" : "";
  return "";
}

std::optional<std::string> print_option(const option_spec& option, const scene_request& r) {
  if (option.omitted && option.omitted(r)) return std::nullopt;
  if (!replaced_by_source(r, option.name).empty()) return std::nullopt;
  return std::visit(
      overloaded{
          [&](const field_ref<double>& f) -> std::optional<std::string> {
            return text::shortest_text(f.of(r));
          },
          [&](const field_ref<std::optional<double>>& f) -> std::optional<std::string> {
            if (!f.of(r)) return std::nullopt;
            return text::shortest_text(*f.of(r));
          },
          [&](const field_ref<std::uint64_t>& f) -> std::optional<std::string> {
            // Beyond TOML's 64-bit signed integers a count is written as a string.
            const std::string digits = std::to_string(f.of(r));
            return f.of(r) > std::uint64_t{INT64_MAX} ? in_quotes(digits) : digits;
          },
          [&](const field_ref<bool>& f) -> std::optional<std::string> {
            return f.of(r) ? "true" : "false";
          },
          [&](const choice_binding& c) -> std::optional<std::string> {
            return in_quotes(c.words[c.get(r)]);
          },
          [&](const custom_binding& c) { return c.print(r); },
      },
      option.binding);
}

namespace {

// hK.key: head K's key.
checked<void> apply_head_sweep(scene_request& r, const std::string& name, double value) {
  const std::size_t dot = name.find('.');
  std::size_t k = 0;
  const char* digits = name.data() + 1;
  const auto [end, ec] = std::from_chars(digits, name.data() + dot, k);
  const bool number = ec == std::errc() && end == name.data() + dot && k >= 1 && *digits != '0';
  double* field = number && k <= r.scene.heads.size()
                      ? head_key_field(r.scene.heads[k - 1], std::string_view(name).substr(dot + 1))
                      : nullptr;
  const std::string_view key = std::string_view(name).substr(dot + 1);
  if (!number || !is_head_key(key))
    return diagnostic::saying("cannot sweep " + quote(name) + "; options: " + sweepable_names());
  if (is_head_word_key(key))
    return diagnostic::saying("cannot sweep " + quote(name) +
                              ": its value is a word, not a number");
  if (!field)
    return diagnostic::saying("cannot sweep " + quote(name) + ": the scene has " +
                              std::to_string(r.scene.heads.size()) + " head(s)");
  *field = value;
  return success();
}

}  // namespace

checked<void> apply_sweep_value(scene_request& r, const std::string& name, double value) {
  if (name.size() > 2 && name[0] == 'h' && name.find('.') != std::string::npos)
    return apply_head_sweep(r, name, value);
  const option_spec* option = find_option(name);
  if (!option || !option->sweepable)
    return diagnostic::saying("cannot sweep " + quote(name) + "; options: " + sweepable_names());
  return std::visit(
      overloaded{
          [&](const field_ref<double>& f) -> checked<void> {
            f.of(r) = value;
            return success();
          },
          [&](const field_ref<std::optional<double>>& f) -> checked<void> {
            f.of(r) = value;
            return success();
          },
          [&](const field_ref<std::uint64_t>& f) -> checked<void> {
            // A count is swept over integers a double holds exactly.
            if (!(value >= 0 && value <= 0x1p53 && value == std::floor(value)))
              return diagnostic::saying(name + " = " + text::shortest_text(value) +
                                        " is not a count in [0, 2^53]: sweep it in whole steps");
            f.of(r) = static_cast<std::uint64_t>(value);
            return success();
          },
          [&](const custom_binding& c) -> checked<void> {
            c.sweep(r, value);
            return success();
          },
          [&](const auto&) -> checked<void> {
            return diagnostic::saying("cannot sweep " + quote(name) +
                                      "; options: " + sweepable_names());
          },
      },
      option->binding);
}

std::string option_names() {
  std::string names;
  for (const option_spec& o : table) names += (names.empty() ? "" : ", ") + std::string(o.name);
  return names;
}

std::string sweepable_names() {
  std::string names;
  for (const option_spec& o : table)
    if (o.sweepable) names += std::string(o.name) + ", ";
  std::string heads;
  for (std::string_view key : head_number_keys())
    heads += (heads.empty() ? "hK." : ", hK.") + std::string(key);
  return names + heads + " (K = 1, 2, ...)";
}

}  // namespace conescan::scene
