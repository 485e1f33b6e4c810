#include "scene_file.hpp"

#include "scene/head_spec.hpp"

#include <charconv>
#include <cmath>
#include <sstream>

namespace conescan::cli {

namespace {

std::string trim(const std::string& s) {
  const std::size_t first = s.find_first_not_of(" \t\r");
  if (first == std::string::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t\r") - first + 1);
}

// The line without a trailing comment (a '#' outside double quotes).
std::string strip_comment(const std::string& line) {
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    if (line[i] == '"') quoted = !quoted;
    if (line[i] == '#' && !quoted) return line.substr(0, i);
  }
  return line;
}

bool is_number(const std::string& text) {
  double value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return !text.empty() && ec == std::errc() && end == text.data() + text.size();
}

}  // namespace

std::string scene_file_format::file_name() const {
  const CLI::Option* config = app_->get_config_ptr();
  return config && config->count() ? config->as<std::string>() : std::string("scene file");
}

std::string scene_file_format::to_config(const CLI::App* app, bool default_also,
                                         bool write_description, std::string prefix) const {
  // CLI11 writes unset optional values as key="" and includes the print-config flag itself:
  // drop both, so that the output reads back as a scene file.
  std::istringstream all(
      CLI::ConfigTOML().to_config(app, default_also, write_description, std::move(prefix)));
  std::string out, line;
  while (std::getline(all, line)) {
    if (line.size() >= 3 && line.compare(line.size() - 3, 3, "=\"\"") == 0) continue;
    if (line.rfind("print-config=", 0) == 0) continue;
    out += line + "\n";
  }
  return out;
}

std::string scene_file_format::where(const std::string& option) const {
  const auto it = lines_.find(option);
  return it == lines_.end() ? std::string() : file_name() + ":" + std::to_string(it->second);
}

std::vector<CLI::ConfigItem> scene_file_format::from_config(std::istream& input) const {
  lines_.clear();
  const std::string file = file_name();
  std::vector<CLI::ConfigItem> result;
  std::vector<std::string> heads;
  bool in_head_table = false;
  std::string line;
  int number = 0;
  auto fail = [&](const std::string& message) {
    throw CLI::ConfigError(file + ":" + std::to_string(number) + ": " + message);
  };
  auto allowed_keys = [&] {
    std::string keys;
    for (const CLI::Option* opt : app_->get_options()) {
      const std::string name = opt->get_single_name();
      if (opt->get_lnames().empty() || name == "help" || name == "config" || name == "print-config")
        continue;
      keys += (keys.empty() ? "" : ", ") + name;
    }
    return keys;
  };
  // A value: "text" (no escapes), a bare token, or an array ["a", "b"] of either.
  auto parse_value = [&](const std::string& text) {
    std::vector<std::string> values;
    std::string body = text;
    const bool array = !body.empty() && body.front() == '[';
    if (array) {
      if (body.back() != ']') fail("malformed array '" + text + "': expected [\"a\", \"b\"]");
      body = body.substr(1, body.size() - 2);
    }
    std::size_t pos = 0;
    while (pos <= body.size()) {
      std::size_t end = body.size();
      std::string piece;
      const std::size_t start = body.find_first_not_of(" \t", pos);
      if (start == std::string::npos) break;
      if (body[start] == '"') {
        const std::size_t close = body.find('"', start + 1);
        if (close == std::string::npos) fail("unterminated string in '" + text + "'");
        piece = body.substr(start + 1, close - start - 1);
        end = body.find(',', close);
        if (trim(body.substr(close + 1, (end == std::string::npos ? body.size() : end) - close - 1))
                .size())
          fail("unexpected text after the string in '" + text + "'");
      } else {
        end = array ? body.find(',', start) : std::string::npos;
        piece =
            trim(body.substr(start, end == std::string::npos ? std::string::npos : end - start));
        if (piece.empty() || piece.find('"') != std::string::npos)
          fail("malformed value '" + text + "'");
      }
      values.push_back(piece);
      if (end == std::string::npos) break;
      if (!array) fail("malformed value '" + text + "'");
      pos = end + 1;
    }
    if (values.empty()) fail("missing value");
    return values;
  };

  // One line at a time, bounded: a scene file is short text, and /dev/zero or a binary file
  // must end in a clear error, not in memory exhaustion or a silent default scene.
  constexpr std::size_t max_line_length = 4096;
  auto read_line = [&]() {
    line.clear();
    for (int c = input.get(); c != std::char_traits<char>::eof(); c = input.get()) {
      if (c == '\n') return true;
      if (c == '\0') fail("a NUL byte: not a text scene file");
      if (line.size() >= max_line_length)
        fail("a line longer than " + std::to_string(max_line_length) + " characters");
      line += static_cast<char>(c);
    }
    return !line.empty();
  };
  while ((++number, read_line())) {
    if (number == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0) line.erase(0, 3);  // a UTF-8 BOM
    const std::string text = trim(strip_comment(line));
    if (text.empty()) continue;
    if (text == "[[head]]") {
      heads.emplace_back();
      lines_["head#" + std::to_string(heads.size())] = number;
      in_head_table = true;
      continue;
    }
    if (text.front() == '[')
      fail("unknown table '" + text + "': the only table is [[head]] (keys " +
           scene::head_keys_text() + ")");
    const std::size_t equals = text.find('=');
    if (equals == std::string::npos) fail("malformed line '" + text + "': expected key = value");
    const std::string key = trim(text.substr(0, equals));
    const std::string value_text = trim(text.substr(equals + 1));
    if (key.empty()) fail("malformed line '" + text + "': missing key before '='");
    if (value_text.empty()) fail("key '" + key + "' has no value");
    const std::vector<std::string> values = parse_value(value_text);

    if (in_head_table) {
      if (!scene::is_head_key(key))
        fail("unknown key '" + key + "' in a [[head]] table; keys: " + scene::head_keys_text());
      if (values.size() != 1 || !is_number(values[0]))
        fail("head key '" + key + "' = " + value_text + " is not a number in degrees");
      std::string& spec = heads.back();
      if (spec.find(key + "=") == 0 || spec.find("," + key + "=") != std::string::npos)
        fail("head key '" + key + "' given twice in one [[head]] table");
      spec += (spec.empty() ? "" : ",") + key + "=" + values[0];
      continue;
    }

    const CLI::Option* opt = app_->get_option_no_throw("--" + key);
    if (!opt || key == "help" || key == "config" || key == "print-config")
      fail("unknown key '" + key + "'; keys: " + allowed_keys());
    if (key == "head") {
      for (const std::string& spec : values) {
        heads.push_back(spec);
        lines_["head#" + std::to_string(heads.size())] = number;
      }
      continue;
    }
    if (lines_.count(key))
      fail("key '" + key + "' given twice (first on line " + std::to_string(lines_[key]) + ")");
    if (values.size() != 1) fail("key '" + key + "' takes one value, not an array");
    const std::string type = opt->get_type_name();
    if (opt->get_expected_max() == 0 || opt->get_type_size_max() == 0) {  // a flag
      if (values[0] != "true" && values[0] != "false")
        fail("key '" + key + "' = " + value_text + " must be true or false");
    } else if (type == "FLOAT" || type == "INT" || type == "UINT") {
      if (!is_number(values[0])) fail("key '" + key + "' = " + value_text + " is not a number");
    }
    lines_[key] = number;
    CLI::ConfigItem item;
    item.name = key;
    item.inputs = values;
    result.push_back(item);
  }
  if (input.bad()) fail("read error (is it a directory?)");
  for (std::size_t k = 0; k < heads.size(); ++k)
    if (heads[k].empty()) {
      number = lines_["head#" + std::to_string(k + 1)];
      fail("empty [[head]] table: give some of " + std::string(scene::head_keys_text()));
    }
  if (!heads.empty()) {
    CLI::ConfigItem item;
    item.name = "head";
    item.inputs = heads;
    result.push_back(item);
  }
  return result;
}

}  // namespace conescan::cli
