#include "MapConsistency.h"

#include "AlgorithmMessages.h"
#include "MapDirectory.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkSurfaceMeshReader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace surfacemap
{

namespace
{

struct MapFile
{
  std::string path;
  vtkSmartPointer<vtkPolyData> mesh;
};

MapFile readMapFile(const std::string& directory, const char* stem, int j)
{
  MapFile file{ directory + "/" + mapFileName(stem, j), nullptr };
  vtkNew<vtkSurfaceMeshReader> reader;
  ErrorCapture quiet(reader);
  reader->SetFileName(file.path.c_str());
  reader->Update();
  if (!quiet.messages().empty() || reader->GetOutput()->GetNumberOfPoints() == 0)
  {
    throw std::runtime_error(file.path + " does not read as a mesh");
  }
  file.mesh = vtkSmartPointer<vtkPolyData>::New();
  file.mesh->ShallowCopy(reader->GetOutput());
  return file;
}

// The point array `name` with `components` values per point of `file`;
// throws naming the file when it has none of that shape.
vtkDataArray* pointArray(const MapFile& file, const char* name, int components)
{
  vtkDataArray* array = file.mesh->GetPointData()->GetArray(name);
  if (!array || array->GetNumberOfComponents() != components ||
    array->GetNumberOfTuples() != file.mesh->GetNumberOfPoints())
  {
    throw std::runtime_error(file.path + " has no " + name + " point array of " +
      std::to_string(components) + " value" + (components == 1 ? "" : "s") +
      " per point: not a file 'surfacemap map' wrote");
  }
  return array;
}

// Where the triangulations of `a` and `b` first differ; empty if they do not.
std::string triangulationDifference(vtkPolyData* a, vtkPolyData* b)
{
  if (a->GetNumberOfPoints() != b->GetNumberOfPoints())
  {
    return std::to_string(a->GetNumberOfPoints()) + " vs " +
      std::to_string(b->GetNumberOfPoints()) + " points";
  }
  vtkCellArray* ta = a->GetPolys();
  vtkCellArray* tb = b->GetPolys();
  if (ta->GetNumberOfCells() != tb->GetNumberOfCells())
  {
    return std::to_string(ta->GetNumberOfCells()) + " vs " +
      std::to_string(tb->GetNumberOfCells()) + " triangles";
  }
  for (vtkIdType t = 0; t < ta->GetNumberOfCells(); ++t)
  {
    vtkIdType na = 0, nb = 0;
    const vtkIdType *pa = nullptr, *pb = nullptr;
    ta->GetCellAtId(t, na, pa);
    tb->GetCellAtId(t, nb, pb);
    if (na != nb || !std::equal(pa, pa + na, pb))
    {
      return "first difference at triangle " + std::to_string(t);
    }
  }
  return {};
}

std::string numberText(double value)
{
  std::ostringstream text;
  text << value;
  return text.str();
}

std::string pointText(const double p[3])
{
  char text[96];
  std::snprintf(text, sizeof(text), "(%.4g, %.4g, %.4g)", p[0], p[1], p[2]);
  return text;
}

// f_j at T's vertex v's source point, normalised; throws naming the files
// when the source point is no point of embedding_j's triangles.
void sourceOnSphere(const MapFile& common,
  const MapFile& embedding,
  vtkDataArray* cellIds,
  vtkDataArray* barycentric,
  vtkDataArray* f,
  vtkIdType v,
  double q[3])
{
  const double cell = cellIds->GetComponent(v, 0);
  vtkPolyData* input = embedding.mesh;
  if (!(cell >= 0.0 && cell < static_cast<double>(input->GetNumberOfCells())))
  {
    throw std::runtime_error(common.path + " places T's vertex " + std::to_string(v) +
      " on triangle " + numberText(cell) + ", which " + embedding.path + " does not have (" +
      std::to_string(input->GetNumberOfCells()) + " cells): the files are not one map");
  }
  vtkIdType n = 0;
  const vtkIdType* corners = nullptr;
  input->GetCellPoints(static_cast<vtkIdType>(cell), n, corners);
  const vtkIdType points = f->GetNumberOfTuples();
  if (n != 3 ||
    !std::all_of(corners, corners + 3, [points](vtkIdType p) { return p >= 0 && p < points; }))
  {
    throw std::runtime_error(embedding.path + ": cell " + numberText(cell) +
      " is no triangle of its points: not a file 'surfacemap map' wrote");
  }
  q[0] = q[1] = q[2] = 0.0;
  for (vtkIdType k = 0; k < 3; ++k)
  {
    const double b = barycentric->GetComponent(v, static_cast<int>(k));
    for (int c = 0; c < 3; ++c)
    {
      q[c] += b * f->GetComponent(corners[k], c);
    }
  }
  const double length = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
  for (int c = 0; c < 3; ++c)
  {
    q[c] = length > 0.0 ? q[c] / length : 0.0;
  }
}

// Checks common_j against embedding_j (see the header).
void checkEmbedding(const MapFile& common, const MapFile& embedding, int j)
{
  vtkDataArray* g = pointArray(common, "SpherePosition", 3);
  vtkDataArray* cellIds = pointArray(common, "SourceCellId", 1);
  vtkDataArray* barycentric = pointArray(common, "SourceBarycentric", 3);
  vtkDataArray* f = pointArray(embedding, "SpherePosition", 3);
  vtkIdType first = -1, count = 0;
  double firstDistance = 0.0, firstG[3] = {}, firstF[3] = {};
  for (vtkIdType v = 0; v < common.mesh->GetNumberOfPoints(); ++v)
  {
    double q[3], p[3];
    sourceOnSphere(common, embedding, cellIds, barycentric, f, v, q);
    g->GetTuple(v, p);
    const double distance = std::sqrt((p[0] - q[0]) * (p[0] - q[0]) +
      (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
    if (!(distance <= MapSphereTolerance))
    {
      if (first < 0)
      {
        first = v;
        firstDistance = distance;
        std::copy(p, p + 3, firstG);
        std::copy(q, q + 3, firstF);
      }
      ++count;
    }
  }
  if (first >= 0)
  {
    char distance[32];
    std::snprintf(distance, sizeof(distance), "%.3g", firstDistance);
    throw std::runtime_error(embedding.path + " and " + common.path + " are not one map: at " +
      std::to_string(count) + " of T's " + std::to_string(common.mesh->GetNumberOfPoints()) +
      " vertices the embedding of input " + std::to_string(j) +
      " does not send the vertex's source point to its sphere position " + "(vertex " +
      std::to_string(first) + ": " + pointText(firstG) + " in the common file, " +
      pointText(firstF) + " by the embedding, " + distance +
      " apart): a file was edited, rotated or swapped after the map was written");
  }
}

} // namespace

void checkMapGeometry(const std::string& directory, const std::vector<int>& inputs)
{
  std::vector<MapFile> commons;
  for (const int j : inputs)
  {
    commons.push_back(readMapFile(directory, "common", j));
    const std::string difference =
      triangulationDifference(commons.front().mesh, commons.back().mesh);
    if (!difference.empty())
    {
      throw std::runtime_error(commons.back().path + " and " + commons.front().path +
        " do not hold the same common triangulation (" + difference + ")");
    }
    checkEmbedding(commons.back(), readMapFile(directory, "embedding", j), j);
  }
}

} // namespace surfacemap
