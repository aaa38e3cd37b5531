#include "map/Remeshing.h"

#include "map/LocalEdit.h"

#include <algorithm>
#include <chrono>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace surfacemaps
{

namespace
{
using VertexHandle = OpenMesh::VertexHandle;
using FaceHandle = OpenMesh::FaceHandle;

// Edge u -> v with faces (u, v, x) and (v, u, y).
struct EdgeStar
{
  OpenMesh::HalfedgeHandle h, o;
  VertexHandle u, v, x, y;
};

EdgeStar edgeStar(const HalfedgeMesh& mesh, OpenMesh::HalfedgeHandle h)
{
  EdgeStar s;
  s.h = h;
  s.o = mesh.opposite_halfedge_handle(h);
  s.u = mesh.from_vertex_handle(h);
  s.v = mesh.to_vertex_handle(h);
  s.x = mesh.to_vertex_handle(mesh.next_halfedge_handle(h));
  s.y = mesh.to_vertex_handle(mesh.next_halfedge_handle(s.o));
  return s;
}

// The link condition for collapsing u -> v in a closed triangle mesh: u and
// v have exactly two common neighbours, x and y. (OpenMesh's own check tags
// vertices and cannot run in parallel.)
bool collapseKeepsManifold(const HalfedgeMesh& mesh, const EdgeStar& s)
{
  int common = 0;
  for (auto a : mesh.vv_range(s.u))
  {
    for (auto b : mesh.vv_range(s.v))
    {
      common += a == b ? 1 : 0;
    }
  }
  return common == 2;
}

// Whether a triangle the edit creates is valid on every sphere, from the
// sphere points alone: its corners are mesh vertices, except `moved`, which
// stands at `movedPoints` (one per sphere) if it is a valid handle. This is
// the test evaluate() makes on the built edit, on the same points, so it
// decides the same; made before building, it spares the vertex copies and
// walks of the fifth of the collapses and the quarter of the flips that fail
// it.
bool validAfterEdit(const CommonTriangulation& T,
  const std::array<VertexHandle, 3>& corners,
  VertexHandle moved = VertexHandle(),
  const PerInput<Eigen::Vector3d>& movedPoints = {})
{
  for (int i = 0; i < T.numberOfInputs(); ++i)
  {
    auto point = [&](VertexHandle v) -> const Eigen::Vector3d&
    { return v == moved ? movedPoints[i] : T.spherePoint(v, i); };
    if (!CommonTriangulation::validOnSphere(
          point(corners[0]), point(corners[1]), point(corners[2])))
    {
      return false;
    }
  }
  return true;
}

bool buildSplit(const CommonTriangulation& T, OpenMesh::EdgeHandle e, LocalEdit& edit)
{
  const HalfedgeMesh& mesh = T.mesh();
  if (mesh.status(e).deleted())
  {
    return false;
  }
  const EdgeStar s = edgeStar(mesh, mesh.halfedge_handle(e, 0));
  addFace(T, edit, mesh.face_handle(s.h));
  addFace(T, edit, mesh.face_handle(s.o));
  const int u = localIndex(T, edit, s.u), v = localIndex(T, edit, s.v);
  const int x = localIndex(T, edit, s.x), y = localIndex(T, edit, s.y);
  edit.moved = T.midpoint(s.u, s.v);
  edit.movedIndex = static_cast<int>(edit.vertices.size());
  const int m = edit.movedIndex;
  edit.after = { { u, m, x }, { m, v, x }, { v, m, y }, { m, u, y } };
  return true;
}

bool buildCollapse(const CommonTriangulation& T, OpenMesh::HalfedgeHandle h, LocalEdit& edit)
{
  const HalfedgeMesh& mesh = T.mesh();
  if (mesh.status(mesh.edge_handle(h)).deleted())
  {
    return false;
  }
  const EdgeStar s = edgeStar(mesh, h);
  if (!collapseKeepsManifold(mesh, s) || T.landmark(s.u) >= 0 || T.landmark(s.v) >= 0 ||
    mesh.valence(s.x) <= 3 || mesh.valence(s.y) <= 3)
  {
    return false;
  }
  const FaceHandle f0 = mesh.face_handle(s.h), f1 = mesh.face_handle(s.o);
  std::vector<FaceHandle> faces;
  for (auto f : mesh.vf_range(s.u))
  {
    faces.push_back(f);
  }
  for (auto f : mesh.vf_range(s.v))
  {
    if (f != f0 && f != f1)
    {
      faces.push_back(f);
    }
  }
  // u and v merge at their midpoint on every sphere (where T.midpoint puts it).
  PerInput<Eigen::Vector3d> merged(T.numberOfInputs());
  for (int i = 0; i < T.numberOfInputs(); ++i)
  {
    merged[i] = T.sphereMidpoint(s.u, s.v, i);
  }
  for (FaceHandle f : faces)
  {
    if (f == f0 || f == f1)
    {
      continue;
    }
    std::array<VertexHandle, 3> corners;
    int k = 0;
    for (auto w : mesh.fv_range(f))
    {
      corners[k++] = w == s.u ? s.v : w;
    }
    if (!validAfterEdit(T, corners, s.v, merged))
    {
      return false;
    }
  }
  for (FaceHandle f : faces)
  {
    addFace(T, edit, f);
  }
  const int u = localIndex(T, edit, s.u), v = localIndex(T, edit, s.v);
  edit.moved = T.midpoint(s.u, s.v);
  edit.moved.landmark = -1;
  edit.movedIndex = v;
  for (const auto& tri : edit.before)
  {
    const bool hasU = std::find(tri.begin(), tri.end(), u) != tri.end();
    const bool hasV = std::find(tri.begin(), tri.end(), v) != tri.end();
    if (hasU && hasV)
    {
      continue;
    }
    std::array<int, 3> t = tri;
    std::replace(t.begin(), t.end(), u, v);
    edit.after.push_back(t);
  }
  return true;
}

bool buildFlip(const CommonTriangulation& T, OpenMesh::EdgeHandle e, LocalEdit& edit)
{
  const HalfedgeMesh& mesh = T.mesh();
  if (mesh.status(e).deleted() || !mesh.is_flip_ok(e))
  {
    return false;
  }
  const EdgeStar s = edgeStar(mesh, mesh.halfedge_handle(e, 0));
  if ((T.landmark(s.x) >= 0 && T.landmark(s.y) >= 0) || mesh.valence(s.u) <= 3 ||
    mesh.valence(s.v) <= 3 || !validAfterEdit(T, { s.u, s.y, s.x }) ||
    !validAfterEdit(T, { s.y, s.v, s.x }))
  {
    return false;
  }
  addFace(T, edit, mesh.face_handle(s.h));
  addFace(T, edit, mesh.face_handle(s.o));
  const int u = localIndex(T, edit, s.u), v = localIndex(T, edit, s.v);
  const int x = localIndex(T, edit, s.x), y = localIndex(T, edit, s.y);
  edit.after = { { u, y, x }, { y, v, x } };
  return true;
}

/// The faces an applied edit made, each matched to the triangle the edit
/// evaluated for it, for the edit's handlers.
EditedFaces editedFaces(const CommonTriangulation& T,
  const LocalEdit& edit,
  const std::vector<FaceHandle>& faces)
{
  const HalfedgeMesh& mesh = T.mesh();
  EditedFaces edited;
  edited.faces = faces;
  for (FaceHandle f : faces)
  {
    std::array<VertexHandle, 3> corners;
    int k = 0;
    for (auto v : mesh.fv_range(f))
    {
      corners[k++] = v;
    }
    int match = -1;
    for (std::size_t t = 0; t < edit.after.size() && match < 0; ++t)
    {
      for (int r = 0; r < 3 && match < 0; ++r)
      {
        if (edit.handles[edit.after[t][r]] == corners[0] &&
          edit.handles[edit.after[t][(r + 1) % 3]] == corners[1] &&
          edit.handles[edit.after[t][(r + 2) % 3]] == corners[2])
        {
          match = static_cast<int>(t);
        }
      }
    }
    if (match < 0)
    {
      throw std::logic_error("remeshing: a face after an edit is not one the edit evaluated");
    }
    edited.triangle.push_back(match);
  }
  edited.lengths = &edit.afterLengths;
  edited.energies = &edit.afterEnergies;
  edited.samples = &edit.samples;
  edited.assignment = &edit.assignment;
  return edited;
}

void notify(const std::vector<EditHandler>& handlers, const EditedFaces& edited)
{
  for (const EditHandler& handler : handlers)
  {
    handler(edited);
  }
}

template<typename Build, typename Handle>
double gainOf(const MapEnergy& energy,
  Handle handle,
  Build build,
  double minGain = -std::numeric_limits<double>::infinity())
{
  thread_local LocalEdit edit;
  edit.clear();
  if (!build(energy.triangulation(), handle, edit))
  {
    return NoGain;
  }
  return evaluate(energy, edit, minGain);
}

/// Builds and evaluates an edit; true (and the gain in `applied`) when it
/// is possible and gains more than minGain.
template<typename Build, typename Handle>
bool worthApplying(const MapEnergy& energy,
  Handle handle,
  Build build,
  double minGain,
  double* applied,
  LocalEdit& edit)
{
  if (!build(energy.triangulation(), handle, edit))
  {
    return false;
  }
  const double gain = evaluate(energy, edit, minGain);
  if (!(gain > minGain))
  {
    return false;
  }
  if (applied)
  {
    *applied = gain;
  }
  return true;
}

std::vector<FaceHandle> facesAround(const HalfedgeMesh& mesh, VertexHandle v)
{
  std::vector<FaceHandle> faces;
  for (auto f : mesh.vf_range(v))
  {
    faces.push_back(f);
  }
  return faces;
}

/// An edit of T when worthApplying: `change(mesh, edit)` changes the mesh
/// (and T's vertex data) and returns the faces around the change, which
/// `handlers` then hear of (the sample bookkeeping, the face caches).
template<typename Build, typename Handle, typename Change>
bool applyEdit(CommonTriangulation& T,
  const MapEnergy& energy,
  Handle handle,
  Build build,
  double minGain,
  double* applied,
  const std::vector<EditHandler>& handlers,
  Change change)
{
  LocalEdit edit;
  if (!worthApplying(energy, handle, build, minGain, applied, edit))
  {
    return false;
  }
  const std::vector<FaceHandle> faces = change(T.mesh(), edit);
  notify(handlers, editedFaces(T, edit, faces));
  return true;
}

/// Evaluates all candidates in parallel, then applies those that gain, best
/// first, each re-evaluated on the mesh as it is by then.
template<typename Handle, typename Gain, typename Apply>
int pass(std::vector<Handle> candidates, double minGain, Gain gain, Apply apply, double& total)
{
  std::vector<double> gains(candidates.size(), NoGain);
#pragma omp parallel for schedule(dynamic, 64)
  for (long long k = 0; k < static_cast<long long>(candidates.size()); ++k)
  {
    try
    {
      gains[k] = gain(candidates[k]);
    }
    catch (const std::exception&)
    {
      gains[k] = NoGain; // e.g. a walk that found no end: not an edit to make
    }
  }
  std::vector<std::size_t> order;
  for (std::size_t k = 0; k < candidates.size(); ++k)
  {
    if (gains[k] > minGain)
    {
      order.push_back(k);
    }
  }
  std::stable_sort(
    order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return gains[a] > gains[b]; });
  int applied = 0;
  for (std::size_t k : order)
  {
    double g = 0.0;
    if (apply(candidates[k], &g))
    {
      ++applied;
      total += g;
    }
  }
  return applied;
}

} // namespace

double splitGain(const MapEnergy& energy, OpenMesh::EdgeHandle e)
{
  return gainOf(energy, e, buildSplit);
}

double collapseGain(const MapEnergy& energy, OpenMesh::HalfedgeHandle h)
{
  return gainOf(energy, h, buildCollapse);
}

double flipGain(const MapEnergy& energy, OpenMesh::EdgeHandle e)
{
  return gainOf(energy, e, buildFlip);
}

bool applySplit(CommonTriangulation& T,
  const MapEnergy& energy,
  const EditHandlers& handlers,
  OpenMesh::EdgeHandle e,
  double minGain,
  double* applied)
{
  return applyEdit(T, energy, e, buildSplit, minGain, applied, handlers.split,
    [&T, e](HalfedgeMesh& mesh, LocalEdit& edit)
    {
      const Eigen::Vector3d& p = edit.moved.lifted[0];
      const VertexHandle m = mesh.add_vertex(HalfedgeMesh::Point(p[0], p[1], p[2]));
      mesh.split(e, m);
      T.setVertex(m, edit.moved);
      edit.handles.push_back(m);
      return facesAround(mesh, m);
    });
}

bool applyCollapse(CommonTriangulation& T,
  const MapEnergy& energy,
  const EditHandlers& handlers,
  OpenMesh::HalfedgeHandle h,
  double minGain,
  double* applied)
{
  return applyEdit(T, energy, h, buildCollapse, minGain, applied, handlers.collapse,
    [&T, h](HalfedgeMesh& mesh, LocalEdit& edit)
    {
      const VertexHandle kept = mesh.to_vertex_handle(h);
      mesh.collapse(h);
      T.setVertex(kept, edit.moved);
      return facesAround(mesh, kept);
    });
}

bool applyFlip(CommonTriangulation& T,
  const MapEnergy& energy,
  const EditHandlers& handlers,
  OpenMesh::EdgeHandle e,
  double minGain,
  double* applied)
{
  return applyEdit(T, energy, e, buildFlip, minGain, applied, handlers.flip,
    [e](HalfedgeMesh& mesh, LocalEdit&)
    {
      mesh.flip(e);
      return std::vector<FaceHandle>{ mesh.face_handle(mesh.halfedge_handle(e, 0)),
        mesh.face_handle(mesh.halfedge_handle(e, 1)) };
    });
}

RemeshingResult remesh(CommonTriangulation& T,
  const MapEnergy& energy,
  const RemeshingOptions& options)
{
  const auto start = std::chrono::steady_clock::now();
  RemeshingResult result;
  HalfedgeMesh& mesh = T.mesh();
  energy.updateFaceEnergies();
  const EditHandlers handlers = triangulationHandlers(T);
  auto allEdges = [&]()
  {
    std::vector<OpenMesh::EdgeHandle> edges;
    edges.reserve(mesh.n_edges());
    for (auto e : mesh.edges())
    {
      edges.push_back(e);
    }
    return edges;
  };
  if (options.split)
  {
    result.splits = pass(
      allEdges(),
      options.minGain,
      [&](OpenMesh::EdgeHandle e) { return gainOf(energy, e, buildSplit, options.minGain); },
      [&](OpenMesh::EdgeHandle e, double* g)
      { return applySplit(T, energy, handlers, e, options.minGain, g); },
      result.gain);
  }
  if (options.collapse)
  {
    // The collapse puts the kept vertex at the midpoint: one direction will do.
    std::vector<OpenMesh::HalfedgeHandle> halfedges;
    for (auto e : allEdges())
    {
      halfedges.push_back(mesh.halfedge_handle(e, 0));
    }
    result.collapses = pass(
      halfedges,
      options.minGain,
      [&](OpenMesh::HalfedgeHandle h) { return gainOf(energy, h, buildCollapse, options.minGain); },
      [&](OpenMesh::HalfedgeHandle h, double* g)
      { return applyCollapse(T, energy, handlers, h, options.minGain, g); },
      result.gain);
    mesh.garbage_collection();
  }
  if (options.flip)
  {
    result.flips = pass(
      allEdges(),
      options.minGain,
      [&](OpenMesh::EdgeHandle e) { return gainOf(energy, e, buildFlip, options.minGain); },
      [&](OpenMesh::EdgeHandle e, double* g)
      { return applyFlip(T, energy, handlers, e, options.minGain, g); },
      result.gain);
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

} // namespace surfacemaps
