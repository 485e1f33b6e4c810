// conescan-sim --merge FILE...: the summary of a whole campaign from its shards' summary states
// (--summary-state; src/simulation/summary_state.hpp), as the single process would print it.
#pragma once

#include <string>
#include <vector>

#include "cli/output_sink.hpp"
#include "scene/scene_plan.hpp"
#include "simulation/summary_state.hpp"

namespace conescan::cli {

struct merged_campaign {
  scene::scene_plan plan;  ///< the campaign's scene, read back from the states
  scene::summary_state state;
};

/// Reads and merges the state files. Every file is checked before anything is printed: an error
/// (option "merge") names the file: missing or unreadable, foreign, truncated, corrupt, of
/// another conescan version, scene or shard count, a shard twice or missing.
conescan::checked<merged_campaign> merge_state_files(const std::vector<std::string>& files);

/// The campaign's summary, as `conescan-sim <scene> --summary` prints it.
void write_merged_summary(output_sink& out, const merged_campaign& campaign);

}  // namespace conescan::cli
