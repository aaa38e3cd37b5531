// Reads two bundled meshes, validates them and maps one onto the other with
// a short schedule, using only the installed SurfaceMaps headers and library.
// Usage: surfacemaps_consumer DATA_DIR; exit code 0 only for a certified map.
#include "vtkSurfaceMapFilter.h"
#include "vtkSurfaceMeshReader.h"
#include "vtkSurfaceMeshValidator.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPolyData.h"

#include <iostream>
#include <string>

int main(int argc, char* argv[])
{
  if (argc != 2)
  {
    std::cerr << "usage: " << argv[0] << " DATA_DIR\n";
    return 2;
  }
  const std::string data = argv[1];

  // The STL file goes through VTK's IOGeometry (one of the module's private
  // dependencies), the OFF file through the module's own reader.
  vtkNew<vtkSurfaceMeshReader> source;
  source->SetFileName((data + "/ellipsoid_coarse.stl").c_str());
  vtkNew<vtkSurfaceMeshReader> target;
  target->SetFileName((data + "/blob.off").c_str());

  vtkNew<vtkSurfaceMeshValidator> validator;
  validator->AddInputConnection(source->GetOutputPort());
  validator->AddInputConnection(target->GetOutputPort());
  validator->Update();
  if (!validator->GetAllValid())
  {
    std::cerr << "consumer: the bundled meshes are not valid inputs\n";
    return 1;
  }

  vtkNew<vtkSurfaceMapFilter> map;
  map->AddInputConnection(source->GetOutputPort());
  map->AddInputConnection(target->GetOutputPort());
  map->SetLandmarkIterations(10);
  map->SetCoarseIterations(3);
  map->SetFineIterations(3);
  map->Update();

  vtkPolyData* lifted = vtkPolyData::SafeDownCast(map->GetOutputDataObject(1));
  vtkDataArray* bijective = lifted
    ? vtkDataArray::SafeDownCast(lifted->GetFieldData()->GetAbstractArray("Bijective"))
    : nullptr;
  if (!bijective || bijective->GetTuple1(0) != 1.0 || lifted->GetNumberOfPoints() == 0)
  {
    std::cerr << "consumer: no certified map\n";
    return 1;
  }
  std::cout << "consumer: 2 valid inputs, certified map, common triangulation of "
            << lifted->GetNumberOfPoints() << " vertices\n";
  return 0;
}
