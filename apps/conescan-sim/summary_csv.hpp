// The summary's CSV (--summary, and --merge's output): a line per source (head, system; or
// budget source, sum) and scene, with the leading columns of the rows (sweep value, runs, seed).
#pragma once

#include <string>
#include <vector>

#include "cli/csv_rows.hpp"
#include "cli/output_sink.hpp"
#include "scene/scene_plan.hpp"
#include "simulation/summary_state.hpp"

namespace conescan::cli {

/// The summary's sources: h1 .. hN and system, or the budget's sources, their sum and the
/// interaction (all − sum).
std::vector<std::string> summary_source_names(const scene::scene_plan& plan);

/// The summary lines of one scene (all of its runs that `stats` holds).
void write_scene_summary(output_sink& out, const scene::scene_plan& plan, leading_columns& leading,
                         const std::vector<std::string>& source_names,
                         const scene::scene_statistics& stats);

}  // namespace conescan::cli
