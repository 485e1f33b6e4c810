#include "scene/scene_file.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>

#include "scene/head_spec.hpp"
#include "scene/option_table.hpp"
#include "text/number_text.hpp"

namespace conescan::scene {

namespace {

// The line without a trailing comment (a '#' outside double quotes).
std::string_view strip_comment(std::string_view line) {
  bool in_quotes = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    if (line[i] == '"') in_quotes = !in_quotes;
    if (line[i] == '#' && !in_quotes) return line.substr(0, i);
  }
  return line;
}

// Lines of a stream, bounded: LF, CR LF and a lone CR end a line.
class line_reader {
 public:
  line_reader(std::istream& input, const std::string& file) : input_(input), file_(file) {}

  // The next line into `line`; false at the end. An error for a NUL byte, a line or a file
  // too long, or a read error.
  checked<bool> next(std::string& line) {
    line.clear();
    ++number_;
    for (int c = input_.get(); c != std::char_traits<char>::eof(); c = input_.get()) {
      if (++bytes_ > max_scene_file_bytes)
        return error("the file is longer than " + std::to_string(max_scene_file_bytes) +
                     " bytes: not a scene file");
      if (c == '\n') return true;
      if (c == '\r') {
        if (input_.peek() == '\n') {
          input_.get();
          ++bytes_;
        }
        return true;
      }
      if (c == '\0') return error("a NUL byte: not a text scene file");
      if (line.size() >= max_scene_file_line)
        return error("a line longer than " + std::to_string(max_scene_file_line) + " bytes");
      line += static_cast<char>(c);
    }
    if (input_.bad()) return error("read error");
    return !line.empty();
  }

  std::uint64_t number() const noexcept { return number_; }
  origin here() const { return origin::file_line(file_, number_); }
  diagnostic error(std::string message, std::string option = {}) const {
    return diagnostic{std::move(option), std::move(message), here()};
  }

 private:
  std::istream& input_;
  const std::string& file_;
  std::uint64_t number_ = 0;
  std::size_t bytes_ = 0;
};

// A value: "text" (no escapes), a bare token, or an array ["a", "b"] of either.
checked<std::vector<std::string>> split_value(std::string_view text, const line_reader& at) {
  std::vector<std::string> values;
  std::string_view body = text;
  const bool array = body.front() == '[';
  if (array) {
    if (body.back() != ']')
      return at.error("malformed array " + quote(text) + ": expected [\"a\", \"b\"]");
    body = body.substr(1, body.size() - 2);
  }
  while (true) {
    const std::size_t start = body.find_first_not_of(" \t");
    if (start == std::string_view::npos) break;
    body.remove_prefix(start);
    std::size_t end = array ? body.find(',') : std::string_view::npos;
    if (body.front() == '"') {
      const std::size_t close = body.find('"', 1);
      if (close == std::string_view::npos) return at.error("unterminated string in " + quote(text));
      values.emplace_back(body.substr(1, close - 1));
      end = body.find(',', close);
      if (!text::trim_blanks(
               body.substr(close + 1, end == std::string_view::npos ? end : end - close - 1))
               .empty())
        return at.error("unexpected text after the string in " + quote(text));
    } else {
      const std::string_view piece = text::trim_blanks(body.substr(0, end));
      if (piece.empty() || piece.find('"') != std::string_view::npos)
        return at.error("malformed value " + quote(text));
      values.emplace_back(piece);
    }
    if (end == std::string_view::npos) break;
    if (!array) return at.error("malformed value " + quote(text));
    body.remove_prefix(end + 1);
  }
  if (values.empty()) return at.error("missing value in " + quote(text));
  return values;
}

// What a file holds while it is read.
struct file_contents {
  std::vector<option_value> options;
  std::vector<option_value> heads;             // head specs, tables assembled as "alpha=..,beta=.."
  std::map<std::string, std::uint64_t> lines;  // top-level key -> its line
  bool in_head_table = false;
  std::map<std::string, std::uint64_t> table_keys;  // keys of the current [[head]] table
};

checked<void> add_head(file_contents& f, std::string spec, const line_reader& at) {
  if (f.heads.size() == max_heads)
    return at.error("more than " + std::to_string(max_heads) + " heads (a scene has at most " +
                        std::to_string(max_heads) + ")",
                    "head");
  f.heads.push_back({"head", std::move(spec), at.here()});
  return success();
}

// key = value inside a [[head]] table: the value is read here, where its line is known.
checked<void> add_head_key(file_contents& f, std::string_view key,
                           const std::vector<std::string>& values, const line_reader& at) {
  if (!is_head_key(key))
    return at.error("unknown key " + quote(key) +
                    " in a [[head]] table; keys: " + head_keys_text());
  if (values.size() != 1) return at.error("head key '" + std::string(key) + "' takes one value");
  if (checked<void> value = check_head_value(key, values[0]); !value.ok())
    return at.error("head key '" + std::string(key) + "': " + value.error().message, "head");
  if (const auto it = f.table_keys.find(std::string(key)); it != f.table_keys.end())
    return at.error("head key '" + std::string(key) +
                    "' given twice in one [[head]] table (first on line " +
                    std::to_string(it->second) + ")");
  f.table_keys[std::string(key)] = at.number();
  std::string& spec = f.heads.back().text;
  spec += (spec.empty() ? "" : ",") + std::string(key) + "=" + values[0];
  return success();
}

checked<void> add_option(file_contents& f, std::string_view key,
                         const std::vector<std::string>& values, const line_reader& at) {
  const option_spec* spec = find_option(key);
  if (key == "config" || key == "print-config" || key == "help")
    return at.error("key " + quote(key) + " is a command-line option, not a scene-file key");
  if (!spec) return at.error("unknown key " + quote(key) + "; keys: " + option_names());
  if (spec->kind == value_kind::head) {
    for (const std::string& head : values)
      if (checked<void> added = add_head(f, head, at); !added.ok()) return added;
    return success();
  }
  if (const auto it = f.lines.find(std::string(key)); it != f.lines.end())
    return at.error("key '" + std::string(key) + "' given twice (first on line " +
                    std::to_string(it->second) + ")");
  if (values.size() != 1)
    return at.error("key '" + std::string(key) + "' takes one value, not an array");
  f.lines[std::string(key)] = at.number();
  f.options.push_back({std::string(key), values[0], at.here()});
  return success();
}

checked<void> read_line(file_contents& f, std::string_view line, const line_reader& at) {
  if (at.number() == 1 && line.substr(0, 3) == "\xEF\xBB\xBF") line.remove_prefix(3);  // UTF-8 BOM
  const std::string_view text = text::trim_blanks(strip_comment(line));
  if (text.empty()) return success();
  if (text == "[[head]]") {
    if (!f.heads.empty() && f.in_head_table && f.heads.back().text.empty())
      return diagnostic{"", "empty [[head]] table: give some of " + std::string(head_keys_text()),
                        f.heads.back().where};
    f.in_head_table = true;
    f.table_keys.clear();
    return add_head(f, "", at);
  }
  if (text.front() == '[')
    return at.error("unknown table " + quote(text) + ": the only table is [[head]] (keys " +
                    head_keys_text() + ")");
  const std::size_t equals = text.find('=');
  if (equals == std::string_view::npos)
    return at.error("malformed line " + quote(text) + ": expected key = value");
  const std::string_view key = text::trim_blanks(text.substr(0, equals));
  const std::string_view value = text::trim_blanks(text.substr(equals + 1));
  if (key.empty()) return at.error("malformed line " + quote(text) + ": missing key before '='");
  if (value.empty()) return at.error("key " + quote(key) + " has no value");
  checked<std::vector<std::string>> values = split_value(value, at);
  if (!values.ok()) return std::move(values).error();
  return f.in_head_table ? add_head_key(f, key, values.value(), at)
                         : add_option(f, key, values.value(), at);
}

}  // namespace

checked<std::vector<option_value>> read_scene_file(std::istream& input,
                                                   const std::string& file_name) {
  line_reader reader(input, file_name);
  file_contents f;
  std::string line;
  while (true) {
    checked<bool> more = reader.next(line);
    if (!more.ok()) return std::move(more).error();
    if (!more.value()) break;
    if (checked<void> read = read_line(f, line, reader); !read.ok()) return std::move(read).error();
  }
  if (f.in_head_table && f.heads.back().text.empty())
    return diagnostic{"", "empty [[head]] table: give some of " + std::string(head_keys_text()),
                      f.heads.back().where};
  std::vector<option_value> entries = std::move(f.options);
  for (option_value& head : f.heads) entries.push_back(std::move(head));
  return entries;
}

checked<std::vector<option_value>> read_scene_file(const std::string& path) {
  if (path.empty()) return diagnostic{"config", "empty file name: give a scene file", {}};
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    return diagnostic{"config", quote(path) + " is a directory, not a scene file", {}};
  std::ifstream input(path, std::ios::binary);
  if (!input)
    return diagnostic{"config", "cannot read " + quote(path) + ": " + std::strerror(errno), {}};
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
