#include "EvaluateMeshPair.h"

#include "CommandSupport.h"
#include "Commands.h"
#include "EvaluationOutputs.h"

#include "vtkSurfaceMapEvaluation.h"

#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <cstdio>
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
      std::printf("  %-22s %s\n", name, jsonNumber(summaryValue(result, name)).c_str());
    }
  }
}

// Writes summary.json, the tables and evaluated.vtp into `outputDir`. Throws
// std::runtime_error naming a file that cannot be written.
void writeOutputs(const std::vector<std::string>& meshes,
  vtkPolyData* result,
  const std::string& outputDir)
{
  std::ostringstream json;
  json << "{\n  \"source\": " << jsonString(meshes[0])
       << ",\n  \"target\": " << jsonString(meshes[1]) << ",\n";
  json << "  \"triangles\": " << result->GetNumberOfCells() << ",\n"
       << summaryMembers(result, "  ") << "\n}\n";
  writeFileAtomically(outputDir + "/summary.json", json.str());
  writeEvaluationTables(result, outputDir + "/");
  writePolyDataAtomically(result, outputDir + "/evaluated.vtp");
}

// The evaluation's figures, printed; the exit code.
int evaluate(vtkSurfaceMapEvaluation* evaluation,
  const std::vector<std::string>& meshes,
  const std::vector<std::string>& originals,
  const std::string& outputDir)
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
  if (!succeeds([&] { writeOutputs(meshes, result, outputDir); }))
  {
    return ExitBadInput;
  }
  std::printf("  written to %s/summary.json, triangles.csv, distortion_curve.csv, evaluated.vtp\n",
    outputDir.c_str());
  return ExitOk;
}

} // namespace

int evaluateMeshPair(const std::vector<std::string>& meshes,
  const std::vector<std::string>& originals,
  const std::string& outputDir)
{
  // The output directory exists and takes files before anything is computed.
  std::string created;
  if (!outputDir.empty() && !prepareOutputDirectory(outputDir, "summary.json", created))
  {
    return ExitBadInput;
  }
  vtkNew<vtkSurfaceMapEvaluation> evaluation;
  const int result = evaluate(evaluation, meshes, originals, outputDir);
  if (result != ExitOk)
  {
    removeCreatedDirectory(created);
  }
  return result;
}

} // namespace surfacemap
