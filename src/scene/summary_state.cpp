#include "scene/summary_state.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>

#include "text/number_text.hpp"

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

// The body's lines one by one, each split at single spaces.
class line_reader {
 public:
  explicit line_reader(std::string_view body) : rest_(body) {}
  std::size_t line_number() const noexcept { return line_; }

  std::optional<std::vector<std::string_view>> words() {
    const std::optional<std::string_view> text = line();
    if (!text) return std::nullopt;
    std::vector<std::string_view> out;
    std::string_view t = *text;
    while (true) {
      const std::size_t space = t.find(' ');
      out.push_back(t.substr(0, space));
      if (space == std::string_view::npos) break;
      t.remove_prefix(space + 1);
    }
    return out;
  }
  std::optional<std::string_view> line() {
    const std::size_t newline = rest_.find('\n');
    if (newline == std::string_view::npos) return std::nullopt;
    ++line_;
    const std::string_view text = rest_.substr(0, newline);
    rest_.remove_prefix(newline + 1);
    return text;
  }
  /// The next `n` bytes (which may hold lines of their own).
  std::optional<std::string_view> bytes(std::uint64_t n) {
    if (n > rest_.size()) return std::nullopt;
    const std::string_view text = rest_.substr(0, n);
    line_ += static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
    rest_.remove_prefix(n);
    return text;
  }
  bool at_end() const noexcept { return rest_.empty(); }

 private:
  std::string_view rest_;
  std::size_t line_ = 0;
};

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

// The lines after the first, up to the end line.
checked<summary_state> read_body(std::string_view body) {
  line_reader in(body);
  summary_state s;
  const auto corrupt = [&] {
    return refused("corrupt summary state (line " + std::to_string(in.line_number() + 1) + ")");
  };
  auto w = in.words();
  if (!w || w->size() != 2 || (*w)[0] != "conescan") return corrupt();
  s.version = std::string((*w)[1]);
  if (w = in.words(); !w || !read_shard(*w, s)) return corrupt();
  if (w = in.words(); !w || w->size() != 1 + status_count || (*w)[0] != "statuses")
    return corrupt();
  for (std::size_t k = 0; k < status_count; ++k)
    if ((*w)[1 + k] != to_string(all_statuses[k])) return corrupt();
  if (w = in.words(); !w || w->size() < 2 || (*w)[0] != "sources") return corrupt();
  for (std::size_t k = 1; k < w->size(); ++k) s.source_names.emplace_back((*w)[k]);
  std::uint64_t scene_bytes = 0;
  if (w = in.words();
      !w || w->size() != 2 || (*w)[0] != "scene-text" || !read_count((*w)[1], scene_bytes))
    return corrupt();
  const std::optional<std::string_view> scene_text = in.bytes(scene_bytes);
  if (!scene_text) return corrupt();
  s.scene_text = std::string(*scene_text);
  while (!in.at_end()) {
    scene_statistics scene;
    if (w = in.words(); !w || w->size() != 4 || (*w)[0] != "scene" || (*w)[2] != "runs" ||
                        !read_count((*w)[1], scene.scene_index) || !read_count((*w)[3], scene.runs))
      return corrupt();
    if (!s.scenes.empty() && scene.scene_index <= s.scenes.back().scene_index) return corrupt();
    scene.sources.resize(s.source_names.size());
    for (error_statistics& source : scene.sources)
      if (w = in.words(); !w || !read_source(*w, source)) return corrupt();
    s.scenes.push_back(std::move(scene));
  }
  return s;
}

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
  if (checked<void> start = check_summary_state_start(text); !start.ok())
    return std::move(start).error();
  if (text.empty()) return refused("truncated summary state");
  const std::size_t first_newline = text.find('\n');
  if (first_newline == std::string_view::npos) return refused("truncated summary state");
  const std::string_view version = text.substr(magic.size(), first_newline - magic.size());
  if (version != format_version)
    return refused("summary state format " + quote(version) + "; this conescan reads format " +
                   std::string(format_version));
  // The end line: the file is whole, and its hash says its bytes are those written.
  const std::size_t last = text.size() >= 2 ? text.rfind('\n', text.size() - 2) : 0;
  const std::string_view end_line =
      text.back() == '\n' && last != std::string_view::npos ? text.substr(last + 1) : "";
  if (end_line.substr(0, end_tag.size()) != end_tag)
    return refused("truncated summary state (no end line)");
  if (end_line != std::string(end_tag) + hex(fnv1a64(text.substr(0, last + 1))) + "\n")
    return refused("corrupt summary state (its hash does not match its contents)");
  return read_body(text.substr(first_newline + 1, last - first_newline));
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
