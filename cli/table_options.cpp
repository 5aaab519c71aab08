#include "table_options.hpp"

#include <CLI/CLI.hpp>

#include <cctype>

namespace vorocrust::cli {

namespace {

std::string type_name(const OptionSpec& spec) {
  switch (spec.kind) {
    case OptionKind::Flag: return "";
    case OptionKind::Integer: return "INT";
    case OptionKind::Real: return "FLOAT";
    case OptionKind::Choice: {
      std::string names;
      for (std::string_view c : spec.choices) names += (names.empty() ? "" : "|") + std::string(c);
      return "{" + names + "}";
    }
    case OptionKind::Choices: return "LIST";
    case OptionKind::File: return "FILE";
    case OptionKind::Box: return "XMIN YMIN ZMIN XMAX YMAX ZMAX";
  }
  return "";
}

std::string help_of(const OptionSpec& spec) {
  std::string help = spell_options(std::string(spec.help), Spelling::Cli);
  if (!spec.section.empty()) help += " (paper " + std::string(spec.section) + ")";
  std::string text = spell_options(default_text(spec), Spelling::Cli);
  text[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(text[0])));
  help += ". " + text;
  if (spec.kind != OptionKind::Flag) help += "; range: " + range_text(spec);
  return help + ".";
}

}  // namespace

void TableOptions::add(CLI::App& command, const std::vector<std::string_view>& names) {
  for (const OptionSpec& spec : mesh_option_specs()) {
    const bool named = std::find(names.begin(), names.end(), spec.name) != names.end();
    if (names.empty() ? !(spec.front_ends & kCli) : !named) continue;
    std::string flag = option_spelling(spec, Spelling::Cli);
    if (!spec.cli_alias.empty()) flag += "," + std::string(spec.cli_alias);
    std::vector<std::string>& value = values_[std::string(spec.name)];
    CLI::Option* option = nullptr;
    if (spec.kind == OptionKind::Flag) {
      option = command.add_flag_callback(flag, [&value] { value = {"true"}; }, help_of(spec));
    } else {
      option = command.add_option(flag, value, help_of(spec))->type_name(type_name(spec));
      if (spec.kind == OptionKind::Box) option->expected(6);
      else if (spec.kind == OptionKind::Choices) option->delimiter(',')->expected(0, CLI::detail::expected_max_vector_size);
      else option->expected(1);
    }
    (void)option;
  }
}

void TableOptions::apply(MeshOptions& options) const {
  for (const auto& [name, words] : values_) {
    if (words.empty()) continue;
    const OptionSpec& spec = *find_option(name);
    std::string text;
    for (const std::string& w : words) text += (text.empty() ? "" : spec.kind == OptionKind::Choices ? "," : " ") + w;
    set_option(options, spec, parse_option_value(spec, text));
  }
}

}  // namespace vorocrust::cli
