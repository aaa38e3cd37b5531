#include "settings/Setting.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace surfacemaps
{

namespace
{

/// The shortest text that reads back as `value`: without an exponent from
/// 1e-4 to below 1e6 (as %g writes six digits: 100, 0.0001), else with the
/// exponent written as people do ("1e-5", "1e6", "2.5e-7").
std::string shortestDecimal(double value)
{
  char text[32];
  int digits = 1;
  for (; digits < 17; ++digits)
  {
    std::snprintf(text, sizeof(text), "%.*g", digits, value);
    if (std::strtod(text, nullptr) == value)
    {
      break;
    }
  }
  const double magnitude = std::abs(value);
  if (magnitude >= 1.0 && magnitude < 1e6)
  {
    // %g uses an exponent once the digits do not reach the decimal point.
    const int whole = static_cast<int>(std::floor(std::log10(magnitude))) + 1;
    digits = std::max(digits, whole);
  }
  std::snprintf(text, sizeof(text), "%.*g", digits, value);
  std::string s = text;
  const std::size_t e = s.find('e');
  if (e == std::string::npos)
  {
    return s;
  }
  std::string exponent = s.substr(e + 1);
  const bool negative = exponent[0] == '-';
  exponent.erase(0, exponent.find_first_not_of("+-0"));
  return s.substr(0, e) + "e" + (negative ? "-" : "") + exponent;
}

bool isWhole(double value)
{
  return value == std::round(value);
}

} // namespace

double Setting::clamp(double value) const
{
  if (std::isnan(value))
  {
    return this->defaultValue;
  }
  value = std::clamp(value, this->minimum, this->maximum);
  return this->kind == SettingKind::Real ? value : std::round(value);
}

std::vector<std::string> Setting::choiceNames() const
{
  std::vector<std::string> names;
  std::istringstream text(this->choices ? this->choices : "");
  for (std::string name; std::getline(text, name, '|');)
  {
    names.push_back(name);
  }
  return names;
}

std::string Setting::format(double value) const
{
  switch (this->kind)
  {
    case SettingKind::Switch:
      return value != 0.0 ? "on" : "off";
    case SettingKind::Choice:
    {
      const std::vector<std::string> names = this->choiceNames();
      const double k = std::round(value);
      return k >= 0 && k < static_cast<double>(names.size()) ? names[static_cast<std::size_t>(k)]
                                                             : shortestDecimal(value);
    }
    case SettingKind::Count:
      return isWhole(value) && std::abs(value) < 1e15 ? std::to_string(std::llround(value))
                                                      : shortestDecimal(value);
    default:
      return shortestDecimal(value);
  }
}

bool Setting::parse(const std::string& text, double& value) const
{
  if (this->kind == SettingKind::Choice)
  {
    const std::vector<std::string> names = this->choiceNames();
    const auto found = std::find(names.begin(), names.end(), text);
    value = static_cast<double>(found - names.begin());
    return found != names.end();
  }
  if (this->kind == SettingKind::Switch && (text == "on" || text == "off"))
  {
    value = text == "on" ? 1.0 : 0.0;
    return true;
  }
  std::size_t used = 0;
  double number = 0.0;
  try
  {
    number = std::stod(text, &used);
  }
  catch (const std::exception&)
  {
    return false;
  }
  // NaN fails every comparison, so it is no value of any setting.
  if (used != text.size() || !(number >= this->minimum && number <= this->maximum) ||
    (this->kind != SettingKind::Real && !isWhole(number)))
  {
    return false;
  }
  value = number;
  return true;
}

std::string Setting::json(double value) const
{
  switch (this->kind)
  {
    case SettingKind::Switch:
      return value != 0.0 ? "true" : "false";
    case SettingKind::Choice:
      return "\"" + this->format(value) + "\"";
    default:
      return std::isfinite(value) ? this->format(value) : "null";
  }
}

std::string Setting::jsonKey() const
{
  std::string key = this->flag;
  std::replace(key.begin(), key.end(), '-', '_');
  return key;
}

std::string Setting::describe() const
{
  std::string text = std::string(this->doc) + " Default " + this->format(this->defaultValue);
  if (this->kind == SettingKind::Real || this->kind == SettingKind::Count)
  {
    text += ", range " + this->format(this->minimum) + " to " + this->format(this->maximum);
  }
  return text + ".";
}

std::string Setting::help() const
{
  std::string line = std::string("  --") + this->flag;
  switch (this->kind)
  {
    case SettingKind::Switch:
      line += std::string(" | --") + this->offFlag;
      break;
    case SettingKind::Choice:
      line += std::string(" ") + this->choices;
      break;
    default:
      line += this->kind == SettingKind::Count ? " N" : " X";
  }
  return line + "\n" + wrapText(this->describe(), 6, 79);
}

double Setting::flagValue(const std::string& argument, const char* text) const
{
  double value = std::nan("");
  if (this->kind == SettingKind::Switch)
  {
    return argument == std::string("--") + this->flag ? 1.0 : 0.0;
  }
  return text && this->parse(text, value) ? value : std::nan("");
}

std::string Setting::valueError(const std::string& option, const char* given) const
{
  if (!given)
  {
    return option + " needs a value";
  }
  const std::string text = given;
  switch (this->kind)
  {
    case SettingKind::Choice:
    {
      const std::vector<std::string> names = this->choiceNames();
      std::string list;
      for (std::size_t c = 0; c < names.size(); ++c)
      {
        list += (c == 0 ? "" : c + 1 == names.size() ? " or " : ", ") + names[c];
      }
      return option + " is " + list + ", not '" + text + "'";
    }
    case SettingKind::Switch:
      return option + " takes no value";
    default:
      return option +
        (this->kind == SettingKind::Count ? " needs a whole number from "
                                          : " needs a number from ") +
        this->format(this->minimum) + " to " + this->format(this->maximum) + ", not '" + text + "'";
  }
}

std::string wrapText(const std::string& text, std::size_t indent, std::size_t width)
{
  std::istringstream words(text);
  std::string out, line;
  for (std::string word; words >> word;)
  {
    if (!line.empty() && indent + line.size() + 1 + word.size() > width)
    {
      out += std::string(indent, ' ') + line + "\n";
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
  }
  if (!line.empty())
  {
    out += std::string(indent, ' ') + line + "\n";
  }
  return out;
}

} // namespace surfacemaps
