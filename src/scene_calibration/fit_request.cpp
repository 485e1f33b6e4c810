#include "scene_calibration/fit_request.hpp"

#include <array>
#include <map>

#include "calibration/parameters.hpp"
#include "scene/scene_plan.hpp"
#include "text/number_text.hpp"
#include "text/parallel_parts.hpp"

namespace conescan::calibration {

namespace {

constexpr int max_iterations_limit = 10000;

using K = fit_option_kind;

constexpr std::array<fit_option_spec, 7> table{{
    {"telemetry", K::text, "FILE",
     "telemetry CSV: t_s and per head hK_chord_deg, hK_phase_deg (conescan-sim's CSV is one); "
     "other columns are ignored"},
    {"free", K::text, "LIST",
     "parameters to estimate, comma-separated: hK.sigma, hK.phase, hK.dgamma, hK.bias-in, "
     "hK.bias-out, and with the sensor physics hK.tau-ms, hK.threshold (K = 1..heads), "
     "horizon-km, horizon-pole-km, horizon-shift-km, and with the physics radiance-offset-km, "
     "radiance-scale-km; the others are held at the scene's values; NAME@SECONDS drifts: one "
     "value per SECONDS of telemetry"},
    {"loss", K::choice, "WORD",
     "huber (robust to outliers, the default) or none (plain weighted least squares)"},
    {"max-iterations", K::count, "COUNT",
     "Levenberg-Marquardt iterations at most, [1, 10000] (default 100); a fit that needs more "
     "reports NOT CONVERGED with its last state and exits 1"},
    {"residuals", K::text, "FILE",
     "also write every measurement's residuals at the solution to FILE (CSV: t_s, row, head, "
     "lat_deg, chord and phase residuals in deg, normalised, fitted), for scripts/plot-fit.py",
     false},
    {"json", K::flag, "", "one JSON object on standard output instead of the table", false},
    {"predict", K::flag, "",
     "experiment design: the 1 sigma each free parameter would reach for the scene as planned "
     "(its orbit, --step-s, --orbits or --duration-s, heads' noise=) from the Fisher information, "
     "without telemetry",
     false},
}};

// The one entry of each fit option given, or the refusal of one given twice.
checked<std::map<std::string_view, const scene::option_value*>> fit_entries(
    std::span<const scene::option_value> entries) {
  std::map<std::string_view, const scene::option_value*> given;
  for (const scene::option_value& v : entries) {
    const fit_option_spec* spec = find_fit_option(v.name);
    if (!spec) continue;
    if (given.count(spec->name))
      return diagnostic{
          v.name, spec->name == "free" ? "given twice: list every parameter in one" : "given twice",
          v.where};
    given[spec->name] = &v;
  }
  return given;
}

checked<bool> flag_of(const scene::option_value* v) {
  if (!v) return false;
  checked<bool> set = text::parse_flag(v->text);
  if (!set.ok()) return diagnostic{v->name, set.error().message, v->where};
  return set;
}

}  // namespace

std::span<const fit_option_spec> fit_option_table() {
  return table;
}

const fit_option_spec* find_fit_option(std::string_view name) {
  for (const fit_option_spec& o : table)
    if (o.name == name) return &o;
  return nullptr;
}

checked<fit_request> read_fit_request(std::span<const scene::option_value> entries,
                                      telemetry_input input) {
  checked<std::map<std::string_view, const scene::option_value*>> read = fit_entries(entries);
  if (!read.ok()) return std::move(read).error();
  const auto& given = read.value();
  const auto entry = [&](std::string_view name) -> const scene::option_value* {
    const auto it = given.find(name);
    return it == given.end() ? nullptr : it->second;
  };
  fit_request r;
  if (const scene::option_value* v = entry("max-iterations")) {
    const checked<std::uint64_t> count = text::parse_count(v->text);
    if (!count.ok() || count.value() < 1 || count.value() > max_iterations_limit)
      return diagnostic{
          "max-iterations",
          quote(v->text) + " is not a count in [1, " + std::to_string(max_iterations_limit) + "]",
          v->where};
    r.max_iterations = static_cast<int>(count.value());
  }
  for (const std::string_view name : {"json", "predict"}) {
    checked<bool> set = flag_of(entry(name));
    if (!set.ok()) return std::move(set).error();
    (name == "json" ? r.json : r.predict) = set.value();
  }
  const scene::option_value* telemetry = entry("telemetry");
  if (telemetry) r.telemetry = telemetry->text;
  const scene::option_value* free = entry("free");
  if (!free)
    return diagnostic{"free", "missing: name the parameters to estimate (conescan-fit --help)"};
  r.free = free->text;
  if (const scene::option_value* loss = entry("loss")) {
    if (loss->text == "none")
      r.loss = robust_loss::none;
    else if (loss->text != "huber")
      return diagnostic{"loss", quote(loss->text) + " is not one of: huber, none", loss->where};
  }
  if (r.predict && telemetry)
    return diagnostic{"telemetry", "--predict plans a scene without data: drop --telemetry",
                      telemetry->where};
  if (input == telemetry_input::in_memory && telemetry)
    return diagnostic{"telemetry", "given twice: as arrays and as a file", telemetry->where};
  if (const scene::option_value* residuals = entry("residuals")) {
    if (r.predict)
      return diagnostic{"residuals", "--predict plans a scene without data: drop --residuals",
                        residuals->where};
    if (residuals->text.empty())  // as every output option refuses it: bad input, exit 2
      return diagnostic{"residuals", "empty value: give a file name", residuals->where};
    r.residuals = residuals->text;
  }
  if (!r.predict && !telemetry && input == telemetry_input::file_option)
    return diagnostic{"telemetry", "missing: give the telemetry CSV to fit (or --predict)"};
  return r;
}

checked<void> single_scene_problem(const scene::scene_request& r) {
  if (r.sweep) return diagnostic{"sweep", "conescan-fit fits one scene"};
  if (r.budget) return diagnostic{"budget", "conescan-fit fits one scene"};
  if (r.summary) return diagnostic{"summary", "conescan-fit prints its own table"};
  if (r.scene.runs != 1) return diagnostic{"runs", "conescan-fit fits one telemetry"};
  if (r.apply_fit)
    return diagnostic{"apply", "conescan-sim corrects with a fit; conescan-fit makes one"};
  return success();
}

checked<fit_plan> build_fit_plan(std::span<const scene::option_value> entries,
                                 telemetry_input input) {
  std::vector<scene::option_value> scene_entries;
  for (const scene::option_value& v : entries)
    if (!find_fit_option(v.name)) scene_entries.push_back(v);
  checked<scene::scene_plan> plan =
      scene::build_scene_plan(scene_entries, scene::scene_program::fit);
  if (!plan.ok()) return std::move(plan).error();
  if (checked<void> one = single_scene_problem(plan.value().request()); !one.ok())
    return std::move(one).error();
  checked<fit_request> request = read_fit_request(entries, input);
  if (!request.ok()) return std::move(request).error();
  const std::uint64_t threads = plan.value().request().threads;
  fit_plan out{plan.value().scene(0),
               std::move(request).value(),
               {},
               static_cast<int>(threads != 0 ? threads : text::available_cores())};
  checked<std::vector<free_parameter>> free =
      parse_free_selection(out.request.free, out.scene.config.heads.size());
  if (!free.ok()) return std::move(free).error();
  out.free = std::move(free).value();
  // The residuals are written over nothing the fit reads (its telemetry, the scene's sources, the
  // scene files of its options).
  std::vector<scene::input_file> inputs = scene::scene_input_files(out.scene.config);
  if (out.request.telemetry) inputs.push_back({"telemetry", *out.request.telemetry});
  for (const scene::option_value& v : entries)
    if (v.where.from_file()) inputs.push_back({"config", v.where.file});
  if (out.request.residuals)
    if (checked<void> apart =
            scene::output_apart_from_inputs("residuals", *out.request.residuals, inputs);
        !apart.ok())
      return std::move(apart).error();
  return out;
}

}  // namespace conescan::calibration
