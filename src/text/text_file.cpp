#include "text/text_file.hpp"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace conescan::text {

checked<std::string> read_text_file(const std::string& path, std::size_t max_bytes,
                                    std::string_view what) {
  if (path.empty()) return diagnostic{{}, "empty file name: give " + std::string(what)};
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    return diagnostic::in_file(path, 0, "is a directory, not " + std::string(what));
  std::ifstream in(path, std::ios::binary);
  if (!in) return diagnostic::in_file(path, 0, "cannot open: " + std::string(std::strerror(errno)));
  std::string text;
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (text.size() > max_bytes)
      return diagnostic::in_file(
          path, 0, "longer than " + std::to_string(max_bytes) + " bytes: not " + std::string(what));
  }
  if (in.bad()) return diagnostic::in_file(path, 0, "read error");
  return text;
}

}  // namespace conescan::text
