// Several maps at once in one process: each filter on its own thread gives
// exactly the map it gives alone (no state shared between filters or runs).
#include "FilterTestData.h"

#include "vtkPointData.h"
#include "vtkPoints.h"

#include <gtest/gtest.h>

#include <thread>

namespace
{

struct Job
{
  const char* source;
  const char* target;
  int fineIterations; // settings differ too, so that no two maps are alike
};

// Two jobs: the machine the suite runs on has two cores.
const Job Jobs[] = { { "ellipsoid_coarse.stl", "blob.off", 2 },
  { "ellipsoid_coarse.stl", "ellipsoid_coarse.stl", 3 } };

// Every output's points and sphere positions, one value after another.
std::vector<double> mapValues(const Job& job)
{
  vtkNew<vtkSurfaceMapFilter> map;
  filtertest::useShortSchedule(map);
  map->SetFineIterations(job.fineIterations);
  map->SetNumberOfThreads(1); // the jobs share the machine's cores
  map->AddInputData(filtertest::read(job.source));
  map->AddInputData(filtertest::read(job.target));
  map->Update();
  std::vector<double> values;
  for (int i = 0; i < 2; ++i)
  {
    vtkPolyData* output = map->GetOutput(i);
    for (vtkIdType v = 0; v < output->GetNumberOfPoints(); ++v)
    {
      double p[3];
      output->GetPoint(v, p);
      values.insert(values.end(), p, p + 3);
      output->GetPointData()->GetArray("SpherePosition")->GetTuple(v, p);
      values.insert(values.end(), p, p + 3);
    }
  }
  return values;
}

} // namespace

TEST(ConcurrentMaps, ThreadsGiveTheMapsOneAtATimeGives)
{
  constexpr std::size_t n = sizeof(Jobs) / sizeof(Jobs[0]);
  std::vector<std::vector<double>> alone(n), together(n);
  for (std::size_t k = 0; k < n; ++k)
  {
    alone[k] = mapValues(Jobs[k]);
    ASSERT_FALSE(alone[k].empty()) << "job " << k << " computed no map";
  }
  std::vector<std::thread> threads;
  for (std::size_t k = 0; k < n; ++k)
  {
    threads.emplace_back([k, &together] { together[k] = mapValues(Jobs[k]); });
  }
  for (std::thread& thread : threads)
  {
    thread.join();
  }
  for (std::size_t k = 0; k < n; ++k)
  {
    // Bit for bit: the engine's results depend neither on the thread count
    // nor on what else runs in the process.
    EXPECT_EQ(together[k], alone[k]) << "job " << k;
  }
}
