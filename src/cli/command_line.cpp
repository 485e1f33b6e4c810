#include "cli/command_line.hpp"

#include "scene/head_spec.hpp"
#include "scene/option_table.hpp"
#include "scene/scene_file.hpp"

namespace conescan::cli {

namespace {

constexpr const char* description =
    "conescan-sim: attitude errors of conical scanning Earth horizon sensors with a misaligned "
    "optical axis, as CSV on standard output (angles in degrees, distances in km, time in s). "
    "With no options: the paper's scene (Ricci & Carrara, INPE).";

// What --help shows for an option's value: the table's name for it, else its kind's.
std::string value_name_of(const scene::option_spec& spec) {
  if (!spec.value_name.empty()) return std::string(spec.value_name);
  return std::string(scene::value_kind_placeholder(spec.kind));
}

// A word that is no option: an unknown option, or a head key typed as a word of its own
// (--head alpha=3 gamma=30: the shell split what must be one comma-separated spec).
conescan::diagnostic stray_word(const std::string& word, scene::scene_program program) {
  // An option of the table that this program does not offer: say whose it is.
  if (word.rfind("--", 0) == 0)
    if (const scene::option_spec* spec = scene::find_option(word.substr(2, word.find('=') - 2)))
      if (!scene::honours(program, *spec)) return scene::not_honoured(program, *spec, {});
  if (word.rfind("-", 0) == 0)
    return {{},
            "unknown option " + conescan::quote(word) + " (" +
                std::string(scene::program_name(program)) + " --help lists them)",
            {}};
  const std::size_t equals = word.find('=');
  if (equals != std::string::npos && scene::is_head_key(word.substr(0, equals)))
    return {"head",
            conescan::quote(word) +
                " is a word of its own: a head's keys go in one word joined by commas, e.g. "
                "--head alpha=3,gamma=30",
            {}};
  return {{}, "unexpected argument " + conescan::quote(word) + " (options start with --)", {}};
}

}  // namespace

command_line_parser::command_line_parser(scene::scene_program program,
                                         std::string program_description)
    : program_(program),
      name_(scene::program_name(program)),
      app_(program_description.empty() ? description : program_description, name_) {
  app_.get_formatter()->column_width(34);
  app_.allow_extras();
  const auto table = scene::option_table();
  options_.reserve(table.size());  // options keep pointers to the vectors
  for (const scene::option_spec& spec : table) {
    if (!scene::honours(program, spec)) continue;  // not offered: not in --help, refused
    options_.push_back({std::string(spec.name), spec.kind == scene::value_kind::flag, nullptr, {}});
    std::vector<std::string>& texts = options_.back().texts;
    const std::string name = "--" + std::string(spec.name);
    CLI::Option* option =
        spec.kind == scene::value_kind::flag
            ? app_.add_flag(name)
                  ->description(scene::option_help(spec, program))
                  ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
            : app_.add_option(name, texts, scene::option_help(spec, program))
                  ->expected(1)
                  ->allow_extra_args(false)  // one word per option: the next word is not its value
                  ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
                  ->type_name(value_name_of(spec));
    option->group(std::string(scene::group_title(spec.group)));
    options_.back().option = option;
  }
  const std::string scenes(scene::group_title(scene::option_group::scenes));
  config_ = app_.add_option("--config", config_texts_,
                            "scene file, TOML: key = value lines with the same options (the "
                            "command line wins over it), heads as head = [\"...\", ...] or "
                            "[[head]] tables; see data/scenes/")
                ->expected(1)
                ->allow_extra_args(false)  // one word per option: the next word is not its value
                ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
                ->type_name("FILE")
                ->group(scenes);
  if (program != scene::scene_program::simulate) return;  // conescan-sim's own
  print_config_ = app_.add_flag("--print-config")
                      ->description(
                          "print the effective scene as a scene file (it reads back to the same "
                          "CSV) and exit")
                      ->group(scenes);
  version_ = app_.add_flag("--version")
                 ->description("print conescan's version (\"conescan-sim 0.1.0\") and exit")
                 ->group(scenes);
  merge_ = app_.add_option("--merge", merge_files_,
                           "print the summary of a whole campaign from the --summary-state files "
                           "of its shards (every shard once; no other option)")
               ->expected(1, -1)
               ->type_name("FILE")
               ->group(scenes);
}

conescan::checked<command_line> command_line_parser::parse(int argc, const char* const* argv) {
  command_line parsed;
  try {
    app_.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    parsed.help = true;
    return parsed;
  } catch (const CLI::ParseError& e) {
    return conescan::diagnostic{{}, e.what(), {}};
  }
  for (const std::string& word : app_.remaining()) return stray_word(word, program_);
  for (const registered& o : options_)
    for (const std::string& text : o.flag ? o.option->results() : o.texts)
      parsed.options.push_back({o.name, text, conescan::origin::command_line()});
  if (config_texts_.size() > 1) return conescan::diagnostic{"config", "given twice", {}};
  if (!config_texts_.empty()) parsed.config = config_texts_.front();
  parsed.print_config = print_config_ && print_config_->count() > 0;
  parsed.version = version_ && version_->count() > 0;
  if (merge_ && merge_->count() > 0) {  // the scene comes from the state files
    if (!parsed.options.empty() || parsed.config || parsed.print_config)
      return conescan::diagnostic{"merge", "takes state files and no other option", {}};
    parsed.merge = merge_files_;
  }
  return parsed;
}

std::string command_line_parser::help() const {
  return app_.help();
}

conescan::checked<std::vector<scene::option_value>> scene_options(const command_line& line) {
  std::vector<scene::option_value> entries;
  if (line.config) {
    auto file = scene::read_scene_file(*line.config);
    if (!file.ok()) return std::move(file).error();
    entries = std::move(file).value();
  }
  entries.insert(entries.end(), line.options.begin(), line.options.end());
  return entries;
}

}  // namespace conescan::cli
