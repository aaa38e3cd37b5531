// surfacemap map: bijective map between N surfaces via a common triangulation.
#include "CommandSupport.h"
#include "Commands.h"

#include "vtkSurfaceMapEvaluation.h"
#include "vtkSurfaceMapFilter.h"
#include "vtkSurfaceMeshValidator.h"

#include "vtkAbstractArray.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"
#include "vtkTable.h"
#include "vtkVariant.h"

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

const char* const MapHelp =
  "usage: surfacemap map A B [C ...] --output-dir DIR [--landmarks FA FB ...]\n"
  "                      [--target-error E] [--coarse-error E] [--max-error F]\n"
  "                      [--pairs star|sequence|cycle|all]\n"
  "                      [--keep-landmarks | --release-landmarks]\n"
  "                      [--landmark-iterations N] [--coarse-iterations N]\n"
  "                      [--fine-iterations N] [--no-landmark-relaxation]\n"
  "                      [--mesh-weight W] [--map-weight W]\n"
  "                      [--approximation-weight W] [--refinement-rounds N]\n"
  "                      [--refinement-distortion D]\n"
  "\n"
  "Computes a bijective map between the meshes A, B, ... (closed, manifold,\n"
  "genus 0) through one adaptive common triangulation T (Schmidt, Pieper,\n"
  "Kobbelt 2023): sphere embeddings, then a landmark phase (with landmarks),\n"
  "a coarse and a fine phase of edge splits, collapses, flips and Newton\n"
  "steps. The result is certified bijective with exact predicates. One mesh\n"
  "alone gives a bijective remeshing. Writes, atomically:\n"
  "  DIR/common_<i>.vtp  T lifted onto input i (same triangles for every i),\n"
  "                      with SpherePosition, SourceCellId, SourceBarycentric,\n"
  "                      Landmarks and the input's point arrays\n"
  "  DIR/mapped_<i>.vtp  input 0's mesh mapped onto input i by the exact map\n"
  "  DIR/embedding_<i>.vtp\n"
  "                      input i with its sphere embedding in the map's frame\n"
  "                      (SpherePosition): with common_<i>.vtp, what\n"
  "                      'surfacemap transfer' reads to carry data between inputs\n"
  "  DIR/report.json     sizes, energies, per-phase iterations and times, the\n"
  "                      certificate, the landmark error and the metrics of the\n"
  "                      approximating map (common_0 -> common_i) and of the\n"
  "                      exact map (input 0 -> mapped_i): symmetric Dirichlet,\n"
  "                      area below distortion 1.5 and 2, max distortion,\n"
  "                      Hausdorff distance per input (% of the bounding-box\n"
  "                      diagonal), min and mean minimum angles\n"
  "\n"
  "  --output-dir DIR         where to write (created if missing; checked for\n"
  "                           writing before computing)\n"
  "  --landmarks FA FB ...    one landmark file per mesh, in the same order (give\n"
  "                           the meshes first); same id = corresponding points\n"
  "  --target-error E         approximation error of the fine phase, unit-area\n"
  "                           units (default 1e-3)\n"
  "  --coarse-error E         the same for the coarse phase (default 1e-2)\n"
  "  --max-error F            error-bounded remeshing: after the fine phase,\n"
  "                           refine T until every input vertex is within F\n"
  "                           times its input's bounding-box diagonal of its\n"
  "                           base point on T, then optimise with that bound as\n"
  "                           a barrier; certified on every input vertex, and\n"
  "                           a bound that cannot be met is exit code 3\n"
  "                           (default 0: off; 0 < F <= 1)\n"
  "  --pairs MODE             pairs whose distortion is minimised with 3 or more\n"
  "                           meshes: star (0-i, default), sequence (i-(i+1)),\n"
  "                           cycle, all\n"
  "  --keep-landmarks         lock landmarks exactly after the landmark phase\n"
  "                           (default)\n"
  "  --release-landmarks      let the optimisation move them afterwards\n"
  "  --landmark-iterations N  iteration caps of the phases (defaults 100, 50,\n"
  "  --coarse-iterations N    50; 0 skips a phase). A phase stopping at its cap\n"
  "  --fine-iterations N      is normal and reported.\n"
  "  --no-landmark-relaxation end the landmark phase as soon as the landmarks\n"
  "                           are reached (default: relax T's embeddings around\n"
  "                           them first, with Newton steps and flips)\n"
  "  --mesh-weight W          weights of the energy's mesh-quality, map-\n"
  "  --map-weight W           distortion and surface-approximation terms\n"
  "  --approximation-weight W (defaults 0.5, 1, 0.25; >= 0): more map\n"
  "                           weight, a lower distortion; more approximation\n"
  "                           weight, a closer T and exact map\n"
  "  --refinement-rounds N    after the fine phase, up to N rounds (default 3;\n"
  "                           0 off) of 10 more iterations (at most the fine\n"
  "                           phase's cap) with T refined where the exact map\n"
  "                           is distorted: first where its distortion exceeds\n"
  "                           D (--refinement-distortion, default 1.4, >= 1;\n"
  "                           10: only squeezes, as before 2026-11-23), then\n"
  "                           only where an input triangle is squeezed\n"
  "                           (distortion above 10)\n"
  "  --refinement-distortion D\n"
  "\n"
  "Exit code 0 with a certified map, 2 for bad usage or input (also an output\n"
  "directory that cannot be written), 3 if no certified map was found, 1 for\n"
  "an internal error.\n";

namespace
{

using Clock = std::chrono::steady_clock;

double parseNumber(const std::string& option, const std::string& text)
{
  std::size_t used = 0;
  double value = 0.0;
  try
  {
    value = std::stod(text, &used);
  }
  catch (const std::exception&)
  {
    used = 0;
  }
  if (used != text.size() || !std::isfinite(value))
  {
    throw UsageError{ option + " needs a number, not '" + text + "'" };
  }
  return value;
}

int parseCount(const std::string& option, const std::string& text)
{
  const double value = parseNumber(option, text);
  if (value < 0 || value > 100000 || value != std::floor(value))
  {
    throw UsageError{ option + " needs a whole number from 0 to 100000, not '" + text + "'" };
  }
  return static_cast<int>(value);
}

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

} // namespace

int runMap(const std::vector<std::string>& args)
{
  std::vector<std::string> meshes, landmarks;
  std::string outputDir;
  vtkNew<vtkSurfaceMapFilter> map;
  std::string pairs = "star";
  bool inLandmarks = false;
  for (std::size_t i = 0; i < args.size(); ++i)
  {
    const std::string& a = args[i];
    const bool takesValue = a == "--output-dir" || a == "--target-error" || a == "--coarse-error" ||
      a == "--max-error" || a == "--pairs" || a == "--landmark-iterations" ||
      a == "--coarse-iterations" || a == "--fine-iterations" || a == "--mesh-weight" ||
      a == "--map-weight" || a == "--approximation-weight" || a == "--refinement-rounds" ||
      a == "--refinement-distortion";
    if (takesValue && i + 1 >= args.size())
    {
      throw UsageError{ a + " needs a value" };
    }
    if (a != "--landmarks" && !a.empty() && a[0] == '-')
    {
      inLandmarks = false;
    }
    if (a == "--landmarks")
    {
      inLandmarks = true;
    }
    else if (a == "--output-dir")
    {
      outputDir = args[++i];
    }
    else if (a == "--target-error" || a == "--coarse-error")
    {
      const double e = parseNumber(a, args[++i]);
      if (e < 1e-6 || e > 1.0)
      {
        throw UsageError{ a + " must be between 1e-6 and 1 (unit-area units)" };
      }
      if (a == "--target-error")
      {
        map->SetTargetError(e);
      }
      else
      {
        map->SetCoarseError(e);
      }
    }
    else if (a == "--max-error")
    {
      const double f = parseNumber(a, args[++i]);
      if (!(f > 0.0 && f <= 1.0))
      {
        throw UsageError{
          "--max-error must be in (0, 1] (a fraction of the bounding-box diagonal)"
        };
      }
      map->SetMaxError(f);
    }
    else if (a == "--mesh-weight" || a == "--map-weight" || a == "--approximation-weight")
    {
      const double w = parseNumber(a, args[++i]);
      if (!(w >= 0.0 && w <= 1e6))
      {
        throw UsageError{ a + " must be between 0 and 1e6" };
      }
      if (a == "--mesh-weight")
      {
        map->SetMeshWeight(w);
      }
      else if (a == "--map-weight")
      {
        map->SetMapWeight(w);
      }
      else
      {
        map->SetApproximationWeight(w);
      }
    }
    else if (a == "--refinement-rounds")
    {
      const double rounds = parseNumber(a, args[++i]);
      if (!(rounds >= 0.0 && rounds <= 100.0) || rounds != std::floor(rounds))
      {
        throw UsageError{ a + " must be a whole number between 0 and 100" };
      }
      map->SetRefinementRounds(static_cast<int>(rounds));
    }
    else if (a == "--refinement-distortion")
    {
      const double d = parseNumber(a, args[++i]);
      if (!(d >= 1.0 && d <= 1e12))
      {
        throw UsageError{ a + " must be between 1 and 1e12" };
      }
      map->SetRefinementDistortion(d);
    }
    else if (a == "--pairs")
    {
      pairs = args[++i];
      if (pairs == "star")
      {
        map->SetPairModeToStar();
      }
      else if (pairs == "sequence")
      {
        map->SetPairModeToSequence();
      }
      else if (pairs == "cycle")
      {
        map->SetPairModeToCycle();
      }
      else if (pairs == "all")
      {
        map->SetPairModeToAll();
      }
      else
      {
        throw UsageError{ "--pairs is star, sequence, cycle or all, not '" + pairs + "'" };
      }
    }
    else if (a == "--no-landmark-relaxation")
    {
      map->RelaxLandmarkPhaseOff();
    }
    else if (a == "--keep-landmarks" || a == "--release-landmarks")
    {
      map->SetKeepLandmarks(a == "--keep-landmarks");
    }
    else if (a == "--landmark-iterations")
    {
      map->SetLandmarkIterations(parseCount(a, args[++i]));
    }
    else if (a == "--coarse-iterations")
    {
      map->SetCoarseIterations(parseCount(a, args[++i]));
    }
    else if (a == "--fine-iterations")
    {
      map->SetFineIterations(parseCount(a, args[++i]));
    }
    else if (!a.empty() && a[0] == '-')
    {
      throw UsageError{ "unknown option '" + a + "'" };
    }
    else
    {
      (inLandmarks ? landmarks : meshes).push_back(a);
    }
  }
  if (meshes.empty())
  {
    throw UsageError{ "no meshes given" };
  }
  if (outputDir.empty())
  {
    throw UsageError{ "no output directory given (--output-dir DIR)" };
  }
  if (!landmarks.empty() && landmarks.size() != meshes.size())
  {
    throw UsageError{ "--landmarks needs one file per mesh (" + std::to_string(meshes.size()) +
      " meshes, " + std::to_string(landmarks.size()) + " landmark files)" };
  }
  const int n = static_cast<int>(meshes.size());

  // Inputs: each valid, landmark ids corresponding.
  std::vector<vtkSmartPointer<vtkPolyData>> inputs;
  for (int i = 0; i < n; ++i)
  {
    inputs.push_back(readValidMesh(meshes[i], landmarks.empty() ? "" : landmarks[i]));
    if (!inputs.back())
    {
      return ExitBadInput;
    }
  }
  if (n > 1)
  {
    vtkNew<vtkSurfaceMeshValidator> validator;
    for (const auto& input : inputs)
    {
      validator->AddInputDataObject(input);
    }
    validator->Update();
    if (!validator->GetAllValid())
    {
      for (vtkIdType r = 0; r < validator->GetOutput()->GetNumberOfRows(); ++r)
      {
        std::istringstream defects(validator->GetOutput()->GetValueByName(r, "Defects").ToString());
        for (std::string line; std::getline(defects, line);)
        {
          printError(line);
        }
      }
      return ExitBadInput;
    }
  }

  // The output directory, before the long computation.
  try
  {
    std::error_code ec;
    std::filesystem::create_directories(outputDir, ec);
    if (ec && !std::filesystem::is_directory(outputDir))
    {
      throw std::runtime_error(
        "cannot create the output directory '" + outputDir + "': " + ec.message());
    }
    checkWritable(outputDir + "/report.json");
  }
  catch (const std::runtime_error& e)
  {
    printError(e.what());
    return ExitBadInput;
  }

  // The map.
  const auto start = Clock::now();
  for (const auto& input : inputs)
  {
    map->AddInputData(input);
  }
  ErrorCapture errors(map);
  {
    ProgressBar bar(map);
    map->Update();
  }
  if (!errors.messages().empty() || map->GetOutput(0)->GetNumberOfPoints() == 0)
  {
    for (const std::string& m : errors.messages())
    {
      printError(m);
    }
    return map->GetErrorCode() == vtkSurfaceMapFilter::InvalidInputError ? ExitBadInput
      : map->GetErrorCode() == vtkSurfaceMapFilter::NotCertifiedError    ? ExitNoCertifiedResult
                                                                         : ExitInternalError;
  }
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();

  vtkPolyData* first = map->GetOutput(0);
  const bool certified = field(first, "Bijective") == 1.0;
  std::printf("map of %d surface%s: %s, T has %lld vertices (%lld triangles), %.2f s\n",
    n,
    n == 1 ? "" : "s",
    certified ? "certified bijective" : "NOT certified",
    static_cast<long long>(field(first, "CommonVertices")),
    static_cast<long long>(field(first, "CommonTriangles")),
    seconds);

  // Absolute paths, so `surfacemap evaluate DIR` finds the inputs from anywhere.
  const auto absolute = [](const std::string& path)
  {
    std::error_code ec;
    const std::filesystem::path p = std::filesystem::absolute(path, ec);
    return ec ? path : p.lexically_normal().string();
  };
  std::ostringstream json;
  json << "{\n  \"inputs\": [";
  for (int i = 0; i < n; ++i)
  {
    json << (i ? ",\n" : "\n") << "    { \"file\": " << jsonString(absolute(meshes[i]))
         << ", \"landmarks\": " << (landmarks.empty() ? "null" : jsonString(absolute(landmarks[i])))
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
  json << "  \"settings\": { \"target_error\": " << jsonNumber(map->GetTargetError())
       << ", \"coarse_error\": " << jsonNumber(map->GetCoarseError())
       << ", \"max_error\": " << jsonNumber(map->GetMaxError())
       << ", \"pairs\": " << jsonString(pairs)
       << ", \"keep_landmarks\": " << (map->GetKeepLandmarks() ? "true" : "false")
       << ", \"landmark_iterations\": " << map->GetLandmarkIterations()
       << ", \"relax_landmark_phase\": " << (map->GetRelaxLandmarkPhase() ? "true" : "false")
       << ", \"coarse_iterations\": " << map->GetCoarseIterations()
       << ", \"fine_iterations\": " << map->GetFineIterations()
       << ", \"mesh_weight\": " << jsonNumber(map->GetMeshWeight())
       << ", \"map_weight\": " << jsonNumber(map->GetMapWeight())
       << ", \"approximation_weight\": " << jsonNumber(map->GetApproximationWeight())
       << ", \"refinement_rounds\": " << map->GetRefinementRounds()
       << ", \"refinement_iterations\": " << map->GetRefinementIterations()
       << ", \"refinement_distortion\": " << jsonNumber(map->GetRefinementDistortion())
       << ", \"refinement_growth\": " << jsonNumber(map->GetRefinementGrowth())
       << ", \"squeeze_distortion\": " << jsonNumber(map->GetSqueezeDistortion()) << " },\n";
  json << "  \"phases\": [";
  auto* phaseNames =
    vtkStringArray::SafeDownCast(first->GetFieldData()->GetAbstractArray("PhaseName"));
  for (vtkIdType k = 0; phaseNames && k < phaseNames->GetNumberOfValues(); ++k)
  {
    const bool converged = field(first, "PhaseConverged", k) == 1.0;
    json << (k ? ",\n" : "\n") << "    { \"name\": " << jsonString(phaseNames->GetValue(k));
    const std::pair<const char*, const char*> columns[] = { { "iterations", "PhaseIterations" },
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
    std::printf("  %-10s %4d iterations%s, %.2f s, %d vertices, %d splits, %d collapses, "
                "%d flips\n",
      (phaseNames->GetValue(k) + ":").c_str(),
      static_cast<int>(field(first, "PhaseIterations", k)),
      converged ? " (converged)" : " (iteration cap)",
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
  // The error bound, certified on every input vertex (input units).
  if (map->GetMaxError() > 0.0)
  {
    json << "  \"error_bound\": [";
    for (int i = 0; i < n; ++i)
    {
      const double distance = field(map->GetOutput(i), "BaseDistance");
      const double bound = field(map->GetOutput(i), "ErrorBound");
      json << (i ? ", " : "") << "{ \"input\": " << i
           << ", \"base_distance\": " << jsonNumber(distance)
           << ", \"bound\": " << jsonNumber(bound) << " }";
      std::printf("  error bound on input %d: every vertex within %.4g of its base point on T "
                  "(bound %.4g = %g x bbox diagonal)\n",
        i,
        distance,
        bound,
        map->GetMaxError());
    }
    json << "],\n";
  }

  // Outputs and metrics: the approximating map while the outputs are T...
  std::vector<std::string> written;
  try
  {
    json << "  \"approximating_map\": [";
    for (int i = 0; i < n; ++i)
    {
      const std::string path = outputDir + "/common_" + std::to_string(i) + ".vtp";
      writePolyDataAtomically(map->GetOutput(i), path);
      written.push_back(path);
    }
    for (int i = n > 1 ? 1 : 0; i < n; ++i)
    {
      json << (i > 1 ? ",\n" : "\n") << "    "
           << evaluate(
                "approximating map", i, map->GetOutput(0), map->GetOutput(i), inputs[0], inputs[i]);
    }
    json << "\n  ],\n";

    // ... then the exact map (the filter reuses the map it computed).
    map->SetOutputModeToMappedFirstInput();
    map->Update();
    if (!errors.messages().empty() || map->GetOutput(0)->GetNumberOfPoints() == 0)
    {
      throw std::logic_error("the mapped outputs failed: " +
        (errors.messages().empty() ? std::string("empty") : errors.messages().front()));
    }
    json << "  \"exact_map\": [";
    for (int i = 0; i < n; ++i)
    {
      const std::string path = outputDir + "/mapped_" + std::to_string(i) + ".vtp";
      writePolyDataAtomically(map->GetOutput(i), path);
      written.push_back(path);
    }
    for (int i = n > 1 ? 1 : 0; i < n; ++i)
    {
      json << (i > 1 ? ",\n" : "\n") << "    "
           << evaluate("exact map", i, map->GetOutput(0), map->GetOutput(i), nullptr, inputs[i]);
    }
    json << "\n  ]\n}\n";

    // ... and the inputs with their embeddings f_i, for `surfacemap transfer`.
    map->SetOutputModeToInputEmbeddings();
    map->Update();
    if (!errors.messages().empty() || map->GetOutput(0)->GetNumberOfPoints() == 0)
    {
      throw std::logic_error("the embedding outputs failed: " +
        (errors.messages().empty() ? std::string("empty") : errors.messages().front()));
    }
    for (int i = 0; i < n; ++i)
    {
      const std::string path = outputDir + "/embedding_" + std::to_string(i) + ".vtp";
      writePolyDataAtomically(map->GetOutput(i), path);
      written.push_back(path);
    }
    writeFileAtomically(outputDir + "/report.json", json.str());
  }
  catch (const std::runtime_error& e)
  {
    printError(e.what());
    return ExitBadInput;
  }
  std::printf("  written to %s: common_<i>.vtp, mapped_<i>.vtp, embedding_<i>.vtp (i < %d), "
              "report.json\n",
    outputDir.c_str(),
    n);
  return certified ? ExitOk : ExitNoCertifiedResult;
}

} // namespace surfacemap
