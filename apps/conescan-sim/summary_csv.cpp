#include "summary_csv.hpp"

namespace conescan::cli {

std::vector<std::string> summary_source_names(const scene::scene_plan& plan) {
  std::vector<std::string> names;
  if (plan.request().budget) {
    for (const scene::budget_source& s : plan.budget()) names.push_back(s.name);
    names.emplace_back(scene::budget_sum_name);
    names.emplace_back(scene::budget_interaction_name);
    return names;
  }
  for (std::size_t h = 0; h < plan.request().scene.heads.size(); ++h)
    names.push_back(scene::summary_source_name(h));
  names.emplace_back(scene::summary_system_name);
  return names;
}

void write_scene_summary(output_sink& out, const scene::scene_plan& plan, leading_columns& leading,
                         const std::vector<std::string>& source_names,
                         const scene::scene_statistics& stats) {
  leading.set(plan, stats.scene_index, plan.scene(stats.scene_index).config, stats.runs);
  for (std::size_t k = 0; k < source_names.size(); ++k)
    write_summary_line(out, leading, source_names[k], stats.sources[k]);
}

}  // namespace conescan::cli
