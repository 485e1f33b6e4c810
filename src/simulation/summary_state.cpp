#include "simulation/summary_state.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>

#include "text/number_text.hpp"
#include "text/text_lines.hpp"

#ifndef CONESCAN_VERSION
#error "CONESCAN_VERSION: CMake's project version (CMakeLists.txt)"
#endif

namespace conescan::scene {

namespace {

constexpr std::string_view magic = "conescan-summary-state ";
constexpr std::string_view format_version = "2";  // 2: the statuses gimbal, sun and moon
constexpr std::string_view end_tag = "end fnv1a64 ";
// The largest |error| a summary holds, rad: roll and pitch errors are angles, (-pi, pi] when
// wrapped; twice that leaves room for any unwrapped difference.
constexpr double largest_error_rad = 2 * 3.14159265358979323846;

std::uint64_t fnv1a64(std::string_view bytes) {
  std::uint64_t hash = 0xcbf29ce484222325u;
  for (const char c : bytes) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 0x100000001b3u;
  }
  return hash;
}

std::string hex(std::uint64_t value) {
  char text[17];
  const auto end = std::to_chars(text, text + 16, value, 16).ptr;
  return std::string(16 - static_cast<std::size_t>(end - text), '0') + std::string(text, end);
}

diagnostic refused(std::string message) {
  return diagnostic{"merge", std::move(message), {}};
}

void append_statistics(std::string& out, const running_statistics& q) {
  out += ' ' + std::to_string(q.count);
  for (const double v : {q.min, q.max, q.mean, q.m2}) out += ' ' + text::shortest_text(v);
}

// A line's words, split at single spaces.
std::vector<std::string_view> words_of(std::string_view t) {
  std::vector<std::string_view> out;
  while (true) {
    const std::size_t space = t.find(' ');
    out.push_back(t.substr(0, space));
    if (space == std::string_view::npos) return out;
    t.remove_prefix(space + 1);
  }
}

bool read_count(std::string_view text, std::uint64_t& out) {
  const checked<std::uint64_t> value = text::parse_count(text);
  if (!value.ok()) return false;
  out = value.value();
  return true;
}

bool read_real(std::string_view text, double& out) {
  const checked<double> value = text::parse_real(text);
  if (!value.ok()) return false;
  out = value.value();
  return true;
}

// Statistics that values of an angle error could have given: finite (parse_real), within
// +-largest_error_rad, min <= mean <= max (to rounding), and M2 (the sum of squared deviations)
// at most count (max - min)^2 / 4 (to rounding). A state edited and re-hashed with a mean of
// 1e308 or min > max would otherwise merge into infinite or meaningless statistics.
bool plausible(const running_statistics& q) {
  if (q.count == 0) return q.min == 0 && q.max == 0 && q.mean == 0 && q.m2 == 0;
  const double slack = 1e-12 * largest_error_rad;
  const double spread = q.max - q.min;
  return q.min >= -largest_error_rad && q.max <= largest_error_rad && q.min <= q.max &&
         q.mean >= q.min - slack && q.mean <= q.max + slack && q.m2 >= 0 &&
         q.m2 <= static_cast<double>(q.count) * (spread * spread / 4 + slack);
}

// "N MIN MAX MEAN M2" at words[at...].
bool read_statistics(const std::vector<std::string_view>& w, std::size_t at,
                     running_statistics& q) {
  return read_count(w[at], q.count) && read_real(w[at + 1], q.min) && read_real(w[at + 2], q.max) &&
         read_real(w[at + 3], q.mean) && read_real(w[at + 4], q.m2) && plausible(q);
}

// "stats ROWS C1..CS N MIN MAX MEAN M2 N MIN MAX MEAN M2"; the counts must add up.
bool read_source(const std::vector<std::string_view>& w, error_statistics& s) {
  if (w.size() != 2 + status_count + 10 || w[0] != "stats" || !read_count(w[1], s.rows))
    return false;
  std::uint64_t sum = 0;
  for (std::size_t k = 0; k < status_count; ++k) {
    if (!read_count(w[2 + k], s.status_counts[k])) return false;
    sum += s.status_counts[k];
  }
  return sum == s.rows && read_statistics(w, 2 + status_count, s.roll) &&
         read_statistics(w, 7 + status_count, s.pitch) && s.roll.count == s.ok_rows() &&
         s.pitch.count == s.ok_rows();
}

bool read_shard(const std::vector<std::string_view>& w, summary_state& s) {
  if (w.size() != 6 || w[0] != "shard" || w[2] != "units") return false;
  const std::size_t slash = w[1].find('/');
  if (slash == std::string_view::npos) return false;
  return read_count(w[1].substr(0, slash), s.shard.index) &&
         read_count(w[1].substr(slash + 1), s.shard.count) && read_count(w[3], s.first_unit) &&
         read_count(w[4], s.end_unit) && read_count(w[5], s.total_units) && s.shard.index >= 1 &&
         s.shard.index <= s.shard.count;
}

// A state read line by line (each without its '\n'): every line checked as it comes, so a file
// that goes wrong is refused at its first wrong line, never held (a valid first line and 900 MB
// of anything after it were read whole, 1.05 GB); the hash summed on the way.
class state_stream {
 public:
  checked<void> line(std::string_view text) {
    ++line_;
    bytes_ += text.size() + 1;
    if (bytes_ > max_summary_state_bytes)
      return refused("larger than " + std::to_string(max_summary_state_bytes) +
                     " bytes: not a summary state");
    if (part_ == part::ended) return corrupt("text after its end line");
    if (part_ != part::first && text.substr(0, end_tag.size()) == end_tag) return end(text);
    hash_bytes(text);
    hash_bytes("\n");
    switch (part_) {
      case part::first:
        return first_line(text);
      case part::scene_text:
        return scene_text_line(text);
      case part::body:
        return body_line(text);
      default:
        return header_line(words_of(text));
    }
  }

  checked<summary_state> finish() {
    if (part_ == part::first) return check_summary_state_start("").error();  // an empty file
    if (part_ != part::ended) return refused("truncated summary state (no end line)");
    return std::move(state_);
  }

 private:
  enum class part {
    first,
    version,
    shard,
    statuses,
    sources,
    scene_header,
    scene_text,
    body,
    ended
  };

  diagnostic corrupt(std::string_view why = {}) const {
    return refused("corrupt summary state (line " + std::to_string(line_) +
                   (why.empty() ? "" : ": " + std::string(why)) + ")");
  }

  void hash_bytes(std::string_view bytes) {
    for (const char c : bytes) {
      hash_ ^= static_cast<unsigned char>(c);
      hash_ *= 0x100000001b3u;
    }
  }

  checked<void> first_line(std::string_view text) {
    if (checked<void> start = check_summary_state_start(text); !start.ok()) return start;
    const std::string_view version = text.substr(magic.size());
    if (version != format_version)
      return refused("summary state format " + quote(version) + "; this conescan reads format " +
                     std::string(format_version));
    part_ = part::version;
    return success();
  }

  checked<void> header_line(const std::vector<std::string_view>& w) {
    summary_state& s = state_;
    switch (part_) {
      case part::version:
        if (w.size() != 2 || w[0] != "conescan") return corrupt();
        s.version = std::string(w[1]);
        part_ = part::shard;
        return success();
      case part::shard:
        if (!read_shard(w, s)) return corrupt();
        part_ = part::statuses;
        return success();
      case part::statuses:
        if (w.size() != 1 + status_count || w[0] != "statuses") return corrupt();
        for (std::size_t k = 0; k < status_count; ++k)
          if (w[1 + k] != to_string(all_statuses[k])) return corrupt();
        part_ = part::sources;
        return success();
      case part::sources:
        if (w.size() < 2 || w[0] != "sources") return corrupt();
        for (std::size_t k = 1; k < w.size(); ++k) s.source_names.emplace_back(w[k]);
        part_ = part::scene_header;
        return success();
      default:  // part::scene_header
        if (w.size() != 2 || w[0] != "scene-text" || !read_count(w[1], scene_bytes_left_) ||
            scene_bytes_left_ > max_summary_state_bytes)
          return corrupt();
        part_ = scene_bytes_left_ == 0 ? part::body : part::scene_text;
        return success();
    }
  }

  // The scene's text: its bytes as the header counted them, in whole lines.
  checked<void> scene_text_line(std::string_view text) {
    if (text.size() + 1 > scene_bytes_left_) return corrupt("the scene's text is not its length");
    state_.scene_text.append(text).push_back('\n');
    scene_bytes_left_ -= text.size() + 1;
    if (scene_bytes_left_ == 0) part_ = part::body;
    return success();
  }

  // "scene j runs r", then one "stats ..." line per source.
  checked<void> body_line(std::string_view text) {
    const std::vector<std::string_view> w = words_of(text);
    summary_state& s = state_;
    if (sources_left_ == 0) {
      scene_statistics scene;
      if (w.size() != 4 || w[0] != "scene" || w[2] != "runs" ||
          !read_count(w[1], scene.scene_index) || !read_count(w[3], scene.runs))
        return corrupt();
      if (!s.scenes.empty() && scene.scene_index <= s.scenes.back().scene_index) return corrupt();
      scene.sources.reserve(s.source_names.size());
      s.scenes.push_back(std::move(scene));
      sources_left_ = s.source_names.size();
      return success();
    }
    error_statistics source;
    if (!read_source(w, source)) return corrupt();
    s.scenes.back().sources.push_back(source);
    --sources_left_;
    return success();
  }

  // The end line: the file is whole, and its hash says its bytes are those written.
  checked<void> end(std::string_view text) {
    if (part_ != part::body || sources_left_ != 0) return corrupt();
    if (text != std::string(end_tag) + hex(hash_))
      return refused("corrupt summary state (its hash does not match its contents)");
    part_ = part::ended;
    return success();
  }

  summary_state state_;
  part part_ = part::first;
  std::size_t line_ = 0;
  std::uint64_t bytes_ = 0;
  std::uint64_t hash_ = 0xcbf29ce484222325u;  // FNV-1a's offset basis, as fnv1a64
  std::uint64_t scene_bytes_left_ = 0;
  std::size_t sources_left_ = 0;
};

}  // namespace

std::string_view conescan_version() {
  return CONESCAN_VERSION;
}

std::string summary_state_text(const summary_state& state) {
  std::string out = std::string(magic) + std::string(format_version) + "\n";
  out += "conescan " + state.version + "\n";
  out += "shard " + std::to_string(state.shard.index) + "/" + std::to_string(state.shard.count) +
         " units " + std::to_string(state.first_unit) + " " + std::to_string(state.end_unit) + " " +
         std::to_string(state.total_units) + "\n";
  out += "statuses";
  for (const status s : all_statuses) out += std::string(" ") + to_string(s);
  out += "\nsources";
  for (const std::string& name : state.source_names) out += " " + name;
  out += "\nscene-text " + std::to_string(state.scene_text.size()) + "\n" + state.scene_text;
  for (const scene_statistics& scene : state.scenes) {
    out +=
        "scene " + std::to_string(scene.scene_index) + " runs " + std::to_string(scene.runs) + "\n";
    for (const error_statistics& s : scene.sources) {
      out += "stats " + std::to_string(s.rows);
      for (const std::uint64_t count : s.status_counts) out += ' ' + std::to_string(count);
      append_statistics(out, s.roll);
      append_statistics(out, s.pitch);
      out += '\n';
    }
  }
  return out + std::string(end_tag) + hex(fnv1a64(out)) + "\n";
}

checked<void> check_summary_state_start(std::string_view start) {
  if (start.substr(0, magic.size()) != magic)
    return refused("not a conescan summary state (it does not start with '" + std::string(magic) +
                   std::string(format_version) + "')");
  return success();
}

checked<summary_state> read_summary_state(std::string_view text) {
  state_stream stream;
  while (!text.empty()) {
    const std::size_t newline = text.find('\n');
    if (newline == std::string_view::npos) break;  // a last line without its '\n': truncated
    if (checked<void> read = stream.line(text.substr(0, newline)); !read.ok()) return read.error();
    text.remove_prefix(newline + 1);
  }
  if (!text.empty()) return refused("truncated summary state (no end line)");
  return stream.finish();
}

checked<summary_state> read_summary_state_file(const std::string& path) {
  state_stream stream;
  bool first = true;
  checked<void> read = text::for_each_line(path, [&](std::string_view line) {
    first = false;
    return stream.line(line);
  });
  if (!read.ok()) {
    diagnostic e = std::move(read).error();
    // A file whose first line cannot be read as one (a NUL byte, no line end in 4 KiB:
    // /dev/zero) is not a state at all.
    const bool unreadable_line =
        e.message.rfind("NUL byte", 0) == 0 || e.message.rfind("line longer than", 0) == 0;
    if (first && unreadable_line) e = check_summary_state_start("").error();
    e.option = "merge";
    return e;
  }
  return stream.finish();
}

checked<summary_state> merge_summary_states(const std::vector<named_state>& states) {
  if (states.empty()) return refused("no summary state to merge");
  const summary_state& first = states.front().state;
  // Every shard once: more shards than files means one is missing, found before allocating a
  // slot per shard (a count of 10^18 in a file would otherwise ask for 8 EB).
  if (first.shard.count > states.size()) {
    std::vector<std::uint64_t> given;
    for (const named_state& n : states) given.push_back(n.state.shard.index);
    std::sort(given.begin(), given.end());
    std::uint64_t missing = 1;
    for (const std::uint64_t k : given)
      if (k == missing) ++missing;
    return refused("shard " + std::to_string(missing) + "/" + std::to_string(first.shard.count) +
                   " is missing (" + std::to_string(states.size()) + " file(s) given)");
  }
  std::vector<const named_state*> by_shard(first.shard.count, nullptr);
  for (const named_state& n : states) {
    const summary_state& s = n.state;
    const auto refuse = [&](const std::string& why) { return refused(n.file + ": " + why); };
    if (s.version != conescan_version())
      return refuse("written by conescan " + s.version + "; this is conescan " +
                    std::string(conescan_version()));
    if (s.scene_text != first.scene_text || s.source_names != first.source_names)
      return refuse("a shard of another scene than " + states.front().file);
    if (s.shard.count != first.shard.count || s.total_units != first.total_units)
      return refuse("a shard of " + std::to_string(s.shard.count) + " where " +
                    states.front().file + " is one of " + std::to_string(first.shard.count));
    if (const named_state* seen = by_shard[s.shard.index - 1])
      return refuse("shard " + std::to_string(s.shard.index) + "/" + std::to_string(s.shard.count) +
                    " again (also " + seen->file + ")");
    by_shard[s.shard.index - 1] = &n;
  }
  for (std::size_t k = 0; k < by_shard.size(); ++k)
    if (!by_shard[k])
      return refused("shard " + std::to_string(k + 1) + "/" + std::to_string(by_shard.size()) +
                     " is missing (" + std::to_string(states.size()) + " file(s) given)");
  summary_state merged = first;
  merged.shard = shard_spec{};
  merged.first_unit = 0;
  merged.end_unit = first.total_units;
  merged.scenes.clear();
  std::uint64_t next_unit = 0;
  for (const named_state* n : by_shard) {
    if (n->state.first_unit != next_unit || n->state.end_unit < n->state.first_unit)
      return refused(n->file + ": its runs do not follow the previous shard's");
    next_unit = n->state.end_unit;
    for (const scene_statistics& scene : n->state.scenes) {
      if (merged.scenes.empty() || merged.scenes.back().scene_index != scene.scene_index) {
        merged.scenes.push_back(scene);
        continue;
      }
      scene_statistics& into = merged.scenes.back();
      into.runs += scene.runs;
      for (std::size_t k = 0; k < into.sources.size(); ++k) into.sources[k].merge(scene.sources[k]);
    }
  }
  if (next_unit != first.total_units)
    return refused(by_shard.back()->file + ": the shards do not cover the campaign's runs");
  return merged;
}

}  // namespace conescan::scene
