#include "cli/fit_options.hpp"

#include <array>

#include "text/number_text.hpp"

namespace conescan::fit_cli {

namespace {

enum class kind { text, flag };

struct fit_option_spec {
  const char* name;
  kind value;
  const char* type;
  const char* help;
};

// The table: name, kind, value type and help of each option only conescan-fit has.
constexpr std::array<fit_option_spec, 7> table{{
    {"--telemetry", kind::text, "FILE",
     "telemetry CSV: t_s and per head hK_chord_deg, hK_phase_deg (conescan-sim's CSV is one); "
     "other columns are ignored"},
    {"--free", kind::text, "LIST",
     "parameters to estimate, comma-separated: hK.sigma, hK.phase, hK.dgamma, hK.bias-in, "
     "hK.bias-out (K = 1..heads), horizon-km, horizon-pole-km, horizon-shift-km; the others are "
     "held at the scene's values; NAME@SECONDS drifts: one value per SECONDS of telemetry"},
    {"--loss", kind::text, "WORD",
     "huber (robust to outliers, the default) or none (plain weighted least squares)"},
    {"--max-iterations", kind::text, "COUNT",
     "Levenberg-Marquardt iterations at most, [1, 10000] (default 100); a fit that needs more "
     "reports NOT CONVERGED with its last state and exits 1"},
    {"--residuals", kind::text, "FILE",
     "also write every measurement's residuals at the solution to FILE (CSV: t_s, row, head, "
     "lat_deg, chord and phase residuals in deg, normalised, fitted), for "
     "scripts/plot-fit.py"},
    {"--json", kind::flag, "", "one JSON object on standard output instead of the table"},
    {"--predict", kind::flag, "",
     "experiment design: the 1 sigma each free parameter would reach for the scene as planned "
     "(its orbit, --step-s, --orbits or --duration-s, heads' noise=) from the Fisher information, "
     "without telemetry"},
}};

}  // namespace

fit_options::fit_options(CLI::App& app) {
  std::array<std::vector<std::string>*, 5> texts{&telemetry_, &free_, &loss_, &max_iterations_,
                                                 &residuals_};
  std::size_t next_text = 0;
  for (const fit_option_spec& spec : table) {
    CLI::Option* option = nullptr;
    if (spec.value == kind::flag) {
      option = app.add_flag(spec.name, spec.help);
      (std::string(spec.name) == "--json" ? json_ : predict_) = option;
    } else {
      option = app.add_option(spec.name, *texts[next_text++], spec.help)
                   ->expected(1)
                   ->allow_extra_args(false)
                   ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
                   ->type_name(spec.type);
    }
    option->group("Calibration");
  }
}

conescan::checked<fit_request> fit_options::read() const {
  using conescan::diagnostic;
  fit_request r;
  if (telemetry_.size() > 1) return diagnostic{"telemetry", "given twice"};
  if (free_.size() > 1) return diagnostic{"free", "given twice: list every parameter in one"};
  if (loss_.size() > 1) return diagnostic{"loss", "given twice"};
  if (max_iterations_.size() > 1) return diagnostic{"max-iterations", "given twice"};
  if (residuals_.size() > 1) return diagnostic{"residuals", "given twice"};
  if (!residuals_.empty()) r.residuals = residuals_.front();
  if (!max_iterations_.empty()) {
    const conescan::checked<std::uint64_t> count = text::parse_count(max_iterations_.front());
    if (!count.ok() || count.value() < 1 || count.value() > 10000)
      return diagnostic{"max-iterations",
                        conescan::quote(max_iterations_.front()) + " is not a count in [1, 10000]"};
    r.max_iterations = static_cast<int>(count.value());
  }
  r.json = json_->count() > 0;
  r.predict = predict_->count() > 0;
  if (!telemetry_.empty()) r.telemetry = telemetry_.front();
  if (free_.empty())
    return diagnostic{"free", "missing: name the parameters to estimate (conescan-fit --help)"};
  r.free = free_.front();
  if (!loss_.empty()) {
    if (loss_.front() == "none")
      r.loss = calibration::robust_loss::none;
    else if (loss_.front() != "huber")
      return diagnostic{"loss", conescan::quote(loss_.front()) + " is not one of: huber, none"};
  }
  if (r.predict && r.telemetry)
    return diagnostic{"telemetry", "--predict plans a scene without data: drop --telemetry"};
  if (r.predict && r.residuals)
    return diagnostic{"residuals", "--predict plans a scene without data: drop --residuals"};
  if (!r.predict && !r.telemetry)
    return diagnostic{"telemetry", "missing: give the telemetry CSV to fit (or --predict)"};
  return r;
}

}  // namespace conescan::fit_cli
