#include "EvaluateMeshPair.h"

#include "AlgorithmMessages.h"
#include "AtomicFiles.h"
#include "Commands.h"
#include "EvaluationOutputs.h"
#include "EvaluationPictures.h"
#include "EvaluationSummary.h"
#include "Json.h"
#include "MeshFiles.h"
#include "OutputDirectory.h"
#include "Terminal.h"

#include "vtkSurfaceMapEvaluation.h"

#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <sstream>

namespace surfacemap
{

namespace
{

// Reads the two meshes (and their originals) into the evaluation's ports;
// false after printing why.
bool readMeshes(vtkSurfaceMapEvaluation* evaluation,
  const std::vector<std::string>& meshes,
  const std::vector<std::string>& originals)
{
  for (int k = 0; k < 2; ++k)
  {
    vtkSmartPointer<vtkPolyData> mesh = readMesh(meshes[k]);
    if (!mesh)
    {
      return false;
    }
    const std::string degenerate = zeroAreaTriangles(mesh, meshes[k]);
    if (!degenerate.empty())
    {
      printError(degenerate);
      return false;
    }
    evaluation->SetInputDataObject(k, mesh);
    if (!originals.empty())
    {
      vtkSmartPointer<vtkPolyData> original = readMesh(originals[k]);
      if (!original)
      {
        return false;
      }
      evaluation->SetInputDataObject(2 + k, original);
    }
  }
  return true;
}

// A summary figure as printed: 10 significant digits, "null" if not finite.
std::string figureText(double value)
{
  if (!std::isfinite(value))
  {
    return "null";
  }
  std::ostringstream text;
  text << std::setprecision(10) << value;
  return text.str();
}

// Prints the map's size and every summary figure present.
void printSummary(const std::vector<std::string>& meshes, vtkPolyData* result)
{
  std::printf("map %s -> %s (%lld triangles)\n",
    meshes[0].c_str(),
    meshes[1].c_str(),
    static_cast<long long>(result->GetNumberOfCells()));
  for (const char* name : evaluationSummaryNames())
  {
    if (result->GetFieldData()->GetArray(name))
    {
      std::printf("  %-22s %s\n", name, figureText(summaryValue(result, name)).c_str());
    }
  }
}

// Writes the pictures of the map source -> target into `outputDir`.
void writePictures(const std::vector<std::string>& meshes,
  vtkSurfaceMapEvaluation* evaluation,
  const std::string& outputDir)
{
  const auto name = [](const std::string& path)
  { return std::filesystem::path(path).filename().string(); };
  vtkPolyData* result = evaluation->GetOutput();
  const MapSides sides{ vtkPolyData::SafeDownCast(evaluation->GetInputDataObject(0, 0)),
    vtkPolyData::SafeDownCast(evaluation->GetInputDataObject(1, 0)),
    "source: " + name(meshes[0]),
    "target: " + name(meshes[1]) };
  writeMapPictures(sides, result, outputDir + "/");
  writeDistortionCurvePicture({ { "map", result } }, outputDir + "/distortion_curve.png");
}

// Writes summary.json, the tables and evaluated.vtp into `outputDir`, with
// `pictures` also the pictures. Throws std::runtime_error naming a file that
// cannot be written.
void writeOutputs(const std::vector<std::string>& meshes,
  vtkSurfaceMapEvaluation* evaluation,
  const std::string& outputDir,
  bool pictures)
{
  vtkPolyData* result = evaluation->GetOutput();
  Json::Value summary = summaryJson(result);
  summary["source"] = meshes[0];
  summary["target"] = meshes[1];
  summary["triangles"] = static_cast<Json::Int64>(result->GetNumberOfCells());
  writeFileAtomically(outputDir + "/summary.json", jsonText(summary));
  writeEvaluationTables(result, outputDir + "/");
  writePolyDataAtomically(result, outputDir + "/evaluated.vtp");
  if (pictures)
  {
    writePictures(meshes, evaluation, outputDir);
  }
}

// The evaluation's figures, printed; the exit code.
int evaluate(vtkSurfaceMapEvaluation* evaluation,
  const std::vector<std::string>& meshes,
  const std::vector<std::string>& originals,
  const std::string& outputDir,
  bool pictures)
{
  if (!readMeshes(evaluation, meshes, originals))
  {
    return ExitBadInput;
  }
  ErrorCapture errors(evaluation);
  evaluation->Update();
  if (!errors.messages().empty())
  {
    printErrors(errors.messages());
    return ExitBadInput;
  }
  vtkPolyData* result = evaluation->GetOutput();
  printSummary(meshes, result);
  if (outputDir.empty())
  {
    return ExitOk;
  }
  if (!succeeds([&] { writeOutputs(meshes, evaluation, outputDir, pictures); }))
  {
    return ExitBadInput;
  }
  std::printf(
    "  written to %s/summary.json, triangles.csv, distortion_curve.csv, evaluated.vtp%s\n",
    outputDir.c_str(),
    pictures ? ", distortion.png, checkerboard.png, distortion_curve.png" : "");
  return ExitOk;
}

} // namespace

int evaluateMeshPair(const std::vector<std::string>& meshes,
  const std::vector<std::string>& originals,
  const std::string& outputDir,
  bool pictures)
{
  // The output directory exists and takes files before anything is computed.
  std::string created;
  if (!outputDir.empty() && !prepareOutputDirectory(outputDir, "summary.json", created))
  {
    return ExitBadInput;
  }
  vtkNew<vtkSurfaceMapEvaluation> evaluation;
  const int result = evaluate(evaluation, meshes, originals, outputDir, pictures);
  if (result != ExitOk)
  {
    removeCreatedDirectory(created);
  }
  return result;
}

} // namespace surfacemap
