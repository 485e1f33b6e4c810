// Buffered, row-atomic output to a file descriptor.
//
// Rows are appended to a fixed buffer and written only at row boundaries, so the output is
// always whole rows. If a write fails part-way through a buffer on a regular file, the file is
// truncated back to the last whole row before the error is reported: a CSV is complete, or ends
// at a row boundary with the error on standard error and a non-zero exit status. This holds for
// a file opened for appending (its earlier contents are never cut) and past a file-size limit
// (a sink on a regular file ignores SIGXFSZ, so the limit shows up as EFBIG, not as a kill).
#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

namespace conescan::cli {

class output_sink {
 public:
  enum class outcome { ok, closed_reader, write_error };

  explicit output_sink(int fd, std::size_t capacity = 1 << 16);

  void append(std::string_view text) noexcept;
  void append(char c) noexcept;
  /// Shortest round-trip decimal form (std::to_chars), "nan" for NaN, "0" for -0.
  void append_number(double value) noexcept;

  /// Ends a row: writes the buffer when it is nearly full. Returns false once writing failed.
  bool end_row() noexcept;
  /// Writes what is buffered. Returns false once writing failed.
  bool flush() noexcept;

  outcome state() const noexcept { return state_; }
  int error_number() const noexcept { return errno_; }

 private:
  void reserve(std::size_t extra) noexcept;

  int fd_;
  std::vector<char> buffer_;
  std::size_t used_ = 0;
  std::size_t flush_at_;
  long long committed_ = 0;      // bytes written as whole rows
  long long start_offset_ = -1;  // file offset at start, for a regular file
  outcome state_ = outcome::ok;
  int errno_ = 0;
};

}  // namespace conescan::cli
