// conescan-fit's own options, in one small table: the scene options are the option
// table's (src/scene/option_table.hpp) and reach conescan-fit exactly as they reach conescan-sim.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "calibration/estimator.hpp"
#include "text/diagnostic.hpp"

namespace conescan::fit_cli {

/// What conescan-fit's own options hold after parsing.
struct fit_request {
  std::optional<std::string> telemetry;                             ///< --telemetry FILE
  std::string free;                                                 ///< --free LIST
  bool json = false;                                                ///< --json
  bool predict = false;                                             ///< --predict
  calibration::robust_loss loss = calibration::robust_loss::huber;  ///< --loss huber|none
  int max_iterations = calibration::fit_options{}.max_iterations;   ///< --max-iterations
  std::optional<std::string> residuals;                             ///< --residuals FILE
};

/// Registers the table's options on `app`; read() then returns their values.
class fit_options {
 public:
  explicit fit_options(CLI::App& app);
  /// The values, checked: --free given once and not empty; --loss a known word; --max-iterations
  /// a count in [1, 10000]; --telemetry given once, and with --predict not at all; --residuals
  /// at most once, not with --predict. The error names the option.
  conescan::checked<fit_request> read() const;

 private:
  std::vector<std::string> telemetry_, free_, loss_, max_iterations_, residuals_;
  CLI::Option* json_ = nullptr;
  CLI::Option* predict_ = nullptr;
};

}  // namespace conescan::fit_cli
