// Files in the working directory for a test: one written for it and removed after it, one read
// whole. Needs no program (support/cli.hpp runs them), so a test of any tier may include it.
#pragma once

#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

namespace conescan_test {

/// A file in the working directory holding `body` (a scene file), removed at the end of scope.
struct temp_file {
  std::string path;
  explicit temp_file(const std::string& body, const std::string& suffix = ".toml") {
    static int counter = 0;
    path = "conescan_test_file_" + std::to_string(::getpid()) + "_" + std::to_string(counter++) +
           suffix;
    std::ofstream(path, std::ios::binary) << body;
  }
  temp_file(const temp_file&) = delete;
  temp_file& operator=(const temp_file&) = delete;
  ~temp_file() { std::remove(path.c_str()); }
};

/// The whole of the file at `path` (empty when it cannot be read).
inline std::string read_file(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace conescan_test
