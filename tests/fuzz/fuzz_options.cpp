// libFuzzer target: conescan-sim's option parsing (declare_options + CLI11 + to_scene) on any
// command line or scene file, then the simulation of every scene it accepts.
//
// Input: lines. If the first line is "CONFIG", the rest is a scene file (--config) fed to
// CLI11's config parser through parse_from_stream; otherwise each line is one argv word.
// Words starting with --config are dropped: the harness must not open files the fuzzer names
// (/dev/zero would hang it; see docs/RELIABILITY.md).
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "fuzz/scene_harness.hpp"
#include "options.hpp"

namespace {

std::string check_options(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::vector<std::string> words;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    words.push_back(text.substr(start, end - start));
    start = end + 1;
  }
  const bool config = !words.empty() && words.front() == "CONFIG";

  CLI::App app{"conescan-sim", "conescan-sim"};
  conescan::cli::options opts;
  conescan::cli::declare_options(app, opts);
  try {
    if (config) {
      std::istringstream file(text.substr(
          words.front().size() + 1 > text.size() ? text.size() : words.front().size() + 1));
      app.parse_from_stream(file);
    } else {
      // CLI11 takes the arguments reversed (the last one first), without argv[0].
      std::vector<std::string> args;
      for (auto it = words.rbegin(); it != words.rend(); ++it)
        if (it->rfind("--config", 0) != 0) args.push_back(*it);
      app.parse(std::move(args));
    }
  } catch (const CLI::ParseError&) {
    return {};  // main.cpp reports these with exit status 2
  }
  const auto scene = conescan::cli::to_scene(app, opts);
  if (const auto* err = std::get_if<conescan::scene::config_error>(&scene)) {
    if (err->option.empty() || err->message.empty()) return "a config_error without its text";
    return {};
  }
  const conescan::scene::scene_config& s = std::get<conescan::scene::scene_config>(scene);
  return conescan_fuzz::check_scene_rows(s);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string failure = check_options(data, size);
  if (!failure.empty()) {
    std::fprintf(stderr, "invariant broken: %s\n", failure.c_str());
    std::abort();
  }
  return 0;
}
