#include "EvaluateMapDirectory.h"

#include "AtomicFiles.h"
#include "Commands.h"
#include "EvaluationOutputs.h"
#include "EvaluationPictures.h"
#include "EvaluationSummary.h"
#include "Json.h"
#include "MapDirectory.h"
#include "MeshFiles.h"
#include "OutputDirectory.h"
#include "Terminal.h"

#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

namespace surfacemap
{

namespace
{

std::string mapFile(const std::string& directory, const char* stem, int i)
{
  return directory + "/" + mapFileName(stem, i);
}

// The meshes of a map directory: input i, T lifted onto input i (common_i)
// and input 0 mapped onto input i (mapped_i).
struct MapMeshes
{
  std::string directory;
  std::vector<std::string> inputFiles;
  std::vector<vtkSmartPointer<vtkPolyData>> inputs, common, mapped;

  int size() const { return static_cast<int>(this->inputFiles.size()); }
  std::string file(const char* stem, int i) const { return mapFile(this->directory, stem, i); }
};

// The number of inputs of the map in `directory`: as its report.json says
// (so that verifyMapFiles names a missing file), else as many as it holds
// common_<i>.vtp, each with its mapped_<i>.vtp; 0 after printing why it is
// no map directory.
int countInputs(const std::string& directory)
{
  if (isFile(directory + "/report.json"))
  {
    int n = 0;
    return succeeds([&] { n = mapInputCount(directory); }) ? n : 0;
  }
  const auto file = [&directory](const char* stem, int i) { return mapFile(directory, stem, i); };
  if (!isFile(file("common", 0)))
  {
    printError(directory + " has no common_0.vtp: not an output directory of 'surfacemap map'");
    return 0;
  }
  int n = 0;
  while (isFile(file("common", n)))
  {
    ++n;
  }
  for (int i = 0; i < n; ++i)
  {
    if (!isFile(file("mapped", i)))
    {
      printError(directory + " has common_" + std::to_string(i) + ".vtp but no mapped_" +
        std::to_string(i) + ".vtp (the exact map)");
      return 0;
    }
  }
  return n;
}

// The map's n input files: those given, or those report.json names. Throws
// std::runtime_error for a report that is missing, invalid or of another
// count, UsageError for --inputs of another count.
void resolveInputs(const std::string& directory, int n, std::vector<std::string>& inputFiles)
{
  if (inputFiles.empty())
  {
    inputFiles = mapReportInputs(directory + "/report.json");
    if (static_cast<int>(inputFiles.size()) != n)
    {
      throw std::runtime_error(directory + "/report.json lists " +
        std::to_string(inputFiles.size()) + " inputs but the directory holds " + std::to_string(n) +
        " (common_0.vtp ... common_" + std::to_string(n - 1) + ".vtp)");
    }
  }
  else if (static_cast<int>(inputFiles.size()) != n)
  {
    throw UsageError{ "--inputs needs one file per input of the map (" + std::to_string(n) +
      " in " + directory + ", " + std::to_string(inputFiles.size()) + " given)" };
  }
}

// Reads every input, common_<i> and mapped_<i>; false after printing why
// (also when common_<i> has no SpherePosition, which the certificate needs).
bool readMeshes(MapMeshes& maps)
{
  for (int i = 0; i < maps.size(); ++i)
  {
    maps.inputs.push_back(readMesh(maps.inputFiles[i]));
    maps.common.push_back(readMesh(maps.file("common", i)));
    maps.mapped.push_back(readMesh(maps.file("mapped", i)));
    if (!maps.inputs.back() || !maps.common.back() || !maps.mapped.back())
    {
      return false;
    }
  }
  const std::string degenerate = zeroAreaTriangles(maps.inputs[0], maps.inputFiles[0]);
  if (!degenerate.empty())
  {
    printError(degenerate); // the exact maps are measured on input 0's triangles
    return false;
  }
  for (int i = 0; i < maps.size(); ++i)
  {
    if (!maps.common[i]->GetPointData()->GetArray("SpherePosition"))
    {
      printError(maps.file("common", i) +
        " has no SpherePosition point array: the certificate cannot be checked");
      return false;
    }
  }
  return true;
}

// Prints the directory's line; returns the summary without its maps.
Json::Value reportDirectory(const MapMeshes& maps)
{
  const int n = maps.size();
  vtkPolyData* common = maps.common[0];
  std::printf("maps in %s: %d input%s, T has %lld vertices (%lld triangles)\n",
    maps.directory.c_str(),
    n,
    n == 1 ? "" : "s",
    static_cast<long long>(common->GetNumberOfPoints()),
    static_cast<long long>(common->GetNumberOfPolys()));
  Json::Value summary(Json::objectValue);
  summary["directory"] = maps.directory;
  summary["inputs"] = Json::Value(Json::arrayValue);
  for (const std::string& input : maps.inputFiles)
  {
    summary["inputs"].append(input);
  }
  summary["common_triangulation"]["vertices"] =
    static_cast<Json::Int64>(common->GetNumberOfPoints());
  summary["common_triangulation"]["triangles"] =
    static_cast<Json::Int64>(common->GetNumberOfPolys());
  summary["maps"] = Json::Value(Json::arrayValue);
  return summary;
}

// One line per measured map, like `surfacemap map` prints.
void printMap(const char* what, int target, vtkPolyData* result)
{
  std::printf("  %-17s 0 -> %d: SD %.4f, a1.5 %.3f, a2 %.3f, max %.3g, H %.3f%% / %.3f%%, "
              "two-sided %.3f%% / %.3f%%, min angle %.1f (mean %.1f)\n",
    what,
    target,
    summaryValue(result, "SymmetricDirichlet"),
    summaryValue(result, "AreaBelow1.5"),
    summaryValue(result, "AreaBelow2"),
    summaryValue(result, "MaxDistortion"),
    summaryValue(result, "HausdorffSource"),
    summaryValue(result, "HausdorffTarget"),
    summaryValue(result, "TwoSidedDistanceSource"),
    summaryValue(result, "TwoSidedDistanceTarget"),
    summaryValue(result, "MinAngleTarget"),
    summaryValue(result, "MeanMinAngleTarget"));
}

// Maps 0 -> j measured: the approximating map (common_0 -> common_j, whose
// evaluation holds the certificate) and the exact map (input 0 -> mapped_j).
struct MeasuredMaps
{
  vtkSmartPointer<vtkPolyData> approximating, exact;
};

// Measures maps 0 -> j. Throws std::runtime_error naming them when they
// cannot be measured (inputs of another connectivity).
MeasuredMaps measureMaps(const MapMeshes& maps, int j)
{
  try
  {
    return { measureMap(maps.common[0], maps.common[j], maps.inputs[0], maps.inputs[j]),
      measureMap(maps.inputs[0], maps.mapped[j], maps.inputs[0], maps.inputs[j]) };
  }
  catch (const std::invalid_argument& e)
  {
    throw std::runtime_error(
      "map 0 -> " + std::to_string(j) + " in " + maps.directory + ": " + e.what());
  }
}

// Prints maps 0 -> j and their certificate; returns whether it holds.
bool reportMaps(int j, const MeasuredMaps& measured)
{
  const bool certified = summaryValue(measured.approximating, "Bijective") == 1.0;
  printMap("approximating map", j, measured.approximating);
  printMap("exact map", j, measured.exact);
  std::printf("  certificate 0 -> %d: %s\n",
    j,
    certified ? "bijective (T's embeddings, exact predicates)" : "FAILED");
  return certified;
}

// Writes the pictures of maps 0 -> j: <kind>_<j>_distortion.png and
// <kind>_<j>_checkerboard.png per map, distortion_curves_<j>.png of both.
void writePictures(const MapMeshes& maps,
  int j,
  const MeasuredMaps& measured,
  const std::string& outputDir)
{
  const std::string jj = std::to_string(j);
  const std::string input0 = std::filesystem::path(maps.inputFiles[0]).filename().string();
  writeMapPictures({ maps.common[0], maps.common[j], "common_0.vtp", "common_" + jj + ".vtp" },
    measured.approximating,
    outputDir + "/approximating_" + jj + "_");
  writeMapPictures(
    { maps.inputs[0], maps.mapped[j], "input 0: " + input0, "mapped_" + jj + ".vtp" },
    measured.exact,
    outputDir + "/exact_" + jj + "_");
  writeDistortionCurvePicture(
    { { "approximating map", measured.approximating }, { "exact map", measured.exact } },
    outputDir + "/distortion_curves_" + jj + ".png");
}

// Writes each map 0 -> j's tables and view as <outputDir>/<kind>_<j>*, with
// `pictures` also their pictures; returns the summary's entry for j. Throws
// std::runtime_error naming a file that cannot be written.
Json::Value writeMaps(const MapMeshes& maps,
  int j,
  const MeasuredMaps& measured,
  bool certified,
  const std::string& outputDir,
  bool pictures)
{
  Json::Value entry(Json::objectValue);
  entry["source"] = 0;
  entry["target"] = j;
  entry["certificate"]["bijective"] = certified;
  entry["certificate"]["non_positive_triangles"] =
    jsonNumber(summaryValue(measured.approximating, "NonPositiveTriangles"));
  struct Output
  {
    const char* kind;
    vtkPolyData* result;
    vtkPolyData* source;
    vtkPolyData* target;
  };
  const Output outputs[] = {
    { "approximating", measured.approximating, maps.common[0], maps.common[j] },
    { "exact", measured.exact, maps.inputs[0], maps.mapped[j] }
  };
  for (const Output& map : outputs)
  {
    const std::string stem = outputDir + "/" + map.kind + "_" + std::to_string(j);
    writeEvaluationTables(map.result, stem + "_");
    writePolyDataAtomically(targetWithFigures(map.target, map.source, map.result), stem + ".vtp");
    Json::Value& figures = entry[std::string(map.kind) + "_map"];
    figures = summaryJson(map.result);
    figures["triangles"] = static_cast<Json::Int64>(map.result->GetNumberOfCells());
  }
  if (pictures)
  {
    writePictures(maps, j, measured, outputDir);
  }
  return entry;
}

// Measures, prints and writes every map 0 -> j, then summary.json; returns
// whether every certificate holds. Throws std::runtime_error for maps that
// cannot be measured or a file that cannot be written.
bool evaluateMaps(const MapMeshes& maps,
  const std::string& outputDir,
  Json::Value summary,
  bool pictures)
{
  bool allCertified = true;
  for (int j = maps.size() > 1 ? 1 : 0; j < maps.size(); ++j)
  {
    const MeasuredMaps measured = measureMaps(maps, j);
    const bool certified = reportMaps(j, measured);
    allCertified = allCertified && certified;
    summary["maps"].append(writeMaps(maps, j, measured, certified, outputDir, pictures));
  }
  writeFileAtomically(outputDir + "/summary.json", jsonText(summary));
  return allCertified;
}

} // namespace

int evaluateMapDirectory(const std::string& directory,
  std::vector<std::string> inputFiles,
  std::string outputDir,
  bool pictures)
{
  const int n = countInputs(directory);
  if (outputDir.empty())
  {
    outputDir = directory;
  }
  std::vector<std::string> mapFiles;
  for (int i = 0; i < n; ++i)
  {
    mapFiles.push_back(mapFileName("common", i));
    mapFiles.push_back(mapFileName("mapped", i));
  }
  std::string created;
  if (n == 0 || !succeeds([&] { verifyMapFiles(directory, mapFiles); }) ||
    !succeeds([&] { resolveInputs(directory, n, inputFiles); }) ||
    !prepareOutputDirectory(outputDir, "summary.json", created))
  {
    return ExitBadInput;
  }
  MapMeshes maps{ directory, inputFiles, {}, {}, {} };
  if (!readMeshes(maps))
  {
    removeCreatedDirectory(created); // nothing written into it
    return ExitBadInput;
  }
  const Json::Value summary = reportDirectory(maps);
  bool certified = false;
  if (!succeeds([&] { certified = evaluateMaps(maps, outputDir, summary, pictures); }))
  {
    return ExitBadInput;
  }
  std::printf("  written to %s: summary.json, approximating_<j>_*.csv, approximating_<j>.vtp, "
              "exact_<j>_*.csv, exact_<j>.vtp%s\n",
    outputDir.c_str(),
    pictures ? ", <kind>_<j>_distortion.png, <kind>_<j>_checkerboard.png (kind approximating, "
               "exact), distortion_curves_<j>.png"
             : "");
  if (!certified)
  {
    printError("the map in " + directory + " is not certified bijective");
    return ExitNoCertifiedResult;
  }
  return ExitOk;
}

} // namespace surfacemap
