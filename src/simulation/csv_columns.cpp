#include "simulation/csv_columns.hpp"

namespace conescan::scene {

std::vector<column_name> leading_layout::columns() const {
  std::vector<column_name> names;
  if (!sweep.empty()) names.push_back({sweep, column_kind::real});
  if (run) names.push_back({"run", column_kind::count});
  if (seed) names.push_back({"seed", column_kind::count});
  return names;
}

leading_layout leading_layout_of(const scene_plan& plan) {
  const scene_request& request = plan.request();
  if (request.budget) {  // no leading columns; the summary's lost fractions with --intrusions
    leading_layout budget;
    budget.intrusions = request.scene.intrusions;
    return budget;
  }
  return {request.sweep ? request.sweep->name : std::string(), plan.any_runs(), plan.any_noise(),
          request.scene.processing == processing_method::horizon_vector, request.scene.intrusions};
}

std::vector<leading_value> leading_values(const leading_layout& layout, const scene_plan& plan,
                                          std::uint64_t j, const scene_config& scene,
                                          std::uint64_t run) {
  std::vector<leading_value> values;
  if (!layout.sweep.empty()) values.push_back({plan.sweep_value(j), 0, false});
  if (layout.run) values.push_back({0, run, true});
  if (layout.seed) values.push_back({0, scene.seed, true});
  return values;
}

std::vector<column_name> row_columns(std::size_t heads, bool condition, bool intrusions) {
  std::vector<column_name> names;
  for (const char* name : {"t_s", "nu_deg", "r_km", "alt_km", "lat_deg", "rho_deg"})
    names.push_back({name, column_kind::real});
  for (std::size_t k = 1; k <= heads; ++k) {
    const std::string h = "h" + std::to_string(k) + "_";
    for (const char* name :
         {"chord_deg", "phase_deg", "eta_err_deg", "roll_err_deg", "pitch_err_deg"})
      names.push_back({h + name, column_kind::real});
    names.push_back({h + "status", column_kind::state});
    if (intrusions)
      for (const char* name : {"sun_deg", "moon_deg"})
        names.push_back({h + name, column_kind::real});
  }
  names.push_back({"roll_err_deg", column_kind::real});
  names.push_back({"pitch_err_deg", column_kind::real});
  names.push_back({"status", column_kind::state});
  if (condition) names.push_back({"condition", column_kind::real});
  return names;
}

std::vector<column_name> budget_columns(const std::vector<budget_source>& sources) {
  std::vector<column_name> names{{"t_s", column_kind::real}, {"nu_deg", column_kind::real}};
  auto add = [&](const std::string& source) {
    names.push_back({source + "_roll_err_deg", column_kind::real});
    names.push_back({source + "_pitch_err_deg", column_kind::real});
    names.push_back({source + "_status", column_kind::state});
  };
  for (const budget_source& s : sources) add(s.name);
  add(budget_sum_name);
  add(budget_interaction_name);
  return names;
}

std::array<const char*, 12> summary_statistic_names() {
  return {"roll_min_deg",   "roll_max_deg",    "roll_mean_deg", "roll_rms_deg",
          "roll_std_deg",   "roll_3sigma_deg", "pitch_min_deg", "pitch_max_deg",
          "pitch_mean_deg", "pitch_rms_deg",   "pitch_std_deg", "pitch_3sigma_deg"};
}

std::vector<column_name> summary_columns(bool intrusions) {
  std::vector<column_name> names{{"source", column_kind::text}, {"rows", column_kind::count}};
  for (status s : all_statuses) names.push_back({to_string(s), column_kind::count});
  for (const char* name : summary_statistic_names()) names.push_back({name, column_kind::real});
  if (intrusions)
    for (const char* name : {"sun_lost_fraction", "moon_lost_fraction"})
      names.push_back({name, column_kind::real});
  return names;
}

std::array<double, 2> summary_lost_fractions(const error_statistics& s) {
  const auto rows = static_cast<double>(s.rows);
  const auto fraction = [&](status body) {
    return s.rows == 0 ? not_a_number<double>()
                       : static_cast<double>(s.status_counts[status_index(body)]) / rows;
  };
  return {fraction(status::sun), fraction(status::moon)};
}

std::array<double, 12> summary_statistics_deg(const error_statistics& s) {
  std::array<double, 12> values{};
  std::size_t k = 0;
  const double nan = not_a_number<double>();
  for (const running_statistics* q : {&s.roll, &s.pitch}) {
    const bool any = q->count > 0;
    for (double v : {any ? q->min : nan, any ? q->max : nan, any ? q->mean : nan, q->rms(),
                     q->std(), 3 * q->std()})
      values[k++] = rad_to_deg(v);
  }
  return values;
}

std::string summary_source_name(std::size_t head) {
  return "h" + std::to_string(head + 1);
}

}  // namespace conescan::scene
