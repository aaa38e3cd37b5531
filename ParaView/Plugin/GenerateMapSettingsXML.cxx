// Build-time generator of the map filter's server-manager XML: the surface
// map's settings become ParaView properties straight from the engine's
// settings table (Core/map/MapSettings.cxx), their one home, so a setting
// added there appears in ParaView with its range, default and documentation
// without touching the plugin.
//
// Usage: GenerateMapSettingsXML TEMPLATE OUTPUT
// Copies TEMPLATE to OUTPUT with the line holding @MAP_SETTINGS@ replaced by
// one property per setting. Exit code 1 (and a message) if the template has no
// such line or a file cannot be read or written.
#include "map/MapSettings.h"

#include <cstdio>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <string>

namespace
{

std::string escaped(const std::string& text)
{
  std::string out;
  for (char c : text)
  {
    switch (c)
    {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

// Full precision, so the property's default is the table's exactly.
std::string number(double value)
{
  char text[64];
  std::snprintf(text, sizeof(text), "%.17g", value);
  return text;
}

// The settings shown without the panel's "advanced" toggle: the ones a
// first map is tuned with (iteration caps, the error, the pairs).
bool basic(const std::string& name)
{
  static const std::set<std::string> names = { "PairMode", "LandmarkIterations",
    "CoarseIterations", "FineIterations", "TargetError", "RefinementRounds", "MaxError" };
  return names.count(name) > 0;
}

void writeProperty(std::ostream& out, const surfacemaps::MapSetting& s)
{
  using surfacemaps::SettingKind;
  const bool real = s.kind == SettingKind::Real;
  const char* element = real ? "DoubleVectorProperty" : "IntVectorProperty";
  const std::string name = s.name;
  out << "      <" << element << " name=\"" << name << "\" command=\"Set" << name
      << "\" number_of_elements=\"1\" default_values=\"" << number(s.defaultValue()) << "\"";
  if (!basic(name))
  {
    out << " panel_visibility=\"advanced\"";
  }
  out << ">\n";
  switch (s.kind)
  {
    case SettingKind::Real:
      out << "        <DoubleRangeDomain name=\"range\" min=\"" << number(s.minimum) << "\" max=\""
          << number(s.maximum) << "\"/>\n";
      break;
    case SettingKind::Count:
      out << "        <IntRangeDomain name=\"range\" min=\"" << number(s.minimum) << "\" max=\""
          << number(s.maximum) << "\"/>\n";
      break;
    case SettingKind::Switch:
      out << "        <BooleanDomain name=\"bool\"/>\n";
      break;
    case SettingKind::Choice:
    {
      out << "        <EnumerationDomain name=\"enum\">\n";
      const auto names = s.choiceNames();
      for (std::size_t c = 0; c < names.size(); ++c)
      {
        out << "          <Entry value=\"" << c << "\" text=\"" << escaped(names[c]) << "\"/>\n";
      }
      out << "        </EnumerationDomain>\n";
      break;
    }
  }
  std::string range;
  if (s.kind == SettingKind::Real || s.kind == SettingKind::Count)
  {
    range = " Range " + s.format(s.minimum) + " to " + s.format(s.maximum) + ".";
  }
  out << "        <Documentation>" << escaped(s.doc) << escaped(range)
      << " Default: " << escaped(s.format(s.defaultValue())) << ". (Command line: --"
      << escaped(s.flag) << ".)</Documentation>\n";
  out << "      </" << element << ">\n";
}

} // namespace

int main(int argc, char* argv[])
{
  if (argc != 3)
  {
    std::cerr << "usage: " << argv[0] << " TEMPLATE OUTPUT\n";
    return 1;
  }
  std::ifstream in(argv[1]);
  if (!in)
  {
    std::cerr << argv[0] << ": cannot read " << argv[1] << "\n";
    return 1;
  }
  std::ostringstream out;
  bool replaced = false;
  for (std::string line; std::getline(in, line);)
  {
    if (line.find("@MAP_SETTINGS@") == std::string::npos)
    {
      out << line << "\n";
      continue;
    }
    for (const surfacemaps::MapSetting& s : surfacemaps::mapSettings())
    {
      writeProperty(out, s);
    }
    replaced = true;
  }
  if (!replaced)
  {
    std::cerr << argv[0] << ": " << argv[1] << " has no @MAP_SETTINGS@ line\n";
    return 1;
  }
  std::ofstream file(argv[2]);
  file << out.str();
  file.close();
  if (!file)
  {
    std::cerr << argv[0] << ": cannot write " << argv[2] << "\n";
    return 1;
  }
  return 0;
}
