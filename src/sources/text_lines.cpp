#include "sources/text_lines.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>

namespace conescan::sources {

std::optional<source_error> for_each_line(const std::string& path, const line_handler& on_line) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return source_error{path, 0, "cannot open: " + std::string(std::strerror(errno))};
  std::array<char, max_line_chars + 2> buffer{};  // the line, its '\r', the terminating NUL
  std::size_t line = 0;
  while (in.getline(buffer.data(), static_cast<std::streamsize>(buffer.size()))) {
    ++line;
    // gcount counts the '\n' that getline extracted (not stored), except on a last line without.
    auto length = static_cast<std::size_t>(in.gcount());
    if (!in.eof()) --length;
    std::string_view text(buffer.data(), length);
    if (line == 1 && text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // UTF-8 BOM
    if (text.find('\0') != std::string_view::npos) {
      return source_error{path, line, "NUL byte: not a text file"};
    }
    if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
    if (text.size() > max_line_chars) {
      return source_error{path, line,
                          "line longer than " + std::to_string(max_line_chars) + " characters"};
    }
    if (std::optional<source_error> e = on_line(text)) {
      e->file = path;
      if (e->line == 0) e->line = line;
      return e;
    }
  }
  if (in.bad()) return source_error{path, line, "read error"};
  if (!in.eof()) {  // getline stopped on a full buffer: the line is longer than the limit
    return source_error{path, line + 1,
                        "line longer than " + std::to_string(max_line_chars) + " characters"};
  }
  return std::nullopt;
}

std::string_view trim(std::string_view text) noexcept {
  const std::size_t first = text.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  const std::size_t last = text.find_last_not_of(" \t");
  return text.substr(first, last - first + 1);
}

std::string to_upper(std::string_view text) {
  std::string upper(text);
  for (char& c : upper) {
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
  }
  return upper;
}

std::optional<double> parse_number(std::string_view text) noexcept {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  if (text.empty() || text.front() == '+') return std::nullopt;
  // from_chars would also read "nan", "inf" and "infinity": only digits may start a mantissa.
  const std::size_t mantissa = text.front() == '-' ? 1 : 0;
  if (text.size() <= mantissa) return std::nullopt;
  const char c = text[mantissa];
  if (!((c >= '0' && c <= '9') || c == '.')) return std::nullopt;
  double value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

std::size_t split_fields(std::string_view line, std::string_view* out,
                         std::size_t capacity) noexcept {
  std::size_t count = 0, pos = 0;
  while (true) {
    pos = line.find_first_not_of(" \t", pos);
    if (pos == std::string_view::npos) return count;
    std::size_t end = line.find_first_of(" \t", pos);
    if (end == std::string_view::npos) end = line.size();
    if (count < capacity) out[count] = line.substr(pos, end - pos);
    ++count;
    pos = end;
  }
}

std::string quoted(std::string_view text) {
  constexpr std::size_t shown = 60;
  if (text.size() > shown) return "'" + std::string(text.substr(0, shown)) + "...'";
  return "'" + std::string(text) + "'";
}

std::string number_text(double value) {
  std::array<char, 32> buffer{};
  const auto [end, ec] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return ec == std::errc() ? std::string(buffer.data(), end) : std::string("?");
}

std::string rounded_text(double value) {
  std::array<char, 32> buffer{};
  const int n = std::snprintf(buffer.data(), buffer.size(), "%.3g", value);
  return std::string(buffer.data(), static_cast<std::size_t>(std::max(n, 0)));
}

}  // namespace conescan::sources
