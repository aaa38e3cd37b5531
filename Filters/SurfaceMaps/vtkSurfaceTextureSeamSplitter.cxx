#include "vtkSurfaceTextureSeamSplitter.h"

#include "vtkSurfaceMapsErrorGuard.h"
#include "vtkSurfaceMapsExecutive.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkSurfaceTextureSeamSplitter);

namespace
{

struct Corner
{
  double u, v;
  vtkIdType point;
};

// Equal values, NaN equal to NaN: corners without a value share one copy.
bool sameValue(double a, double b)
{
  return a == b || (std::isnan(a) && std::isnan(b));
}

// Per output point, which input point it copies, and every triangle corner's
// output point: a point's first value keeps the input point, each further
// distinct value gets a new copy after the input's points.
struct Split
{
  std::vector<vtkIdType> original;
  vtkSmartPointer<vtkCellArray> polys;
  std::vector<double> values; // u, v per output point
};

Split splitCorners(vtkPolyData* input, vtkDataArray* corners)
{
  const vtkIdType n = input->GetNumberOfPoints();
  Split split;
  split.original.resize(n);
  for (vtkIdType p = 0; p < n; ++p)
  {
    split.original[p] = p;
  }
  split.values.assign(2 * n, std::numeric_limits<double>::quiet_NaN());
  std::vector<std::vector<Corner>> seen(n);
  split.polys = vtkSmartPointer<vtkCellArray>::New();
  auto cells = vtk::TakeSmartPointer(input->GetPolys()->NewIterator());
  vtkIdType cell = input->GetNumberOfVerts() + input->GetNumberOfLines();
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell(), ++cell)
  {
    vtkIdType size;
    const vtkIdType* ids;
    cells->GetCurrentCell(size, ids);
    if (size != 3)
    {
      throw std::invalid_argument("polygon " + std::to_string(cells->GetCurrentCellId()) +
        " has " + std::to_string(size) + " corners: texture seams are split on triangles only");
    }
    double t[6];
    corners->GetTuple(cell, t);
    vtkIdType out[3];
    for (int k = 0; k < 3; ++k)
    {
      std::vector<Corner>& copies = seen[ids[k]];
      out[k] = -1;
      for (const Corner& c : copies)
      {
        if (sameValue(c.u, t[2 * k]) && sameValue(c.v, t[2 * k + 1]))
        {
          out[k] = c.point;
        }
      }
      if (out[k] < 0)
      {
        out[k] = copies.empty() ? ids[k] : static_cast<vtkIdType>(split.original.size());
        if (out[k] != ids[k])
        {
          split.original.push_back(ids[k]);
          split.values.resize(split.values.size() + 2);
        }
        copies.push_back({ t[2 * k], t[2 * k + 1], out[k] });
        split.values[2 * out[k]] = t[2 * k];
        split.values[2 * out[k] + 1] = t[2 * k + 1];
      }
    }
    split.polys->InsertNextCell(3, out);
  }
  return split;
}

// The output of `split`: copied points and point data, the split triangles,
// the input's other cells, cell and field data.
void buildOutput(vtkPolyData* input, const Split& split, vtkPolyData* output)
{
  const vtkIdType n = static_cast<vtkIdType>(split.original.size());
  vtkNew<vtkPoints> points;
  points->SetDataType(input->GetPoints()->GetDataType());
  points->SetNumberOfPoints(n);
  vtkPointData* from = input->GetPointData();
  vtkPointData* to = output->GetPointData();
  to->CopyAllocate(from, n);
  for (vtkIdType p = 0; p < n; ++p)
  {
    points->SetPoint(p, input->GetPoint(split.original[p]));
    to->CopyData(from, split.original[p], p);
  }
  output->SetPoints(points);
  output->SetVerts(input->GetVerts());
  output->SetLines(input->GetLines());
  output->SetPolys(split.polys);
  output->SetStrips(input->GetStrips());
  output->GetCellData()->PassData(input->GetCellData());
  output->GetFieldData()->PassData(input->GetFieldData());

  vtkNew<vtkDoubleArray> tcoords;
  tcoords->SetName("TCoords");
  tcoords->SetNumberOfComponents(2);
  tcoords->SetNumberOfTuples(n);
  vtkDataArray* old = from->GetTCoords();
  for (vtkIdType p = 0; p < n; ++p)
  {
    double t[2] = { split.values[2 * p], split.values[2 * p + 1] };
    if (std::isnan(t[0]) && std::isnan(t[1]) && old && old->GetNumberOfComponents() >= 2)
    {
      t[0] = old->GetComponent(split.original[p], 0);
      t[1] = old->GetComponent(split.original[p], 1);
    }
    tcoords->SetTypedTuple(p, t);
  }
  to->SetTCoords(tcoords);
}

vtkSmartPointer<vtkIdTypeArray> originalIds(const std::vector<vtkIdType>& original)
{
  auto ids = vtkSmartPointer<vtkIdTypeArray>::New();
  ids->SetName("OriginalPointId");
  ids->SetNumberOfValues(static_cast<vtkIdType>(original.size()));
  for (std::size_t p = 0; p < original.size(); ++p)
  {
    ids->SetValue(static_cast<vtkIdType>(p), original[p]);
  }
  return ids;
}

} // namespace

int vtkSurfaceTextureSeamSplitter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  return vtkSurfaceMapsErrorGuard::Run(
    this,
    vtkSurfaceMapsErrorGuard::Policy(),
    [&]
    {
      vtkDataArray* corners = input->GetCellData()->GetArray("CornerTCoords");
      if (!corners || input->GetNumberOfPoints() == 0)
      {
        output->ShallowCopy(input);
        std::vector<vtkIdType> identity(input->GetNumberOfPoints());
        for (std::size_t p = 0; p < identity.size(); ++p)
        {
          identity[p] = static_cast<vtkIdType>(p);
        }
        output->GetPointData()->AddArray(originalIds(identity));
        return 1;
      }
      if (corners->GetNumberOfComponents() != 6 ||
        corners->GetNumberOfTuples() != input->GetNumberOfCells())
      {
        throw std::invalid_argument("\"CornerTCoords\" has " +
          std::to_string(corners->GetNumberOfComponents()) + " components and " +
          std::to_string(corners->GetNumberOfTuples()) + " tuples: expected 6 and one per cell (" +
          std::to_string(input->GetNumberOfCells()) + ")");
      }
      const Split split = splitCorners(input, corners);
      buildOutput(input, split, output);
      output->GetPointData()->AddArray(originalIds(split.original));
      return 1;
    },
    [output] { output->Initialize(); });
}

const char* vtkSurfaceTextureSeamSplitter::GetLastErrorMessage() const
{
  return vtkSurfaceMapsErrorGuard::LastErrorMessage(this);
}

vtkExecutive* vtkSurfaceTextureSeamSplitter::CreateDefaultExecutive()
{
  return vtkSurfaceMapsExecutive::New();
}

void vtkSurfaceTextureSeamSplitter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
