#include "vtkSurfaceMapsPointDataTransfer.h"

#include "vtkSurfaceArrayTransferAlgorithm.h"

#include "vtkAbstractArray.h"
#include "vtkIdList.h"
#include "vtkNew.h"
#include "vtkPointData.h"

#include <stdexcept>
#include <string>

vtkSmartPointer<vtkAbstractArray> vtkSurfaceMapsPointDataTransfer::Sample(vtkAbstractArray* array,
  const std::vector<std::array<int, 3>>& triangles,
  const std::vector<surfacemaps::SurfacePoint>& points,
  bool categorical)
{
  auto result = vtk::TakeSmartPointer(array->NewInstance());
  result->SetName(array->GetName());
  result->SetNumberOfComponents(array->GetNumberOfComponents());
  result->CopyComponentNames(array);
  result->SetNumberOfTuples(static_cast<vtkIdType>(points.size()));
  vtkNew<vtkIdList> corners;
  corners->SetNumberOfIds(3);
  for (std::size_t v = 0; v < points.size(); ++v)
  {
    const surfacemaps::SurfacePoint& p = points[v];
    if (p.triangle < 0 || static_cast<std::size_t>(p.triangle) >= triangles.size())
    {
      throw std::logic_error("point " + std::to_string(v) + " lies on no triangle of its input");
    }
    const std::array<int, 3>& t = triangles[p.triangle];
    if (categorical)
    {
      result->SetTuple(static_cast<vtkIdType>(v), t[surfacemaps::nearestCorner(p)], array);
      continue;
    }
    double w[3] = { p.barycentric[0], p.barycentric[1], p.barycentric[2] };
    for (int k = 0; k < 3; ++k)
    {
      corners->SetId(k, t[k]);
    }
    result->InterpolateTuple(static_cast<vtkIdType>(v), corners, array, w);
  }
  return result;
}

void vtkSurfaceMapsPointDataTransfer::SampleArrays(vtkPointData* from,
  const std::vector<vtkAbstractArray*>& arrays,
  vtkPointData* to,
  const std::vector<std::array<int, 3>>& triangles,
  const std::vector<surfacemaps::SurfacePoint>& points,
  vtkSurfaceArrayTransferAlgorithm* modes)
{
  for (vtkAbstractArray* array : arrays)
  {
    const bool categorical = modes->ResolveArrayTransferMode(array) ==
      vtkSurfaceArrayTransferAlgorithm::ARRAY_TRANSFER_CATEGORICAL;
    to->AddArray(Sample(array, triangles, points, categorical));
    int index = -1;
    from->GetAbstractArray(array->GetName(), index);
    const int attribute = index >= 0 ? from->IsArrayAnAttribute(index) : -1;
    if (attribute >= 0)
    {
      to->SetActiveAttribute(array->GetName(), attribute);
    }
  }
}
