#include "cli/output_sink.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>

namespace conescan::cli {

output_sink::output_sink(int fd, std::size_t capacity)
    : fd_(fd), buffer_(capacity + 4096), flush_at_(capacity) {
  struct stat st {};
  if (fstat(fd_, &st) != 0 || !S_ISREG(st.st_mode)) return;
  // Where our rows start. With O_APPEND (a shell's >>) every write goes to the end of the file
  // while the descriptor's offset still reads 0: the rows start at the current size, and
  // truncating to "offset + committed" would cut into what the file already held.
  const int flags = fcntl(fd_, F_GETFL);
  start_offset_ = flags != -1 && (flags & O_APPEND)
                      ? static_cast<long long>(st.st_size)
                      : static_cast<long long>(lseek(fd_, 0, SEEK_CUR));
  // Past a file-size limit (ulimit -f) the kernel writes what fits, then kills the writer with
  // SIGXFSZ at the next write: the file would end inside a row with no message. Ignored, the
  // signal becomes EFBIG, which flush() reports after taking the partial row back.
  std::signal(SIGXFSZ, SIG_IGN);
}

void output_sink::grow(std::size_t extra) noexcept {
  // A row longer than the slack (thousands of heads) grows the buffer once, outside the loop's
  // steady state.
  buffer_.resize((used_ + extra) * 2);
}

bool output_sink::flush() noexcept {
  if (state_ != outcome::ok) return false;
  std::size_t done = 0;
  while (done < used_) {
    const ssize_t n = ::write(fd_, buffer_.data() + done, used_ - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      errno_ = errno;
      state_ = errno_ == EPIPE ? outcome::closed_reader : outcome::write_error;
      // Take back a partial buffer so the file ends at a row boundary.
      if (start_offset_ >= 0 && done > 0)
        (void)!ftruncate(fd_, static_cast<off_t>(start_offset_ + committed_));
      return false;
    }
    done += static_cast<std::size_t>(n);
  }
  committed_ += static_cast<long long>(used_);
  used_ = 0;
  return true;
}

int finish_output(const output_sink& out, const char* program, const char* what) {
  constexpr int exit_write_error = 1;
  // What a shell reports for a process ended by SIGPIPE; used when SIGPIPE is ignored and the
  // closed reader shows up as EPIPE instead.
  constexpr int exit_closed_reader = 141;
  switch (out.state()) {
    case output_sink::outcome::ok:
      return 0;
    case output_sink::outcome::closed_reader:
      return exit_closed_reader;
    case output_sink::outcome::write_error:
      std::fprintf(stderr, "%s: error writing %s to standard output: %s\n", program, what,
                   std::strerror(out.error_number()));
      return exit_write_error;
  }
  return exit_write_error;
}

int write_whole_text(std::string_view text, const char* program, const char* what) {
  output_sink out(STDOUT_FILENO, text.size());
  out.append(text);
  out.flush();
  return finish_output(out, program, what);
}

}  // namespace conescan::cli
