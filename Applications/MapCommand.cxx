// surfacemap map: bijective map between N surfaces via a common triangulation.
#include "ArrayTransferFlags.h"
#include "CommandSupport.h"
#include "Commands.h"
#include "MapDirectory.h"
#include "SettingFlags.h"

#include "vtkSurfaceMapEvaluation.h"
#include "vtkSurfaceMapFilter.h"

#include "vtkAbstractArray.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <stdexcept>
#include <system_error>

namespace surfacemap
{

namespace
{
const char* const MapHelpIntro =
  "usage: surfacemap map A B [C ...] --output-dir DIR [--landmarks FA FB ...]\n"
  "                      [--sizing SA SB ...] [--categorical NAME]\n"
  "                      [--continuous NAME] [SETTING ...]\n"
  "\n"
  "Computes a bijective map between the meshes A, B, ... (closed, manifold,\n"
  "genus 0) through one adaptive common triangulation T (Schmidt, Pieper,\n"
  "Kobbelt 2023): sphere embeddings, then a landmark phase (with landmarks),\n"
  "a coarse and a fine phase of edge splits, collapses, flips and Newton\n"
  "steps, and refinement where the exact map is distorted. The result is\n"
  "certified bijective with exact predicates. One mesh alone gives a\n"
  "bijective remeshing. Writes, each file atomically and report.json last:\n"
  "  DIR/common_<i>.vtp  T lifted onto input i (same triangles for every i),\n"
  "                      with SpherePosition, SourceCellId, SourceBarycentric,\n"
  "                      Landmarks and the input's point arrays (integer\n"
  "                      arrays categorical, floating-point ones interpolated,\n"
  "                      unless --categorical / --continuous say otherwise)\n"
  "  DIR/mapped_<i>.vtp  input 0's mesh mapped onto input i by the exact map\n"
  "  DIR/embedding_<i>.vtp\n"
  "                      input i with its sphere embedding in the map's frame\n"
  "                      (SpherePosition): with common_<i>.vtp, what\n"
  "                      'surfacemap transfer' reads to carry data between inputs\n"
  "  DIR/report.json     every setting of the run, sizes, energies, per-phase\n"
  "                      iterations and times, the certificate, the landmark\n"
  "                      error and the metrics of the approximating map\n"
  "                      (common_0 -> common_i) and of the exact map (input 0 ->\n"
  "                      mapped_i): symmetric Dirichlet, area below distortion\n"
  "                      1.5 and 2, max distortion, Hausdorff distance per input\n"
  "                      (% of the bounding-box diagonal; input 0's with the\n"
  "                      first pair only), min and mean minimum angles; the\n"
  "                      map's id and every file's size and MD5 checksum,\n"
  "                      which 'evaluate' and 'transfer' verify\n"
  "\n"
  "  --output-dir DIR     where to write (created if missing; checked for\n"
  "                       writing before computing)\n"
  "  --overwrite          replace an earlier map in DIR as a whole: the new map\n"
  "                       is written beside DIR and checked, then swapped in;\n"
  "                       on failure the earlier map stays; other files in DIR\n"
  "                       stay; without it a DIR holding a map is refused\n"
  "                       before computing\n"
  "  --landmarks FA FB ...\n"
  "                       one landmark file per mesh, in the same order (give\n"
  "                       the meshes first); same id = corresponding points\n"
  "                       (formats below; points snap to the closest vertex)\n"
  "  --sizing SA SB ...   the target edge lengths of T, one source per mesh, in\n"
  "                       the same order: a file with one length per vertex\n"
  "                       per line (in the mesh's units; finite, positive, one\n"
  "                       per vertex), or the name of a point array of that\n"
  "                       mesh (a VTP input's); a name that is an existing\n"
  "                       file is read as the file. Used instead of the\n"
  "                       curvature sizing; where the inputs disagree, T\n"
  "                       follows the smallest\n";

const char* const MapHelpSettings =
  "\n"
  "Settings (unit-area units: each input centred and scaled to unit area; a\n"
  "phase stopping at its iteration cap is normal and reported):\n";

const char* const MapExitCodes =
  "\n"
  "Exit code 0 with a certified map, 2 for bad usage or input (also an output\n"
  "directory that cannot be written), 3 if no certified map was found, 1 for\n"
  "an internal error.\n";

const std::string MapHelpText = std::string(MapHelpIntro) + ArrayTransferFlagsHelp +
  MapHelpSettings + presetsHelp() + settingsHelp() + LandmarkFormatsHelp + MapExitCodes;
} // namespace

const char* const MapHelp = MapHelpText.c_str();

namespace
{

// A field-data value of a map output (tuple k), NaN if absent.
double field(vtkPolyData* data, const char* name, vtkIdType k = 0)
{
  vtkDataArray* a = data->GetFieldData()->GetArray(name);
  return a && k < a->GetNumberOfTuples() ? a->GetTuple1(k) : std::nan("");
}

// Measures source -> target (same connectivity); originals may be null.
// Returns the JSON object; prints one line.
std::string evaluate(const char* what,
  int target,
  vtkPolyData* source,
  vtkPolyData* targetMesh,
  vtkPolyData* sourceOriginal,
  vtkPolyData* targetOriginal)
{
  vtkSmartPointer<vtkPolyData> evaluated;
  try
  {
    evaluated = measureMap(source, targetMesh, sourceOriginal, targetOriginal);
  }
  catch (const std::invalid_argument& e)
  {
    throw std::logic_error(
      "evaluating the " + std::string(what) + " 0 -> " + std::to_string(target) + ": " + e.what());
  }
  auto figure = [&evaluated](const char* name) { return summaryValue(evaluated, name); };
  std::ostringstream json;
  json << "{ \"source\": 0, \"target\": " << target;
  for (const char* name : evaluationSummaryNames())
  {
    // The certificate has its own section of the report (T's embeddings).
    const bool certificate =
      std::strcmp(name, "Bijective") == 0 || std::strcmp(name, "NonPositiveTriangles") == 0;
    const double value = figure(name);
    if (!certificate && !std::isnan(value))
    {
      json << ", " << jsonString(name) << ": " << jsonNumber(value);
    }
  }
  json << " }";
  std::printf("  %s 0 -> %d: SD %.4f, a1.5 %.3f, a2 %.3f, max %.3g",
    what,
    target,
    figure("SymmetricDirichlet"),
    figure("AreaBelow1.5"),
    figure("AreaBelow2"),
    figure("MaxDistortion"));
  if (sourceOriginal)
  {
    std::printf(", H %.3f%% / %.3f%%", figure("HausdorffSource"), figure("HausdorffTarget"));
  }
  else if (targetOriginal)
  {
    std::printf(", H %.3f%% on input %d", figure("HausdorffTarget"), target);
  }
  std::printf(", min angle %.1f\n", figure("MinAngleTarget"));
  return json.str();
}

struct MapArguments
{
  std::vector<std::string> meshes, landmarks, sizing;
  std::string outputDir;
  /// --preset's name, "" without one.
  std::string preset;
  bool overwrite = false;
};

MapArguments parseArguments(const std::vector<std::string>& args, vtkSurfaceMapFilter* map)
{
  MapArguments parsed;
  parsed.preset = applyPresetFlag(map, args);
  // Where a file name goes: the meshes, or the list of the last --landmarks
  // or --sizing.
  std::vector<std::string>* list = &parsed.meshes;
  for (std::size_t i = 0; i < args.size(); ++i)
  {
    const std::string& a = args[i];
    if (isOption(a))
    {
      list = &parsed.meshes;
    }
    if (a == "--landmarks")
    {
      list = &parsed.landmarks;
    }
    else if (a == "--sizing")
    {
      list = &parsed.sizing;
    }
    else if (a == "--output-dir")
    {
      parsed.outputDir = optionValue(args, i);
    }
    else if (a == "--overwrite")
    {
      parsed.overwrite = true;
    }
    else if (parseSettingFlag(map, args, i) || parseArrayTransferFlag(map, args, i))
    {
    }
    else if (isOption(a))
    {
      unknownOption(a);
    }
    else
    {
      list->push_back(a);
    }
  }
  if (parsed.meshes.empty())
  {
    throw UsageError{ parsed.landmarks.empty() && parsed.sizing.empty()
        ? "no meshes given"
        : "no meshes given (the meshes come before --landmarks and --sizing: map A B "
          "--landmarks FA FB)" };
  }
  if (parsed.outputDir.empty())
  {
    throw UsageError{ "no output directory given (--output-dir DIR)" };
  }
  if (!parsed.landmarks.empty() && parsed.landmarks.size() != parsed.meshes.size())
  {
    throw UsageError{ "--landmarks needs one file per mesh (" +
      std::to_string(parsed.meshes.size()) + " meshes, " + std::to_string(parsed.landmarks.size()) +
      " landmark files)" };
  }
  if (!parsed.sizing.empty() && parsed.sizing.size() != parsed.meshes.size())
  {
    throw UsageError{ "--sizing needs one file or array name per mesh (" +
      std::to_string(parsed.meshes.size()) + " meshes, " + std::to_string(parsed.sizing.size()) +
      " sizing sources)" };
  }
  return parsed;
}

// --sizing NAME where NAME is not a file: the point array NAME of `mesh`
// becomes its "Sizing" array, once checked (one component, finite, positive).
// Throws std::runtime_error naming the mesh, the array and the vertex.
void sizingFromArray(vtkPolyData* mesh, const std::string& name, const std::string& meshPath)
{
  vtkDataArray* array = mesh->GetPointData()->GetArray(name.c_str());
  if (!array)
  {
    throw std::runtime_error("--sizing " + name + ": no such file, and " + meshPath +
      " has no numeric point array of that name");
  }
  if (array->GetNumberOfComponents() != 1)
  {
    throw std::runtime_error("--sizing " + name + ": the point array of " + meshPath + " has " +
      std::to_string(array->GetNumberOfComponents()) + " components, not one length per vertex");
  }
  vtkNew<vtkDoubleArray> sizing;
  sizing->SetName("Sizing");
  sizing->SetNumberOfValues(array->GetNumberOfTuples());
  for (vtkIdType v = 0; v < array->GetNumberOfTuples(); ++v)
  {
    const double value = array->GetTuple1(v);
    if (!std::isfinite(value) || value <= 0.0)
    {
      std::ostringstream message;
      message << "--sizing " << name << ": the point array of " << meshPath << " has "
              << value << " at vertex " << v << ", not a finite positive length";
      throw std::runtime_error(message.str());
    }
    sizing->SetValue(v, value);
  }
  mesh->GetPointData()->AddArray(sizing);
}

// Every mesh read (with its landmark file and sizing); null after printing why. The map
// filter validates them (once, with every defect of every input named).
std::vector<vtkSmartPointer<vtkPolyData>> readInputs(const MapArguments& arguments)
{
  std::vector<vtkSmartPointer<vtkPolyData>> inputs;
  for (std::size_t i = 0; i < arguments.meshes.size(); ++i)
  {
    const std::string sizing = arguments.sizing.empty() ? "" : arguments.sizing[i];
    const bool sizingFile = !sizing.empty() && isFile(sizing);
    inputs.push_back(readMesh(arguments.meshes[i],
      arguments.landmarks.empty() ? "" : arguments.landmarks[i],
      sizingFile ? sizing : ""));
    if (!inputs.back() ||
      (!sizing.empty() && !sizingFile &&
        !succeeds([&] { sizingFromArray(inputs.back(), sizing, arguments.meshes[i]); })))
    {
      return {};
    }
  }
  return inputs;
}

// Runs the filter; prints its errors and returns the exit code on failure.
int computeMap(vtkSurfaceMapFilter* map,
  const std::vector<vtkSmartPointer<vtkPolyData>>& inputs,
  ErrorCapture& errors)
{
  for (const auto& input : inputs)
  {
    map->AddInputData(input);
  }
  {
    WarningPrinter warnings(map);
    ProgressBar bar(map);
    map->Update();
  }
  if (errors.messages().empty() && map->GetOutput(0)->GetNumberOfPoints() > 0)
  {
    return ExitOk;
  }
  printErrors(errors.messages());
  return map->GetErrorCode() == vtkSurfaceMapFilter::InvalidInputError ? ExitBadInput
    : map->GetErrorCode() == vtkSurfaceMapFilter::NotCertifiedError    ? ExitNoCertifiedResult
                                                                       : ExitInternalError;
}

// Absolute paths, so `surfacemap evaluate DIR` finds the inputs from anywhere.
std::string absolute(const std::string& path)
{
  std::error_code ec;
  const std::filesystem::path p = std::filesystem::absolute(path, ec);
  return ec ? path : p.lexically_normal().string();
}

// The report's inputs, sizes, certificate, energies and times; prints the summary line.
std::string reportMap(vtkSurfaceMapFilter* map,
  const MapArguments& arguments,
  const std::vector<vtkSmartPointer<vtkPolyData>>& inputs,
  double seconds)
{
  const int n = static_cast<int>(inputs.size());
  vtkPolyData* first = map->GetOutput(0);
  const bool certified = field(first, "Bijective") == 1.0;
  std::printf("map of %d surface%s: %s, T has %lld vertices (%lld triangles), %.2f s\n",
    n,
    n == 1 ? "" : "s",
    certified ? "certified bijective" : "NOT certified",
    static_cast<long long>(field(first, "CommonVertices")),
    static_cast<long long>(field(first, "CommonTriangles")),
    seconds);
  std::ostringstream json;
  json << "{\n  \"inputs\": [";
  for (int i = 0; i < n; ++i)
  {
    json << (i ? ",\n" : "\n") << "    { \"file\": " << jsonString(absolute(arguments.meshes[i]))
         << ", \"landmarks\": "
         << (arguments.landmarks.empty() ? "null" : jsonString(absolute(arguments.landmarks[i])))
         << ", \"landmark_snap\": " << landmarkSnapJson(inputs[i]) << ", \"sizing\": "
         << (arguments.sizing.empty()        ? "null"
                : isFile(arguments.sizing[i]) ? jsonString(absolute(arguments.sizing[i]))
                                              : jsonString("point array " + arguments.sizing[i]))
         << ", \"vertices\": " << inputs[i]->GetNumberOfPoints()
         << ", \"triangles\": " << inputs[i]->GetNumberOfPolys()
         << ", \"embedding_seconds\": " << jsonNumber(field(first, "EmbeddingSeconds", i)) << " }";
  }
  json << "\n  ],\n";
  json << "  \"common_triangulation\": { \"vertices\": "
       << jsonNumber(field(first, "CommonVertices"))
       << ", \"triangles\": " << jsonNumber(field(first, "CommonTriangles")) << " },\n";
  json << "  \"certificate\": { \"bijective\": " << (certified ? "true" : "false")
       << ", \"spherical_degrees\": [";
  for (int i = 0; i < n; ++i)
  {
    json << (i ? ", " : "") << jsonNumber(field(map->GetOutput(i), "SphericalDegree"));
  }
  json << "] },\n";
  json << "  \"landmark_error\": " << jsonNumber(field(first, "LandmarkError")) << ",\n";
  json << "  \"energy\": { \"total\": " << jsonNumber(field(first, "Energy"))
       << ", \"barrier\": " << jsonNumber(field(first, "BarrierEnergy"))
       << ", \"mesh\": " << jsonNumber(field(first, "MeshEnergy"))
       << ", \"approximation\": " << jsonNumber(field(first, "ApproximationEnergy"))
       << ", \"map\": " << jsonNumber(field(first, "MapEnergy")) << " },\n";
  json << "  \"seconds\": { \"total\": " << jsonNumber(seconds)
       << ", \"map\": " << jsonNumber(field(first, "MapSeconds")) << " },\n";
  json << "  \"preset\": " << (arguments.preset.empty() ? "null" : jsonString(arguments.preset))
       << ",\n";
  json << "  \"settings\": " << settingsJson(map) << ",\n";
  json << "  \"array_transfer_modes\": {";
  for (int k = 0; k < map->GetNumberOfArrayTransferModes(); ++k)
  {
    const char* name = map->GetArrayTransferModeArrayName(k);
    json << (k ? ", " : " ") << jsonString(name) << ": "
         << jsonString(
              vtkSurfaceMapFilter::GetArrayTransferModeAsString(map->GetArrayTransferMode(name)));
  }
  json << (map->GetNumberOfArrayTransferModes() ? " },\n" : "},\n");
  return json.str();
}

// The report's phases, printed one line each.
std::string reportPhases(vtkPolyData* first)
{
  std::ostringstream json;
  json << "  \"phases\": [";
  auto* phaseNames =
    vtkStringArray::SafeDownCast(first->GetFieldData()->GetAbstractArray("PhaseName"));
  for (vtkIdType k = 0; phaseNames && k < phaseNames->GetNumberOfValues(); ++k)
  {
    const bool converged = field(first, "PhaseConverged", k) == 1.0;
    json << (k ? ",\n" : "\n") << "    { \"name\": " << jsonString(phaseNames->GetValue(k));
    const std::pair<const char*, const char*> columns[] = { { "iterations", "PhaseIterations" },
      { "stalled_iterations", "PhaseStalledIterations" },
      { "seconds", "PhaseSeconds" },
      { "vertices", "PhaseVertices" },
      { "energy", "PhaseEnergy" },
      { "splits", "PhaseSplits" },
      { "collapses", "PhaseCollapses" },
      { "flips", "PhaseFlips" },
      { "landmark_error", "PhaseLandmarkError" },
      { "remesh_seconds", "PhaseRemeshSeconds" },
      { "derivative_seconds", "PhaseDerivativeSeconds" },
      { "solve_seconds", "PhaseSolveSeconds" },
      { "line_search_seconds", "PhaseLineSearchSeconds" } };
    for (const auto& [key, name] : columns)
    {
      json << ", " << jsonString(key) << ": " << jsonNumber(field(first, name, k));
    }
    json << ", \"converged\": " << (converged ? "true" : "false") << " }";
    std::printf("  %-10s %4d iterations%s, %d stalled, %.2f s, %d vertices, %d splits, "
                "%d collapses, %d flips\n",
      (phaseNames->GetValue(k) + ":").c_str(),
      static_cast<int>(field(first, "PhaseIterations", k)),
      converged ? " (converged)" : " (iteration cap)",
      static_cast<int>(field(first, "PhaseStalledIterations", k)),
      field(first, "PhaseSeconds", k),
      static_cast<int>(field(first, "PhaseVertices", k)),
      static_cast<int>(field(first, "PhaseSplits", k)),
      static_cast<int>(field(first, "PhaseCollapses", k)),
      static_cast<int>(field(first, "PhaseFlips", k)));
  }
  json << "\n  ],\n";
  if (phaseNames && phaseNames->GetNumberOfValues() > 0 && phaseNames->GetValue(0) == "landmarks")
  {
    std::printf("  landmark error %.3g (input units)\n", field(first, "LandmarkError"));
  }
  return json.str();
}

// The error bound, certified on every input vertex (input units).
std::string reportErrorBound(vtkSurfaceMapFilter* map, int n)
{
  if (map->GetMaxError() <= 0.0)
  {
    return "";
  }
  std::ostringstream json;
  json << "  \"error_bound\": [";
  for (int i = 0; i < n; ++i)
  {
    const double distance = field(map->GetOutput(i), "BaseDistance");
    const double bound = field(map->GetOutput(i), "ErrorBound");
    json << (i ? ", " : "") << "{ \"input\": " << i
         << ", \"base_distance\": " << jsonNumber(distance) << ", \"bound\": " << jsonNumber(bound)
         << " }";
    std::printf("  error bound on input %d: every vertex within %.4g of its base point on T "
                "(bound %.4g = %g x bbox diagonal)\n",
      i,
      distance,
      bound,
      map->GetMaxError());
  }
  json << "],\n";
  return json.str();
}

// Writes one output mode's outputs as DIR/<prefix>_<i>.vtp (the filter reuses
// the computed map); returns the report's metrics of maps 0 -> i under `key`,
// or nothing with a null `what`.
std::string writeOutputs(vtkSurfaceMapFilter* map,
  ErrorCapture& errors,
  MapWriter& files,
  const char* prefix,
  const char* what,
  const char* key,
  const std::vector<vtkSmartPointer<vtkPolyData>>& inputs,
  bool withSourceOriginal)
{
  map->Update();
  if (!errors.messages().empty() || map->GetOutput(0)->GetNumberOfPoints() == 0)
  {
    throw std::logic_error(std::string("the ") + prefix + " outputs failed: " +
      (errors.messages().empty() ? std::string("empty") : errors.messages().front()));
  }
  const int n = static_cast<int>(inputs.size());
  for (int i = 0; i < n; ++i)
  {
    files.write(map->GetOutput(i), mapFileName(prefix, i));
  }
  if (!what)
  {
    return "";
  }
  std::ostringstream json;
  json << "  \"" << key << "\": [";
  for (int i = n > 1 ? 1 : 0; i < n; ++i)
  {
    json << (i > 1 ? ",\n" : "\n") << "    "
         << evaluate(what,
              i,
              map->GetOutput(0),
              map->GetOutput(i),
              // Input 0's distance to T_0 is the same for every pair: measured once.
              withSourceOriginal && i <= 1 ? inputs[0].Get() : nullptr,
              inputs[i]);
  }
  json << "\n  ]";
  return json.str();
}

} // namespace

int runMap(const std::vector<std::string>& args)
{
  vtkNew<vtkSurfaceMapFilter> map;
  const MapArguments arguments = parseArguments(args, map);
  const std::vector<vtkSmartPointer<vtkPolyData>> inputs = readInputs(arguments);
  if (inputs.empty())
  {
    return ExitBadInput;
  }
  const std::string missing =
    missingArrayTransferNames(map, std::vector<vtkPolyData*>(inputs.begin(), inputs.end()));
  if (!missing.empty())
  {
    throw UsageError{ "no input has a point array " + missing +
      " (named by --categorical or --continuous)" };
  }
  std::string created;
  if (!prepareOutputDirectory(arguments.outputDir, "report.json", created))
  {
    return ExitBadInput;
  }
  if (!arguments.overwrite && holdsMap(arguments.outputDir))
  {
    throw UsageError{ arguments.outputDir +
      " holds an earlier map (report.json or common_/mapped_/embedding_ files); give "
      "--overwrite to replace it" };
  }
  const auto start = std::chrono::steady_clock::now();
  ErrorCapture errors(map);
  const int computed = computeMap(map, inputs, errors);
  if (computed != ExitOk)
  {
    removeCreatedDirectory(created); // created here, nothing written yet
    return computed;
  }
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const bool certified = field(map->GetOutput(0), "Bijective") == 1.0;
  std::string report = reportMap(map, arguments, inputs, seconds) +
    reportPhases(map->GetOutput(0)) + reportErrorBound(map, static_cast<int>(inputs.size()));
  try
  {
    // The earlier map, if any, stays untouched until the new one is
    // complete and checked beside it (MapDestination).
    MapDestination destination(arguments.outputDir, holdsMap(arguments.outputDir));
    if (!destination.note().empty())
    {
      std::fprintf(stderr, "note: %s\n", destination.note().c_str());
    }
    const std::string& dir = destination.path();
    MapWriter files(dir);
    report += writeOutputs(
      map, errors, files, "common", "approximating map", "approximating_map", inputs, true);
    map->SetOutputModeToMappedFirstInput();
    report +=
      ",\n" + writeOutputs(map, errors, files, "mapped", "exact map", "exact_map", inputs, false);
    map->SetOutputModeToInputEmbeddings();
    writeOutputs(map, errors, files, "embedding", nullptr, nullptr, inputs, false);
    writeFileAtomically(dir + "/report.json", report + ",\n" + files.reportJson() + "\n}\n");
    destination.commit(files.names());
  }
  catch (const std::runtime_error& e)
  {
    printError(e.what());
    return ExitBadInput;
  }
  std::printf("  written to %s: common_<i>.vtp, mapped_<i>.vtp, embedding_<i>.vtp (i < %d), "
              "report.json\n",
    arguments.outputDir.c_str(),
    static_cast<int>(inputs.size()));
  return certified ? ExitOk : ExitNoCertifiedResult;
}

} // namespace surfacemap
