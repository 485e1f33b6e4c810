// Fuzz harnesses of options as users give them: a scene file's text, or a command line with an
// optional scene file, through the whole of the scene layer (option table, scene plan, sweeps,
// the error budget) and conescan-sim's command-line parser. Shared by the fuzz targets and
// tests/apps/test_robustness.cpp (which replays their corpora).
//
// Invariants: no crash, hang or exception; an error has a message; every scene of an accepted
// plan (the first and the last sweep value, each budget source) simulates with consistent rows
// (scene_harness.hpp); and --print-config's text reads back to a plan that prints the same text
// (a fixed point: the same options, so the same CSV).
#pragma once

#include <sstream>
#include <string>
#include <vector>

#include "cli/command_line.hpp"
#include "fuzz/scene_harness.hpp"
#include "scene/scene_file.hpp"
#include "scene/scene_plan.hpp"

namespace conescan_fuzz {

namespace sc = conescan::scene;

/// Most rows a fuzz input may ask for (its --max-rows is replaced): the plan validates a sweep
/// value by value, so this bounds one input's time.
inline constexpr const char* fuzz_max_rows = "100000";

inline void bound_work(std::vector<sc::option_value>& entries) {
  std::vector<sc::option_value> kept;
  for (sc::option_value& v : entries)
    if (v.name != "max-rows") kept.push_back(std::move(v));
  kept.push_back({"max-rows", fuzz_max_rows, conescan::origin::command_line()});
  entries = std::move(kept);
}

/// The plan of `entries`, its scenes simulated, and --print-config's round trip.
inline std::string check_plan(std::vector<sc::option_value> entries) {
  bound_work(entries);
  const conescan::checked<sc::scene_plan> plan = sc::build_scene_plan(entries);
  if (!plan.ok())
    return plan.error().message.empty() ? "an error without a message: " + plan.error().text()
                                        : std::string();
  const sc::scene_plan& p = plan.value();
  if (p.scene_count() < 1 || p.total_rows() < 1 || p.total_rows() > 100000)
    return "a plan of " + std::to_string(p.scene_count()) + " scenes and " +
           std::to_string(p.total_rows()) + " rows";
  for (const std::uint64_t j : {std::uint64_t(0), p.scene_count() - 1})
    if (std::string f = check_scene_rows(p.scene(j)); !f.empty()) return f;
  for (const sc::budget_source& source : p.budget())
    if (std::string f = check_scene_rows(source.scene); !f.empty())
      return "budget source " + source.name + ": " + f;
  const std::string printed = sc::scene_file_text(p.request());
  std::istringstream file(printed);
  const auto read_back = sc::read_scene_file(file, "printed.toml");
  if (!read_back.ok())
    return "--print-config does not read back: " + read_back.error().text() + "\n" + printed;
  const auto again = sc::build_scene_plan(read_back.value());
  if (!again.ok())
    return "--print-config's scene is refused: " + again.error().text() + "\n" + printed;
  if (sc::scene_file_text(again.value().request()) != printed)
    return "--print-config is not a fixed point:\n" + printed + "---\n" +
           sc::scene_file_text(again.value().request());
  if (again.value().scene_count() != p.scene_count() ||
      again.value().total_rows() != p.total_rows())
    return "--print-config's scene has other scenes or rows";
  return {};
}

/// A scene file's text.
inline std::string check_scene_file(const std::uint8_t* data, std::size_t size) {
  std::istringstream file(std::string(reinterpret_cast<const char*>(data), size));
  const auto entries = sc::read_scene_file(file, "fuzz.toml");
  if (!entries.ok())
    return entries.error().message.empty() ? "a scene-file error without a message" : std::string();
  return check_plan(entries.value());
}

/// Lines: argv words, one per line, then optionally a line CONFIG and a scene file. Words
/// starting with --config are dropped: the harness must not open files the fuzzer names
/// (/dev/zero would hang it).
inline std::string check_command_line(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const std::size_t config = text.rfind("CONFIG\n", 0) == 0 ? 0 : text.find("\nCONFIG\n");
  const std::string words_text = text.substr(0, config);
  std::vector<std::string> words{"conescan-sim"};
  std::istringstream lines(words_text);
  for (std::string word; std::getline(lines, word);)
    if (word.rfind("--config", 0) != 0) words.push_back(word);
  std::vector<const char*> argv;
  for (const std::string& w : words) argv.push_back(w.c_str());
  conescan::cli::command_line_parser parser;
  const auto line = parser.parse(static_cast<int>(argv.size()), argv.data());
  if (!line.ok()) return line.error().text().empty() ? "a command-line error without text" : "";
  if (line.value().help) return parser.help().empty() ? "empty help" : "";
  std::vector<sc::option_value> entries;
  if (config != std::string::npos) {
    std::istringstream file(text.substr(text.find("CONFIG\n", config) + 7));
    const auto read = sc::read_scene_file(file, "fuzz.toml");
    if (!read.ok())
      return read.error().message.empty() ? "a scene-file error without a message" : "";
    entries = read.value();
  }
  entries.insert(entries.end(), line.value().options.begin(), line.value().options.end());
  return check_plan(std::move(entries));
}

}  // namespace conescan_fuzz
