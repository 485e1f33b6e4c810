#include "options.hpp"

#include <charconv>

#include "conescan/scalar.hpp"
#include "orbit/sun.hpp"
#include "scene/head_spec.hpp"
#include "scene/number_text.hpp"
#include "scene/sweep.hpp"
#include "scene_file.hpp"

namespace conescan::cli {

void declare_options(CLI::App& app, options& o) {
  scene::scene_config& s = o.scene;
  app.get_formatter()->column_width(34);
  const std::string orbit = "Orbit (classical elements at t = 0)";
  app.add_option("--a-km", s.a_km, "semi-major axis, km")->capture_default_str()->group(orbit);
  app.add_option("--e", s.e, "eccentricity, [0, 1)")->capture_default_str()->group(orbit);
  app.add_option("--i-deg", s.i_deg, "inclination, deg, [0, 180]")
      ->capture_default_str()
      ->group(orbit);
  app.add_option("--raan-deg", s.raan_deg, "right ascension of the ascending node, deg")
      ->capture_default_str()
      ->group(orbit);
  app.add_option("--argp-deg", s.argp_deg, "argument of perigee, deg")
      ->capture_default_str()
      ->group(orbit);
  app.add_option("--m0-deg", s.m0_deg, "mean anomaly at t = 0, deg")
      ->capture_default_str()
      ->group(orbit);
  app.add_flag("--sun-sync", s.sun_sync,
               "derive i from a and e for a sun-synchronous node rate (ignores --i-deg)")
      ->group(orbit);
  app.add_flag("--j2", s.j2,
               "J2 secular drift of the node, perigee and mean anomaly (default: "
               "two-body)")
      ->group(orbit);

  const std::string time = "Time (rows at t = k * step while t <= duration)";
  app.add_option("--step-s", s.step_s, "time step, s, > 0")->capture_default_str()->group(time);
  auto* orbits = app.add_option("--orbits", s.orbits, "duration in two-body orbital periods, >= 0")
                     ->capture_default_str()
                     ->group(time);
  app.add_option("--duration-s", o.duration_s, "duration, s, >= 0 (instead of --orbits)")
      ->excludes(orbits)
      ->group(time);
  app.add_option("--max-rows", s.max_rows, "refuse scenes with more rows than this")
      ->capture_default_str()
      ->group(time);

  const std::string earth = "Earth";
  app.add_option("--earth", o.earth, "truth Earth: sphere | wgs84 (inflated WGS84 ellipsoid)")
      ->capture_default_str()
      ->group(earth);
  app.add_option("--radius-km", o.radius_km, "sphere radius, km (default WGS84 a = 6378.137)")
      ->group(earth);
  app.add_option("--horizon-km", s.horizon_km,
                 "IR horizon height above the surface, km (about 40 for a 14-16 um sensor)")
      ->capture_default_str()
      ->group(earth);
  app.add_option("--horizon-pole-km", s.horizon_pole_km,
                 "apparent horizon: polar radius b + horizon-km + this, km (wgs84 only)")
      ->capture_default_str()
      ->group(earth);
  app.add_option("--horizon-shift-km", s.horizon_shift_km,
                 "apparent horizon: centre moved along the polar axis by this times sin(Sun's "
                 "declination), km (wgs84 only; needs --date or --sun-declination-deg)")
      ->capture_default_str()
      ->group(earth);
  app.add_option("--horizon-preset", o.horizon_preset,
                 "none | co2-15um: the 14-16 um CO2 horizon fitted to flight data (SeaWiFS Earth "
                 "sensor navigation): horizon-km 40, horizon-pole-km -13, horizon-shift-km 11.5, "
                 "each unless given (wgs84 only; needs --date or --sun-declination-deg)")
      ->capture_default_str()
      ->group(earth);
  auto* date =
      app.add_option("--date", o.date, "date YYYY-MM-DD for the Sun's declination (noon UTC)")
          ->group(earth);
  app.add_option("--sun-declination-deg", o.sun_declination_deg,
                 "the Sun's declination, deg, [-90, 90] (instead of --date)")
      ->excludes(date)
      ->group(earth);
  app.add_option("--processing-horizon-km", o.processing_horizon_km,
                 "horizon height the processing assumes, km (default: --horizon-km)")
      ->group(earth);
  app.add_option("--processing-radius", o.processing_radius,
                 "Earth radius the processing assumes: equatorial (WGS84 a) | local (WGS84 "
                 "radius under the satellite) | a number in km (default: the sphere's radius, "
                 "or equatorial on wgs84)")
      ->group(earth);

  const std::string model = "Model";
  app.add_option("--model", o.model,
                 "forward model: bias (the paper's fixed cone-angle bias, sphere only) | scan "
                 "(exact per-crossing geometry)")
      ->capture_default_str()
      ->group(model);
  app.add_option("--head", o.heads,
                 "a sensor head, degrees: alpha=..,beta=..,gamma=..,sigma=..,phase=.. "
                 "(repeatable; replaces the default head alpha=0,beta=90,gamma=45,sigma=0.02,"
                 "phase=0; keys left out keep those values), and noise=.. (1 sigma per "
                 "crossing) and lsb=.. (telemetry step of chord and phase), default 0")
      ->expected(1)
      ->take_all()
      ->group(model);
  app.add_option("--processing", o.processing,
                 "system solution: chord-phase (SPEC 6: mean of the per-head nadirs) | "
                 "horizon-vector (least squares over every crossing's horizon vector)")
      ->capture_default_str()
      ->group(model);
  app.add_option("--seed", s.seed, "seed of the detector noise draws (head key noise=)")
      ->capture_default_str()
      ->group(model);
  app.add_option("--runs", s.runs, "repeat the scene with independent noise, >= 1")
      ->capture_default_str()
      ->group(model);
  app.add_flag("--trace", o.trace,
               "write the scan model's root-finder iterations per row and head to stderr")
      ->group(model);

  const std::string attitude = "True attitude (3-2-1 Euler, orbital to body)";
  app.add_option("--roll-deg", s.roll_deg, "roll, deg")->capture_default_str()->group(attitude);
  app.add_option("--pitch-deg", s.pitch_deg, "pitch, deg, (-90, 90)")
      ->capture_default_str()
      ->group(attitude);
  app.add_option("--yaw-deg", s.yaw_deg, "yaw, deg")->capture_default_str()->group(attitude);
  app.add_option("--attitude-envelope-deg", s.attitude_envelope_deg,
                 "largest excursion of the true nadir angle from nominal, deg, [0, 90]: a head "
                 "whose chord has both inversion roots within it is 'ambiguous' (SPEC 7)")
      ->capture_default_str()
      ->group(attitude);

  const std::string scenes = "Scenes and output";
  app.set_config("--config", "",
                 "scene file: key = value lines with the same options (command line wins), "
                 "heads as head = \"...\" lines or [[head]] tables; see data/scenes/")
      ->group(scenes);
  app.config_formatter(std::make_shared<scene_file_format>(&app));

  // CLI11 2.1 reads an empty value as 0 (`--e ''` would simulate e = 0 without a word): every
  // option that takes a value refuses an empty one.
  const CLI::Validator not_empty(
      [](std::string& value) { return value.empty() ? std::string("empty value") : std::string(); },
      "", "not empty");
  for (CLI::Option* opt : app.get_options())
    if (opt->get_expected_max() > 0 && opt->get_type_size_max() > 0 &&
        opt->get_single_name() != "config")
      opt->check(not_empty);
  app.add_option("--sweep", o.sweep,
                 "NAME=FROM:TO:STEP: run the scene for each value of a numeric option (e.g. "
                 "e=0:0.1:0.025, h1.alpha=0:25:5); the value becomes the first column")
      ->group(scenes);
  app.add_flag("--budget", o.budget,
               "run the scene once per error source alone (misalignment, oblateness, horizon "
               "height, pole and season terms, noise, quantisation) and with all, each with the "
               "scan model: per row, or with --summary per source")
      ->group(scenes);
  app.add_flag("--summary", o.summary,
               "instead of rows: per head and system (and sweep value) min, max, mean, RMS of "
               "the roll and pitch errors (deg) and the count of each status")
      ->group(scenes);
}

std::variant<scene::scene_config, scene::config_error> to_scene(const CLI::App& app,
                                                                const options& o) {
  scene::scene_config s = o.scene;
  if (app.count("--radius-km")) s.radius_km = o.radius_km;
  if (app.count("--duration-s")) s.duration_s = o.duration_s;

  if (o.earth == "sphere")
    s.earth = scene::earth_model::sphere;
  else if (o.earth == "wgs84")
    s.earth = scene::earth_model::wgs84;
  else
    return scene::config_error{"earth", "earth = '" + o.earth + "' is not one of: sphere, wgs84"};

  if (o.budget)
    s.model = scene::forward_model::scan;  // every run of the budget uses the exact model
  else if (o.model == "bias")
    s.model = scene::forward_model::bias;
  else if (o.model == "scan")
    s.model = scene::forward_model::scan;
  else
    return scene::config_error{"model", "model = '" + o.model + "' is not one of: bias, scan"};

  if (app.count("--processing-horizon-km")) s.processing_horizon_km = o.processing_horizon_km;
  if (app.count("--sun-declination-deg")) s.sun_declination_deg = o.sun_declination_deg;
  if (!o.date.empty()) {
    const std::optional<double> declination = orbit::sun_declination_from_iso_date(o.date);
    if (!declination)
      return scene::config_error{
          "date", "date = '" + o.date + "' is not a valid YYYY-MM-DD date in 1900-2100"};
    s.sun_declination_deg = rad_to_deg(*declination);
  }
  if (o.horizon_preset == "co2-15um") {
    // SeaWiFS Earth-sensor navigation (its earth.f), fitted to flight data: the CO2 horizon
    // sits ~40 km up, ~13 km lower over the poles than a geodetic ellipsoid puts it, and moves
    // ~11.5 km sin(declination) north with the seasons.
    if (!app.count("--horizon-km")) s.horizon_km = 40;
    if (!app.count("--horizon-pole-km")) s.horizon_pole_km = -13;
    if (!app.count("--horizon-shift-km")) s.horizon_shift_km = 11.5;
  } else if (o.horizon_preset != "none") {
    return scene::config_error{"horizon-preset", "horizon-preset = '" + o.horizon_preset +
                                                     "' is not one of: none, co2-15um"};
  }
  if (o.processing == "chord-phase")
    s.processing = scene::processing_method::chord_phase;
  else if (o.processing == "horizon-vector")
    s.processing = scene::processing_method::horizon_vector;
  else
    return scene::config_error{"processing", "processing = '" + o.processing +
                                                 "' is not one of: chord-phase, horizon-vector"};

  if (o.processing_radius.empty()) {
    s.processing_radius = scene::processing_radius_kind::truth;
  } else if (o.processing_radius == "equatorial") {
    s.processing_radius = scene::processing_radius_kind::equatorial;
  } else if (o.processing_radius == "local") {
    s.processing_radius = scene::processing_radius_kind::local;
  } else {
    const std::string& text = o.processing_radius;
    double km = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), km);
    if (ec != std::errc() || end != text.data() + text.size())
      return scene::config_error{
          "processing-radius",
          "processing-radius = '" + text + "' is not one of: equatorial, local, a radius in km"};
    s.processing_radius = scene::processing_radius_kind::value;
    s.processing_radius_km = km;
  }

  if (!o.heads.empty()) {
    s.heads.clear();
    for (const std::string& spec : o.heads) {
      auto parsed = scene::parse_head_spec(spec);
      if (auto* message = std::get_if<std::string>(&parsed))
        return scene::config_error{
            "head", "head " + std::to_string(s.heads.size() + 1) + " '" + spec + "': " + *message,
            s.heads.size() + 1};
      s.heads.push_back(std::get<scene::head_config>(parsed));
    }
  }
  if (auto err = scene::validate(s)) return *err;
  return s;
}

std::variant<std::vector<scene_run>, scene::config_error> to_scene_runs(const CLI::App& app,
                                                                        const options& o) {
  auto base = to_scene(app, o);
  if (auto* err = std::get_if<scene::config_error>(&base)) return *err;
  const scene::scene_config& scene = std::get<scene::scene_config>(base);
  if (o.sweep.empty()) return std::vector<scene_run>{{std::nan(""), scene}};

  auto parsed = scene::parse_sweep(o.sweep);
  if (auto* message = std::get_if<std::string>(&parsed))
    return scene::config_error{"sweep", "sweep " + *message};
  const scene::sweep_spec& spec = std::get<scene::sweep_spec>(parsed);
  std::vector<scene_run> runs;
  std::uint64_t rows = 0;
  for (double value : scene::sweep_values(spec)) {
    scene_run run{value, scene};
    const std::string problem = scene::apply_sweep_value(run.scene, spec.name, value);
    if (!problem.empty()) return scene::config_error{"sweep", problem};
    if (auto err = scene::validate(run.scene))
      return scene::config_error{
          "sweep", "at " + spec.name + " = " + scene::shortest_text(value) + ": " + err->message};
    rows += scene::row_count(run.scene);
    runs.push_back(run);
  }
  if (rows > scene.max_rows)
    return scene::config_error{
        "max-rows", "the sweep has " + std::to_string(rows) +
                        " rows, more than --max-rows = " + std::to_string(scene.max_rows)};
  return runs;
}

}  // namespace conescan::cli
