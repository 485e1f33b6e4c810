#include "cli/fit_options.hpp"

#include "scene_calibration/fit_request.hpp"

namespace conescan::fit_cli {

fit_options::fit_options(CLI::App& app) {
  const auto table = calibration::fit_option_table();
  options_.reserve(table.size());  // CLI11 keeps pointers to the vectors
  for (const calibration::fit_option_spec& spec : table) {
    options_.push_back(
        {std::string(spec.name), spec.kind == calibration::fit_option_kind::flag, nullptr, {}});
    registered& o = options_.back();
    const std::string name = "--" + o.name;
    const std::string help(spec.help);
    o.option = o.flag
                   ? app.add_flag(name, help)->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
                   : app.add_option(name, o.texts, help)
                         ->expected(1)
                         ->allow_extra_args(false)
                         ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
                         ->type_name(std::string(spec.value_name));
    o.option->group("Calibration");
  }
}

std::vector<scene::option_value> fit_options::entries() const {
  std::vector<scene::option_value> out;
  for (const registered& o : options_)
    for (const std::string& text : o.flag ? o.option->results() : o.texts)
      out.push_back({o.name, text, conescan::origin::command_line()});
  return out;
}

}  // namespace conescan::fit_cli
