#include "campaign_run.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <memory>
#include <mutex>
#include <new>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <thread>
#include <utility>
#include <vector>

#include "cli/csv_rows.hpp"
#include "scene/campaign.hpp"
#include "simulation/budget_run.hpp"
#include "simulation/simulation.hpp"
#include "simulation/summary_state.hpp"
#include "summary_csv.hpp"
#include "text/parallel_parts.hpp"

namespace conescan::cli {

namespace {

// "thread" or "threads", as a count of them reads.
const char* thread_word(std::uint64_t count) {
  return count == 1 ? "thread" : "threads";
}

using scene::error_statistics;

// --- What a chunk is ---------------------------------------------------------------------------

// A scene's runs within the campaign part, shared by its chunks.
struct scene_job {
  scene::scene_part part;
  std::vector<scene::simulation> sims;      // the scene (empty for the budget)
  std::optional<scene::budget_run> budget;  // the budget's sources and their sum
  leading_columns leading;                  // the names (each worker sets the values)

  const std::vector<scene::simulation>& simulations() const {
    return budget ? budget->simulations() : sims;
  }
};

struct chunk {
  std::shared_ptr<const scene_job> job;
  std::uint64_t run = 0;  // 0-based
  std::uint64_t first_row = 0;
  std::size_t rows = 0;
  bool last_of_job = false;
};

// What a worker makes of a chunk.
struct chunk_output {
  output_sink text{-1};  // the formatted rows (a buffer: never flushed)
  std::string trace;     // --trace's lines
  // The statistics of the chunk's rows (scene::run_summary's and budget_summary's rules): one of
  // the two is used, per head and system, or per budget source, sum and interaction.
  scene::run_summary scene_stats{0};
  scene::budget_summary budget_stats{0};

  // Source k's statistics, in the order of summary_source_names.
  const error_statistics& statistics(bool budget, std::size_t k) const {
    if (budget) return budget_stats.line(k);
    return k < scene_stats.heads.size() ? scene_stats.heads[k] : scene_stats.system;
  }
  // Empties the statistics of `sources` summary lines (the last the system; or the sum and the
  // interaction).
  void reset_statistics(bool budget, std::size_t sources) {
    if (budget) {
      budget_stats.reset(sources);
      return;
    }
    scene_stats.heads.assign(sources - 1, error_statistics{});
    scene_stats.system = error_statistics{};
  }
};

// A worker's rows, reused from chunk to chunk (no allocation in the steady state).
struct worker_scratch {
  std::vector<std::vector<scene::row>> rows;  // per simulation
  scene::budget_row budget;                   // one time step of the budget's sources
  leading_columns leading;
};

// The campaign part's chunks, in order.
class chunk_source {
 public:
  // `threads`: the workers', on which a scene's physics tables are built too.
  chunk_source(const scene::scene_plan& plan, scene::unit_range units,
               const scene::crossing_correction* correction, unsigned threads)
      : plan_(&plan),
        walk_(plan, units),
        correction_(correction),
        threads_(static_cast<int>(threads)) {}

  std::optional<chunk> next() {
    if (job_ && row_ >= job_->simulations().front().rows()) {  // a run is done: the next run
      ++run_;
      row_ = 0;
    }
    if ((!job_ || run_ >= job_->part.end_run) && !start_job()) return std::nullopt;
    const std::uint64_t rows = job_->simulations().front().rows();
    chunk c{job_, run_, row_,
            static_cast<std::size_t>(std::min<std::uint64_t>(rows_per_chunk, rows - row_)), false};
    row_ += c.rows;
    c.last_of_job = row_ >= rows && run_ + 1 == job_->part.end_run;
    return c;
  }

 private:
  bool start_job() {
    std::optional<scene::scene_part> part = walk_.next();
    if (!part) return false;
    auto job = std::make_shared<scene_job>();
    job->part = std::move(*part);
    if (plan_->request().budget) {
      job->budget.emplace(plan_->budget(), threads_);
    } else {
      job->sims.push_back(scene::simulation::of(job->part.scene, threads_).value());
      job->sims.back().set_correction(correction_);  // --apply (const: shared by the workers)
    }
    job->leading = leading_columns::of(*plan_);  // the values: per chunk
    job_ = std::move(job);
    run_ = job_->part.first_run;
    row_ = 0;
    return true;
  }

  const scene::scene_plan* plan_;
  scene::campaign_walk walk_;
  const scene::crossing_correction* correction_;
  int threads_;
  std::shared_ptr<const scene_job> job_;
  std::uint64_t run_ = 0;
  std::uint64_t row_ = 0;
};

// --- Computing a chunk -------------------------------------------------------------------------

void trace(std::string& out, const scene::row& row, const char* source) {
  char line[256];
  for (std::size_t h = 0; h < row.heads.size(); ++h) {
    std::snprintf(line, sizeof line, "trace: %s%s%st_s=%.17g head=%zu iterations=%d status=%s\n",
                  source ? "source=" : "", source ? source : "", source ? " " : "", row.t_s, h + 1,
                  row.heads[h].iterations, to_string(row.heads[h].state));
    out += line;
  }
}

// The chunk's rows of each simulation, in scratch.rows.
void compute_rows(const chunk& c, worker_scratch& scratch) {
  const std::vector<scene::simulation>& sims = c.job->simulations();
  scratch.rows.resize(sims.size());
  for (std::size_t i = 0; i < sims.size(); ++i) {
    std::vector<scene::row>& rows = scratch.rows[i];
    if (rows.empty() || rows.front().heads.size() != sims[i].head_count()) rows.clear();
    rows.resize(std::max(rows.size(), c.rows), sims[i].make_row());
    sims[i].compute_rows(c.first_row, c.rows, rows.data(), c.run);
  }
}

// A scene's chunk: its rows (or only their statistics), per head and system.
void compute_scene_chunk(const scene::scene_request& request, const scene::scene_plan& plan,
                         const chunk& c, worker_scratch& scratch, chunk_output& out) {
  compute_rows(c, scratch);
  scratch.leading = c.job->leading;
  scratch.leading.set(plan, c.job->part.scene_index, c.job->part.scene.config, c.run + 1);
  for (std::size_t i = 0; i < c.rows; ++i) {
    const scene::row& row = scratch.rows.front()[i];
    if (request.trace) trace(out.trace, row, nullptr);
    out.scene_stats.add(row);
    if (!request.summary) write_row(out.text, row, scratch.leading);
  }
}

// The budget's chunk: every source's rows in lock step (computed in blocks), each measured from
// its baseline, plus the sum of the single sources and the interaction (scene::budget_run's rule,
// its CSV row csv_rows').
void compute_budget_chunk(const scene::scene_request& request,
                          const std::vector<scene::budget_source>& sources, const chunk& c,
                          worker_scratch& scratch, chunk_output& out) {
  const scene::budget_run& budget = *c.job->budget;
  compute_rows(c, scratch);
  scene::budget_row& step = scratch.budget;
  if (step.sources.size() != sources.size()) step = budget.make_row();  // once per worker
  for (std::size_t k = 0; k < c.rows; ++k) {
    // Swapped, not copied: no allocation, and the rows stay fit for the next chunk.
    for (std::size_t i = 0; i < sources.size(); ++i) std::swap(step.sources[i], scratch.rows[i][k]);
    budget.combine_sources(step);
    if (request.trace)
      for (std::size_t i = 0; i < sources.size(); ++i)
        trace(out.trace, step.sources[i], sources[i].name.c_str());
    out.budget_stats.add(step);
    if (!request.summary) write_budget_csv_row(out.text, step);
  }
}

void compute_chunk(const scene::scene_plan& plan, std::size_t sources, const chunk& c,
                   worker_scratch& scratch, chunk_output& out) {
  out.text.discard();
  out.trace.clear();
  out.reset_statistics(plan.request().budget, sources);
  if (plan.request().budget)
    compute_budget_chunk(plan.request(), plan.budget(), c, scratch, out);
  else
    compute_scene_chunk(plan.request(), plan, c, scratch, out);
}

// --- Progress ----------------------------------------------------------------------------------

// One line on standard error when it is a terminal, for campaigns longer than about 1 s: rows
// done, rows per second and the time left, redrawn 4 times a second by a thread of its own. Its
// own thread, because what comes before the first chunk can take minutes on one thread while the
// others wait for it (a long run's table of the sensor physics on a field of view, built when its
// simulation is): the run never starts silently. Nothing when standard error is no terminal, or
// when no thread can be started for the line (the rows matter more).
class progress {
 public:
  explicit progress(std::uint64_t total) : total_(total), start_(clock::now()) {
    if (isatty(STDERR_FILENO) != 1) return;
    try {
      drawer_ = std::thread([this] { draw_until_stopped(); });
    } catch (const std::system_error&) {
    }
  }
  ~progress() {
    if (!drawer_.joinable()) return;
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    stopped_.notify_one();
    drawer_.join();
    if (shown_) std::fputs("\r\033[K", stderr);
  }
  progress(const progress&) = delete;
  progress& operator=(const progress&) = delete;

  void add(std::uint64_t rows) { done_.fetch_add(rows, std::memory_order_relaxed); }

 private:
  using clock = std::chrono::steady_clock;

  void draw_until_stopped() {
    std::unique_lock<std::mutex> lock(mutex_);
    while (!stopped_.wait_for(lock, std::chrono::milliseconds(250), [this] { return stop_; }))
      draw(std::chrono::duration<double>(clock::now() - start_).count());
  }

  void draw(double seconds) {
    if (seconds < 1) return;
    shown_ = true;
    const std::uint64_t done = done_.load(std::memory_order_relaxed);
    if (done == 0) {
      std::fprintf(stderr,
                   "\r\033[Kconescan-sim: 0/%llu rows, %.0f s: the first rows are being computed",
                   static_cast<unsigned long long>(total_), seconds);
      return;
    }
    const double rate = static_cast<double>(done) / seconds;
    const auto left = static_cast<long long>(static_cast<double>(total_ - done) / rate);
    std::fprintf(
        stderr,
        "\r\033[Kconescan-sim: %llu/%llu rows (%.0f%%), %.3g rows/s, %lld:%02lld:%02lld left",
        static_cast<unsigned long long>(done), static_cast<unsigned long long>(total_),
        100.0 * static_cast<double>(done) / static_cast<double>(total_), rate, left / 3600,
        left / 60 % 60, left % 60);
  }

  std::uint64_t total_;
  std::atomic<std::uint64_t> done_{0};
  clock::time_point start_;
  bool shown_ = false;  // the drawer's, read after it is joined
  bool stop_ = false;
  std::mutex mutex_;
  std::condition_variable stopped_;
  std::thread drawer_;  // last: started once the members it reads are
};

// The rows of the campaign part (for the progress line).
std::uint64_t part_rows(const scene::scene_plan& plan, scene::unit_range units) {
  if (!plan.request().shard || plan.request().budget) return plan.total_rows();
  std::uint64_t rows = 0;
  scene::campaign_walk walk(plan, units);
  while (const std::optional<scene::scene_part> part = walk.next())
    rows += scene::row_count(part->scene) * (part->end_run - part->first_run);
  return rows;
}

// --- The writer --------------------------------------------------------------------------------

// Takes the chunks in order: their trace, rows and statistics; a scene's summary once its last
// chunk is in.
class campaign_writer {
 public:
  campaign_writer(output_sink& out, const scene::scene_plan& plan, scene::unit_range units)
      : out_(out),
        plan_(plan),
        names_(summary_source_names(plan)),
        leading_(leading_columns::of(plan)),
        bar_(part_rows(plan, units)) {}

  const std::vector<std::string>& source_names() const { return names_; }

  // Whole rows, flushed where the sink would flush them appended one by one (at the first row
  // end past its threshold): a file-size limit or a full disk keeps the same rows as with one
  // thread.
  void append_rows(std::string_view rows) {
    while (!rows.empty() && ok()) {
      const std::size_t used = out_.size();
      const std::size_t need = used < out_.flush_threshold() ? out_.flush_threshold() - used : 1;
      const std::size_t newline = rows.find('\n', need - 1);
      const std::size_t end = newline == std::string_view::npos ? rows.size() : newline + 1;
      out_.append(rows.substr(0, end));
      out_.end_row();
      rows.remove_prefix(end);
    }
  }
  std::vector<scene::scene_statistics>& scenes() { return scenes_; }
  bool ok() const { return out_.state() == output_sink::outcome::ok; }

  void take(const chunk& c, const chunk_output& o) {
    if (!o.trace.empty()) std::fputs(o.trace.c_str(), stderr);
    append_rows(o.text.buffered());
    if (!current_ || current_->scene_index != c.job->part.scene_index) {
      scenes_.push_back({c.job->part.scene_index, c.job->part.end_run - c.job->part.first_run,
                         std::vector<error_statistics>(names_.size())});
      current_ = &scenes_.back();
    }
    for (std::size_t k = 0; k < names_.size(); ++k)
      current_->sources[k].merge(o.statistics(plan_.request().budget, k));
    bar_.add(c.rows);
    if (!c.last_of_job) return;
    if (plan_.request().summary) write_scene_summary(out_, plan_, leading_, names_, *current_);
    current_ = nullptr;
    // Keep the statistics only for the state file: memory stays flat over a long sweep.
    if (plan_.request().summary_state.empty()) scenes_.clear();
  }

 private:
  output_sink& out_;
  const scene::scene_plan& plan_;
  std::vector<std::string> names_;
  leading_columns leading_;
  progress bar_;
  std::vector<scene::scene_statistics> scenes_;
  scene::scene_statistics* current_ = nullptr;
};

// --- Threads -----------------------------------------------------------------------------------

void run_inline(const scene::scene_plan& plan, chunk_source& source, campaign_writer& writer) {
  worker_scratch scratch;
  chunk_output output;
  while (writer.ok()) {
    const std::optional<chunk> c = source.next();
    if (!c) return;
    compute_chunk(plan, writer.source_names().size(), *c, scratch, output);
    writer.take(*c, output);
  }
}

// Workers claim chunks in order into a ring of slots; the writer takes slot after slot.
class worker_pool {
 public:
  worker_pool(const scene::scene_plan& plan, chunk_source& source, campaign_writer& writer,
              unsigned threads)
      : plan_(plan), source_(source), writer_(writer), slots_(2 * threads) {}

  // false when no worker thread could be started (the caller then runs inline). A thread that
  // cannot be started leaves fewer workers (said once on standard error); memory that runs out
  // in a worker stops the run: out_of_memory() then says so.
  bool run(unsigned threads) {
    std::vector<std::thread> workers;
    try {
      for (unsigned t = 0; t < threads; ++t) workers.emplace_back([this] { work(); });
    } catch (const std::system_error&) {
      if (workers.empty()) return false;  // else fewer threads than asked: still correct
      std::fprintf(stderr, "conescan-sim: --threads %u: only %zu worker %s could start\n", threads,
                   workers.size(), thread_word(workers.size()));
    }
    write();
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    claimable_.notify_all();
    for (std::thread& w : workers) w.join();
    return true;
  }

  bool out_of_memory() const noexcept { return out_of_memory_; }

 private:
  struct slot {
    chunk task;
    chunk_output output;
    bool done = false;
  };

  // A worker: chunks until none is left. Memory that runs out here (a chunk's rows, its text)
  // stops every worker and the writer: the run ends with a message, never std::terminate.
  void work() noexcept {
    try {
      work_on();
    } catch (const std::bad_alloc&) {
      const std::lock_guard<std::mutex> lock(mutex_);
      out_of_memory_ = stop_ = true;
      claimable_.notify_all();
      done_.notify_all();
    }
  }

  void work_on() {
    worker_scratch scratch;
    const std::size_t sources = writer_.source_names().size();
    std::unique_lock<std::mutex> lock(mutex_);
    while (true) {
      claimable_.wait(lock,
                      [&] { return stop_ || exhausted_ || claimed_ < written_ + slots_.size(); });
      if (stop_ || exhausted_) return;
      std::optional<chunk> c = source_.next();
      if (!c) {
        exhausted_ = true;
        done_.notify_one();
        return;
      }
      slot& s = slots_[claimed_++ % slots_.size()];
      s.task = std::move(*c);
      lock.unlock();
      compute_chunk(plan_, sources, s.task, scratch, s.output);
      lock.lock();
      s.done = true;
      done_.notify_one();
    }
  }

  void write() {
    while (writer_.ok()) {
      slot* s = nullptr;
      {
        std::unique_lock<std::mutex> lock(mutex_);
        const auto ready = [&] {
          return stop_ || slots_[written_ % slots_.size()].done ||
                 (exhausted_ && written_ == claimed_);
        };
        done_.wait(lock, ready);
        if (stop_ || !slots_[written_ % slots_.size()].done) return;  // every chunk written
        s = &slots_[written_ % slots_.size()];
      }
      writer_.take(s->task, s->output);  // the slot is the writer's until written_ moves on
      {
        const std::lock_guard<std::mutex> lock(mutex_);
        s->done = false;
        s->task.job.reset();
        ++written_;
      }
      claimable_.notify_one();
    }
  }

  const scene::scene_plan& plan_;
  chunk_source& source_;
  campaign_writer& writer_;
  std::vector<slot> slots_;
  std::mutex mutex_;
  std::condition_variable claimable_;  // a slot is free, or stop
  std::condition_variable done_;       // a chunk is computed, or the source is exhausted
  std::uint64_t claimed_ = 0;          // chunks handed out (sequence numbers)
  std::uint64_t written_ = 0;          // chunks written
  bool exhausted_ = false;
  bool stop_ = false;
  bool out_of_memory_ = false;
};

// --- The state file ----------------------------------------------------------------------------

bool write_state_file(const scene::scene_plan& plan, scene::unit_range units,
                      campaign_writer& writer, text::output_file& file) {
  const scene::scene_request& r = plan.request();
  scene::summary_state state;
  state.version = std::string(scene::conescan_version());
  state.scene_text = scene::campaign_scene_text(r);
  state.shard = r.shard.value_or(scene::shard_spec{});
  state.first_unit = units.first;
  state.end_unit = units.end;
  state.total_units = units.total;
  state.source_names = writer.source_names();
  state.scenes = std::move(writer.scenes());
  checked<void> written = file.write(scene::summary_state_text(state));
  if (written.ok()) written = file.commit();
  if (written.ok()) return true;
  // No partial state: the output_file removes its own temporary file, and nothing else.
  std::fprintf(stderr, "conescan-sim: %s\n", written.error().text().c_str());
  return false;
}

// The worker threads to start: --threads (or every core), but no more than the campaign has
// chunks to share, nor than the address-space limit (ulimit -v) leaves room for: each worker
// reserves a stack (RLIMIT_STACK, 8 MiB by default) and, with its own malloc arena, up to
// 64 MiB. A smaller plan than asked is said once on standard error.
unsigned planned_threads(const scene::scene_plan& plan, scene::unit_range units) {
  const scene::scene_request& r = plan.request();
  const std::uint64_t asked = r.threads != 0 ? r.threads : text::available_cores();
  const std::uint64_t chunks =
      std::max<std::uint64_t>(1, (part_rows(plan, units) + rows_per_chunk - 1) / rows_per_chunk);
  std::uint64_t threads = std::min(asked, chunks);
  rlimit space{};
  if (::getrlimit(RLIMIT_AS, &space) == 0 && space.rlim_cur != RLIM_INFINITY) {
    rlimit stack{};
    const std::uint64_t stack_bytes =
        ::getrlimit(RLIMIT_STACK, &stack) == 0 && stack.rlim_cur != RLIM_INFINITY
            ? stack.rlim_cur
            : std::uint64_t{8} << 20;
    constexpr std::uint64_t arena_bytes = std::uint64_t{64} << 20,
                            reserve = std::uint64_t{512} << 20;
    const std::uint64_t per_worker = stack_bytes + arena_bytes;
    const std::uint64_t limit = space.rlim_cur;
    const std::uint64_t room = limit > reserve ? (limit - reserve) / per_worker : 0;
    const std::uint64_t affordable = std::max<std::uint64_t>(1, room);
    if (affordable < threads) {
      if (r.threads != 0)
        std::fprintf(stderr,
                     "conescan-sim: --threads %llu: the address-space limit (ulimit -v) leaves "
                     "room for %llu worker %s: running %llu\n",
                     static_cast<unsigned long long>(r.threads),
                     static_cast<unsigned long long>(affordable), thread_word(affordable),
                     static_cast<unsigned long long>(affordable));
      threads = affordable;
    }
  }
  return static_cast<unsigned>(threads);
}

}  // namespace

bool run_campaign(output_sink& out, const scene::scene_plan& plan,
                  const scene::crossing_correction* correction, text::output_file* state) {
  const scene::scene_request& r = plan.request();
  const scene::unit_range units = scene::shard_units(scene::campaign_units(plan), r.shard);
  campaign_writer writer(out, plan, units);
  if (r.summary) {
    write_summary_header(out, leading_columns::of(plan));
  } else if (r.budget) {
    write_budget_csv_header(out, plan.budget());
  } else {
    write_header(out, r.scene.heads.size(), leading_columns::of(plan));
    out.end_row();
  }
  const unsigned threads = planned_threads(plan, units);
  chunk_source source(plan, units, correction, threads);
  if (threads > 1) {
    worker_pool pool(plan, source, writer, threads);
    if (!pool.run(threads)) {
      run_inline(plan, source, writer);
    } else if (pool.out_of_memory()) {
      std::fprintf(stderr,
                   "conescan-sim: out of memory with %u worker %s: run with fewer --threads\n",
                   threads, thread_word(threads));
      return false;
    }
  } else {
    run_inline(plan, source, writer);
  }
  if (out.state() != output_sink::outcome::ok || !state) return true;
  return write_state_file(plan, units, writer, *state);
}

}  // namespace conescan::cli
