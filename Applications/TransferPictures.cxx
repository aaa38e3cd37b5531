#include "TransferPictures.h"

#include "Pictures.h"

#include "vtkSurfaceMapTransfer.h"
#include "vtkSurfaceTextureSeamSplitter.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkIdList.h"
#include "vtkLookupTable.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPointDataToCellData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkSmartPointer.h"
#include "vtkTexture.h"
#include "vtkVariant.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <set>
#include <utility>

namespace surfacemap
{

namespace
{

// Categorical arrays with more labels than this get no legend (it would not
// fit beside the surfaces).
const std::size_t MaxLegendLabels = 12;

// What one picture shows: the source side's and the target side's mesh (each
// with the array), their captions, and the rotation taking the target onto
// the source through the map (mapRotation).
struct TransferSides
{
  vtkPolyData* source;
  vtkPolyData* target;
  std::string sourceCaption, targetCaption;
  double rotation[3][3] = { { 1.0, 0.0, 0.0 }, { 0.0, 1.0, 0.0 }, { 0.0, 0.0, 1.0 } };
};

// The rotation taking `target` (the transfer's output) onto `source`, fitted
// between each target vertex and the source point it maps to ("SourceCellId"
// and "SourceBarycentric"); the identity without those arrays.
void mapRotation(vtkPolyData* source, vtkPolyData* target, double rotation[3][3])
{
  vtkDataArray* cells = target->GetPointData()->GetArray("SourceCellId");
  vtkDataArray* weights = target->GetPointData()->GetArray("SourceBarycentric");
  if (!cells || !weights || weights->GetNumberOfComponents() < 2)
  {
    return;
  }
  vtkNew<vtkPoints> mapped;
  vtkNew<vtkIdList> corners;
  for (vtkIdType v = 0; v < target->GetNumberOfPoints(); ++v)
  {
    source->GetCellPoints(static_cast<vtkIdType>(cells->GetComponent(v, 0)), corners);
    const double w[3] = { weights->GetComponent(v, 0),
      weights->GetComponent(v, 1),
      weights->GetNumberOfComponents() > 2
        ? weights->GetComponent(v, 2)
        : 1.0 - weights->GetComponent(v, 0) - weights->GetComponent(v, 1) };
    double p[3] = { 0.0, 0.0, 0.0 };
    for (vtkIdType k = 0; k < std::min<vtkIdType>(3, corners->GetNumberOfIds()); ++k)
    {
      const double* corner = source->GetPoint(corners->GetId(k));
      for (int i = 0; i < 3; ++i)
      {
        p[i] += w[k] * corner[i];
      }
    }
    mapped->InsertNextPoint(p);
  }
  alignRotation(mapped, target->GetPoints(), rotation);
}

// `panels` (source, target) with the target seen from the source's side.
std::vector<SurfacePanel> turned(std::vector<SurfacePanel> panels, const TransferSides& sides)
{
  std::copy(&sides.rotation[0][0], &sides.rotation[0][0] + 9, &panels[1].rotation[0][0]);
  return panels;
}

// The two sides as (mesh, caption), source first.
std::array<std::pair<vtkPolyData*, std::string>, 2> bothSides(const TransferSides& sides)
{
  return { std::make_pair(sides.source, sides.sourceCaption),
    std::make_pair(sides.target, sides.targetCaption) };
}

// Arrays that are not data carried from the source (TCoords: the texture
// coordinates, for a textured picture).
bool isBookkeeping(const std::string& name)
{
  return name == "SourceCellId" || name == "SourceBarycentric" || name == "TCoords" ||
    name == "SpherePosition" || name == "Landmarks";
}

bool isColours(vtkDataArray* array)
{
  return array->GetDataType() == VTK_UNSIGNED_CHAR &&
    (array->GetNumberOfComponents() == 3 || array->GetNumberOfComponents() == 4);
}

void writeContinuousPicture(const TransferSides& sides,
  const std::string& name,
  const std::string& path)
{
  vtkDataArray* arrays[2] = { sides.source->GetPointData()->GetArray(name.c_str()),
    sides.target->GetPointData()->GetArray(name.c_str()) };
  const bool magnitude = arrays[0]->GetNumberOfComponents() > 1;
  double range[2] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MIN };
  for (vtkDataArray* array : arrays)
  {
    double side[2];
    array->GetRange(side, magnitude ? -1 : 0);
    range[0] = std::min(range[0], side[0]);
    range[1] = std::max(range[1], side[1]);
  }
  vtkSmartPointer<vtkLookupTable> colours = rainbowTable(range);
  if (magnitude)
  {
    colours->SetVectorModeToMagnitude();
  }
  std::vector<SurfacePanel> panels;
  for (const auto& [mesh, caption] : bothSides(sides))
  {
    vtkSmartPointer<vtkPolyDataMapper> mapper = arrayMapper(mesh, name, false);
    mapper->SetColorModeToMapScalars();
    mapper->SetLookupTable(colours);
    mapper->UseLookupTableScalarRangeOn();
    mapper->InterpolateScalarsBeforeMappingOn();
    panels.push_back({ mapper, caption });
  }
  writeSurfacePicture(
    turned(panels, sides), colours, magnitude ? name + " (magnitude)" : name, path);
}

// `mesh` with one cell array `name`: per triangle the label most of its
// corners carry in the point array `name`.
vtkSmartPointer<vtkPolyData> cellLabels(vtkPolyData* mesh, const std::string& name)
{
  vtkNew<vtkPolyData> labelled;
  labelled->CopyStructure(mesh);
  // VTK 9.1's categorical mode converts the active scalars only.
  labelled->GetPointData()->SetScalars(mesh->GetPointData()->GetArray(name.c_str()));
  vtkNew<vtkPointDataToCellData> toCells;
  toCells->SetInputData(labelled);
  toCells->CategoricalDataOn();
  toCells->PassPointDataOff();
  toCells->Update();
  auto result = vtkSmartPointer<vtkPolyData>::New();
  result->ShallowCopy(toCells->GetOutput());
  return result;
}

// One colour per label of `labels` (the source's: the target has no others),
// hues spread by the golden angle so neighbouring labels differ.
vtkSmartPointer<vtkLookupTable> labelTable(vtkDataArray* labels)
{
  std::set<vtkVariant, vtkVariantLessThan> values;
  for (vtkIdType i = 0; i < labels->GetNumberOfTuples(); ++i)
  {
    values.insert(labels->GetVariantValue(i));
  }
  auto table = vtkSmartPointer<vtkLookupTable>::New();
  table->IndexedLookupOn();
  table->SetNumberOfTableValues(static_cast<vtkIdType>(values.size()));
  vtkIdType k = 0;
  for (const vtkVariant& value : values)
  {
    const double hsv[3] = { std::fmod(0.618033988749895 * k, 1.0), 0.65, k % 2 ? 0.75 : 0.95 };
    double rgb[3];
    vtkMath::HSVToRGB(hsv, rgb);
    table->SetTableValue(k, rgb[0], rgb[1], rgb[2], 1.0);
    table->SetAnnotation(value, value.ToString());
    ++k;
  }
  table->SetNanColor(0.5, 0.5, 0.5, 1.0);
  return table;
}

void writeCategoricalPicture(const TransferSides& sides,
  const std::string& name,
  const std::string& path)
{
  vtkSmartPointer<vtkLookupTable> colours =
    labelTable(sides.source->GetPointData()->GetArray(name.c_str()));
  std::vector<SurfacePanel> panels;
  for (const auto& [mesh, caption] : bothSides(sides))
  {
    vtkSmartPointer<vtkPolyDataMapper> mapper = arrayMapper(cellLabels(mesh, name), name, true);
    mapper->SetColorModeToMapScalars();
    mapper->SetLookupTable(colours);
    panels.push_back({ mapper, caption });
  }
  const bool legend =
    static_cast<std::size_t>(colours->GetNumberOfAnnotatedValues()) <= MaxLegendLabels;
  writeSurfacePicture(turned(panels, sides), legend ? colours.GetPointer() : nullptr, name, path);
}

void writeColourPicture(const TransferSides& sides,
  const std::string& name,
  const std::string& path)
{
  std::vector<SurfacePanel> panels;
  for (const auto& [mesh, caption] : bothSides(sides))
  {
    vtkSmartPointer<vtkPolyDataMapper> mapper = arrayMapper(mesh, name, false);
    mapper->SetColorModeToDirectScalars();
    panels.push_back({ mapper, caption });
  }
  writeSurfacePicture(turned(panels, sides), nullptr, "", path);
}

// Both sides textured with the checkerboard through their per-corner
// texture coordinates, split at the seams (the target's carried per corner,
// so no triangle stretches across the texture).
void writeTexturePicture(const TransferSides& sides, const std::string& path)
{
  vtkSmartPointer<vtkTexture> texture = checkerboardTexture();
  std::vector<SurfacePanel> panels;
  for (const auto& [mesh, caption] : bothSides(sides))
  {
    vtkNew<vtkSurfaceTextureSeamSplitter> splitter;
    splitter->SetInputData(mesh);
    splitter->Update();
    auto split = vtkSmartPointer<vtkPolyData>::New();
    split->ShallowCopy(splitter->GetOutput());
    auto mapper = vtkSmartPointer<vtkPolyDataMapper>::New();
    mapper->SetInputData(split);
    mapper->ScalarVisibilityOff();
    panels.push_back({ mapper, caption, texture });
  }
  writeSurfacePicture(turned(panels, sides), nullptr, "", path);
}

} // namespace

std::string transferPicturePath(const std::string& output, const std::string& name)
{
  std::string safe = name;
  for (char& c : safe)
  {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_' && c != '.')
    {
      c = '_';
    }
  }
  std::filesystem::path path(output);
  path.replace_extension();
  return path.string() + "_" + safe + ".png";
}

std::vector<std::string> writeTransferPictures(vtkSurfaceMapTransfer* transfer,
  int from,
  int to,
  const std::string& output)
{
  auto* source = vtkPolyData::SafeDownCast(transfer->GetInputDataObject(1, 0));
  vtkPolyData* target = transfer->GetOutput();
  TransferSides sides{ source,
    target,
    "input " + std::to_string(from) + " (source)",
    "input " + std::to_string(to) + " (received)" };
  mapRotation(source, target, sides.rotation);
  std::vector<std::string> written;
  vtkPointData* received = target->GetPointData();
  for (int a = 0; a < received->GetNumberOfArrays(); ++a)
  {
    const char* name = received->GetArrayName(a);
    vtkDataArray* carried = name ? source->GetPointData()->GetArray(name) : nullptr;
    if (!carried || !received->GetArray(a) || isBookkeeping(name))
    {
      continue; // not numeric, or not data from the source
    }
    const std::string path = transferPicturePath(output, name);
    if (isColours(carried))
    {
      writeColourPicture(sides, name, path);
    }
    else if (carried->GetNumberOfComponents() == 1 &&
      transfer->ResolveArrayTransferMode(carried) ==
        vtkSurfaceArrayTransferAlgorithm::ARRAY_TRANSFER_CATEGORICAL)
    {
      writeCategoricalPicture(sides, name, path);
    }
    else
    {
      writeContinuousPicture(sides, name, path);
    }
    written.push_back(path);
  }
  if (source->GetCellData()->GetArray("CornerTCoords") &&
    target->GetCellData()->GetArray("CornerTCoords"))
  {
    const std::string path = transferPicturePath(output, "texture");
    writeTexturePicture(sides, path);
    written.push_back(path);
  }
  return written;
}

} // namespace surfacemap
