// surfacemap evaluate: distortion and approximation error of a map.
#include "CommandSupport.h"
#include "Commands.h"

#include "vtkSurfaceMapEvaluation.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPolyData.h"

#include <cmath>
#include <cstdio>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace surfacemap
{

const char* const EvaluateHelp =
  "usage: surfacemap evaluate SOURCE TARGET [--originals A B] [--output-dir DIR]\n"
  "\n"
  "Measures the map between two meshes of identical connectivity (for example\n"
  "the common triangulation lifted onto two inputs, or input A and input A\n"
  "mapped onto B), both centred and scaled to unit area: symmetric Dirichlet\n"
  "energy (1 for an isometry), area fractions with distortion max(s1, 1/s2)\n"
  "below 1.5 and 2, the largest distortion, minimum and mean minimum angles,\n"
  "and, when both carry SpherePosition, the exact bijectivity certificate.\n"
  "\n"
  "  --originals A B   the surfaces SOURCE and TARGET approximate: adds the\n"
  "                    Hausdorff figure H per side (largest distance of an\n"
  "                    original vertex to the approximation, in % of the\n"
  "                    original's bounding-box diagonal)\n"
  "  --output-dir DIR  also write DIR/summary.json, DIR/triangles.csv (per\n"
  "                    triangle s1, s2, distortion, unit areas) and\n"
  "                    DIR/distortion_curve.csv (area fraction below each\n"
  "                    distortion, the cumulative curve) and DIR/evaluated.vtp\n"
  "                    (SOURCE with the per-triangle figures as cell data)\n"
  "\n"
  "Exit code 0 on success, 2 for bad usage or input.\n";

namespace
{
std::string number(double value)
{
  if (!std::isfinite(value))
  {
    return "null"; // JSON has no infinity
  }
  std::ostringstream s;
  s << std::setprecision(10) << value;
  return s.str();
}
} // namespace

int runEvaluate(const std::vector<std::string>& args)
{
  std::vector<std::string> meshes, originals;
  std::string outputDir;
  for (std::size_t i = 0; i < args.size(); ++i)
  {
    const std::string& a = args[i];
    if (a == "--originals")
    {
      if (i + 2 >= args.size())
      {
        throw UsageError{ "--originals needs two files" };
      }
      originals = { args[i + 1], args[i + 2] };
      i += 2;
    }
    else if (a == "--output-dir")
    {
      if (i + 1 >= args.size())
      {
        throw UsageError{ "--output-dir needs a directory" };
      }
      outputDir = args[++i];
    }
    else if (!a.empty() && a[0] == '-')
    {
      throw UsageError{ "unknown option '" + a + "'" };
    }
    else
    {
      meshes.push_back(a);
    }
  }
  if (meshes.size() != 2)
  {
    throw UsageError{ "evaluate takes two meshes, SOURCE and TARGET" };
  }

  vtkNew<vtkSurfaceMapEvaluation> evaluation;
  for (int k = 0; k < 2; ++k)
  {
    vtkSmartPointer<vtkPolyData> mesh = readMesh(meshes[k]);
    if (!mesh)
    {
      return ExitBadInput;
    }
    evaluation->SetInputDataObject(k, mesh);
    if (!originals.empty())
    {
      vtkSmartPointer<vtkPolyData> original = readMesh(originals[k]);
      if (!original)
      {
        return ExitBadInput;
      }
      evaluation->SetInputDataObject(2 + k, original);
    }
  }
  ErrorCapture errors(evaluation);
  evaluation->Update();
  if (!errors.messages().empty())
  {
    for (const std::string& m : errors.messages())
    {
      printError(m);
    }
    return ExitBadInput;
  }

  vtkPolyData* result = evaluation->GetOutput();
  vtkFieldData* fields = result->GetFieldData();
  std::ostringstream json;
  json << "{\n  \"source\": \"" << meshes[0] << "\",\n  \"target\": \"" << meshes[1] << "\",\n";
  json << "  \"triangles\": " << result->GetNumberOfCells();
  std::printf("map %s -> %s (%lld triangles)\n",
    meshes[0].c_str(),
    meshes[1].c_str(),
    static_cast<long long>(result->GetNumberOfCells()));
  // The evaluation's own figures (the source's field data rides along too).
  const char* summary[] = { "SymmetricDirichlet",
    "AreaBelow1.5",
    "AreaBelow2",
    "MaxDistortion",
    "DegenerateTriangles",
    "MinAngleSource",
    "MeanMinAngleSource",
    "MinAngleTarget",
    "MeanMinAngleTarget",
    "HausdorffSource",
    "HausdorffTarget",
    "TwoSidedDistanceSource",
    "TwoSidedDistanceTarget",
    "Bijective",
    "NonPositiveTriangles" };
  for (const char* name : summary)
  {
    vtkDataArray* a = fields->GetArray(name);
    if (!a)
    {
      continue; // figures that need inputs not given
    }
    std::printf("  %-22s %s\n", name, number(a->GetTuple1(0)).c_str());
    json << ",\n  \"" << name << "\": " << number(a->GetTuple1(0));
  }
  json << "\n}\n";

  if (!outputDir.empty())
  {
    try
    {
      writeFileAtomically(outputDir + "/summary.json", json.str());
      std::ostringstream csv;
      csv << "triangle,s1,s2,distortion,area_source,area_target\n";
      vtkCellData* cd = result->GetCellData();
      const char* names[] = {
        "SingularValueMax", "SingularValueMin", "Distortion", "AreaSource", "AreaTarget"
      };
      for (vtkIdType t = 0; t < result->GetNumberOfCells(); ++t)
      {
        csv << t;
        for (const char* name : names)
        {
          csv << "," << std::setprecision(10) << cd->GetArray(name)->GetTuple1(t);
        }
        csv << "\n";
      }
      writeFileAtomically(outputDir + "/triangles.csv", csv.str());
      std::ostringstream curve;
      curve << "distortion,area_fraction_below\n";
      vtkDataArray* samples = fields->GetArray("DistortionCurve");
      for (vtkIdType k = 0; samples && k < samples->GetNumberOfTuples(); ++k)
      {
        curve << std::setprecision(10) << samples->GetComponent(k, 0) << ","
              << samples->GetComponent(k, 1) << "\n";
      }
      writeFileAtomically(outputDir + "/distortion_curve.csv", curve.str());
      writePolyDataAtomically(result, outputDir + "/evaluated.vtp");
    }
    catch (const std::runtime_error& e)
    {
      printError(e.what());
      return ExitBadInput;
    }
    std::printf(
      "  written to %s/summary.json, triangles.csv, distortion_curve.csv, evaluated.vtp\n",
      outputDir.c_str());
  }
  return ExitOk;
}

} // namespace surfacemap
