// Helpers shared by the VTK filter tests: reading Data/ meshes and looking at
// a vtkPolyData's triangles.
#pragma once

#include "vtkSurfaceMeshReader.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

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

} // namespace filtertest
