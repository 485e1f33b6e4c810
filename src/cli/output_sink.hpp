// Buffered, row-atomic output to a file descriptor.
//
// Rows are appended to a fixed buffer and written only at row boundaries, so the output is
// always whole rows. If a write fails part-way through a buffer on a regular file, the file is
// truncated back to the last whole row before the error is reported: a CSV is complete, or ends
// at a row boundary with the error on standard error and a non-zero exit status. This holds for
// a file opened for appending (its earlier contents are never cut) and past a file-size limit
// (a sink on a regular file ignores SIGXFSZ, so the limit shows up as EFBIG, not as a kill).
#pragma once

#include <charconv>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string_view>
#include <vector>

#include "text/shortest_double.hpp"

namespace conescan::cli {

class output_sink {
 public:
  enum class outcome { ok, closed_reader, write_error };

  explicit output_sink(int fd, std::size_t capacity = 1 << 16);

  // The per-field calls are inline: a CSV row makes ~20 of them (docs/PERFORMANCE.md).
  void append(std::string_view text) noexcept {
    reserve(text.size());
    std::memcpy(buffer_.data() + used_, text.data(), text.size());
    used_ += text.size();
  }
  void append(char c) noexcept {
    reserve(1);
    buffer_[used_++] = c;
  }
  /// Shortest round-trip decimal form (the text of std::to_chars, src/text/shortest_double.hpp),
  /// "nan" for NaN, "0" for -0.
  void append_number(double value) noexcept {
    if (value != value) return append("nan");
    if (value == 0) value = 0;  // no "-0"
    reserve(text::shortest_double_room);
    used_ = static_cast<std::size_t>(text::write_shortest_double(buffer_.data() + used_, value) -
                                     buffer_.data());
  }

  /// A count in decimal digits, exactly (a seed of 2^53 + 1 is not a double).
  void append_count(std::uint64_t value) noexcept {
    reserve(20);
    used_ = static_cast<std::size_t>(
        std::to_chars(buffer_.data() + used_, buffer_.data() + used_ + 20, value).ptr -
        buffer_.data());
  }

  /// The offset of the next character: with append_copy, a text already written in this row
  /// can be written again without formatting it again (the buffer is only written between rows).
  std::size_t size() const noexcept { return used_; }
  /// Appends a copy of the text at offsets [from, to) of this row.
  void append_copy(std::size_t from, std::size_t to) noexcept {
    reserve(to - from);
    std::memcpy(buffer_.data() + used_, buffer_.data() + from, to - from);
    used_ += to - from;
  }

  /// What is buffered and not yet written: a sink on no file (fd -1, never flushed) is a
  /// worker thread's buffer of formatted rows (campaign_run.hpp).
  std::string_view buffered() const noexcept { return {buffer_.data(), used_}; }
  /// The size at which end_row() writes the buffer.
  std::size_t flush_threshold() const noexcept { return flush_at_; }
  /// Drops what is buffered (a worker's buffer, once the writer has taken its rows).
  void discard() noexcept { used_ = 0; }

  /// Ends a row: writes the buffer when it is nearly full. Returns false once writing failed.
  bool end_row() noexcept {
    if (used_ >= flush_at_) return flush();
    return state_ == outcome::ok;
  }
  /// Writes what is buffered. Returns false once writing failed.
  bool flush() noexcept;

  outcome state() const noexcept { return state_; }
  int error_number() const noexcept { return errno_; }

 private:
  void reserve(std::size_t extra) noexcept {
    if (used_ + extra > buffer_.size()) grow(extra);
  }
  void grow(std::size_t extra) noexcept;

  int fd_;
  std::vector<char> buffer_;
  std::size_t used_ = 0;
  std::size_t flush_at_;
  long long committed_ = 0;      // bytes written as whole rows
  long long start_offset_ = -1;  // file offset at start, for a regular file
  outcome state_ = outcome::ok;
  int errno_ = 0;
};

/// How a program ends after writing to `out`: 0; 141 for a reader that closed (quietly, as
/// SIGPIPE ends a process); or 1 with "PROGRAM: error writing WHAT to standard output: errno's
/// text" on standard error.
int finish_output(const output_sink& out, const char* program, const char* what);

/// All of `text` on standard output as one row (on a regular file: all of it, or nothing added
/// and the error), then finish_output's status: what both programs write whole (the help, a
/// scene file, a fit's report or JSON).
int write_whole_text(std::string_view text, const char* program, const char* what);

}  // namespace conescan::cli
