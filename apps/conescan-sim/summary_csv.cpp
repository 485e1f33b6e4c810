#include "summary_csv.hpp"

namespace conescan::cli {

namespace {

// The summary's columns: a count per status, in the order of all_statuses (status.hpp).
std::string statistics_header() {
  std::string header = "source,rows";
  for (status s : all_statuses) header += std::string(",") + to_string(s);
  return header +
         ",roll_min_deg,roll_max_deg,roll_mean_deg,roll_rms_deg,roll_std_deg,roll_3sigma_deg,"
         "pitch_min_deg,pitch_max_deg,pitch_mean_deg,pitch_rms_deg,pitch_std_deg,"
         "pitch_3sigma_deg\n";
}

// One summary line: counts, then min, max, mean, RMS, 1 sigma and 3 sigma of roll and pitch
// over the ok rows (NaN when there are none).
void write_statistics(output_sink& out, const leading_columns& leading, const std::string& source,
                      const scene::error_statistics& s) {
  leading.write_values(out);
  out.append(source);
  out.append(',');
  out.append_count(s.rows);
  for (std::uint64_t count : s.status_counts) {
    out.append(',');
    out.append_count(count);
  }
  const double nan = not_a_number<double>();
  for (const scene::running_statistics* q : {&s.roll, &s.pitch}) {
    const bool any = q->count > 0;
    for (double v : {any ? q->min : nan, any ? q->max : nan, any ? q->mean : nan, q->rms(),
                     q->std(), 3 * q->std()}) {
      out.append(',');
      out.append_number(rad_to_deg(v));
    }
  }
  out.append('\n');
  out.end_row();
}

}  // namespace

leading_columns leading_columns_of(const scene::scene_plan& plan) {
  leading_columns leading;
  if (plan.request().budget) return leading;
  if (plan.request().sweep) leading.names.push_back(plan.request().sweep->name);
  if (plan.any_runs()) leading.names.push_back("run");
  if (plan.any_noise()) leading.names.push_back("seed");
  leading.values.resize(leading.names.size());
  leading.condition = plan.request().scene.processing == scene::processing_method::horizon_vector;
  return leading;
}

void set_leading_values(leading_columns& leading, const scene::scene_plan& plan, std::uint64_t j,
                        const scene::scene_config& scene, std::uint64_t run) {
  if (plan.request().budget) return;
  std::size_t column = 0;
  if (plan.request().sweep) leading.values[column++] = {plan.sweep_value(j), 0, false};
  if (plan.any_runs()) leading.values[column++] = {0, run, true};
  if (plan.any_noise()) leading.values[column++] = {0, scene.seed, true};
}

std::vector<std::string> summary_source_names(const scene::scene_plan& plan) {
  std::vector<std::string> names;
  if (plan.request().budget) {
    for (const scene::budget_source& s : plan.budget()) names.push_back(s.name);
    names.emplace_back("sum");
    return names;
  }
  for (std::size_t h = 0; h < plan.request().scene.heads.size(); ++h)
    names.push_back("h" + std::to_string(h + 1));
  names.emplace_back("system");
  return names;
}

void write_summary_header(output_sink& out, const leading_columns& leading) {
  leading.write_names(out);
  out.append(statistics_header());
  out.end_row();
}

void write_scene_summary(output_sink& out, const scene::scene_plan& plan, leading_columns& leading,
                         const std::vector<std::string>& source_names,
                         const scene::scene_statistics& stats) {
  set_leading_values(leading, plan, stats.scene_index, plan.scene(stats.scene_index), stats.runs);
  for (std::size_t k = 0; k < source_names.size(); ++k)
    write_statistics(out, leading, source_names[k], stats.sources[k]);
}

}  // namespace conescan::cli
