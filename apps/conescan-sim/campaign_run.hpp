// Running a campaign: every run of every scene of a plan, or of its shard, or the
// error budget, computed on worker threads and written in order.
//
// The campaign is cut into chunks of at most rows_per_chunk rows of one run of one scene (a
// chunk never spans two runs). Workers take chunks in order, each computes its chunk's rows,
// formats them into its own buffer and sums their statistics; the writer (the calling thread)
// takes the chunks in order, appends their text to the output sink and merges their statistics
// (Chan's update, summary.hpp). At most 2 chunks per worker are in flight, so memory is bounded
// by the threads, not the campaign. Chunks are cut and merged the same way whatever the number
// of threads, so the output is byte for byte that of --threads 1, summaries included. A write
// that fails stops the workers; the sink ends at a row boundary (output_sink.hpp).
#pragma once

#include <cstddef>

#include "cli/output_sink.hpp"
#include "scene/scene_plan.hpp"
#include "simulation/simulation.hpp"
#include "simulation/summary.hpp"
#include "text/output_file.hpp"

namespace conescan::cli {

/// Rows of one chunk: a few milliseconds of work, ~0.5 MB of CSV for two heads. The summary's
/// chunk (summary.hpp), so that other runners of a summary reproduce its bits.
inline constexpr std::size_t rows_per_chunk = scene::summary_chunk_rows;

/// Runs the plan (its shard) with --threads workers, writing its CSV or summary to `out` and
/// updating a progress line on a terminal's standard error. With --summary-state, writes the
/// state into `state` (opened before any output: text::output_file) and commits it once the
/// output is written; false (after a message on standard error) when it cannot be written.
/// `correction` (--apply; may be null) changes every scene's measured crossings; it is called
/// from every worker at once.
bool run_campaign(output_sink& out, const scene::scene_plan& plan,
                  const scene::crossing_correction* correction = nullptr,
                  text::output_file* state = nullptr);

}  // namespace conescan::cli
