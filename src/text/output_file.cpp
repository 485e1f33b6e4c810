#include "text/output_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <utility>

namespace conescan::text {

namespace {

// The directory a path's file lives in ("." for a bare name), and its last component.
std::pair<std::string, std::string> split_path(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  if (slash == std::string::npos) return {".", path};
  return {slash == 0 ? "/" : path.substr(0, slash), path.substr(slash + 1)};
}

// The absolute path a file would have: its directory resolved (realpath), then its name.
std::string resolved_path(const std::string& path) {
  const auto [directory, name] = split_path(path);
  char buffer[PATH_MAX];
  if (::realpath(directory.c_str(), buffer) == nullptr) return path;
  const std::string resolved(buffer);
  return (resolved == "/" ? "" : resolved) + "/" + name;
}

bool same_inode(const struct stat& a, const struct stat& b) noexcept {
  return a.st_dev == b.st_dev && a.st_ino == b.st_ino;
}

bool is_standard_output(const struct stat& st) noexcept {
  struct stat out {};
  return ::fstat(STDOUT_FILENO, &out) == 0 && same_inode(st, out);
}

}  // namespace

checked<output_file> output_file::open(const std::string& path, const std::string& option) {
  output_file f;
  f.path_ = path;
  f.option_ = option;
  // A file-size limit (ulimit -f) kills the writer with SIGXFSZ: ignored, it becomes EFBIG and
  // a message.
  std::signal(SIGXFSZ, SIG_IGN);
  if (path.empty()) return f.failure(ENOENT);
  struct stat link {};
  const bool absent = ::lstat(path.c_str(), &link) != 0;
  if (absent && errno != ENOENT) return f.failure(errno);
  struct stat st = link;
  f.target_ = path;
  if (!absent && S_ISLNK(link.st_mode)) {
    if (::stat(path.c_str(), &st) != 0)
      return diagnostic{option, "cannot write " + quote(path) + ": a symbolic link to nothing"};
    char buffer[PATH_MAX];
    if (::realpath(path.c_str(), buffer) == nullptr) return f.failure(errno);
    f.target_ = buffer;
  }
  // The file or pipe standard output goes to holds the program's own output (the CSV, a fit's
  // report): a second output there would be mixed into it (`--write-oem x > x` was the OEM and
  // the CSV in one file). A terminal or /dev/null is a device that shows or drops each in turn.
  if (!absent && is_standard_output(st) && !S_ISCHR(st.st_mode))
    return diagnostic{option, quote(path) +
                                  " is the file standard output goes to: give the output a file "
                                  "of its own"};
  if (!absent && (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode) || S_ISSOCK(st.st_mode))) {
    f.fd_ = ::open(f.target_.c_str(), O_WRONLY | O_CLOEXEC | O_NOCTTY);
    if (f.fd_ < 0) return f.failure(errno);
    return f;
  }
  if (!absent && S_ISDIR(st.st_mode)) return f.failure(EISDIR);
  if (!absent && !S_ISREG(st.st_mode))
    return diagnostic{option, "cannot write " + quote(path) +
                                  ": not a regular file, a character device or a FIFO"};
  if (!absent && ((st.st_mode & 0222) == 0 || ::access(f.target_.c_str(), W_OK) != 0))
    return f.failure(EACCES);
  const mode_t mode = absent ? 0666 : (st.st_mode & 07777);
  for (int attempt = 0; f.fd_ < 0; ++attempt) {
    f.temporary_ = f.target_ + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(attempt);
    f.fd_ = ::open(f.temporary_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, mode);
    if (f.fd_ < 0 && (errno != EEXIST || attempt == 99)) {
      const int error = errno;
      f.temporary_.clear();
      return f.failure(error);
    }
  }
  // The replaced file's permission bits, whatever the umask made of them.
  if (!absent) (void)!::fchmod(f.fd_, mode);
  return f;
}

output_file::output_file(output_file&& other) noexcept
    : path_(std::move(other.path_)),
      option_(std::move(other.option_)),
      target_(std::move(other.target_)),
      temporary_(std::move(other.temporary_)),
      fd_(std::exchange(other.fd_, -1)),
      committed_(other.committed_),
      error_(std::move(other.error_)) {
  other.temporary_.clear();
}

output_file& output_file::operator=(output_file&& other) noexcept {
  if (this != &other) {
    discard();
    path_ = std::move(other.path_);
    option_ = std::move(other.option_);
    target_ = std::move(other.target_);
    temporary_ = std::move(other.temporary_);
    other.temporary_.clear();
    fd_ = std::exchange(other.fd_, -1);
    committed_ = other.committed_;
    error_ = std::move(other.error_);
  }
  return *this;
}

output_file::~output_file() {
  discard();
}

void output_file::discard() noexcept {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  if (!committed_ && !temporary_.empty()) ::unlink(temporary_.c_str());
  temporary_.clear();
}

diagnostic output_file::failure(int error_number) const {
  return diagnostic{option_, "cannot write " + quote(path_) + ": " + std::strerror(error_number)};
}

checked<void> output_file::write(std::string_view bytes) {
  if (error_) return *error_;
  if (fd_ < 0) return failure(EBADF);
  while (!bytes.empty()) {
    const ssize_t n = ::write(fd_, bytes.data(), bytes.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      error_ = failure(n < 0 ? errno : EIO);
      return *error_;
    }
    bytes.remove_prefix(static_cast<std::size_t>(n));
  }
  return success();
}

checked<void> output_file::commit() {
  if (error_ || fd_ < 0) {
    const diagnostic error = error_ ? *error_ : failure(EBADF);
    discard();
    return error;
  }
  // A device or FIFO is not synced (EINVAL on many); a regular file must reach the disk before
  // it replaces the old one.
  const bool synced = direct() || ::fsync(fd_) == 0;
  int error = synced ? 0 : errno;
  if (::close(fd_) != 0 && error == 0) error = errno;
  fd_ = -1;
  if (error == 0 && !direct() && std::rename(temporary_.c_str(), target_.c_str()) != 0)
    error = errno;
  if (error != 0) {
    discard();
    return failure(error);
  }
  committed_ = true;
  temporary_.clear();
  return success();
}

bool same_output_file(const std::string& a, const std::string& b) {
  struct stat sa {
  }, sb{};
  if (::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0) return same_inode(sa, sb);
  return resolved_path(a) == resolved_path(b);
}

}  // namespace conescan::text
