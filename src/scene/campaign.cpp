#include "scene/campaign.hpp"

#include <algorithm>

#include "scene/scene_file.hpp"

namespace conescan::scene {

unit_range shard_units(std::uint64_t total, const std::optional<shard_spec>& shard) {
  if (!shard) return {0, total, total};
  // floor(K U / N) in 128 bits: K U may pass 2^64 (GCC's and Clang's extension).
  __extension__ using wide = unsigned __int128;
  const auto bound = [&](std::uint64_t k) {
    return static_cast<std::uint64_t>(static_cast<wide>(k) * total / shard->count);
  };
  return {bound(shard->index - 1), bound(shard->index), total};
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
