// The `surfacemap` command line: JSON numbers, text and files through
// jsoncpp.
#include "Json.h"

#include <cmath>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace surfacemap
{

Json::Value jsonNumber(double value)
{
  if (!std::isfinite(value))
  {
    return Json::Value(Json::nullValue);
  }
  // Below 2^53 every integer is a double and the conversion is exact.
  constexpr double ExactIntegers = 9007199254740992.0;
  if (std::trunc(value) == value && std::abs(value) < ExactIntegers)
  {
    return Json::Value(static_cast<Json::Int64>(value));
  }
  return Json::Value(value);
}

std::string jsonText(const Json::Value& document)
{
  Json::StreamWriterBuilder builder;
  builder["indentation"] = "  ";
  builder["precision"] = 17;
  builder["precisionType"] = "significant";
  builder["emitUTF8"] = true;
  const std::unique_ptr<Json::StreamWriter> writer(builder.newStreamWriter());
  std::ostringstream text;
  writer->write(document, &text);
  text << "\n";
  return text.str();
}

Json::Value readJsonFile(const std::string& path, const std::string& needed)
{
  std::ifstream in(path);
  if (!in)
  {
    throw std::runtime_error(path + " is missing: " + needed);
  }
  Json::CharReaderBuilder builder;
  Json::Value root;
  std::string problems;
  if (!Json::parseFromStream(builder, in, &root, &problems))
  {
    while (!problems.empty() && (problems.back() == '\n' || problems.back() == ' '))
    {
      problems.pop_back();
    }
    throw std::runtime_error(path + " is not valid JSON: " + problems);
  }
  return root;
}

} // namespace surfacemap
