#include "scene/scene_plan.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>

#include "scene/calendar_span.hpp"
#include "scene/head_spec.hpp"
#include "scene/loaded_scene.hpp"
#include "scene/option_table.hpp"
#include "scene/scene_validation.hpp"
#include "scene/sensor_preset.hpp"
#include "text/number_text.hpp"
#include "text/output_file.hpp"

namespace conescan::scene {

namespace {

// Where each option the user gave came from.
struct given_options {
  std::map<std::string, origin, std::less<>> last;  // by name: its (single) origin
  std::vector<origin> heads;                        // head K's origin at [K - 1]
  std::vector<std::set<std::string>> head_keys;     // the keys head K's spec gave, at [K - 1]

  const origin* find(std::string_view name) const {
    const auto it = last.find(name);
    return it == last.end() ? nullptr : &it->second;
  }
};

std::string place(const origin& where) {
  return where.from_file() ? "at " + where.text() : "on the command line";
}

// The command line wins over a scene file: a file entry is dropped when the command line gives
// the same option or one it excludes; the file's heads are dropped when the command line gives
// any. `dropped` receives the file's entries left out.
std::vector<const option_value*> command_line_first(std::span<const option_value> entries,
                                                    std::vector<const option_value*>& dropped) {
  std::map<std::string_view, bool> on_command_line;
  for (const option_value& v : entries)
    if (!v.where.from_file()) on_command_line[v.name] = true;
  std::vector<const option_value*> kept;
  for (const option_value& v : entries) {
    if (v.where.from_file()) {
      const option_spec* spec = find_option(v.name);
      const auto excluded_by_command_line = [&](const auto& given) {
        return spec && excludes(*spec, given.first);
      };
      if (on_command_line.count(v.name) ||
          std::any_of(on_command_line.begin(), on_command_line.end(), excluded_by_command_line)) {
        dropped.push_back(&v);
        continue;
      }
    }
    kept.push_back(&v);
  }
  return kept;
}

// A file's entries the command line overrides are checked as if they were used (each on a
// scene of its own): a file that says `duration-s = nan` is wrong whatever the command line says.
checked<void> check_overridden(const std::vector<const option_value*>& dropped) {
  for (const option_value* v : dropped) {
    const option_spec* spec = find_option(v->name);
    if (!spec) continue;  // check_names refuses it with the others
    scene_request scratch;
    if (checked<void> applied = apply_option(*spec, scratch, *v); !applied.ok()) return applied;
  }
  return success();
}

// Unknown names, an option given twice, two options that exclude each other.
checked<void> check_names(const std::vector<const option_value*>& entries) {
  std::map<std::string_view, const option_value*> seen;
  for (const option_value* v : entries) {
    const option_spec* spec = find_option(v->name);
    if (!spec)
      return diagnostic{
          {}, "unknown option " + quote(v->name) + "; options: " + option_names(), v->where};
    if (spec->kind == value_kind::head) continue;
    if (const auto it = seen.find(spec->name); it != seen.end())
      return diagnostic{v->name, "given twice (first " + place(it->second->where) + ")", v->where};
    for (const auto& [name, first] : seen)
      if (excludes(*spec, name))
        return diagnostic{v->name,
                          "excludes --" + std::string(name) + " (given " + place(first->where) +
                              "): give one of them",
                          v->where};
    seen[spec->name] = v;
  }
  return success();
}

// The options `program` does not honour (option_table.hpp, scene_program): given on the command
// line (or as a keyword), refused; in a scene file refused when applying it after the other
// entries changes what --print-config would write of it (it asks for something), else dropped.
checked<std::vector<const option_value*>> honoured_only(
    const std::vector<const option_value*>& entries, scene_program program) {
  std::vector<const option_value*> kept, dropped;
  for (const option_value* v : entries) {
    const option_spec* spec = find_option(v->name);
    if (spec && !honours(program, *spec)) {
      if (!v->where.from_file()) return not_honoured(program, *spec, v->where);
      dropped.push_back(v);
    } else {
      kept.push_back(v);
    }
  }
  if (dropped.empty()) return kept;
  scene_request without;
  for (const option_value* v : kept)  // errors here are reported by apply_entries after
    (void)apply_option(*find_option(v->name), without, *v);
  for (const option_value* v : dropped) {
    const option_spec& spec = *find_option(v->name);
    scene_request with = without;
    if (!apply_option(spec, with, *v).ok() ||
        print_option(spec, with) != print_option(spec, without))
      return not_honoured(program, spec, v->where);
  }
  return kept;
}

checked<void> apply_entries(const std::vector<const option_value*>& entries, scene_request& r,
                            given_options& given) {
  for (const option_value* v : entries) {
    const option_spec& spec = *find_option(v->name);
    if (checked<void> applied = apply_option(spec, r, *v); !applied.ok()) return applied;
    if (spec.kind == value_kind::head) {
      given.heads.push_back(v->where);
      given.head_keys.push_back(head_spec_keys(v->text));
    } else {
      given.last[v->name] = v->where;
    }
  }
  return success();
}

// SeaWiFS Earth-sensor navigation (its earth.f), fitted to flight data: the CO2 horizon sits
// ~40 km up, ~13 km lower over the poles than a geodetic ellipsoid puts it, and moves ~11.5 km
// sin(declination) north with the seasons. Each figure unless the user gave it.
void fill_in_preset(scene_request& r, const given_options& given) {
  if (r.preset != horizon_preset::co2_15um) return;
  if (!given.find("horizon-km")) r.scene.horizon_km = 40;
  if (!given.find("horizon-pole-km")) r.scene.horizon_pole_km = -13;
  if (!given.find("horizon-shift-km")) r.scene.horizon_shift_km = 11.5;
}

// validate() names the option whose value is out of range, or the first of a relation it
// checks. Pin the error on an option the user gave, at its origin: the one named if given,
// else the first given of the option's blame_instead list (option_table.cpp). A diagnostic
// already placed on a line of a file (an element set, an ephemeris, a table) keeps that place,
// the more precise one; one about a whole file (it cannot be opened, it holds nothing) names the
// file in its message and takes the place of the option that named it.
diagnostic placed(diagnostic error, const given_options& given) {
  if (error.where.from_file() && error.where.line != 0) return error;
  if (error.where.from_file()) {
    error.message = error.where.file + ": " + error.message;
    error.where = origin::command_line();
  }
  if (error.option == "head" && error.head >= 1 && error.head <= given.heads.size()) {
    error.where = given.heads[error.head - 1];
    return error;
  }
  if (const origin* where = given.find(error.option)) {
    error.where = *where;
    return error;
  }
  const option_spec* spec = find_option(error.option);
  std::string_view candidates = spec ? spec->blame_instead : std::string_view();
  while (!candidates.empty()) {
    const std::size_t space = candidates.find(' ');
    const std::string_view name = candidates.substr(0, space);
    if (const origin* where = given.find(name)) {
      error.option = std::string(name);
      error.where = *where;
      return error;
    }
    candidates =
        space == std::string_view::npos ? std::string_view() : candidates.substr(space + 1);
  }
  return error;
}

checked<void> check_budget(scene_request& r, const given_options& given) {
  if (!r.budget) return success();
  r.scene.model = forward_model::scan;  // every run of the budget uses the exact model
  const origin where = *given.find("budget");
  if (r.sweep)
    return diagnostic{"budget",
                      "runs one scene: drop --sweep (given " + place(*given.find("sweep")) + ")",
                      where};
  if (r.scene.runs != 1) return diagnostic{"budget", "runs the scene once: drop --runs", where};
  return success();
}

// --apply corrects the one scene its fit was made for (fit_correction.hpp): conescan-sim's and
// the Python module's rule.
checked<void> check_apply(const scene_request& r, const given_options& given) {
  if (!r.apply_fit || (!r.sweep && !r.budget)) return success();
  return diagnostic{"apply", "corrects one scene: not with --sweep or --budget",
                    *given.find("apply")};
}

// MODEL §10: one orbit source and one attitude source. An element or angle given with a file that
// replaces it is refused, naming both; the files are then read and checked (before any row): the
// one place a plan's files are loaded, for all its scenes.
checked<std::shared_ptr<const source_files>> read_sources(const scene_request& r,
                                                          const given_options& given) {
  for (const auto& [name, where] : given.last) {
    const std::string_view source = replaced_by_source(r, name);
    if (source.empty()) continue;
    return diagnostic{
        name,
        "the " +
            std::string(source == "tle" || source == "omm" || source == "oem" ? "orbit"
                                                                              : "attitude") +
            " comes from --" + std::string(source) + " (given " + place(*given.find(source)) +
            "): give one of them",
        where};
  }
  if (!r.write_oem_file.empty() && r.sweep)
    return diagnostic{
        "write-oem",
        "writes one scene's orbit: drop --sweep (given " + place(*given.find("sweep")) + ")",
        *given.find("write-oem")};
  checked<loaded_scene> loaded = load_scene(r.scene, r.sweep.has_value());
  if (!loaded.ok()) return placed(std::move(loaded).error(), given);
  return std::move(loaded).value().files;
}

// The files a run writes (--write-oem, --write-aem, --summary-state): one file each, or the second
// would replace the first; and none of them a file the run reads (a source, the fit it applies,
// the scene files its entries came from).
checked<void> check_outputs(const scene_request& r, const given_options& given,
                            std::span<const option_value> entries) {
  const std::pair<std::string_view, const std::string*> outputs[] = {
      {"write-oem", &r.write_oem_file},
      {"write-aem", &r.write_aem_file},
      {"summary-state", &r.summary_state}};
  std::vector<input_file> inputs = scene_input_files(r.scene);
  if (r.apply_fit) inputs.push_back({"apply", *r.apply_fit});
  for (const option_value& v : entries)
    if (v.where.from_file() &&
        std::none_of(inputs.begin(), inputs.end(),
                     [&](const input_file& in) { return in.path == v.where.file; }))
      inputs.push_back({"config", v.where.file});
  for (const auto& [option, path] : outputs)
    if (checked<void> apart = output_apart_from_inputs(option, *path, inputs); !apart.ok())
      return placed(std::move(apart).error(), given);
  for (std::size_t j = 1; j < std::size(outputs); ++j)
    for (std::size_t i = 0; i < j; ++i) {
      const auto& [first, first_path] = outputs[i];
      const auto& [second, second_path] = outputs[j];
      if (first_path->empty() || second_path->empty() ||
          !text::same_output_file(*first_path, *second_path))
        continue;
      return diagnostic{std::string(second),
                        quote(*second_path) + " is also the file of --" + std::string(first) +
                            " (given " + place(*given.find(first)) +
                            "): give each output a file of its own",
                        *given.find(second)};
    }
  return success();
}

// --calendar (blinding_calendar.hpp): one scene's Sun and Moon (it implies --intrusions), over a
// year from the epoch unless the span was given, sampled at 1 s unless the step was given. The
// rows it stands for are not computed: unless --max-rows was given, it holds them.
checked<void> check_calendar(scene_request& r, const std::shared_ptr<const source_files>& files,
                             const given_options& given) {
  if (r.calendar_dir.empty()) return success();
  const origin where = *given.find("calendar");
  const std::pair<const char*, bool> others[] = {{"sweep", r.sweep.has_value()},
                                                 {"budget", r.budget},
                                                 {"summary", r.summary},
                                                 {"summary-state", !r.summary_state.empty()},
                                                 {"shard", r.shard.has_value()},
                                                 {"apply", r.apply_fit.has_value()},
                                                 {"runs", r.scene.runs != 1},
                                                 {"write-oem", !r.write_oem_file.empty()},
                                                 {"write-aem", !r.write_aem_file.empty()}};
  for (const auto& [other, asked] : others)
    if (const origin* at = given.find(other); asked && at)
      return diagnostic{"calendar",
                        "writes one scene's calendar: drop --" + std::string(other) + " (given " +
                            place(*at) + ")",
                        where};
  if (r.scene.model != forward_model::scan)
    return diagnostic{"calendar",
                      "needs --model scan: MODEL §13's rule is on the true scan cone, which the "
                      "bias model does not trace",
                      given.find("model") ? *given.find("model") : where};
  r.scene.intrusions = true;
  if (!given.find("step-s")) r.scene.step_s = 1;
  if (!(r.scene.step_s >= calendar_least_step_s))
    return diagnostic{"step-s",
                      "step-s = " + text::shortest_text(r.scene.step_s) +
                          " is below the calendar's least resolution, " +
                          text::shortest_text(calendar_least_step_s) + " s",
                      given.find("step-s") ? *given.find("step-s") : where};
  if (!given.find("duration-s") && !given.find("orbits"))
    r.scene.duration_s = calendar_year_s(files->epoch);
  if (!given.find("max-rows"))
    r.scene.max_rows = std::max(r.scene.max_rows, row_count(loaded_scene{r.scene, files}));
  return success();
}

// Scene j of a swept request (j < count), and whether the sweep could set it.
checked<scene_config> swept_scene(const scene_request& r, std::uint64_t j) {
  scene_request copy = r;
  const double value = sweep_value(*r.sweep, j);
  if (checked<void> set = apply_sweep_value(copy, r.sweep->name, value); !set.ok())
    return std::move(set).error();
  return std::move(copy.scene);
}

struct run_totals {
  std::uint64_t rows = 0;
  bool any_runs = false;
  bool any_noise = false;

  // Adds a validated scene's rows (all its runs: at most max_rows, validate() checked);
  // false, adding nothing, when the sum would pass max_rows.
  bool add(const loaded_scene& scene) {
    const scene_config& s = scene.config;
    const std::uint64_t scene_rows = row_count(scene) * s.runs;
    if (scene_rows > s.max_rows - rows) return false;
    rows += scene_rows;
    any_runs = any_runs || s.runs > 1;
    any_noise = any_noise || has_noise(s);
    return true;
  }
};

diagnostic sweep_error(std::string message, const origin& where) {
  return diagnostic{"sweep", std::move(message), where};
}

// A sweep: its name can be swept and takes effect in this scene; its values fit --max-rows
// (counted before any is computed: each scene has at least one row), advance, and each gives a
// valid scene (checked one by one, nothing stored).
checked<run_totals> check_sweep(const scene_request& r,
                                const std::shared_ptr<const source_files>& files,
                                const origin& where) {
  const sweep_spec& sweep = *r.sweep;
  if (checked<scene_config> first = swept_scene(r, 0); !first.ok())
    return sweep_error(first.error().message, where);
  if (const option_spec* spec = find_option(sweep.name); spec && spec->ignored)
    if (const char* why = spec->ignored(r))
      return sweep_error("sweeping " + sweep.name + " changes nothing: " + why, where);
  if (const std::string_view source = replaced_by_source(r, sweep.name); !source.empty())
    return sweep_error(
        "sweeping " + sweep.name + " changes nothing: --" + std::string(source) + " replaces it",
        where);
  const std::uint64_t max_rows = r.scene.max_rows;
  if (sweep.count > max_rows)
    return sweep_error(quote(sweep.text) + " has " + std::to_string(sweep.count) +
                           " values, each a scene of at least one row: more than --max-rows = " +
                           std::to_string(max_rows),
                       where);
  run_totals totals;
  double previous = 0;
  for (std::uint64_t j = 0; j < sweep.count; ++j) {
    const double value = sweep_value(sweep, j);
    if (j > 0 && !(value > previous))
      return sweep_error(quote(sweep.text) + ": STEP does not advance the value past " +
                             text::shortest_text(previous) + " (below a double's resolution there)",
                         where);
    previous = value;
    checked<scene_config> swept = swept_scene(r, j);
    if (!swept.ok()) return sweep_error(swept.error().message, where);
    const loaded_scene scene{std::move(swept).value(), files};
    if (checked<void> valid = validate(scene); !valid.ok())
      return sweep_error("at " + sweep.name + " = " + text::shortest_text(value) + ": --" +
                             valid.error().option + ": " + valid.error().message,
                         where);
    if (!totals.add(scene))
      return diagnostic{"max-rows",
                        "the sweep has more than --max-rows = " + std::to_string(max_rows) +
                            " rows (all values and runs): raise --max-rows, or the step",
                        where};
  }
  return totals;
}

// The request of the entries: precedence, names, values, preset, its files loaded (into `files`),
// validation.
checked<scene_request> read_request(std::span<const option_value> entries, scene_program program,
                                    given_options& given,
                                    std::shared_ptr<const source_files>& files) {
  std::vector<const option_value*> overridden;
  const std::vector<const option_value*> given_entries = command_line_first(entries, overridden);
  if (checked<void> names = check_names(given_entries); !names.ok())
    return std::move(names).error();
  if (checked<void> checked_too = check_overridden(overridden); !checked_too.ok())
    return std::move(checked_too).error();
  checked<std::vector<const option_value*>> kept = honoured_only(given_entries, program);
  if (!kept.ok()) return std::move(kept).error();
  scene_request r;
  if (checked<void> applied = apply_entries(kept.value(), r, given); !applied.ok())
    return std::move(applied).error();
  fill_in_sensor_preset(
      r, [&](std::string_view name) { return given.find(name) != nullptr; }, given.head_keys);
  fill_in_preset(r, given);
  checked<std::shared_ptr<const source_files>> sources = read_sources(r, given);
  if (!sources.ok()) return std::move(sources).error();
  files = std::move(sources).value();
  if (checked<void> budget = check_budget(r, given); !budget.ok()) return std::move(budget).error();
  if (checked<void> calendar = check_calendar(r, files, given); !calendar.ok())
    return std::move(calendar).error();
  if (checked<void> apply = check_apply(r, given); !apply.ok()) return std::move(apply).error();
  if (checked<void> outputs = check_outputs(r, given, entries); !outputs.ok())
    return std::move(outputs).error();
  if (checked<void> valid = validate(loaded_scene{r.scene, files}); !valid.ok())
    return placed(std::move(valid).error(), given);
  return r;
}

// A shard must not be empty: N at most the campaign's units. The error names --shard at `where`.
checked<void> check_shard(const scene_plan& plan, const origin& where) {
  const std::optional<shard_spec>& shard = plan.request().shard;
  if (!shard) return success();
  const std::uint64_t units = campaign_units(plan);
  if (shard->count <= units) return success();
  return diagnostic{"shard",
                    "'" + std::to_string(shard->index) + "/" + std::to_string(shard->count) +
                        "': the campaign has " + std::to_string(units) +
                        " run(s) (sweep values x runs) to share: N must be at most " +
                        std::to_string(units),
                    where};
}

}  // namespace

std::uint64_t runs_of(const scene_plan& plan, std::uint64_t j) {
  const scene_request& r = plan.request();
  if (r.budget) return 1;
  if (r.sweep && r.sweep->name == "runs") return plan.scene(j).config.runs;
  return r.scene.runs;
}

std::uint64_t campaign_units(const scene_plan& plan) {
  const scene_request& r = plan.request();
  if (!(r.sweep && r.sweep->name == "runs")) return plan.scene_count() * runs_of(plan, 0);
  std::uint64_t total = 0;  // at most --max-rows: every run has a row
  for (std::uint64_t j = 0; j < plan.scene_count(); ++j) total += runs_of(plan, j);
  return total;
}

std::optional<std::string> interpolation_tolerance_note(const scene_plan& plan) {
  const loaded_scene first = plan.scene(0);
  if (!first.files || !first.files->oem ||
      !(first.config.interpolation_tolerance_deg > default_interpolation_tolerance_deg))
    return std::nullopt;
  double last_t_s = 0;
  for (std::uint64_t j = 0; j < plan.scene_count(); ++j)
    last_t_s = std::max(last_t_s, last_row_t_s(plan.scene(j)));
  return interpolation_tolerance_note(first, last_t_s);
}

double scene_plan::sweep_value(std::uint64_t j) const {
  return request_.sweep ? scene::sweep_value(*request_.sweep, j) : std::nan("");
}

loaded_scene scene_plan::scene(std::uint64_t j) const {
  return {request_.sweep ? swept_scene(request_, j).value() : request_.scene, files_};
}

checked<scene_plan> build_scene_plan(std::span<const option_value> entries, scene_program program) {
  given_options given;
  scene_plan plan;
  checked<scene_request> request = read_request(entries, program, given, plan.files_);
  if (!request.ok()) return std::move(request).error();
  plan.request_ = std::move(request).value();
  const scene_request& r = plan.request_;
  run_totals totals;
  if (r.sweep) {
    checked<run_totals> swept = check_sweep(r, plan.files_, *given.find("sweep"));
    if (!swept.ok()) return std::move(swept).error();
    totals = swept.value();
    plan.scene_count_ = r.sweep->count;
  } else {
    totals.add(plan.scene(0));
  }
  plan.total_rows_ = totals.rows;
  plan.any_runs_ = totals.any_runs;
  plan.any_noise_ = totals.any_noise;
  if (r.budget) {
    checked<std::vector<budget_source>> sources = budget_sources(plan.scene(0));
    if (!sources.ok()) {
      diagnostic error = std::move(sources).error();
      error.where = *given.find("budget");
      return error;
    }
    plan.budget_ = std::move(sources).value();
  }
  if (r.shard)  // no empty shard (campaign.hpp)
    if (checked<void> shard = check_shard(plan, *given.find("shard")); !shard.ok())
      return std::move(shard).error();
  return plan;
}

}  // namespace conescan::scene
