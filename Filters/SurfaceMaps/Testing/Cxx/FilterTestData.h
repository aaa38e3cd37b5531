// Helpers shared by the VTK filter tests: reading Data/ meshes and looking at
// a vtkPolyData's triangles.
#pragma once

#include "vtkSurfaceMapFilter.h"
#include "vtkSurfaceMeshReader.h"

#include "vtkAlgorithm.h"
#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <array>
#include <string>
#include <vector>

namespace filtertest
{

/// Data/<file> read by vtkSurfaceMeshReader, with Data/<landmarks> if given.
inline vtkSmartPointer<vtkPolyData> read(const std::string& file, const std::string& landmarks = "")
{
  const std::string data = SURFACEMAPS_DATA_DIR;
  vtkNew<vtkSurfaceMeshReader> reader;
  reader->SetFileName((data + "/" + file).c_str());
  if (!landmarks.empty())
  {
    reader->SetLandmarkFileName((data + "/" + landmarks).c_str());
  }
  reader->Update();
  vtkSmartPointer<vtkPolyData> output = reader->GetOutput();
  return output;
}

/// The point ids of every polygon, one after another.
inline std::vector<vtkIdType> connectivity(vtkPolyData* data)
{
  std::vector<vtkIdType> ids;
  vtkDataArray* c = data->GetPolys()->GetConnectivityArray();
  for (vtkIdType k = 0; k < c->GetNumberOfTuples(); ++k)
  {
    ids.push_back(static_cast<vtkIdType>(c->GetTuple1(k)));
  }
  return ids;
}

/// The triangles of a triangle mesh.
inline std::vector<std::array<int, 3>> triangles(vtkPolyData* data)
{
  const std::vector<vtkIdType> ids = connectivity(data);
  std::vector<std::array<int, 3>> result;
  for (std::size_t k = 0; k + 2 < ids.size(); k += 3)
  {
    result.push_back(
      { static_cast<int>(ids[k]), static_cast<int>(ids[k + 1]), static_cast<int>(ids[k + 2]) });
  }
  return result;
}

/// What a filter reported during updates: error messages, progress values
/// and texts; progress above AbortAbove aborts the update.
struct Events
{
  std::vector<std::string> Errors;
  std::vector<double> Progress;
  std::vector<std::string> Texts;
  double AbortAbove = 2.0;
};

/// Records a filter's errors and progress into `events`.
inline void watch(vtkAlgorithm* filter, Events& events)
{
  vtkNew<vtkCallbackCommand> onError;
  onError->SetClientData(&events);
  onError->SetCallback([](vtkObject*, unsigned long, void* client, void* text)
    { static_cast<Events*>(client)->Errors.emplace_back(static_cast<const char*>(text)); });
  filter->AddObserver(vtkCommand::ErrorEvent, onError);
  vtkNew<vtkCallbackCommand> onProgress;
  onProgress->SetClientData(&events);
  onProgress->SetCallback(
    [](vtkObject* object, unsigned long, void* client, void*)
    {
      auto* e = static_cast<Events*>(client);
      auto* f = static_cast<vtkAlgorithm*>(object);
      e->Progress.push_back(f->GetProgress());
      e->Texts.emplace_back(f->GetProgressText() ? f->GetProgressText() : "");
      if (f->GetProgress() > e->AbortAbove)
      {
        f->AbortExecuteOn();
      }
    });
  filter->AddObserver(vtkCommand::ProgressEvent, onProgress);
}

/// Whether the watched vtkSurfaceMapFilter computed a map (rather than
/// reusing the kept one) during the recorded updates.
inline bool computedTheMap(const Events& events)
{
  return std::any_of(events.Texts.begin(),
    events.Texts.end(),
    [](const std::string& t) { return t.find(" phase, iteration ") != std::string::npos; });
}

/// A schedule short enough for tests (about a second for 642-vertex meshes).
inline void useShortSchedule(vtkSurfaceMapFilter* filter)
{
  filter->SetLandmarkIterations(10);
  filter->SetCoarseIterations(3);
  filter->SetFineIterations(3);
}

} // namespace filtertest
