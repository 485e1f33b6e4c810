// conescan-fit's own options on CLI11: the table of src/scene_calibration/fit_request.hpp,
// registered here and read back as (name, text, origin) entries, which build_fit_plan checks
// exactly as it checks conescan.fit's keywords. The scene options are the option table's
// (command_line.hpp, for scene_program::fit).
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "scene/scene_request.hpp"

namespace conescan::fit_cli {

/// Registers every fit option on `app`; entries() then returns what was given.
class fit_options {
 public:
  explicit fit_options(CLI::App& app);
  /// Each value given, in the table's order, as the command line's entries.
  std::vector<scene::option_value> entries() const;

 private:
  struct registered {
    std::string name;
    bool flag = false;
    CLI::Option* option = nullptr;
    std::vector<std::string> texts;
  };
  std::vector<registered> options_;
};

}  // namespace conescan::fit_cli
