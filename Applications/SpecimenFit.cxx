#include "SpecimenFit.h"

#include "NumpyArchive.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkIdList.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>

namespace surfacemap
{

namespace
{

// Landmark id -> vertex of `mesh` ("Landmarks" >= 0); empty without the array.
std::map<long long, vtkIdType> landmarkVertices(vtkPolyData* mesh)
{
  std::map<long long, vtkIdType> vertices;
  vtkDataArray* ids = mesh->GetPointData()->GetArray("Landmarks");
  for (vtkIdType v = 0; ids && v < ids->GetNumberOfTuples(); ++v)
  {
    const auto id = static_cast<long long>(ids->GetTuple1(v));
    if (id >= 0)
    {
      vertices.emplace(id, v);
    }
  }
  return vertices;
}

// The figure `key` of the report's `section` entry whose target is `target`;
// null when there is none.
Json::Value pairFigure(const Json::Value& report, const char* section, int target, const char* key)
{
  for (const Json::Value& pair : report[section])
  {
    if (pair["target"].asInt() == target && pair.isMember(key))
    {
      return pair[key];
    }
  }
  return Json::Value();
}

// A CSV field: quoted when it holds a comma, quote or line break.
std::string csvField(const std::string& text)
{
  if (text.find_first_of(",\"\n\r") == std::string::npos)
  {
    return text;
  }
  std::string quoted = "\"";
  for (const char c : text)
  {
    quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  }
  return quoted + "\"";
}

const char* const FitColumns[] = { "input", "name", "file", "hausdorff", "two_sided_distance",
  "approximating_sd", "exact_sd", "exact_max_distortion", "exact_area_below_1.5",
  "landmark_error" };

} // namespace

std::vector<std::string> specimenNames(const std::vector<std::string>& files)
{
  std::vector<std::string> stems;
  std::map<std::string, int> uses;
  for (const std::string& file : files)
  {
    stems.push_back(std::filesystem::path(file).stem().string());
    ++uses[stems.back()];
  }
  for (std::size_t i = 0; i < stems.size(); ++i)
  {
    if (uses[stems[i]] > 1)
    {
      stems[i] += "_" + std::to_string(i);
    }
  }
  return stems;
}

std::string correspondencesArchive(
  const std::vector<std::string>& names, const std::vector<vtkPolyData*>& common)
{
  const std::size_t n = common.size();
  const auto vertices = static_cast<std::size_t>(common[0]->GetNumberOfPoints());
  std::vector<double> points;
  points.reserve(n * vertices * 3);
  for (vtkPolyData* mesh : common)
  {
    for (vtkIdType v = 0; v < mesh->GetNumberOfPoints(); ++v)
    {
      double x[3];
      mesh->GetPoint(v, x);
      points.insert(points.end(), x, x + 3);
    }
  }
  std::vector<std::int64_t> triangles;
  vtkNew<vtkIdList> corners;
  for (vtkIdType t = 0; t < common[0]->GetNumberOfPolys(); ++t)
  {
    common[0]->GetPolys()->GetCellAtId(t, corners);
    for (vtkIdType c = 0; c < 3; ++c)
    {
      triangles.push_back(corners->GetId(c));
    }
  }
  NumpyArchive archive;
  archive.addDoubles("points", { n, vertices, 3 }, points);
  archive.addIntegers("triangles", { triangles.size() / 3, 3 }, triangles);
  archive.addStrings("names", names);
  return archive.bytes();
}

std::vector<double> landmarkErrors(const std::vector<vtkSmartPointer<vtkPolyData>>& inputs,
  const std::vector<vtkPolyData*>& common)
{
  std::vector<double> errors;
  for (std::size_t i = 0; i < inputs.size(); ++i)
  {
    const auto onInput = landmarkVertices(inputs[i]);
    const auto onT = landmarkVertices(common[i]);
    double largest = std::nan("");
    for (const auto& [id, v] : onInput)
    {
      const auto found = onT.find(id);
      if (found == onT.end())
      {
        continue;
      }
      double a[3], b[3];
      inputs[i]->GetPoint(v, a);
      common[i]->GetPoint(found->second, b);
      const double d = std::sqrt(vtkMath::Distance2BetweenPoints(a, b));
      largest = std::isnan(largest) ? d : std::max(largest, d);
    }
    errors.push_back(100.0 * largest / inputs[i]->GetLength());
  }
  return errors;
}

Json::Value specimenFit(const Json::Value& report,
  const std::vector<std::string>& names,
  const std::vector<double>& landmarkErrors)
{
  Json::Value rows(Json::arrayValue);
  const int n = static_cast<int>(names.size());
  for (int i = 0; i < n; ++i)
  {
    Json::Value row(Json::objectValue);
    row["input"] = i;
    row["name"] = names[i];
    row["file"] = report["inputs"][i]["file"];
    // Input 0's own distances are measured with its first pair (as the source).
    const bool source = i == 0 && n > 1;
    const int pair = source ? 1 : i;
    row["hausdorff"] =
      pairFigure(report, "approximating_map", pair, source ? "HausdorffSource" : "HausdorffTarget");
    row["two_sided_distance"] = pairFigure(
      report, "approximating_map", pair, source ? "TwoSidedDistanceSource" : "TwoSidedDistanceTarget");
    const bool mapped = i > 0; // input 0 is every pair's source
    row["approximating_sd"] =
      mapped ? pairFigure(report, "approximating_map", i, "SymmetricDirichlet") : Json::Value();
    row["exact_sd"] = mapped ? pairFigure(report, "exact_map", i, "SymmetricDirichlet") : Json::Value();
    row["exact_max_distortion"] =
      mapped ? pairFigure(report, "exact_map", i, "MaxDistortion") : Json::Value();
    row["exact_area_below_1.5"] =
      mapped ? pairFigure(report, "exact_map", i, "AreaBelow1.5") : Json::Value();
    row["landmark_error"] = jsonNumber(landmarkErrors[i]);
    rows.append(row);
  }
  return rows;
}

std::string specimenFitCsv(const Json::Value& rows)
{
  std::string text;
  for (const char* column : FitColumns)
  {
    text += (text.empty() ? "" : ",") + std::string(column);
  }
  text += "\n";
  for (const Json::Value& row : rows)
  {
    std::string line;
    for (const char* column : FitColumns)
    {
      const Json::Value& value = row[column];
      std::string field;
      if (value.isString())
      {
        field = csvField(value.asString());
      }
      else if (value.isIntegral())
      {
        field = std::to_string(value.asInt64());
      }
      else if (value.isDouble())
      {
        char number[32];
        std::snprintf(number, sizeof number, "%.9g", value.asDouble());
        field = number;
      }
      line += (column == FitColumns[0] ? "" : ",") + field;
    }
    text += line + "\n";
  }
  return text;
}

} // namespace surfacemap
