// Scene files for --config: the command line's options as `key = value` lines (issue 5).
//
//   # comment                     a-km = 7280          earth = "wgs84"
//   sun-sync = true               sweep = "e=0:0.1:0.025"
//   head = "alpha=0,beta=90"      (repeatable), or tables:
//   [[head]]
//   alpha = 0                     keys alpha, beta, gamma, sigma, phase (degrees)
//
// Keys are the long option names without dashes. Top-level keys come before the first
// [[head]] table (as in TOML, a table runs to the next table header). Options given on the
// command line override the file's; heads given on the command line replace the file's.
// The reader is a CLI11 Config, so CLI11 applies the values exactly as it applies options; it
// checks each line itself to report errors as FILE:LINE with the allowed keys or values.
#pragma once

#include <CLI/CLI.hpp>
#include <map>
#include <string>
#include <vector>

namespace conescan::cli {

class scene_file_format : public CLI::Config {
 public:
  /// `app` is the application whose options the file may set; its --config option names the file.
  explicit scene_file_format(const CLI::App* app) : app_(app) {}

  /// Writes the effective scene (CLI11's TOML writer; used by --print-config).
  std::string to_config(const CLI::App* app, bool default_also, bool write_description,
                        std::string prefix) const override;

  /// Reads the file; throws CLI::ConfigError("FILE:LINE: ...") for a malformed line, an unknown
  /// key, a repeated key, or a value that does not fit its option (flag, number).
  std::vector<CLI::ConfigItem> from_config(std::istream& input) const override;

  /// "FILE:LINE" of the line that set `option` (long name without dashes; "head#K" for head K),
  /// or "" when the file did not set it.
  std::string where(const std::string& option) const;

 private:
  std::string file_name() const;

  const CLI::App* app_;
  mutable std::map<std::string, int> lines_;
};

}  // namespace conescan::cli
