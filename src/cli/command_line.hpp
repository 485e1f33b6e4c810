// conescan-sim's command line: CLI11 collects the text of every option of the option table
// (src/scene/option_table.hpp) as typed, and makes --help from the table; the scene layer reads
// the texts (scene_plan.hpp), so the command line, scene files and the Python bindings read
// every value alike.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "scene/option_table.hpp"
#include "scene/scene_request.hpp"
#include "text/diagnostic.hpp"

namespace conescan::cli {

/// What the command line holds: the scene options as typed, and the program's own options.
struct command_line {
  std::vector<scene::option_value> options;  ///< in the option table's order
  std::optional<std::string> config;         ///< --config FILE
  bool print_config = false;                 ///< --print-config
  bool help = false;                         ///< --help or -h
  bool version = false;                      ///< --version
  std::vector<std::string> merge;            ///< --merge FILE...: summary states to add up
};

class command_line_parser {
 public:
  /// The parser of `program`: the scene options it honours (option_table.hpp, scene_program),
  /// --config, and conescan-sim's --print-config and --merge. conescan-fit passes its
  /// description and adds its own options through app() before parse (fit_options.hpp).
  explicit command_line_parser(scene::scene_program program = scene::scene_program::simulate,
                               std::string program_description = {});
  command_line_parser(const command_line_parser&) = delete;
  command_line_parser& operator=(const command_line_parser&) = delete;

  /// The options of argv (argv[0] is the program). Errors: CLI11's (a value missing), a word
  /// that is no option (with a hint when it looks like a head key left out of --head's
  /// comma-separated spec), --config given twice.
  conescan::checked<command_line> parse(int argc, const char* const* argv);

  /// --help's text.
  std::string help() const;

  /// The CLI11 application, for a program's own options (add them before parse).
  CLI::App& app() noexcept { return app_; }

 private:
  scene::scene_program program_;
  std::string name_;
  CLI::App app_;
  // Per option of the table that the program honours: its name, CLI11 option and texts.
  struct registered {
    std::string name;
    bool flag = false;
    const CLI::Option* option = nullptr;
    std::vector<std::string> texts;
  };
  std::vector<registered> options_;
  CLI::Option* config_ = nullptr;
  CLI::Option* print_config_ = nullptr;
  std::vector<std::string> config_texts_;
  CLI::Option* merge_ = nullptr;
  CLI::Option* version_ = nullptr;
  std::vector<std::string> merge_files_;
};

/// The scene options: the scene file's (--config), then the command line's (which win over
/// them). Errors: the scene file's.
conescan::checked<std::vector<scene::option_value>> scene_options(const command_line& line);

}  // namespace conescan::cli
