// Benchmark of the sphere embedding (not a test): time, peak memory and
// quality per mesh. Prints a Markdown table row per mesh.
//
//   build/bin/BenchmarkEmbedding MESH.(obj|off|ply)...
#include "BenchmarkSupport.h"
#include "mesh/MeshValidation.h"
#include "embedding/SphereEmbedding.h"

#include <chrono>
#include <cstdio>
#include <iostream>
#include <string>

using namespace surfacemaps;

using benchmark::peakMegabytes;
using benchmark::read;

int main(int argc, char* argv[])
{
  if (argc < 2)
  {
    std::fprintf(stderr, "usage: BenchmarkEmbedding MESH...\n");
    return 2;
  }
  std::printf(
    "| mesh | vertices | time (s) | peak RSS (MB) | certified | attempt | SD distortion | "
    "levels | Newton iterations | decimation / placement / derivatives / solve / line search "
    "(s) |\n|---|---|---|---|---|---|---|---|---|---|\n");
  double total = 0.0;
  for (int i = 1; i < argc; ++i)
  {
    try
    {
      const auto start = std::chrono::steady_clock::now();
      const PolygonMesh mesh = read(argv[i]);
      const MeshValidationResult validation = validateMesh(mesh);
      if (!validation.valid())
      {
        std::fprintf(stderr, "%s: %s\n", argv[i], validation.defects[0].c_str());
        return 2;
      }
      SphereEmbeddingOptions options;
      if (const char* w = std::getenv("SURFACEMAPS_BARRIER"))
      {
        options.barrierWeight = std::atof(w);
      }
      if (const char* w = std::getenv("SURFACEMAPS_LEVEL_ITERATIONS"))
      {
        options.levelIterationsLarge = std::atoi(w);
      }
      if (std::getenv("SURFACEMAPS_VERBOSE"))
      {
        options.log.sink = [](Logger::Level, const std::string& m) { std::cerr << m << "\n"; };
      }
      const SphereEmbeddingResult r = embedOnSphere(mesh, options);
      const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      total += seconds;
      std::printf(
        "| %s | %zu | %.2f | %.0f | %s | %d | %.3f | %d | %d | %.2f / %.2f / %.2f / %.2f / "
        "%.2f |\n",
        argv[i],
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
      std::printf("| %s | | | | FAILED: %s | | | | | |\n", argv[i], e.what());
    }
  }
  std::printf("\ntotal time %.2f s\n", total);
  return 0;
}
