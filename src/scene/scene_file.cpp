#include "scene/scene_file.hpp"

#include <toml++/toml.h>
#include <algorithm>
#include <fstream>

#include "scene/head_spec.hpp"
#include "scene/option_table.hpp"
#include "text/number_text.hpp"
#include "text/text_lines.hpp"

namespace conescan::scene {

namespace {

// --- The text, bounded -------------------------------------------------------------------------

/// The file's lines joined by "\n" (LF, CR LF and a lone CR end a line, so that toml++, which
/// knows only the first two, numbers lines as the file's reader sees them), and where each
/// line begins.
struct scene_text {
  std::string text;
  std::vector<std::size_t> line_starts{0};
  const std::string& file;

  /// The 1-based byte column of toml++'s position, whose columns count code points.
  std::uint64_t byte_column(const toml::source_position& at) const {
    if (at.line == 0 || at.line > line_starts.size()) return at.column;
    std::size_t i = line_starts[at.line - 1];
    for (toml::source_index c = 1; c < at.column && i < text.size() && text[i] != '\n'; ++c) {
      ++i;
      while (i < text.size() && (static_cast<unsigned char>(text[i]) & 0xC0) == 0x80) ++i;
    }
    return i - line_starts[at.line - 1] + 1;
  }
  origin where(const toml::source_position& at) const {
    return origin::file_line(file, at.line, byte_column(at));
  }
  /// The text of a value on one line, [begin, end) as toml++ places it; "" when not known.
  std::string_view written(const toml::source_region& r) const {
    if (r.begin.line == 0 || r.begin.line != r.end.line) return {};
    const std::size_t start = line_starts[r.begin.line - 1];
    const std::uint64_t from = byte_column(r.begin), to = byte_column(r.end);
    if (to <= from) return {};
    return std::string_view(text).substr(start + from - 1, to - from);
  }
};

diagnostic error_at(origin where, std::string message, std::string option = {}) {
  return diagnostic{std::move(option), std::move(message), std::move(where)};
}

/// Reads the stream into a scene_text: a NUL byte, a line longer than max_scene_file_line and a
/// file longer than max_scene_file_bytes are refused as they are met (whatever the stream's size).
checked<void> read_bounded(std::istream& input, scene_text& out) {
  std::uint64_t line = 1;
  std::size_t bytes = 0, line_length = 0;
  const auto here = [&] { return origin::file_line(out.file, line); };
  for (int c = input.get(); c != std::char_traits<char>::eof(); c = input.get()) {
    if (++bytes > max_scene_file_bytes)
      return error_at(here(), "the file is longer than " + std::to_string(max_scene_file_bytes) +
                                  " bytes: not a scene file");
    if (c == '\r' && input.peek() == '\n') continue;  // CR LF: the LF ends the line
    if (c == '\n' || c == '\r') {
      out.text += '\n';
      out.line_starts.push_back(out.text.size());
      ++line;
      line_length = 0;
      continue;
    }
    if (c == '\0') return error_at(here(), "a NUL byte: not a text scene file");
    if (++line_length > max_scene_file_line)
      return error_at(here(),
                      "a line longer than " + std::to_string(max_scene_file_line) + " bytes");
    out.text += static_cast<char>(c);
  }
  if (input.bad()) return error_at(here(), "read error");
  if (out.text.rfind("\xEF\xBB\xBF", 0) == 0) out.text.replace(0, 3, "   ");  // BOM: columns kept
  return success();
}

// --- Values ------------------------------------------------------------------------------------

/// A scalar as the option table reads it (docs/CLI.md, "Scene files"), or an error placed at it
/// (`option` named).
checked<std::string> value_text(const toml::node& node, const scene_text& t,
                                const std::string& option, const std::string& what) {
  if (const auto* s = node.as_string()) return std::string(s->get());
  if (const auto* b = node.as_boolean()) return std::string(b->get() ? "true" : "false");
  if (node.is_array() || node.is_table())
    return error_at(t.where(node.source().begin),
                    what + " takes one value, not " + (node.is_array() ? "an array" : "a table"),
                    option);
  std::string written(t.written(node.source()));
  // TOML's underscores only separate digits: 100_000 is 100000 to any reader.
  written.erase(std::remove(written.begin(), written.end(), '_'), written.end());
  if (!written.empty()) return written;
  // Not expected (toml++ places every value it reads): the value's own decimal text.
  if (const auto* i = node.as_integer()) return std::to_string(i->get());
  if (const auto* x = node.as_floating_point()) return text::shortest_text(x->get());
  return error_at(t.where(node.source().begin), what + ": a value conescan cannot read", option);
}

// --- What a file holds -------------------------------------------------------------------------

struct file_contents {
  std::vector<option_value> options;
  std::vector<option_value> heads;  // head specs, tables assembled as "alpha=..,beta=.."
};

/// The entries of a TOML table in the order the file wrote them (toml++ keeps them by name).
std::vector<std::pair<const toml::key*, const toml::node*>> in_file_order(const toml::table& t) {
  std::vector<std::pair<const toml::key*, const toml::node*>> out;
  for (auto&& [key, node] : t) out.emplace_back(&key, &node);
  std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) {
    const toml::source_position &x = a.first->source().begin, &y = b.first->source().begin;
    return x.line != y.line ? x.line < y.line : x.column < y.column;
  });
  return out;
}

checked<void> add_head(file_contents& f, std::string spec, origin where) {
  if (f.heads.size() == max_heads)
    return error_at(std::move(where),
                    "more than " + std::to_string(max_heads) + " heads (a scene has at most " +
                        std::to_string(max_heads) + ")",
                    "head");
  f.heads.push_back({"head", std::move(spec), std::move(where)});
  return success();
}

/// How a message names a head's table: "[[head]] table" or "inline head table".
std::string table_kind(const toml::table& table, const scene_text& t) {
  const std::size_t line = table.source().begin.line;
  const bool header =
      line > 0 && line <= t.line_starts.size() &&
      t.text.compare(t.line_starts[line - 1] + t.byte_column(table.source().begin) - 1, 2, "[[") ==
          0;
  return header ? "[[head]] table" : "inline head table";
}

/// A head given as a table (inline, or [[head]]): its keys as one spec, "alpha=0,beta=90".
checked<void> add_head_table(file_contents& f, const toml::table& table, const scene_text& t) {
  const origin where = t.where(table.source().begin);
  if (table.empty())
    return error_at(
        where, "empty " + table_kind(table, t) + ": give some of " + std::string(head_keys_text()));
  std::string spec;
  for (const auto& [key, node] : in_file_order(table)) {
    const std::string name(key->str());
    const origin key_at = t.where(key->source().begin);
    if (!is_head_key(name))
      return error_at(key_at, "unknown key " + quote(name) + " in a " + table_kind(table, t) +
                                  "; keys: " + head_keys_text());
    checked<std::string> value = value_text(*node, t, "head", "head key '" + name + "'");
    if (!value.ok()) return std::move(value).error();
    if (checked<void> valid = check_head_value(name, value.value()); !valid.ok())
      return error_at(t.where(node->source().begin),
                      "head key '" + name + "': " + valid.error().message, "head");
    spec += (spec.empty() ? "" : ",") + name + "=" + value.value();
  }
  return add_head(f, std::move(spec), where);
}

/// One head given in `head = ...`: a spec string or an inline table.
checked<void> add_head_value(file_contents& f, const toml::node& node, const scene_text& t) {
  if (const auto* table = node.as_table()) return add_head_table(f, *table, t);
  if (const auto* s = node.as_string())
    return add_head(f, std::string(s->get()), t.where(node.source().begin));
  return error_at(t.where(node.source().begin),
                  "a head is a spec string (\"alpha=0,beta=90\") or a table ({beta = 90})", "head");
}

/// `head = ...` (one head or an array of them) or [[head]] tables.
checked<void> add_heads(file_contents& f, const toml::node& node, const scene_text& t) {
  const toml::array* array = node.as_array();
  if (!array) return add_head_value(f, node, t);
  if (array->empty())  // as Python's head=[]: no head is not the default head
    return error_at(t.where(node.source().begin),
                    "an empty list: give at least one head, or leave head out for the default one",
                    "head");
  for (const toml::node& head : *array)
    if (checked<void> added = add_head_value(f, head, t); !added.ok()) return added;
  return success();
}

checked<void> add_option(file_contents& f, const toml::key& key, const toml::node& node,
                         const scene_text& t) {
  const std::string name(key.str());
  const origin key_at = t.where(key.source().begin);
  if (name == "config" || name == "print-config" || name == "help")
    return error_at(key_at,
                    "key " + quote(name) + " is a command-line option, not a scene-file key");
  const option_spec* spec = find_option(name);
  if (!spec && node.is_table())
    return error_at(t.where(node.source().begin), "unknown table " + quote("[" + name + "]") +
                                                      ": the only table is [[head]] (keys " +
                                                      head_keys_text() + ")");
  if (!spec) return error_at(key_at, "unknown key " + quote(name) + "; keys: " + option_names());
  if (spec->kind == value_kind::head) return add_heads(f, node, t);
  checked<std::string> value = value_text(node, t, name, "the key");
  if (!value.ok()) return std::move(value).error();
  f.options.push_back({name, std::move(value).value(), t.where(node.source().begin)});
  return success();
}

/// The option a line `key = ...` gives, or "" (for a syntax error's message to name it).
std::string option_of_line(const scene_text& t, toml::source_index line) {
  if (line == 0 || line > t.line_starts.size()) return {};
  std::string_view text = std::string_view(t.text).substr(t.line_starts[line - 1]);
  text = text.substr(0, text.find('\n'));
  const std::size_t equals = text.find('=');
  if (equals == std::string_view::npos) return {};
  const std::string key(text::trim_blanks(text.substr(0, equals)));
  const option_spec* spec = find_option(key);
  return spec ? std::string(spec->name) : std::string();
}

/// toml++'s syntax error as one printable line (it quotes the file's raw bytes), naming the
/// option of its line and with a hint where TOML differs from what a user may expect.
diagnostic syntax_error(const toml::parse_error& e, const scene_text& t) {
  std::string message = requoted(e.description());
  const origin where = t.where(e.source().begin);
  if (message.find("redefine") != std::string::npos && message.find("'head'") != std::string::npos)
    message +=
        " (TOML allows a key once: write several heads as head = [\"...\", \"...\"] or "
        "[[head]] tables)";
  if (message.find("not representable in 64 bits") != std::string::npos)
    message +=
        " (TOML integers are 64-bit signed: write a larger count in quotes, e.g. seed = "
        "\"18446744073709551615\")";
  return error_at(where, message, option_of_line(t, e.source().begin.line));
}

}  // namespace

checked<std::vector<option_value>> read_scene_file(std::istream& input,
                                                   const std::string& file_name) {
  scene_text t{{}, {0}, file_name};
  if (checked<void> read = read_bounded(input, t); !read.ok()) return std::move(read).error();
  toml::table document;
  try {
    document = toml::parse(std::string_view(t.text), std::string_view(file_name));
  } catch (const toml::parse_error& e) {
    return syntax_error(e, t);
  }
  file_contents f;
  for (const auto& [key, node] : in_file_order(document))
    if (checked<void> added = add_option(f, *key, *node, t); !added.ok()) return added.error();
  std::vector<option_value> entries = std::move(f.options);
  for (option_value& head : f.heads) entries.push_back(std::move(head));
  return entries;
}

checked<std::vector<option_value>> read_scene_file(const std::string& path) {
  if (path.empty()) return diagnostic{"config", "empty file name: give a scene file", {}};
  // Said as every reader of a file says it: "--config: PATH: cannot read: Is a directory".
  std::ifstream input;
  if (checked<void> opened = text::open_for_reading(path, input); !opened.ok())
    return diagnostic{"config", path + ": " + opened.error().message, {}};
  return read_scene_file(input, path);
}

std::string scene_file_text(const scene_request& r) {
  std::string out = "# conescan-sim --print-config: the effective scene\n";
  for (const option_spec& option : option_table())
    if (const std::optional<std::string> value = print_option(option, r))
      out += std::string(option.name) + " = " + *value + "\n";
  for (const head_config& h : r.scene.heads) {
    out += "\n[[head]]\n";
    const std::string spec = format_head_spec(h);  // key=value,key=value,...
    std::size_t start = 0;
    while (start < spec.size()) {
      const std::size_t comma = spec.find(',', start);
      const std::string item = spec.substr(start, comma - start);
      const std::string key = item.substr(0, item.find('='));
      const std::string value = item.substr(item.find('=') + 1);
      out += key + " = " + (is_head_word_key(key) ? "\"" + value + "\"" : value) + "\n";
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
  }
  return out;
}

}  // namespace conescan::scene
