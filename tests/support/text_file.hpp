// A text file written for one test and removed after it: hand-made CCSDS and CSV inputs whose
// content sits in the test beside the expected result.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

namespace conescan_test {

class text_file {
 public:
  /// Writes `content` to a file named `name` in a directory of this process under the system's
  /// temporary directory (the name shows in the readers' messages).
  text_file(std::string_view name, std::string_view content) {
    static int counter = 0;
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() /
        ("conescan_tests_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    std::filesystem::create_directories(dir);
    path_ = (dir / name).string();
    std::ofstream(path_, std::ios::binary) << content;
  }
  ~text_file() { std::filesystem::remove_all(std::filesystem::path(path_).parent_path()); }
  text_file(const text_file&) = delete;
  text_file& operator=(const text_file&) = delete;

  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

/// The content of a file, whole.
inline std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// `text` with every `from` replaced by `to`.
inline std::string replaced(std::string text, std::string_view from, std::string_view to) {
  for (std::size_t at = text.find(from); at != std::string::npos;
       at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
  return text;
}

}  // namespace conescan_test
