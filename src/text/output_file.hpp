// Files a program writes besides its standard output (--write-oem, --write-aem,
// --summary-state): written whole or not at all, and never at the expense of what is not ours.
//
// The rules, checked when the file is opened (before the program writes its first byte of any
// output), one per kind of path:
//  - absent, or a regular file we may write (a write permission bit set, and access(W_OK): a
//    read-only file stays read-only for root too): written to a temporary file beside it,
//    PATH.tmp-PID-N, created here (O_EXCL) with the permission bits of the file it replaces,
//    flushed and synced, then renamed over PATH by commit();
//  - a symbolic link: the rules of the file it names (a regular file is replaced, the link kept;
//    a link to nothing is refused);
//  - the very file or pipe standard output goes to (same device and inode), where the program's
//    own output goes: refused (a terminal or /dev/null, character devices, are written as below);
//  - a character device, a FIFO or a socket (/dev/null, a pipe, /dev/stdout on a terminal):
//    written directly, no temporary;
//  - a directory, a block device, anything else: refused, nothing written.
// Nothing but the temporary file this object created is ever removed: an output_file that is
// destroyed without commit() unlinks its own temporary file and touches nothing else. Every
// failure (open, write, a full device, a file-size limit: SIGXFSZ is ignored so that the limit
// shows up as EFBIG, fsync, rename) is a diagnostic naming the option and the path with errno's
// text: "cannot write 'PATH': No space left on device". A program prints it and exits 1.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "text/diagnostic.hpp"

namespace conescan::text {

class output_file {
 public:
  /// Checks `path` by the rules above and prepares to write it (creates the temporary file, or
  /// opens the device). `option`: the option that named it, for the diagnostic.
  static checked<output_file> open(const std::string& path, const std::string& option);

  output_file(output_file&& other) noexcept;
  output_file& operator=(output_file&& other) noexcept;
  output_file(const output_file&) = delete;
  output_file& operator=(const output_file&) = delete;
  /// Removes the temporary file when commit() did not succeed (and only it).
  ~output_file();

  /// Appends `bytes`. After the first error every call returns that error.
  checked<void> write(std::string_view bytes);

  /// The file complete: synced and renamed over the path (or the device closed). On error the
  /// temporary file is removed and the path left as it was.
  checked<void> commit();

  /// The path as given.
  const std::string& path() const noexcept { return path_; }
  /// True when written directly (a device, FIFO or socket).
  bool direct() const noexcept { return temporary_.empty(); }

 private:
  output_file() = default;
  diagnostic failure(int error_number) const;
  void discard() noexcept;

  std::string path_, option_;
  std::string target_;     // what commit() renames over: the path, or the file a link names
  std::string temporary_;  // empty: written directly
  int fd_ = -1;
  bool committed_ = false;
  std::optional<diagnostic> error_;
};

/// Whether two output paths would write the same file: the same device and inode when both
/// exist, else the same absolute path once the directory that would hold each is resolved. Two
/// options must not name one file (the second would replace the first).
bool same_output_file(const std::string& a, const std::string& b);

}  // namespace conescan::text
