// conescan._conescan's scene runner: conescan-sim's scenes from Python (python/conescan/_scenes.py
// turns keyword arguments into option texts; this file does everything else).
//
// The options go through the scene layer exactly as conescan-sim's do: (name, text, origin)
// entries, a scene file's first, then build_scene_plan (src/scene/scene_plan.hpp), whose
// diagnostic text becomes the ValueError's message, word for word the CLI's. The rows are
// computed by scene::simulation and converted by src/simulation/csv_columns.hpp, the same code as
// the CSV's, so every number is the double whose shortest text conescan-sim prints. apply=FILE
// corrects every row with the fit's correction (scene::fit_correction), as conescan-sim --apply.
// New options of the option table therefore reach Python without a change here.
#include "scenes.hpp"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <bit>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "conescan/enum_names.hpp"
#include "scene/option_table.hpp"
#include "scene/scene_file.hpp"
#include "scene/scene_plan.hpp"
#include "scene_calibration/fit_correction.hpp"
#include "simulation/budget_run.hpp"
#include "simulation/csv_columns.hpp"
#include "simulation/simulation.hpp"
#include "simulation/summary.hpp"
#include "simulation/truth_source.hpp"

namespace conescan::python {

[[noreturn]] void raise(const conescan::diagnostic& error) {
  throw py::value_error(error.text());
}

void warn(const std::string& note) {
  if (PyErr_WarnEx(PyExc_UserWarning, note.c_str(), 1) != 0) throw py::error_already_set();
}

std::vector<scene::option_value> scene_entries(const option_texts& options,
                                               const std::optional<std::string>& config) {
  std::vector<scene::option_value> entries;
  if (config) {
    auto file = scene::read_scene_file(*config);
    if (!file.ok()) raise(file.error());
    entries = std::move(file).value();
  }
  for (const auto& [name, text] : options)
    entries.push_back({name, text, conescan::origin::command_line()});
  return entries;
}

namespace {

// The plan of a scene file (or none) and the keyword arguments' texts, which win over the file
// as the command line does. What `program` does not honour (conescan-sim's trace, threads,
// shards, state and ephemeris files; the summary for conescan.simulate, which the function
// chooses) is refused by the option table's rule (option_table.hpp, scene_program).
scene::scene_plan plan_of(const option_texts& options, const std::optional<std::string>& config,
                          scene::scene_program program) {
  std::vector<scene::option_value> entries = scene_entries(options, config);
  conescan::checked<scene::scene_plan> plan = scene::build_scene_plan(entries, program);
  if (!plan.ok()) raise(plan.error());
  if (const auto note = scene::interpolation_tolerance_note(plan.value())) warn(*note);
  return std::move(plan).value();
}

// apply=FILE: the fit's correction of the plan's one scene (conescan-sim --apply), or none.
std::unique_ptr<scene::fit_correction> correction_of(const scene::scene_plan& plan) {
  const auto& fit = plan.request().apply_fit;
  if (!fit) return nullptr;
  auto made = scene::fit_correction::of(plan.scene(0), *fit);
  if (!made.ok()) throw py::value_error(made.error().text());
  return std::move(made).value();
}

// -0 as 0: the CSV writes "0" for it (cli::output_sink::append_number), which reads back as +0.
double as_printed(double value) {
  return value == 0 ? 0.0 : value;
}

// The leading columns, then `rest`, as NumPy field names: unique, unlike the CSV's header, where
// a sweep of the seed is followed by the seed column (both "seed"); the swept one is then named
// "sweep_seed".
std::vector<scene::column_name> field_columns(const scene::leading_layout& layout,
                                              std::vector<scene::column_name> rest) {
  std::vector<scene::column_name> columns = layout.columns();
  columns.insert(columns.end(), std::make_move_iterator(rest.begin()),
                 std::make_move_iterator(rest.end()));
  if (!layout.sweep.empty())
    for (std::size_t k = 1; k < columns.size(); ++k)
      if (columns[k].name == layout.sweep) columns.front().name = "sweep_" + layout.sweep;
  return columns;
}

// --- Rows ------------------------------------------------------------------------------------

// A NumPy record of the columns: one 8-byte slot per column, so every field is aligned and no
// byte of a record is left unwritten (a status, uint8, is the low byte of its slot, the rest
// zero: records compare and hash by their bytes).
constexpr std::size_t slot_bytes = 8;
static_assert(std::endian::native == std::endian::little, "a status is its slot's first byte");

const char* format_of(scene::column_kind kind) {
  switch (kind) {
    case scene::column_kind::real:
      return "<f8";
    case scene::column_kind::count:
      return "<u8";
    case scene::column_kind::state:
      return "u1";
    case scene::column_kind::text:
      break;  // summary only, built in Python
  }
  throw std::logic_error("no record format for a text column");
}

py::dtype record_of(const std::vector<scene::column_name>& columns) {
  py::list names, formats, offsets;
  for (std::size_t k = 0; k < columns.size(); ++k) {
    names.append(columns[k].name);
    formats.append(format_of(columns[k].kind));
    offsets.append(k * slot_bytes);
  }
  return py::dtype(names, formats, offsets, static_cast<py::ssize_t>(columns.size() * slot_bytes));
}

// Writes one record's fields in column order (scene::visit_row's writer).
class record_writer {
 public:
  explicit record_writer(char* record) : next_(record) {}

  void leading(const scene::leading_value& v) {
    if (v.is_count)
      put(v.count);
    else
      put(as_printed(v.real));
  }
  void real(scene::row_column, double value) { put(as_printed(value)); }
  void state(scene::row_column, status s) { put(static_cast<std::uint64_t>(s)); }

 private:
  template <class T>
  void put(T value) {
    static_assert(sizeof value == slot_bytes);
    std::memcpy(next_, &value, slot_bytes);
    next_ += slot_bytes;
  }
  char* next_;
};

// Ctrl-C in a long run: Python's signal handlers run every 2^16 rows (the GIL taken for them);
// an exception they raise (KeyboardInterrupt) ends the run.
class signal_checks {
 public:
  void after(std::uint64_t rows_done) {
    if (rows_done < next_) return;
    next_ = rows_done + (std::uint64_t(1) << 16);
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  }

 private:
  std::uint64_t next_ = 0;
};

// Calls each(run, row) for every row of every run of a scene, in order (0-based runs), computed
// in chunks of conescan-sim's (scene::summary_chunk_rows rows of one run: a file source's
// state, an SGP4 resonance integration, is carried over a chunk). Called without the GIL.
template <class Each>
void for_each_row(const scene::simulation& sim, std::uint64_t runs, signal_checks& signals,
                  std::uint64_t& done, Each&& each) {
  const auto block_rows = static_cast<std::size_t>(
      std::min<std::uint64_t>(scene::summary_chunk_rows, sim.rows()));  // a sweep's short scenes
  std::vector<scene::row> block(block_rows, sim.make_row());
  for (std::uint64_t run = 0; run < runs; ++run)
    for (std::uint64_t k = 0; k < sim.rows(); k += block.size()) {
      signals.after(done);
      const auto count =
          static_cast<std::size_t>(std::min<std::uint64_t>(block.size(), sim.rows() - k));
      sim.compute_rows(k, count, block.data(), run);
      for (std::size_t i = 0; i < count; ++i, ++done) each(run, block[i]);
    }
}

// Every row of every scene and run into `data` (plan.total_rows() records), without the GIL.
void fill_rows(const scene::scene_plan& plan, const scene::leading_layout& layout,
               const scene::crossing_correction* correction, std::size_t itemsize, char* data) {
  py::gil_scoped_release release;
  std::uint64_t done = 0;
  signal_checks signals;
  for (std::uint64_t j = 0; j < plan.scene_count(); ++j) {
    const scene::loaded_scene scene = plan.scene(j);
    std::vector<scene::leading_value> leading;
    std::uint64_t leading_run = 0;  // the run `leading` is for, 1-based; 0: none yet
    scene::simulation sim = scene::simulation::of(scene).value();
    sim.set_correction(correction);
    for_each_row(sim, scene.config.runs, signals, done,
                 [&](std::uint64_t run, const scene::row& row) {
                   if (run + 1 != leading_run) {
                     leading_run = run + 1;
                     leading = scene::leading_values(layout, plan, j, scene.config, leading_run);
                   }
                   record_writer out(data + done * itemsize);
                   for (const scene::leading_value& v : leading) out.leading(v);
                   scene::visit_row(row, layout.condition, out, layout.intrusions);
                 });
  }
}

// Calls each(k, row) for every row of the budget (--budget), in order. Called without the GIL.
template <class Each>
void for_each_budget_row(const scene::budget_run& run, Each&& each) {
  signal_checks signals;
  scene::budget_row row = run.make_row();
  for (std::uint64_t k = 0; k < run.rows(); ++k) {
    signals.after(k);
    run.compute(k, row);
    each(k, row);
  }
}

// The budget's rows into `data` (run.rows() records), without the GIL.
void fill_budget_rows(const scene::budget_run& run, std::size_t itemsize, char* data) {
  py::gil_scoped_release release;
  for_each_budget_row(run, [&](std::uint64_t k, const scene::budget_row& row) {
    record_writer out(data + k * itemsize);
    scene::visit_budget_row(row, out);
  });
}

py::array records(const py::dtype& record, std::uint64_t count) {
  return py::array(record, std::vector<py::ssize_t>{static_cast<py::ssize_t>(count)});
}

py::array simulate(const option_texts& options, const std::optional<std::string>& config) {
  const scene::scene_plan plan = plan_of(options, config, scene::scene_program::python_rows);
  if (plan.request().budget) {
    const scene::budget_run run(plan.budget());
    const py::dtype record = record_of(scene::budget_columns(plan.budget()));
    py::array rows = records(record, run.rows());
    fill_budget_rows(run, static_cast<std::size_t>(record.itemsize()),
                     static_cast<char*>(rows.mutable_data()));
    return rows;
  }
  const scene::leading_layout layout = scene::leading_layout_of(plan);
  const py::dtype record =
      record_of(field_columns(layout, scene::row_columns(plan.request().scene.heads.size(),
                                                         layout.condition, layout.intrusions)));
  py::array rows = records(record, plan.total_rows());
  const std::unique_ptr<scene::fit_correction> correction = correction_of(plan);
  fill_rows(plan, layout, correction.get(), static_cast<std::size_t>(record.itemsize()),
            static_cast<char*>(rows.mutable_data()));
  return rows;
}

// --- Summary ---------------------------------------------------------------------------------

// A summary line: the leading values, the source, its counts and statistics (degrees).
py::tuple summary_line(const std::vector<scene::leading_value>& leading, const std::string& source,
                       const scene::error_statistics& s, bool intrusions) {
  py::list values;
  for (const scene::leading_value& v : leading)
    values.append(v.is_count ? py::object(py::int_(v.count))
                             : py::object(py::float_(as_printed(v.real))));
  values.append(source);
  values.append(s.rows);
  for (std::uint64_t count : s.status_counts) values.append(count);
  for (double v : scene::summary_statistics_deg(s)) values.append(as_printed(v));
  if (intrusions)
    for (double v : scene::summary_lost_fractions(s)) values.append(as_printed(v));
  return py::tuple(values);
}

// The summary of scene j over all its runs: one line per head and one for the system.
void add_summary_lines(const scene::scene_plan& plan, const scene::leading_layout& layout,
                       const scene::crossing_correction* correction, std::uint64_t j,
                       py::list& lines) {
  const scene::loaded_scene scene = plan.scene(j);
  scene::simulation sim = scene::simulation::of(scene).value();
  sim.set_correction(correction);
  scene::chunked_summary<scene::run_summary> chunked(scene::run_summary(sim.head_count()));
  {
    py::gil_scoped_release release;
    signal_checks signals;
    std::uint64_t done = 0;
    std::uint64_t current_run = 0;
    for_each_row(sim, scene.config.runs, signals, done,
                 [&](std::uint64_t run, const scene::row& row) {
                   if (run != current_run) chunked.end_run();  // a chunk never spans two runs
                   current_run = run;
                   chunked.add(row);
                 });
    chunked.end_run();
  }
  const scene::run_summary& summary = chunked.total();
  const std::vector<scene::leading_value> leading =
      scene::leading_values(layout, plan, j, scene.config, scene.config.runs);
  for (std::size_t h = 0; h < summary.heads.size(); ++h)
    lines.append(
        summary_line(leading, scene::summary_source_name(h), summary.heads[h], layout.intrusions));
  lines.append(
      summary_line(leading, scene::summary_system_name, summary.system, layout.intrusions));
}

// The budget's summary: one line per source, then the sum of the single sources and the
// interaction (all - sum).
void add_budget_summary_lines(const scene::scene_plan& plan, py::list& lines) {
  const bool intrusions = scene::leading_layout_of(plan).intrusions;
  const scene::budget_run run(plan.budget());
  scene::chunked_summary<scene::budget_summary> chunked(
      scene::budget_summary(plan.budget().size()));
  {
    py::gil_scoped_release release;
    for_each_budget_row(run,
                        [&](std::uint64_t, const scene::budget_row& row) { chunked.add(row); });
    chunked.end_run();
  }
  const scene::budget_summary& summary = chunked.total();
  for (std::size_t i = 0; i < summary.sources.size(); ++i)
    lines.append(summary_line({}, plan.budget()[i].name, summary.sources[i], intrusions));
  lines.append(summary_line({}, scene::budget_sum_name, summary.sum, intrusions));
  lines.append(summary_line({}, scene::budget_interaction_name, summary.interaction, intrusions));
}

const char* kind_name(scene::column_kind kind) {
  static constexpr enum_names<scene::column_kind, 4> names{{{scene::column_kind::real, "real"},
                                                            {scene::column_kind::count, "count"},
                                                            {scene::column_kind::state, "status"},
                                                            {scene::column_kind::text, "text"}}};
  return name_of(names, kind, "");
}

// (columns as (name, kind) pairs, lines as tuples): python/conescan/_scenes.py makes the array.
py::tuple summary(const option_texts& options, const std::optional<std::string>& config) {
  const scene::scene_plan plan = plan_of(options, config, scene::scene_program::python_summary);
  const scene::leading_layout layout = scene::leading_layout_of(plan);
  py::list columns;
  for (const scene::column_name& c :
       field_columns(layout, scene::summary_columns(layout.intrusions)))
    columns.append(py::make_tuple(c.name, kind_name(c.kind)));
  py::list lines;
  if (plan.request().budget)
    add_budget_summary_lines(plan, lines);
  else {
    const std::unique_ptr<scene::fit_correction> correction = correction_of(plan);
    for (std::uint64_t j = 0; j < plan.scene_count(); ++j)
      add_summary_lines(plan, layout, correction.get(), j, lines);
  }
  return py::make_tuple(columns, lines);
}

}  // namespace

void def_scenes(py::module_& m) {
  m.def("_simulate", &simulate, py::arg("options"), py::arg("config"),
        "The rows of a scene as a structured array (conescan.simulate).");
  m.def("_summary", &summary, py::arg("options"), py::arg("config"),
        "The summary lines of a scene: (columns, lines) (conescan.summary).");
  m.def(
      "_options",
      [] {
        py::list options;
        for (const scene::option_spec& o : scene::option_table()) {
          // The value's form (FILE, K/N...) leads the help, as --help shows it before the help.
          const std::string form = o.value_name.empty() ? "" : std::string(o.value_name) + ": ";
          py::list honoured_by;
          for (const scene::scene_program p :
               {scene::scene_program::python_rows, scene::scene_program::python_summary,
                scene::scene_program::fit})
            if (scene::honours(p, o)) honoured_by.append(std::string(scene::program_name(p)));
          options.append(py::make_tuple(std::string(o.name),
                                        std::string(scene::value_kind_name(o.kind)),
                                        form + scene::option_help(o), py::tuple(honoured_by)));
        }
        return options;
      },
      "The option table: (name, kind, help, the functions that honour it) per option, in "
      "--help's order.");
}

}  // namespace conescan::python
