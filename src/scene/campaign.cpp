#include "scene/campaign.hpp"

#include <algorithm>

#include "scene/scene_file.hpp"

namespace conescan::scene {

namespace {

// Scene j's runs: every scene's unless --runs is swept (each scene then has its own).
std::uint64_t runs_of(const scene_plan& plan, std::uint64_t j) {
  const scene_request& r = plan.request();
  if (r.budget) return 1;
  if (r.sweep && r.sweep->name == "runs") return plan.scene(j).config.runs;
  return r.scene.runs;
}

}  // namespace

std::uint64_t campaign_units(const scene_plan& plan) {
  const scene_request& r = plan.request();
  if (!(r.sweep && r.sweep->name == "runs")) return plan.scene_count() * runs_of(plan, 0);
  std::uint64_t total = 0;  // at most --max-rows: every run has a row
  for (std::uint64_t j = 0; j < plan.scene_count(); ++j) total += runs_of(plan, j);
  return total;
}

unit_range shard_units(std::uint64_t total, const std::optional<shard_spec>& shard) {
  if (!shard) return {0, total, total};
  // floor(K U / N) in 128 bits: K U may pass 2^64 (GCC's and Clang's extension).
  __extension__ using wide = unsigned __int128;
  const auto bound = [&](std::uint64_t k) {
    return static_cast<std::uint64_t>(static_cast<wide>(k) * total / shard->count);
  };
  return {bound(shard->index - 1), bound(shard->index), total};
}

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

std::string campaign_scene_text(const scene_request& request) {
  scene_request scene_only = request;
  scene_only.threads = 0;
  scene_only.shard.reset();
  scene_only.summary_state.clear();
  scene_only.summary = false;
  scene_only.trace = false;
  return scene_file_text(scene_only);
}

std::optional<scene_part> campaign_walk::next() {
  while (scene_ < plan_->scene_count() && unit_ < units_.end) {
    const std::uint64_t j = scene_++;
    const std::uint64_t runs = runs_of(*plan_, j);
    const std::uint64_t first = unit_;
    unit_ += runs;
    if (unit_ <= units_.first) continue;  // before the part
    const std::uint64_t first_run = units_.first > first ? units_.first - first : 0;
    const std::uint64_t end_run = std::min(runs, units_.end - first);
    return scene_part{j, plan_->scene(j), first_run, end_run};
  }
  return std::nullopt;
}

}  // namespace conescan::scene
