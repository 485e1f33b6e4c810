// Mergeable summaries: --summary-state writes a campaign part's statistics as a
// versioned text file, and --merge adds the parts' files into the summary of the whole campaign.
//
//   conescan-summary-state 1              the format and its version
//   conescan 0.1.0                        the conescan that wrote it
//   shard 2/4 units 250 500 1000          shard K/N: units [250, 500) of 1000 (campaign.hpp)
//   statuses ok none invalid ...          the columns of the status counts
//   sources h1 h2 system                  the statistics of each scene, in this order
//   scene-text 1234                       the scene (campaign_scene_text), then its 1234 bytes
//   scene 0 runs 250                      scene j and the runs of it the part holds, then per
//   stats ROWS C1..CS  N MIN MAX MEAN M2  N MIN MAX MEAN M2     source: roll, pitch (rad)
//   end fnv1a64 0123456789abcdef          the FNV-1a hash of every byte before this line
//
// Numbers are exact: counts in decimal digits, reals in their shortest round-trip form. A file
// that does not start with the first line is foreign; one without the end line is truncated; a
// hash or a line that does not match is corrupt. Two states merge only when written by the same
// conescan for the same scene and shard count; the merge needs every shard once.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene_request.hpp"
#include "simulation/summary.hpp"
#include "text/diagnostic.hpp"

namespace conescan::scene {

/// The statistics of one scene's runs within a part of a campaign.
struct scene_statistics {
  std::uint64_t scene_index = 0;
  std::uint64_t runs = 0;
  std::vector<error_statistics> sources;  ///< one per summary_state::source_names
};

struct summary_state {
  std::string version;     ///< the conescan that wrote it
  std::string scene_text;  ///< campaign_scene_text
  shard_spec shard;
  std::uint64_t first_unit = 0, end_unit = 0, total_units = 0;
  std::vector<std::string> source_names;  ///< h1 .. hN, system; or the budget's sources, sum
  std::vector<scene_statistics> scenes;   ///< in scene order
};

/// This conescan's version (CMake's project version).
std::string_view conescan_version();

/// The state as its file holds it.
std::string summary_state_text(const summary_state& state);

/// Largest state file --merge reads (1 GiB, about four million summary lines: a sweep of over a
/// million values of a two-head scene). A file is read line by line and each line checked as it
/// comes, so what is held is the statistics read (about the file's size for a valid state) and
/// a file that goes wrong is refused at its first wrong line. A larger campaign is split by its
/// sweep.
inline constexpr std::size_t max_summary_state_bytes = std::size_t{1} << 30;

/// Whether the start of a file (its first bytes) is a summary state's first line: checked before
/// the rest is read. The error (option "merge") says it is foreign.
checked<void> check_summary_state_start(std::string_view start);

/// A state file's text read back. The error (option "merge") says why: foreign, truncated,
/// corrupt (with the line), or statistics no angle errors could have (a mean beyond +-2 pi,
/// min > max, a spread M2 larger than the range allows).
checked<summary_state> read_summary_state(std::string_view text);

/// The same from the file at `path`, line by line (text::for_each_line): refused at its first
/// line that is not a state's (a file of zeros at its first), at most max_summary_state_bytes.
checked<summary_state> read_summary_state_file(const std::string& path);

/// A state file and its name.
struct named_state {
  std::string file;
  summary_state state;
};

/// The states of every shard of one campaign added up, in shard order (Chan's merge of the
/// statistics). Refused, naming the file (option "merge"): another conescan version than this
/// one, another scene or shard count than the first file's, a shard given twice or missing.
checked<summary_state> merge_summary_states(const std::vector<named_state>& states);

}  // namespace conescan::scene
