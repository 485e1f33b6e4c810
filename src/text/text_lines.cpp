#include "text/text_lines.hpp"
#include "text/number_text.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>

namespace conescan::text {

checked<void> for_each_line(const std::string& path, const line_handler& on_line) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return diagnostic::in_file(path, 0, "cannot open: " + std::string(std::strerror(errno)));
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
      return diagnostic::in_file(path, line, "NUL byte: not a text file");
    }
    if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
    if (text.size() > max_line_chars) {
      return diagnostic::in_file(
          path, line, "line longer than " + std::to_string(max_line_chars) + " characters");
    }
    if (checked<void> handled = on_line(text); !handled.ok()) {
      diagnostic& e = handled.error();
      e.where.file = path;
      if (e.where.line == 0) e.where.line = line;
      return handled;
    }
  }
  if (in.bad()) return diagnostic::in_file(path, line, "read error");
  if (!in.eof()) {  // getline stopped on a full buffer: the line is longer than the limit
    return diagnostic::in_file(
        path, line + 1, "line longer than " + std::to_string(max_line_chars) + " characters");
  }
  return success();
}

std::string to_upper(std::string_view text) {
  std::string upper(text);
  for (char& c : upper) {
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
  }
  return upper;
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

}  // namespace conescan::text
