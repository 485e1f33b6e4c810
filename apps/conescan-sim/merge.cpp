#include "merge.hpp"

#include <sstream>

#include "scene/scene_file.hpp"
#include "summary_csv.hpp"
#include "text/out_of_memory.hpp"
#include "text/text_lines.hpp"

namespace conescan::cli {

namespace {

conescan::diagnostic refused(const std::string& file, const std::string& why) {
  return conescan::diagnostic{"merge", file + ": " + why, {}};
}

// Read line by line, each line checked as it comes (--merge /dev/zero, or a valid first line and
// anything after it, is refused at its first wrong line, never held).
conescan::checked<scene::summary_state> read_state_file(const std::string& file) {
  conescan::checked<scene::summary_state> state = scene::read_summary_state_file(file);
  if (!state.ok()) return refused(file, state.error().message);
  return state;
}

}  // namespace

conescan::checked<merged_campaign> merge_state_files(const std::vector<std::string>& files) {
  std::vector<scene::named_state> states;
  for (const std::string& file : files) {
    conescan::checked<scene::summary_state> state =
        text::naming_input("merge", file, [&] { return read_state_file(file); });
    if (!state.ok()) return std::move(state).error();
    states.push_back({file, std::move(state).value()});
  }
  conescan::checked<scene::summary_state> merged = scene::merge_summary_states(states);
  if (!merged.ok()) return std::move(merged).error();
  // The scene as the shards ran it: their state's text, read as a scene file.
  std::istringstream scene_text(merged.value().scene_text);
  const auto entries = scene::read_scene_file(scene_text, files.front());
  if (!entries.ok()) return refused(files.front(), "its scene: " + entries.error().text());
  conescan::checked<scene::scene_plan> plan = scene::build_scene_plan(entries.value());
  if (!plan.ok()) return refused(files.front(), "its scene: " + plan.error().text());
  const std::vector<std::string> names = summary_source_names(plan.value());
  if (names != merged.value().source_names)
    return refused(files.front(), "its sources do not match its scene");
  for (const scene::scene_statistics& s : merged.value().scenes)
    if (s.scene_index >= plan.value().scene_count())
      return refused(files.front(), "a scene beyond its scene's sweep");
  return merged_campaign{std::move(plan).value(), std::move(merged).value()};
}

void write_merged_summary(output_sink& out, const merged_campaign& campaign) {
  leading_columns leading = leading_columns::of(campaign.plan);
  write_summary_header(out, leading);
  for (const scene::scene_statistics& s : campaign.state.scenes)
    write_scene_summary(out, campaign.plan, leading, campaign.state.source_names, s);
}

}  // namespace conescan::cli
