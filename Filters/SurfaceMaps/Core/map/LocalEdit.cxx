// SurfaceMaps engine: LocalEdit's evaluation.
#include "map/LocalEdit.h"

#include <algorithm>
#include <cmath>

namespace surfacemaps
{

namespace
{
/// The samples of the edit's faces, per input in the order of its faces.
void gatherSamples(const CommonTriangulation& T, LocalEdit& edit)
{
  if (!T.tracksSamples() || !edit.samples.empty())
  {
    return;
  }
  edit.samples.resize(T.numberOfInputs());
  for (int i = 0; i < T.numberOfInputs(); ++i)
  {
    for (OpenMesh::FaceHandle f : edit.faces)
    {
      const std::vector<int>& s = T.faceSamples(f, i);
      edit.samples[i].insert(edit.samples[i].end(), s.begin(), s.end());
    }
  }
}

/// The energies of triangles over `vertices` with the given target lengths.
std::vector<double> triangleEnergies(const MapEnergy& energy,
  const std::vector<MapVertex>& vertices,
  const std::vector<std::array<int, 3>>& triangles,
  const std::vector<double>& lengths)
{
  std::vector<double> energies(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    const auto& tri = triangles[t];
    energies[t] =
      energy.triangleEnergy(vertices[tri[0]], vertices[tri[1]], vertices[tri[2]], lengths[t]);
  }
  return energies;
}

/// The energy of the faces an edit replaces: from the face-energy cache, or
/// computed (with their samples).
double energyBefore(const MapEnergy& energy, LocalEdit& edit)
{
  if (edit.beforeCached)
  {
    return edit.cachedBefore;
  }
  gatherSamples(energy.triangulation(), edit);
  return energy.localEnergy(edit.vertices,
    edit.before,
    triangleEnergies(energy, edit.vertices, edit.before, edit.beforeLengths),
    edit.samples,
    nullptr);
}

/// Turns the edit's vertices into those after it (the moved one moved, the
/// split's new one appended); false when a triangle it creates is not valid
/// on every sphere.
bool moveToAfter(const CommonTriangulation& T, LocalEdit& edit)
{
  std::vector<MapVertex>& after = edit.vertices;
  if (edit.movedIndex >= static_cast<int>(after.size()))
  {
    after.push_back(edit.moved);
  }
  else if (edit.movedIndex >= 0)
  {
    after[edit.movedIndex] = edit.moved;
  }
  for (const auto& tri : edit.after)
  {
    if (!T.validTriangle(after[tri[0]], after[tri[1]], after[tri[2]]))
    {
      return false;
    }
  }
  return true;
}

/// The terms, target lengths and energies (without samples) of the
/// triangles the edit creates. Every triangle's energy is >= 0 (the
/// barrier's -log(det / 6) is, as det <= 1 on the unit sphere), so the
/// running sum only grows, and so does a running sum of lower bounds below
/// it: with `bounded`, false as soon as the first triangles cost what the
/// edit may (before - minGain), first with the mesh-quality terms at their
/// smallest over all target lengths (no walk on any sphere), then with the
/// target lengths.
bool afterTriangles(const MapEnergy& energy,
  LocalEdit& edit,
  bool bounded,
  double before,
  double minGain)
{
  const CommonTriangulation& T = energy.triangulation();
  const std::vector<MapVertex>& v = edit.vertices;
  std::vector<MapEnergy::TriangleTerms>& terms = edit.afterTerms;
  terms.resize(edit.after.size());
  double bound = 0.0;
  for (std::size_t t = 0; t < edit.after.size(); ++t)
  {
    const auto& tri = edit.after[t];
    terms[t] = energy.triangleTerms(v[tri[0]], v[tri[1]], v[tri[2]]);
    if (bounded)
    {
      bound += energy.triangleEnergyBound(terms[t]);
      if (!(before - bound > minGain))
      {
        return false;
      }
    }
  }
  edit.afterLengths.assign(edit.after.size(), 1.0);
  std::vector<double>& energies = edit.afterTriangleEnergies;
  energies.resize(edit.after.size());
  double triangles = 0.0;
  for (std::size_t t = 0; t < edit.after.size(); ++t)
  {
    const auto& tri = edit.after[t];
    if (energy.weights().mesh > 0.0)
    {
      edit.afterLengths[t] = T.targetLength(v[tri[0]], v[tri[1]], v[tri[2]]);
    }
    energies[t] = energy.triangleEnergy(terms[t], edit.afterLengths[t]);
    if (bounded)
    {
      triangles += energies[t];
      if (!(before - triangles > minGain))
      {
        return false;
      }
    }
  }
  return true;
}

} // namespace

int localIndex(const CommonTriangulation& T, LocalEdit& edit, OpenMesh::VertexHandle v)
{
  const auto it = std::find(edit.handles.begin(), edit.handles.end(), v);
  if (it != edit.handles.end())
  {
    return static_cast<int>(it - edit.handles.begin());
  }
  edit.handles.push_back(v);
  edit.vertices.push_back(T.vertex(v));
  return static_cast<int>(edit.handles.size()) - 1;
}

void addFace(const CommonTriangulation& T, LocalEdit& edit, OpenMesh::FaceHandle f)
{
  const HalfedgeMesh& mesh = T.mesh();
  std::array<int, 3> tri;
  int k = 0;
  for (auto v : mesh.fv_range(f))
  {
    tri[k++] = localIndex(T, edit, v);
  }
  edit.before.push_back(tri);
  edit.beforeLengths.push_back(T.targetLength(f));
  edit.cachedBefore += T.faceEnergy(f);
  edit.beforeCached = edit.beforeCached && T.faceEnergiesValid();
  edit.faces.push_back(f);
}

double evaluate(const MapEnergy& energy, LocalEdit& edit, double minGain)
{
  const double before = energyBefore(energy, edit);
  if (!moveToAfter(energy.triangulation(), edit))
  {
    return NoGain;
  }
  const bool bounded = std::isfinite(minGain) && std::isfinite(before);
  if (!afterTriangles(energy, edit, bounded, before, minGain))
  {
    return NoGain;
  }
  gatherSamples(energy.triangulation(), edit);
  const double after = energy.localEnergy(edit.vertices,
    edit.after,
    edit.afterTriangleEnergies,
    edit.samples,
    &edit.assignment,
    &edit.afterEnergies);
  if (!std::isfinite(before) || !std::isfinite(after))
  {
    return NoGain;
  }
  return before - after;
}

} // namespace surfacemaps
