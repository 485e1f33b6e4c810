// A campaign: every run of every scene of a plan (sweep values x runs), as units
// numbered in order (scene-major: scene 0's runs 1..R, then scene 1's, ...). A shard --shard K/N
// takes the units [floor((K-1) U / N), floor(K U / N)) of the U units: contiguous, so its CSV
// rows are the single process's rows of those runs, with the same run numbers and seeds (each
// noise draw is a function of the seed, run, row, head and crossing: random.hpp), and the
// shards' CSVs concatenated (without their headers) are the single process's CSV. The plan counts
// the units (campaign_units, runs_of: scene_plan.hpp) and refuses an empty shard.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "scene/scene_plan.hpp"
#include "text/diagnostic.hpp"

namespace conescan::scene {

/// Units [first, end) of a campaign of `total` units.
struct unit_range {
  std::uint64_t first = 0;
  std::uint64_t end = 0;
  std::uint64_t total = 0;
};

/// The units of shard `shard` (all of them without one).
unit_range shard_units(std::uint64_t total, const std::optional<shard_spec>& shard);

/// The scene as a shard's state file records it (--print-config's text without the options
/// that only say how it runs: threads, shard, summary-state, summary, trace): two states merge
/// only when these texts are equal.
std::string campaign_scene_text(const scene_request& request);

/// One scene's runs within a part of the campaign.
struct scene_part {
  std::uint64_t scene_index = 0;  ///< j of scene_plan::scene(j)
  loaded_scene scene;             ///< plan.scene(scene_index)
  std::uint64_t first_run = 0;    ///< 0-based, [first_run, end_run)
  std::uint64_t end_run = 0;
};

/// Walks the scenes of a part of the campaign in order, each with the runs of the part.
class campaign_walk {
 public:
  campaign_walk(const scene_plan& plan, unit_range units) : plan_(&plan), units_(units) {}
  /// The next scene with runs in the part, or nullopt at the end.
  std::optional<scene_part> next();

 private:
  const scene_plan* plan_;
  unit_range units_;
  std::uint64_t scene_ = 0;
  std::uint64_t unit_ = 0;  // the first unit of scene_
};

}  // namespace conescan::scene
