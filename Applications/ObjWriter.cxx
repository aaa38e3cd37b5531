// The `surfacemap` command line: the OBJ writer (points, per-corner
// texture coordinates and normals, triangles).
#include "ObjWriter.h"

#include "AtomicFiles.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <sstream>
#include <vector>

namespace surfacemap
{

namespace
{

// A per-corner cell array of an OBJ's faces ("CornerTCoords" as vt,
// "CornerNormals" as vn): one line per distinct value, numbered in order of
// appearance; a face whose corners are not all finite goes without it.
class ObjCornerAttribute
{
public:
  ObjCornerAttribute(vtkPolyData* data, const char* name, int components, const char* keyword)
    : Keyword(keyword)
    , Components(components)
  {
    vtkDataArray* array = data->GetCellData()->GetArray(name);
    this->Array = array && array->GetNumberOfComponents() == 3 * components ? array : nullptr;
  }

  /// Writes the new values of `cell`'s corners to `obj`; their indices (0: none).
  std::array<long long, 3> add(vtkIdType cell, std::ostream& obj)
  {
    std::array<long long, 3> index{ 0, 0, 0 };
    if (!this->Array)
    {
      return index;
    }
    std::vector<double> values(3 * this->Components);
    this->Array->GetTuple(cell, values.data());
    if (!std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); }))
    {
      return index;
    }
    for (int k = 0; k < 3; ++k)
    {
      const std::vector<double> value(
        values.begin() + k * this->Components, values.begin() + (k + 1) * this->Components);
      const auto added =
        this->Indices.emplace(value, static_cast<long long>(this->Indices.size()) + 1);
      if (added.second)
      {
        obj << this->Keyword;
        for (double v : value)
        {
          obj << ' ' << v;
        }
        obj << '\n';
      }
      index[k] = added.first->second;
    }
    return index;
  }

private:
  const char* Keyword;
  int Components;
  vtkDataArray* Array = nullptr;
  std::map<std::vector<double>, long long> Indices;
};

} // namespace

void writeObjAtomically(vtkPolyData* data, const std::string& path)
{
  std::ostringstream obj;
  obj.precision(17);
  obj << "# written by surfacemap\n";
  for (vtkIdType p = 0; p < data->GetNumberOfPoints(); ++p)
  {
    const double* x = data->GetPoint(p);
    obj << "v " << x[0] << ' ' << x[1] << ' ' << x[2] << '\n';
  }
  ObjCornerAttribute texture(data, "CornerTCoords", 2, "vt");
  ObjCornerAttribute normals(data, "CornerNormals", 3, "vn");
  // Per face: vertex, texture and normal index (1-based; 0: none) per corner.
  std::vector<std::array<std::array<long long, 3>, 3>> faces;
  auto cells = vtk::TakeSmartPointer(data->GetPolys()->NewIterator());
  vtkIdType cell = data->GetNumberOfVerts() + data->GetNumberOfLines();
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell(), ++cell)
  {
    vtkIdType size;
    const vtkIdType* ids;
    cells->GetCurrentCell(size, ids);
    if (size != 3)
    {
      writeFailed(
        path, "polygon " + std::to_string(cells->GetCurrentCellId()) + " is not a triangle");
    }
    faces.push_back({ std::array<long long, 3>{ ids[0] + 1, ids[1] + 1, ids[2] + 1 },
      texture.add(cell, obj),
      normals.add(cell, obj) });
  }
  for (const auto& face : faces)
  {
    obj << 'f';
    for (int k = 0; k < 3; ++k)
    {
      obj << ' ' << face[0][k];
      if (face[1][k] > 0 || face[2][k] > 0)
      {
        obj << '/' << (face[1][k] > 0 ? std::to_string(face[1][k]) : std::string());
      }
      if (face[2][k] > 0)
      {
        obj << '/' << face[2][k];
      }
    }
    obj << '\n';
  }
  writeFileAtomically(path, obj.str());
}

} // namespace surfacemap
