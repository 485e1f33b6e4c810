#include "text/text_lines.hpp"
#include "text/number_text.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace conescan::text {

namespace {

// A file read in blocks through its descriptor, closed at the end of scope.
class file_descriptor {
 public:
  explicit file_descriptor(const std::string& path)
      : fd_(::open(path.c_str(), O_RDONLY | O_CLOEXEC)) {}
  ~file_descriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  file_descriptor(const file_descriptor&) = delete;
  file_descriptor& operator=(const file_descriptor&) = delete;
  int get() const noexcept { return fd_; }

 private:
  int fd_;
};

// The lines of a byte stream: each ends at "\n", "\r\n" or a lone "\r" (old Mac files), the
// last one also at the end of the stream. At most max_line_chars + 1 bytes of a line are held.
class line_splitter {
 public:
  // Feeds `bytes`; each complete line goes to `each(line)`, which returns false to stop (then
  // feed returns false too).
  template <class Each>
  bool feed(std::string_view bytes, Each&& each) {
    for (const char c : bytes) {
      if (after_cr_ && c == '\n') {  // the "\n" of a "\r\n"
        after_cr_ = false;
        continue;
      }
      after_cr_ = false;
      if (c == '\n' || c == '\r') {
        after_cr_ = c == '\r';
        if (!each(line())) return false;
        length_ = 0;
        overlong_ = false;
        continue;
      }
      if (length_ < line_.size()) {
        line_[length_++] = c;
      } else if (!overlong_) {
        // Said at once: a file without line ends (/dev/zero) was read on for ever, waiting for
        // the end of a line that would be refused anyway.
        overlong_ = true;
        if (!each(line())) return false;
      }
    }
    return true;
  }
  // The last line when the stream does not end with a line end.
  template <class Each>
  bool finish(Each&& each) {
    return length_ == 0 && !overlong_ ? true : each(line());
  }
  // The line held; longer than max_line_chars when it was cut.
  std::string_view line() const noexcept {
    return {line_.data(), overlong_ ? line_.size() : length_};
  }

 private:
  std::array<char, max_line_chars + 1> line_{};
  std::size_t length_ = 0;
  bool overlong_ = false;
  bool after_cr_ = false;
};

}  // namespace

diagnostic file_error(const std::string& path, std::string_view what, int error_number) {
  return diagnostic::in_file(path, 0, std::string(what) + ": " + std::strerror(error_number));
}

checked<void> for_each_line(const std::string& path, const line_handler& on_line) {
  const file_descriptor file(path);
  if (file.get() < 0) return file_error(path, "cannot open", errno);
  std::size_t line = 0;
  std::optional<checked<void>> stopped;
  const auto each = [&](std::string_view text) {
    ++line;
    if (line == 1 && text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // UTF-8 BOM
    if (text.find('\0') != std::string_view::npos) {
      stopped = diagnostic::in_file(path, line, "NUL byte: not a text file");
    } else if (text.size() > max_line_chars) {
      stopped = diagnostic::in_file(
          path, line, "line longer than " + std::to_string(max_line_chars) + " characters");
    } else if (checked<void> handled = on_line(text); !handled.ok()) {
      diagnostic& e = handled.error();
      e.where.file = path;
      if (e.where.line == 0) e.where.line = line;
      stopped = std::move(handled);
    }
    return !stopped;
  };
  line_splitter lines;
  std::array<char, 1 << 16> block;
  while (true) {
    const ssize_t n = ::read(file.get(), block.data(), block.size());
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return file_error(path, "cannot read", errno);
    if (n == 0) break;
    if (!lines.feed(std::string_view(block.data(), static_cast<std::size_t>(n)), each))
      return std::move(*stopped);
  }
  if (!lines.finish(each)) return std::move(*stopped);
  return success();
}

checked<void> open_for_reading(const std::string& path, std::ifstream& in) {
  const file_descriptor probe(path);
  if (probe.get() < 0) return file_error(path, "cannot open", errno);
  struct stat st {};
  if (::fstat(probe.get(), &st) == 0 && S_ISDIR(st.st_mode))
    return file_error(path, "cannot read", EISDIR);
  in.open(path, std::ios::binary);
  if (!in.is_open()) return file_error(path, "cannot open", errno);
  return success();
}

checked<std::string> read_bounded_file(const std::string& path, std::size_t max_bytes,
                                       std::string_view what, const start_check& check_start) {
  constexpr std::size_t start_bytes = 4096;  // what the start of a file is checked on
  const file_descriptor file(path);
  if (file.get() < 0) return file_error(path, "cannot open", errno);
  std::string text;
  bool started = !check_start;
  std::array<char, 1 << 16> block;
  while (true) {
    const ssize_t n = ::read(file.get(), block.data(), block.size());
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return file_error(path, "cannot read", errno);
    text.append(block.data(), static_cast<std::size_t>(n));
    if (!started && (n == 0 || text.size() >= start_bytes)) {
      started = true;
      if (checked<void> start = check_start(text); !start.ok()) {
        diagnostic refusal = std::move(start).error();
        refusal.where.file = path;  // the line too, when the check knows it
        return refusal;
      }
    }
    if (n == 0) return text;
    if (text.size() > max_bytes)
      return diagnostic::in_file(
          path, 0, "larger than " + std::to_string(max_bytes) + " bytes: not " + std::string(what));
  }
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
