#include <common/filter_parameter/rich_parameter_list.h>

#include "option_parameters.hpp"

#include <charconv>
#include <cmath>

#include "vorocrust/error.hpp"

namespace vorocrust::meshlab {

namespace {

QString key_of(const OptionSpec& spec) { return QString::fromStdString(option_spelling(spec, Spelling::MeshLab)); }

QString tooltip_of(const OptionSpec& spec) {
  std::string text = spell_options(std::string(spec.help), Spelling::Label);
  if (!spec.section.empty()) text += " (VoroCrust paper, section " + std::string(spec.section) + ")";
  std::string default_line = spell_options(default_text(spec), Spelling::Label);
  default_line[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(default_line[0])));
  text += ". " + default_line;
  if (spec.unset_number && spec.default_value.index() == 0) {
    text += " (" + format_option_value(spec, *spec.unset_number) + " here)";
  }
  if (spec.kind != OptionKind::Flag) text += "; range: " + range_text(spec);
  return QString::fromStdString(text + ".");
}

QString label_of(const OptionSpec& spec) {
  return QString::fromStdString(std::string(spec.label) + (spec.unit.empty() ? "" : " (" + std::string(spec.unit) + ")"));
}

// A float as the user typed it: its shortest decimal text, read as a double.
double widened(float x) {
  char text[32];
  const auto [end, ec] = std::to_chars(text, text + sizeof text, x);
  double value = x;
  if (ec == std::errc()) std::from_chars(text, end, value);
  return value;
}

double number_of(const OptionSpec& spec, const OptionValue& v) {
  if (v.index() == 0) return spec.unset_number.value_or(0);
  if (std::holds_alternative<std::int64_t>(v)) return static_cast<double>(std::get<std::int64_t>(v));
  return std::get<double>(v);
}

}  // namespace

QString choice_parameter(const OptionSpec& spec, std::string_view choice) {
  QString name = QString::fromUtf8(choice.data(), static_cast<int>(choice.size()));
  name[0] = name[0].toUpper();
  return key_of(spec) + name;
}

void add_option_parameters(RichParameterList& parameters, const std::vector<std::string_view>& names) {
  for (const OptionSpec& spec : mesh_option_specs()) {
    const bool named = std::find(names.begin(), names.end(), spec.name) != names.end();
    if (names.empty() ? !(spec.front_ends & kMeshLab) : !named) continue;
    const QString key = key_of(spec), label = label_of(spec), tip = tooltip_of(spec);
    switch (spec.kind) {
      case OptionKind::Flag:
        parameters.addParam(RichBool(key, std::get<bool>(spec.default_value), label, tip));
        break;
      case OptionKind::Integer:
        parameters.addParam(RichInt(key, static_cast<int>(number_of(spec, spec.default_value)), label, tip));
        break;
      case OptionKind::Real:
        parameters.addParam(RichFloat(key, static_cast<float>(number_of(spec, spec.default_value)), label, tip));
        break;
      case OptionKind::Choice: {
        QStringList choices;
        int index = 0;
        for (std::size_t k = 0; k < spec.choices.size(); ++k) {
          choices << QString::fromUtf8(spec.choices[k].data(), static_cast<int>(spec.choices[k].size()));
          if (spec.choices[k] == std::get<std::string>(spec.default_value)) index = static_cast<int>(k);
        }
        parameters.addParam(RichEnum(key, index, choices, label, tip));
        break;
      }
      case OptionKind::Choices: {
        const auto& chosen = std::get<std::vector<std::string>>(spec.default_value);
        for (std::string_view choice : spec.choices) {
          const bool on = std::find(chosen.begin(), chosen.end(), choice) != chosen.end();
          parameters.addParam(RichBool(choice_parameter(spec, choice), on,
                                       QString("Write %1").arg(QString::fromUtf8(choice.data(), int(choice.size()))),
                                       tip));
        }
        break;
      }
      case OptionKind::File:
        parameters.addParam(RichOpenFile(key, QString(), QStringList{"*.txt", "*"}, label, tip));
        break;
      case OptionKind::Box:
        parameters.addParam(RichString(key, QString(), label, tip));
        break;
    }
  }
}

MeshOptions options_from_parameters(const RichParameterList& parameters) {
  MeshOptions options;
  for (const OptionSpec& spec : mesh_option_specs()) {
    const QString key = key_of(spec);
    OptionValue value;
    try {
      switch (spec.kind) {
        case OptionKind::Flag:
          if (!parameters.hasParameter(key)) continue;
          value = parameters.getBool(key);
          break;
        case OptionKind::Integer:
          if (!parameters.hasParameter(key)) continue;
          value = static_cast<std::int64_t>(parameters.getInt(key));
          break;
        case OptionKind::Real:
          if (!parameters.hasParameter(key)) continue;
          value = widened(parameters.getFloat(key));
          break;
        case OptionKind::Choice: {
          if (!parameters.hasParameter(key)) continue;
          const int index = parameters.getEnum(key);
          if (index < 0 || index >= static_cast<int>(spec.choices.size())) {
            throw Error(Error::Kind::Usage, std::string(spec.name) + " has no choice " + std::to_string(index),
                        {.option = std::string(spec.name)});
          }
          value = std::string(spec.choices[static_cast<std::size_t>(index)]);
          break;
        }
        case OptionKind::Choices: {
          std::vector<std::string> chosen;
          bool any = false;
          for (std::string_view choice : spec.choices) {
            if (!parameters.hasParameter(choice_parameter(spec, choice))) continue;
            any = true;
            if (parameters.getBool(choice_parameter(spec, choice))) chosen.emplace_back(choice);
          }
          if (!any) continue;
          value = chosen;
          break;
        }
        case OptionKind::File:
          if (!parameters.hasParameter(key)) continue;
          value = parse_option_value(spec, parameters.getOpenFileName(key).trimmed().toStdString());
          break;
        case OptionKind::Box:
          if (!parameters.hasParameter(key)) continue;
          value = parse_option_value(spec, parameters.getString(key).toStdString());
          break;
      }
      // A number widget shows unset as the table's unset_number.
      if (spec.unset_number && spec.default_value.index() == 0 && number_of(spec, value) == *spec.unset_number) {
        value = std::monostate{};
      }
      set_option(options, spec, value);
    } catch (const Error& e) {
      throw Error(e.kind(), spelled_message(e.message(), e.where().option, Spelling::Label), e.where());
    }
  }
  return options;
}

}  // namespace vorocrust::meshlab
