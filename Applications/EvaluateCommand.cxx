// surfacemap evaluate: distortion and approximation error of a map.
#include "CommandSupport.h"
#include "Commands.h"

#include "vtkSurfaceMapEvaluation.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include "vtk_jsoncpp.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <system_error>

namespace surfacemap
{

const char* const EvaluateHelp =
  "usage: surfacemap evaluate SOURCE TARGET [--originals A B] [--output-dir DIR]\n"
  "       surfacemap evaluate MAPDIR [--inputs A B ...] [--output-dir DIR]\n"
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
  "                    original's bounding-box diagonal) and a two-sided\n"
  "                    distance (points sampled in the triangles of both\n"
  "                    surfaces, the same unit)\n"
  "  --output-dir DIR  also write DIR/summary.json, DIR/triangles.csv (per\n"
  "                    triangle s1, s2, distortion, unit areas) and\n"
  "                    DIR/distortion_curve.csv (area fraction below each\n"
  "                    distortion, the cumulative curve) and DIR/evaluated.vtp\n"
  "                    (SOURCE with the per-triangle figures as cell data)\n"
  "\n"
  "The second form evaluates every map in MAPDIR, an output directory of\n"
  "'surfacemap map' (common_<i>.vtp, mapped_<i>.vtp, report.json), for each\n"
  "input j > 0 (j = 0 for a single input):\n"
  "  approximating map  common_0 -> common_j, H against inputs 0 and j\n"
  "  exact map          input 0 -> mapped_j (input 0 on input j), H against\n"
  "                     input j (and 0 against input 0 itself)\n"
  "  certificate        T's embeddings on the sphere (SpherePosition of\n"
  "                     common_0 and common_j), exact predicates and degree 1;\n"
  "                     the exact map is bijective through them\n"
  "The inputs are the files report.json names, or those given with\n"
  "  --inputs A B ...   one file per input, in the order of the map\n"
  "It writes, into --output-dir (default MAPDIR):\n"
  "  summary.json                        both maps' figures and the\n"
  "                                      certificate for every j\n"
  "  approximating_<j>_triangles.csv     per triangle figures, as above\n"
  "  approximating_<j>_distortion_curve.csv\n"
  "  approximating_<j>.vtp               common_j with the per-triangle\n"
  "                                      figures (cell data) and\n"
  "                                      SourcePosition: common_0's points,\n"
  "                                      centred, longest bounding-box side 2\n"
  "                                      (a checkerboard of it shows the map)\n"
  "  exact_<j>_triangles.csv, exact_<j>_distortion_curve.csv, exact_<j>.vtp\n"
  "                                      the same for input 0 -> mapped_j\n"
  "\n"
  "Exit code 0 on success, 2 for bad usage or input (also a directory that is\n"
  "not a map output), 3 when a map directory's certificate fails (its files\n"
  "are written all the same).\n";

namespace
{

// The evaluation's per-triangle arrays and their CSV columns.
const char* const TriangleArrays[] = { "SingularValueMax",
  "SingularValueMin",
  "Distortion",
  "AreaSource",
  "AreaTarget" };
const char* const TriangleColumns = "triangle,s1,s2,distortion,area_source,area_target\n";

// The summary figures present, as JSON object members, each on its own line.
std::string summaryMembers(vtkPolyData* result, const std::string& indent)
{
  std::ostringstream json;
  const char* separator = "";
  for (const char* name : evaluationSummaryNames())
  {
    if (result->GetFieldData()->GetArray(name))
    {
      json << separator << indent << jsonString(name) << ": "
           << jsonNumber(summaryValue(result, name));
      separator = ",\n";
    }
  }
  return json.str();
}

std::string trianglesCsv(vtkPolyData* result)
{
  std::ostringstream csv;
  csv << TriangleColumns;
  vtkCellData* cd = result->GetCellData();
  for (vtkIdType t = 0; t < result->GetNumberOfCells(); ++t)
  {
    csv << t;
    for (const char* name : TriangleArrays)
    {
      csv << "," << std::setprecision(10) << cd->GetArray(name)->GetTuple1(t);
    }
    csv << "\n";
  }
  return csv.str();
}

std::string curveCsv(vtkPolyData* result)
{
  std::ostringstream curve;
  curve << "distortion,area_fraction_below\n";
  vtkDataArray* samples = result->GetFieldData()->GetArray("DistortionCurve");
  for (vtkIdType k = 0; samples && k < samples->GetNumberOfTuples(); ++k)
  {
    curve << std::setprecision(10) << samples->GetComponent(k, 0) << ","
          << samples->GetComponent(k, 1) << "\n";
  }
  return curve.str();
}

// `target` with the evaluation's per-triangle figures and summary, and the
// point array SourcePosition: the source's points centred on its bounding box
// and scaled to a longest side of 2, so a checkerboard of them (drawn on the
// target) shows how the map carries a regular pattern across.
vtkSmartPointer<vtkPolyData> targetWithFigures(vtkPolyData* target,
  vtkPolyData* source,
  vtkPolyData* result)
{
  auto view = vtkSmartPointer<vtkPolyData>::New();
  view->ShallowCopy(target);
  for (const char* name : TriangleArrays)
  {
    view->GetCellData()->AddArray(result->GetCellData()->GetArray(name));
  }
  for (const char* name : evaluationSummaryNames())
  {
    if (vtkDataArray* a = result->GetFieldData()->GetArray(name))
    {
      view->GetFieldData()->AddArray(a);
    }
  }
  view->GetFieldData()->AddArray(result->GetFieldData()->GetArray("DistortionCurve"));

  double bounds[6];
  source->GetBounds(bounds);
  const double longest =
    std::max({ bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4] });
  const double scale = longest > 0.0 ? 2.0 / longest : 1.0;
  vtkNew<vtkDoubleArray> positions;
  positions->SetName("SourcePosition");
  positions->SetNumberOfComponents(3);
  positions->SetNumberOfTuples(source->GetNumberOfPoints());
  for (vtkIdType v = 0; v < source->GetNumberOfPoints(); ++v)
  {
    double p[3];
    source->GetPoint(v, p);
    for (int k = 0; k < 3; ++k)
    {
      p[k] = (p[k] - 0.5 * (bounds[2 * k] + bounds[2 * k + 1])) * scale;
    }
    positions->SetTuple(v, p);
  }
  view->GetPointData()->AddArray(positions);
  return view;
}

// Creates `directory` if needed and checks a file can be written there.
// Throws std::runtime_error naming it.
void prepareOutputDirectory(const std::string& directory)
{
  std::error_code ec;
  std::filesystem::create_directories(directory, ec);
  if (ec && !std::filesystem::is_directory(directory))
  {
    throw std::runtime_error(
      "cannot create the output directory '" + directory + "': " + ec.message());
  }
  checkWritable(directory + "/summary.json");
}

// The input files `report.json` names, in order. Throws std::runtime_error
// naming the file and what is wrong with it.
std::vector<std::string> reportedInputs(const std::string& report)
{
  std::ifstream in(report);
  if (!in)
  {
    throw std::runtime_error(
      report + " is missing: it names the map's inputs (or give them with --inputs A B ...)");
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
    throw std::runtime_error(report + " is not valid JSON: " + problems);
  }
  const Json::Value& inputs = root["inputs"];
  std::vector<std::string> files;
  for (Json::ArrayIndex i = 0; inputs.isArray() && i < inputs.size(); ++i)
  {
    if (!inputs[i]["file"].isString())
    {
      throw std::runtime_error(
        report + ": inputs[" + std::to_string(i) + "] has no \"file\" (give --inputs A B ...)");
    }
    files.push_back(inputs[i]["file"].asString());
  }
  if (files.empty())
  {
    throw std::runtime_error(report + " lists no inputs (give --inputs A B ...)");
  }
  return files;
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

bool isFile(const std::string& path)
{
  std::error_code ec;
  return std::filesystem::is_regular_file(path, ec);
}

// `surfacemap evaluate MAPDIR [--inputs ...] [--output-dir OUT]`.
int evaluateMapDirectory(const std::string& directory,
  std::vector<std::string> inputFiles,
  std::string outputDir)
{
  const auto file = [&](const char* stem, int i)
  { return directory + "/" + stem + "_" + std::to_string(i) + ".vtp"; };
  if (!isFile(file("common", 0)))
  {
    printError(directory + " has no common_0.vtp: not an output directory of 'surfacemap map'");
    return ExitBadInput;
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
      return ExitBadInput;
    }
  }
  try
  {
    if (inputFiles.empty())
    {
      inputFiles = reportedInputs(directory + "/report.json");
      if (static_cast<int>(inputFiles.size()) != n)
      {
        throw std::runtime_error(directory + "/report.json lists " +
          std::to_string(inputFiles.size()) + " inputs but the directory holds " +
          std::to_string(n) + " (common_0.vtp ... common_" + std::to_string(n - 1) + ".vtp)");
      }
    }
    else if (static_cast<int>(inputFiles.size()) != n)
    {
      throw UsageError{ "--inputs needs one file per input of the map (" + std::to_string(n) +
        " in " + directory + ", " + std::to_string(inputFiles.size()) + " given)" };
    }
    if (outputDir.empty())
    {
      outputDir = directory;
    }
    prepareOutputDirectory(outputDir);
  }
  catch (const std::runtime_error& e)
  {
    printError(e.what());
    return ExitBadInput;
  }

  std::vector<vtkSmartPointer<vtkPolyData>> inputs, common, mapped;
  for (int i = 0; i < n; ++i)
  {
    inputs.push_back(readMesh(inputFiles[i]));
    common.push_back(readMesh(file("common", i)));
    mapped.push_back(readMesh(file("mapped", i)));
    if (!inputs.back() || !common.back() || !mapped.back())
    {
      return ExitBadInput;
    }
  }
  for (int i = 0; i < n; ++i)
  {
    if (!common[i]->GetPointData()->GetArray("SpherePosition"))
    {
      printError(file("common", i) +
        " has no SpherePosition point array: the certificate cannot be checked");
      return ExitBadInput;
    }
  }

  std::printf("maps in %s: %d input%s, T has %lld vertices (%lld triangles)\n",
    directory.c_str(),
    n,
    n == 1 ? "" : "s",
    static_cast<long long>(common[0]->GetNumberOfPoints()),
    static_cast<long long>(common[0]->GetNumberOfPolys()));
  std::ostringstream json;
  json << "{\n  \"directory\": " << jsonString(directory) << ",\n  \"inputs\": [";
  for (int i = 0; i < n; ++i)
  {
    json << (i ? ", " : "") << jsonString(inputFiles[i]);
  }
  json << "],\n  \"common_triangulation\": { \"vertices\": " << common[0]->GetNumberOfPoints()
       << ", \"triangles\": " << common[0]->GetNumberOfPolys() << " },\n  \"maps\": [";
  bool allCertified = true;
  try
  {
    for (int j = n > 1 ? 1 : 0; j < n; ++j)
    {
      const std::string tag = std::to_string(j);
      vtkSmartPointer<vtkPolyData> approximating, exact;
      try
      {
        approximating = measureMap(common[0], common[j], inputs[0], inputs[j]);
        exact = measureMap(inputs[0], mapped[j], inputs[0], inputs[j]);
      }
      catch (const std::invalid_argument& e)
      {
        printError("map 0 -> " + tag + " in " + directory + ": " + e.what());
        return ExitBadInput;
      }
      const bool certified = summaryValue(approximating, "Bijective") == 1.0;
      allCertified = allCertified && certified;
      printMap("approximating map", j, approximating);
      printMap("exact map", j, exact);
      std::printf("  certificate 0 -> %d: %s\n",
        j,
        certified ? "bijective (T's embeddings, exact predicates)" : "FAILED");

      json << (j > 1 ? ",\n" : "\n") << "    {\n      \"source\": 0,\n      \"target\": " << j
           << ",\n      \"certificate\": { \"bijective\": " << (certified ? "true" : "false")
           << ", \"non_positive_triangles\": "
           << jsonNumber(summaryValue(approximating, "NonPositiveTriangles")) << " }";
      const std::pair<const char*, vtkPolyData*> maps[] = { { "approximating", approximating },
        { "exact", exact } };
      for (const auto& [kind, result] : maps)
      {
        const std::string stem = outputDir + "/" + kind + "_" + tag;
        vtkPolyData* source = std::string(kind) == "exact" ? inputs[0] : common[0];
        vtkPolyData* target = std::string(kind) == "exact" ? mapped[j] : common[j];
        writeFileAtomically(stem + "_triangles.csv", trianglesCsv(result));
        writeFileAtomically(stem + "_distortion_curve.csv", curveCsv(result));
        writePolyDataAtomically(targetWithFigures(target, source, result), stem + ".vtp");
        json << ",\n      \"" << kind
             << "_map\": {\n        \"triangles\": " << result->GetNumberOfCells() << ",\n"
             << summaryMembers(result, "        ") << "\n      }";
      }
      json << "\n    }";
    }
    json << "\n  ]\n}\n";
    writeFileAtomically(outputDir + "/summary.json", json.str());
  }
  catch (const std::runtime_error& e)
  {
    printError(e.what());
    return ExitBadInput;
  }
  std::printf("  written to %s: summary.json, approximating_<j>_*.csv, approximating_<j>.vtp, "
              "exact_<j>_*.csv, exact_<j>.vtp\n",
    outputDir.c_str());
  if (!allCertified)
  {
    printError("the map in " + directory + " is not certified bijective");
    return ExitNoCertifiedResult;
  }
  return ExitOk;
}

} // namespace

int runEvaluate(const std::vector<std::string>& args)
{
  std::vector<std::string> meshes, originals, inputs;
  std::string outputDir;
  bool inInputs = false;
  for (std::size_t i = 0; i < args.size(); ++i)
  {
    const std::string& a = args[i];
    if (!a.empty() && a[0] == '-')
    {
      inInputs = false;
    }
    if (a == "--originals")
    {
      if (i + 2 >= args.size())
      {
        throw UsageError{ "--originals needs two files" };
      }
      originals = { args[i + 1], args[i + 2] };
      i += 2;
    }
    else if (a == "--inputs")
    {
      inInputs = true;
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
      (inInputs ? inputs : meshes).push_back(a);
    }
  }
  std::error_code ec;
  if (meshes.size() == 1 && !std::filesystem::exists(meshes[0], ec))
  {
    printError("cannot open '" + meshes[0] + "': no such file or directory");
    return ExitBadInput;
  }
  if (meshes.size() == 1 && std::filesystem::is_directory(meshes[0], ec))
  {
    if (!originals.empty())
    {
      throw UsageError{ "--originals is for two meshes; a map directory takes --inputs A B ..." };
    }
    return evaluateMapDirectory(meshes[0], inputs, outputDir);
  }
  if (meshes.size() != 2)
  {
    throw UsageError{ "evaluate takes two meshes, SOURCE and TARGET, or a map output directory" };
  }
  if (!inputs.empty())
  {
    throw UsageError{ "--inputs is for a map directory; two meshes take --originals A B" };
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
  std::ostringstream json;
  json << "{\n  \"source\": " << jsonString(meshes[0])
       << ",\n  \"target\": " << jsonString(meshes[1]) << ",\n";
  json << "  \"triangles\": " << result->GetNumberOfCells() << ",\n"
       << summaryMembers(result, "  ") << "\n}\n";
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

  if (!outputDir.empty())
  {
    try
    {
      writeFileAtomically(outputDir + "/summary.json", json.str());
      writeFileAtomically(outputDir + "/triangles.csv", trianglesCsv(result));
      writeFileAtomically(outputDir + "/distortion_curve.csv", curveCsv(result));
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
