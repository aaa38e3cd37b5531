// SurfaceMaps engine: the sphere embedding's entry points: embedOnSphere
// (decimation, the attempts with their retries, certification and the
// distortion check), embedAllOnSphere (several meshes on shared threads)
// and embeddingDistortion.
#include "embedding/SphereEmbedding.h"
#include "base/Error.h"

#include "embedding/Decimation.h"
#include "embedding/Embedder.h"
#include "geometry/MapMetrics.h"

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <limits>
#include <memory>
#include <optional>

namespace surfacemaps
{

namespace
{
using Clock = std::chrono::steady_clock;

// Notes why attempt `a` (0-based) failed: in `reasons` (the final error)
// and in the log, as "sphere embedding attempt <a + 1><how><reason>".
void noteFailure(std::string& reasons,
  int a,
  const std::string& reason,
  const char* how,
  const Logger& log)
{
  reasons += (reasons.empty() ? "" : "; ") + ("attempt " + std::to_string(a + 1) + ": " + reason);
  log(Logger::Warning, "sphere embedding attempt " + std::to_string(a + 1) + how + reason);
}

// Attempt `a` with the weights `attempt`: the embedding, certified and
// measured, or nothing (noted in `reasons`) if it failed or is not
// bijective. Its progress covers what is left of the range from `reached`
// on, and moves `reached` with it: progress never goes back.
std::optional<SphereEmbeddingResult> certifiedAttempt(const PolygonMesh& mesh,
  const DecimationResult& hierarchy,
  const SphereEmbeddingOptions& options,
  const Attempt& attempt,
  int a,
  double& reached,
  std::string& reasons)
{
  SphereEmbeddingResult result;
  result.attempt = a + 1;
  SphereEmbeddingOptions attemptOptions = options;
  if (options.progress)
  {
    const double from = reached;
    attemptOptions.progress = [&options, &reached, from](double fraction)
    {
      reached = from + (1.0 - from) * fraction;
      return options.progress(reached);
    };
  }
  Embedder embedder(mesh, hierarchy, attemptOptions);
  try
  {
    embedder.run(attempt, result);
  }
  catch (const AttemptFailed& failure)
  {
    noteFailure(reasons, a, failure.reason, " failed: ", options.log);
    return std::nullopt;
  }
  result.certificate = certifyBijective(result.positions, hierarchy.triangles);
  if (!result.certificate.bijective)
  {
    noteFailure(reasons, a, result.certificate.reason, " not bijective: ", options.log);
    return std::nullopt;
  }
  result.distortion = embeddingDistortion(mesh.points, result.positions, hierarchy.triangles);
  result.smallestAreaRatio =
    smallestAreaRatioOf(mesh.points, result.positions, hierarchy.triangles);
  return result;
}

SphereEmbeddingResult finished(SphereEmbeddingResult result,
  Clock::time_point start,
  const SphereEmbeddingOptions& options)
{
  result.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  if (options.progress)
  {
    options.progress(1.0);
  }
  return result;
}

// The state embedAllOnSphere's threads share: each mesh's fraction done, the
// abort flag, and how many embeddings run. One mesh per thread. Embeddings
// take unequal times (one may need a second attempt), so a thread whose
// meshes are done lends itself to the ones still running: each running
// embedding's own parallel regions (a nested level) get an equal share of
// the threads, updated after every Newton step. The results do not depend
// on the thread count, only the time does.
class SharedEmbeddings
{
public:
  SharedEmbeddings(int n, const SphereEmbeddingOptions& options)
    : N(n)
    , Options(options)
    , Fractions(new std::atomic<double>[n])
    , Available(omp_get_max_threads())
  {
    for (int i = 0; i < n; ++i)
    {
      this->Fractions[i] = 0.0;
    }
  }

  int available() const { return this->Available; }
  bool aborted() const { return this->Aborted; }
  void started() { ++this->Running; }
  void stopped() { --this->Running; }
  void done(int i) { this->Fractions[i] = 1.0; }

  // The threads each running embedding's own parallel regions get.
  int share() const { return std::max(1, this->Available / std::max(1, this->Running.load())); }

  // Mesh i's options: its progress updates its fraction and its thread
  // share; the reporter also reports the mean fraction to the caller.
  SphereEmbeddingOptions optionsFor(int i, bool reporter)
  {
    SphereEmbeddingOptions local = this->Options;
    local.progress = [this, i, reporter](double fraction)
    {
      this->Fractions[i] = fraction;
      omp_set_num_threads(this->share());
      if (this->Aborted)
      {
        return false;
      }
      if (reporter && this->Options.progress)
      {
        double mean = 0.0;
        for (int k = 0; k < this->N; ++k)
        {
          mean += this->Fractions[k] / this->N;
        }
        if (!this->Options.progress(mean))
        {
          this->Aborted = true;
          return false;
        }
      }
      return true;
    };
    return local;
  }

private:
  const int N;
  const SphereEmbeddingOptions& Options;
  std::unique_ptr<std::atomic<double>[]> Fractions;
  std::atomic<bool> Aborted{ false };
  const int Available;
  std::atomic<int> Running{ 0 };
};

// Rethrows the first mesh's (by index) error: Aborted as it is, any other
// as EmbeddingFailure.
void rethrowFirstError(const std::vector<std::exception_ptr>& errors)
{
  for (std::size_t i = 0; i < errors.size(); ++i)
  {
    if (errors[i])
    {
      try
      {
        std::rethrow_exception(errors[i]);
      }
      catch (const Aborted&)
      {
        throw;
      }
      catch (const std::exception& e)
      {
        throw EmbeddingFailure(static_cast<int>(i), e.what());
      }
    }
  }
}
} // namespace

double embeddingDistortion(const std::vector<Eigen::Vector3d>& input,
  const std::vector<Eigen::Vector3d>& sphere,
  const std::vector<std::array<int, 3>>& triangles)
{
  // The map from the input to its chord triangles, measured like any map.
  return measureMap(input, sphere, triangles).symmetricDirichlet;
}

std::vector<SphereEmbeddingResult> embedAllOnSphere(const std::vector<const PolygonMesh*>& meshes,
  const SphereEmbeddingOptions& options)
{
  const int n = static_cast<int>(meshes.size());
  std::vector<SphereEmbeddingResult> results(n);
  if (n == 1)
  {
    try
    {
      results[0] = embedOnSphere(*meshes[0], options);
    }
    catch (const std::runtime_error& e)
    {
      throw EmbeddingFailure(0, e.what());
    }
    return results;
  }
  SharedEmbeddings shared(n, options);
  std::vector<std::exception_ptr> errors(n);
  const int threads = std::max(1, std::min(n, shared.available()));
  const int previousLevels = omp_get_max_active_levels();
  omp_set_max_active_levels(std::max(previousLevels, 2));
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (int i = 0; i < n; ++i)
  {
    shared.started();
    omp_set_num_threads(shared.share());
    const SphereEmbeddingOptions local = shared.optionsFor(i, omp_get_thread_num() == 0);
    try
    {
      results[i] = embedOnSphere(*meshes[i], local);
      shared.done(i);
    }
    catch (...)
    {
      errors[i] = std::current_exception();
    }
    shared.stopped();
  }
  omp_set_max_active_levels(previousLevels);
  if (shared.aborted())
  {
    throw Aborted{};
  }
  rethrowFirstError(errors);
  return results;
}

SphereEmbeddingResult embedOnSphere(const PolygonMesh& mesh, const SphereEmbeddingOptions& options)
{
  const auto start = Clock::now();
  DecimationOptions decimation;
  decimation.log = options.log;
  const DecimationResult hierarchy = decimateToTetrahedron(mesh, decimation);
  const double decimationSeconds = std::chrono::duration<double>(Clock::now() - start).count();
  options.log(Logger::Detail,
    "sphere embedding: " + std::to_string(hierarchy.levels.size()) + " decimation levels");

  const double never = std::numeric_limits<double>::infinity();
  const Attempt attempts[] = {
    { options.barrierWeight, 1.0, options.maxDistortion },
    { 100.0 * options.barrierWeight,
      1.0,
      never },           // the last to minimise distortion: runs to the end
    { 1.0, 0.0, never }, // barrier alone
  };
  std::string reasons;
  double reached = 0.0;
  std::optional<SphereEmbeddingResult> best;
  for (int a = 0; a < 3; ++a)
  {
    std::optional<SphereEmbeddingResult> result =
      certifiedAttempt(mesh, hierarchy, options, attempts[a], a, reached, reasons);
    if (!result)
    {
      continue;
    }
    result->decimationSeconds = decimationSeconds;
    if (!(result->distortion <= options.maxDistortion))
    {
      const std::string reason = "nearly degenerate triangles on the sphere (distortion " +
        std::to_string(result->distortion) + ")";
      noteFailure(reasons, a, reason, ": ", options.log);
      if (!best || result->distortion < best->distortion)
      {
        best = std::move(result);
      }
      continue;
    }
    return finished(std::move(*result), start, options);
  }
  // Every certified attempt was too distorted: the least distorted one is
  // still a valid embedding, and better than none.
  if (best)
  {
    options.log(Logger::Warning,
      "sphere embedding: no attempt reached distortion " + std::to_string(options.maxDistortion) +
        "; keeping attempt " + std::to_string(best->attempt) + " (distortion " +
        std::to_string(best->distortion) + ")");
    return finished(std::move(*best), start, options);
  }
  throw NoResultError("no bijective sphere embedding found (" + reasons + ")");
}

} // namespace surfacemaps
