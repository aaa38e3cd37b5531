// Benchmark of the surface map (not a test): wall time per stage, peak
// memory, T size and the DESIGN.md section 6 metrics of the approximating
// map (T_0 -> T_j) and of the exact map (input 0 -> input 0 on input j).
//
//   build/bin/BenchmarkMap A B [C...] [--landmarks FA FB ...] [-v] [SETTING ...]
// with the settings' flags of `surfacemap map` (the engine's settings table).
#include "BenchmarkSupport.h"
#include "embedding/SphereEmbedding.h"
#include "geometry/MapMetrics.h"
#include "io/LandmarkReader.h"
#include "map/MapSettings.h"
#include "map/SurfaceMap.h"
#include "mesh/MeshValidation.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

using namespace surfacemaps;

namespace
{
double minMeanMinAngle(const std::vector<Eigen::Vector3d>& p,
  const std::vector<std::array<int, 3>>& triangles,
  double* mean)
{
  double smallest = 180.0, sum = 0.0;
  for (const auto& t : triangles)
  {
    double m = 180.0;
    for (int k = 0; k < 3; ++k)
    {
      const Eigen::Vector3d a = p[t[(k + 1) % 3]] - p[t[k]], b = p[t[(k + 2) % 3]] - p[t[k]];
      m = std::min(m, std::atan2(a.cross(b).norm(), a.dot(b)) * 180.0 / M_PI);
    }
    smallest = std::min(smallest, m);
    sum += m;
  }
  *mean = sum / triangles.size();
  return smallest;
}

struct Arguments
{
  std::vector<std::string> meshes, landmarkFiles;
  SurfaceMapOptions options;
};

// The command line; false after printing why (an unknown option or a bad
// setting, or the usage).
bool parseArguments(const std::vector<std::string>& args, Arguments& parsed)
{
  bool verbose = false;
  try
  {
    for (std::size_t a = 0; a < args.size(); ++a)
    {
      if (args[a] == "--landmarks")
      {
        while (a + 1 < args.size() && args[a + 1][0] != '-')
        {
          parsed.landmarkFiles.push_back(args[++a]);
        }
      }
      else if (args[a] == "-v")
      {
        verbose = true;
      }
      else if (!parseSettingFlag(args, a, parsed.options))
      {
        if (args[a][0] == '-')
        {
          throw std::invalid_argument("unknown option '" + args[a] + "'");
        }
        parsed.meshes.push_back(args[a]);
      }
    }
  }
  catch (const std::invalid_argument& e)
  {
    std::fprintf(stderr, "BenchmarkMap: %s\n", e.what());
    return false;
  }
  if (parsed.meshes.empty() ||
    (!parsed.landmarkFiles.empty() && parsed.landmarkFiles.size() != parsed.meshes.size()))
  {
    std::fprintf(stderr,
      "usage: BenchmarkMap A B [C...] [--landmarks FA FB ...] [-v] [SETTING ...]\n"
      "settings: the flags of `surfacemap map` (`surfacemap map --help`):");
    for (const MapSetting& s : mapSettings())
    {
      std::fprintf(stderr, " --%s", s.flag);
    }
    std::fprintf(stderr, "\n");
    return false;
  }
  if (verbose)
  {
    parsed.options.log.sink = [](Logger::Level, const std::string& m) { std::cerr << m << "\n"; };
  }
  return true;
}

// Every input read and validated, with its landmarks; false after printing
// the first defect.
bool readInputs(const Arguments& arguments, std::vector<MapInput>& inputs)
{
  inputs.resize(arguments.meshes.size());
  for (std::size_t i = 0; i < arguments.meshes.size(); ++i)
  {
    inputs[i].mesh = benchmark::read(arguments.meshes[i]);
    const MeshValidationResult validation = validateMesh(inputs[i].mesh);
    if (!validation.valid())
    {
      std::fprintf(stderr, "%s: %s\n", arguments.meshes[i].c_str(), validation.defects[0].c_str());
      return false;
    }
    if (!arguments.landmarkFiles.empty())
    {
      inputs[i].landmarks = landmarkIdsFromIndices(readLandmarks(arguments.landmarkFiles[i]),
        inputs[i].mesh.points.size(),
        arguments.landmarkFiles[i]);
    }
  }
  return true;
}

// Embeds every input on the sphere; returns the seconds it took.
double embedInputs(std::vector<MapInput>& inputs)
{
  const auto start = std::chrono::steady_clock::now();
  std::vector<const PolygonMesh*> meshes;
  for (const MapInput& input : inputs)
  {
    meshes.push_back(&input.mesh);
  }
  std::vector<SphereEmbeddingResult> embeddings = embedAllOnSphere(meshes);
  for (std::size_t i = 0; i < inputs.size(); ++i)
  {
    inputs[i].spherePositions = std::move(embeddings[i].positions);
  }
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void printTimes(const Arguments& arguments,
  const std::vector<MapInput>& inputs,
  const SurfaceMapResult& r,
  double seconds,
  double embeddingSeconds)
{
  std::printf("inputs:");
  for (std::size_t i = 0; i < arguments.meshes.size(); ++i)
  {
    std::printf(" %s (%zu vertices)", arguments.meshes[i].c_str(), inputs[i].mesh.points.size());
  }
  std::printf("\ntotal %.2f s: embeddings %.2f s, map %.2f s; peak RSS %.0f MB; T %zu vertices\n",
    seconds,
    embeddingSeconds,
    r.seconds,
    benchmark::peakMegabytes(),
    r.lifted[0].size());
}

void printPhases(const SurfaceMapResult& r)
{
  std::printf(
    "| phase | iterations | converged | vertices | splits / collapses / flips | time (s) | "
    "remesh / derivatives / solve / line search / bookkeeping (s) "
    "|\n|---|---|---|---|---|---|---|\n");
  for (const MapPhaseReport& p : r.phases)
  {
    std::printf("| %s | %d | %s | %d | %d / %d / %d | %.2f | %.2f / %.2f / %.2f / %.2f / %.2f |\n",
      phaseName(p.kind),
      p.iterations,
      p.converged ? "yes" : "no",
      p.vertices,
      p.splits,
      p.collapses,
      p.flips,
      p.seconds,
      p.remeshSeconds,
      p.derivativeSeconds,
      p.solveSeconds,
      p.lineSearchSeconds,
      p.bookkeepingSeconds);
  }
}

// Prints the certificate, the landmark error, the energy and the error
// bounds; returns whether every certificate holds.
bool printResult(const SurfaceMapResult& r)
{
  bool certified = true;
  for (const auto& c : r.certificates)
  {
    certified = certified && c.bijective;
  }
  std::printf("certified: %s; landmark error %.3g\n", certified ? "yes" : "NO", r.landmarkError);
  std::printf(
    "final energy %.5g: barrier %.5g, mesh %.5g, approximation %.5g, map %.5g (unweighted)\n",
    r.energy.total,
    r.energy.barrier,
    r.energy.meshQuality,
    r.energy.approximation,
    r.energy.distortion);
  for (std::size_t i = 0; i < r.baseDistance.size(); ++i)
  {
    std::printf("input %zu: largest base-point distance %.4g (bound %.4g)\n",
      i,
      r.baseDistance[i],
      r.errorBound[i]);
  }
  return certified;
}

// The metrics of the approximating map T_0 -> T_j and of the exact map
// (input 0 -> input 0 on input j), for every j > 0.
void printMetrics(const std::vector<MapInput>& inputs, const SurfaceMapResult& r)
{
  std::printf("| map | SD | a1.5 | a2 | max | min angle T_0 / T_j | mean min angle |\n"
              "|---|---|---|---|---|---|---|\n");
  for (std::size_t j = 1; j < inputs.size(); ++j)
  {
    const MapMetrics approx = measureMap(r.lifted[0], r.lifted[j], r.triangles);
    const MapMetrics exact = measureMap(inputs[0].mesh.points,
      mappedVertices(r, inputs, 0, static_cast<int>(j)),
      inputs[0].mesh.triangles());
    double mean0 = 0.0, meanj = 0.0;
    const double min0 = minMeanMinAngle(r.lifted[0], r.triangles, &mean0);
    const double minj = minMeanMinAngle(r.lifted[j], r.triangles, &meanj);
    std::printf("| T_0 -> T_%zu | %.4f | %.3f | %.3f | %.3g | %.1f / %.1f | %.1f / %.1f |\n",
      j,
      approx.symmetricDirichlet,
      approx.areaFractionBelow(1.5),
      approx.areaFractionBelow(2.0),
      approx.maxDistortion,
      min0,
      minj,
      mean0,
      meanj);
    std::printf("| input 0 -> %zu (exact) | %.4f | %.3f | %.3f | %.3g | | |\n",
      j,
      exact.symmetricDirichlet,
      exact.areaFractionBelow(1.5),
      exact.areaFractionBelow(2.0),
      exact.maxDistortion);
  }
}

} // namespace

int main(int argc, char* argv[])
{
  Arguments arguments;
  if (!parseArguments(std::vector<std::string>(argv + 1, argv + argc), arguments))
  {
    return 2;
  }
  const auto start = std::chrono::steady_clock::now();
  std::vector<MapInput> inputs;
  if (!readInputs(arguments, inputs))
  {
    return 2;
  }
  const double embeddingSeconds = embedInputs(inputs);
  const SurfaceMapResult r = computeSurfaceMap(inputs, arguments.options);
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  printTimes(arguments, inputs, r, seconds, embeddingSeconds);
  printPhases(r);
  const bool certified = printResult(r);
  printMetrics(inputs, r);
  return certified ? 0 : 3;
}
