// Benchmark of the sphere embedding (not a test): time, peak memory and
// quality per mesh. Prints a Markdown table row per mesh.
//
//   build/bin/BenchmarkEmbedding MESH.(obj|off|ply)... [-v] [SETTING ...]
// with the settings' flags of `surfacemap embed` (the engine's list).
#include "BenchmarkSupport.h"
#include "embedding/SphereEmbedding.h"
#include "map/MapSettings.h"
#include "mesh/MeshValidation.h"

#include <chrono>
#include <cstdio>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

using namespace surfacemaps;

using benchmark::peakMegabytes;
using benchmark::read;

namespace
{
// The meshes and the options the command line gives; false after printing
// why (an unknown option, a bad setting, no mesh).
bool parseArguments(const std::vector<std::string>& args,
  std::vector<std::string>& meshes,
  SphereEmbeddingOptions& options)
{
  try
  {
    for (std::size_t a = 0; a < args.size(); ++a)
    {
      if (args[a] == "-v")
      {
        options.log.sink = [](Logger::Level, const std::string& m) { std::cerr << m << "\n"; };
      }
      else if (!parseSettingFlag(args, a, options))
      {
        if (args[a][0] == '-')
        {
          throw std::invalid_argument("unknown option '" + args[a] + "'");
        }
        meshes.push_back(args[a]);
      }
    }
  }
  catch (const std::invalid_argument& e)
  {
    std::fprintf(stderr, "BenchmarkEmbedding: %s\n", e.what());
    return false;
  }
  if (meshes.empty())
  {
    std::fprintf(stderr, "usage: BenchmarkEmbedding MESH... [-v] [SETTING ...]\nsettings:");
    for (const EmbeddingSetting& s : embeddingSettings())
    {
      std::fprintf(stderr, " --%s", s.flag);
    }
    std::fprintf(stderr, "\n");
    return false;
  }
  return true;
}
} // namespace

int main(int argc, char* argv[])
{
  std::vector<std::string> meshes;
  SphereEmbeddingOptions options;
  if (!parseArguments(std::vector<std::string>(argv + 1, argv + argc), meshes, options))
  {
    return 2;
  }
  std::printf(
    "| mesh | vertices | time (s) | peak RSS (MB) | certified | attempt | SD distortion | "
    "levels | Newton iterations | decimation / placement / derivatives / solve / line search "
    "(s) |\n|---|---|---|---|---|---|---|---|---|---|\n");
  double total = 0.0;
  for (const std::string& file : meshes)
  {
    try
    {
      const auto start = std::chrono::steady_clock::now();
      const PolygonMesh mesh = read(file);
      const MeshValidationResult validation = validateMesh(mesh);
      if (!validation.valid())
      {
        std::fprintf(stderr, "%s: %s\n", file.c_str(), validation.defects[0].c_str());
        return 2;
      }
      const SphereEmbeddingResult r = embedOnSphere(mesh, options);
      const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      total += seconds;
      std::printf(
        "| %s | %zu | %.2f | %.0f | %s | %d | %.3f | %d | %d | %.2f / %.2f / %.2f / %.2f / "
        "%.2f |\n",
        file.c_str(),
        mesh.points.size(),
        seconds,
        peakMegabytes(),
        r.certificate.bijective ? "yes" : "NO",
        r.attempt,
        r.distortion,
        r.levels,
        r.newtonIterations,
        r.decimationSeconds,
        r.placementSeconds,
        r.derivativeSeconds,
        r.solveSeconds,
        r.lineSearchSeconds);
      std::fflush(stdout);
    }
    catch (const std::exception& e)
    {
      std::printf("| %s | | | | FAILED: %s | | | | | |\n", file.c_str(), e.what());
    }
  }
  std::printf("\ntotal time %.2f s\n", total);
  return 0;
}
