#include "vtkSurfaceMapsMarkups.h"

#include "base/Error.h"
#include "io/LandmarkReader.h"
#include "io/TextFile.h"

#include "vtk_jsoncpp.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <sstream>

namespace
{
// The 1-based line of byte `offset` of `text`.
int lineAt(const std::string& text, std::size_t offset)
{
  offset = std::min(offset, text.size());
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + offset, '\n'));
}

// `text` as a JSON document; a syntax error is reported at its line.
Json::Value parseJsonDocument(const std::string& text, const std::string& path)
{
  Json::CharReaderBuilder builder;
  builder["collectComments"] = false;
  const std::unique_ptr<Json::CharReader> reader(builder.newCharReader());
  Json::Value root;
  std::string problems;
  if (!reader->parse(text.data(), text.data() + text.size(), &root, &problems))
  {
    // jsoncpp: "* Line 3, Column 5\n  Syntax error: ..."
    int line = 0;
    const std::size_t at = problems.find("Line ");
    if (at != std::string::npos)
    {
      line = std::atoi(problems.c_str() + at + 5);
    }
    std::string what = problems.substr(std::min(problems.size(), problems.find('\n') + 1));
    what.erase(0, what.find_first_not_of(" \n"));
    what = what.substr(0, what.find('\n'));
    surfacemaps::failAtLine(path, std::max(line, 1), "not valid JSON: " + what);
  }
  return root;
}

// A parsed JSON file: reports a problem at the line of the value concerned.
struct JsonFile
{
  const std::string& Text;
  const std::string& Path;

  int lineOf(const Json::Value& value) const
  {
    const ptrdiff_t offset = std::max<ptrdiff_t>(0, value.getOffsetStart());
    return lineAt(this->Text, static_cast<std::size_t>(offset));
  }

  [[noreturn]] void fail(const Json::Value& where, const std::string& what) const
  {
    surfacemaps::failAtLine(this->Path, this->lineOf(where), what);
  }
};

// markups[0].controlPoints of a Slicer markups document.
const Json::Value& markupControlPoints(const Json::Value& root, const JsonFile& file)
{
  if (!root.isObject() || !root["markups"].isArray() || root["markups"].empty() ||
    !root["markups"][0].isObject())
  {
    file.fail(root, "not a Slicer markups file (no \"markups\" list)");
  }
  const Json::Value& markup = root["markups"][0];
  const Json::Value& points = markup["controlPoints"];
  if (!points.isArray())
  {
    file.fail(markup, "markups[0] has no \"controlPoints\" list");
  }
  return points;
}

// The position and label of one control point, which must have a position.
surfacemaps::LandmarkRecord controlPointRecord(const Json::Value& point,
  const std::string& which,
  const JsonFile& file)
{
  if (!point.isObject())
  {
    file.fail(point, which + " is not an object");
  }
  const Json::Value& status = point["positionStatus"];
  if (status.isString() && (status.asString() == "undefined" || status.asString() == "missing"))
  {
    file.fail(point, which + " has no position (positionStatus \"" + status.asString() + "\")");
  }
  const Json::Value& position = point["position"];
  if (!position.isArray() || position.size() != 3)
  {
    file.fail(point.isMember("position") ? position : point,
      which + " has no \"position\" of three numbers");
  }
  surfacemaps::LandmarkRecord record;
  record.Line = file.lineOf(point);
  for (Json::ArrayIndex c = 0; c < 3; ++c)
  {
    if (!position[c].isNumeric() || !std::isfinite(position[c].asDouble()))
    {
      file.fail(position[c], which + " has a position that is not three finite numbers");
    }
    record.Point[c] = position[c].asDouble();
  }
  if (point["label"].isString())
  {
    record.Label = point["label"].asString();
  }
  return record;
}

// Slicer's ids are strings ("1") or node names (markupLandmarkId), or
// numbers; `text` receives the id as the file gives it, for messages.
long long controlPointId(const Json::Value& point,
  const std::string& which,
  const JsonFile& file,
  std::string& text)
{
  const Json::Value& given = point["id"];
  std::ostringstream number;
  number.precision(17);
  if (given.isString())
  {
    text = given.asString();
  }
  else if (given.isInt64())
  {
    text = std::to_string(given.asInt64());
  }
  else if (given.isUInt64())
  {
    text = std::to_string(given.asUInt64());
  }
  else if (given.isNumeric())
  {
    number << given.asDouble();
    text = number.str();
  }
  else if (!given.isNull())
  {
    file.fail(given, which + " has an id that is neither a string nor a number");
  }
  return surfacemaps::markupLandmarkId(text, which, file.Path, file.lineOf(point));
}

// 3D Slicer's markups JSON (.mrk.json): markups[0].controlPoints[i] with
// "position" [x, y, z] and optional "id" and "label".
std::vector<surfacemaps::LandmarkRecord> parseMarkupsJsonValues(const std::string& text,
  const std::string& path)
{
  const Json::Value root = parseJsonDocument(text, path);
  const JsonFile file{ text, path };
  const Json::Value& points = markupControlPoints(root, file);
  std::vector<surfacemaps::LandmarkRecord> records;
  std::vector<long long> ids;
  std::vector<std::string> idTexts(points.size());
  for (Json::ArrayIndex k = 0; k < points.size(); ++k)
  {
    const Json::Value& point = points[k];
    const std::string which = "control point " + std::to_string(k);
    records.push_back(controlPointRecord(point, which, file));
    ids.push_back(controlPointId(point, which, file, idTexts[k]));
  }
  surfacemaps::finishLandmarkIds(records, ids, path, idTexts);
  return records;
}

} // namespace

std::vector<surfacemaps::LandmarkRecord> vtkSurfaceMapsMarkups::parse(const std::string& text,
  const std::string& path)
{
  try
  {
    return parseMarkupsJsonValues(text, path);
  }
  catch (const surfacemaps::InputError&)
  {
    throw;
  }
  catch (const std::exception& e)
  {
    // jsoncpp's own limits (nesting depth, number ranges) throw its exceptions.
    throw surfacemaps::InputError(path + ": not a usable markups file: " + e.what());
  }
}

