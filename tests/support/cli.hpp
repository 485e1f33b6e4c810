// Runs conescan-sim from the tests and reads its CSV (the files it writes and reads:
// support/temp_file.hpp).
#pragma once

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "support/temp_file.hpp"

namespace conescan_test {

struct run_result {
  int exit_status;
  std::string out;
  std::string err;
};

/// Runs `program <args>` through the shell (args are shell words) and captures both streams.
/// `before` is shell text put in front of the command: a pipe into its standard input
/// ("yes x |"), a limit ("ulimit -t 60;").
inline run_result run_program(const std::string& program, const std::string& args,
                              const std::string& before = "") {
  static int counter = 0;
  const std::string err_path =
      "conescan_test_stderr_" + std::to_string(::getpid()) + "_" + std::to_string(counter++);
  const std::string command = before + " " + program + " " + args + " 2>" + err_path;
  run_result r{-1, {}, {}};
  FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return r;
  char buffer[1 << 14];
  std::size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) r.out.append(buffer, n);
  const int status = ::pclose(pipe);
  r.exit_status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  std::ifstream err(err_path);
  std::stringstream ss;
  ss << err.rdbuf();
  r.err = ss.str();
  std::remove(err_path.c_str());
  return r;
}

/// conescan-sim <args>.
inline run_result run_sim(const std::string& args, const std::string& before = "") {
  return run_program(CONESCAN_SIM_PATH, args, before);
}

/// `ulimit -v KILOBYTES;` for a child's shell, or nothing where the programs run under
/// AddressSanitizer (the sanitizer preset sets ASAN_OPTIONS), which reserves terabytes of address
/// space for its shadow memory at start: any such limit aborts it before main.
inline std::string address_space_limit(long kilobytes) {
  if (std::getenv("ASAN_OPTIONS") != nullptr) return "";
  return "ulimit -v " + std::to_string(kilobytes) + ";";
}

/// A shell word holding `text` exactly (single quotes, quotes within escaped).
inline std::string shell_word(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

/// A CSV as its header and rows of fields.
struct csv_table {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;

  std::size_t column(const std::string& name) const {
    for (std::size_t i = 0; i < header.size(); ++i)
      if (header[i] == name) return i;
    throw std::out_of_range("no column " + name);
  }
  double number(std::size_t row, const std::string& name) const {
    return std::stod(rows.at(row).at(column(name)));
  }
  const std::string& text(std::size_t row, const std::string& name) const {
    return rows.at(row).at(column(name));
  }
};

inline std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, ',')) fields.push_back(field);
  if (!line.empty() && line.back() == ',') fields.emplace_back();
  return fields;
}

inline csv_table parse_csv(const std::string& text) {
  csv_table t;
  std::istringstream in(text);
  std::string line;
  if (std::getline(in, line)) t.header = split_csv_line(line);
  while (std::getline(in, line))
    if (!line.empty()) t.rows.push_back(split_csv_line(line));
  return t;
}

}  // namespace conescan_test
