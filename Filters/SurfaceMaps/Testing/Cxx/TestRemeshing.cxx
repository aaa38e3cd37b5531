// Edge splits, collapses and flips of the common triangulation: each changes
// the total energy by exactly its local gain and keeps every invariant.
#include "MapTestInputs.h"
#include "geometry/Predicates.h"
#include "map/PreparedInput.h"
#include "map/Remeshing.h"
#include "map/SurfaceMap.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

using namespace surfacemaps;
using namespace surfacemaps::testing;

namespace
{
constexpr double Always = -std::numeric_limits<double>::infinity();

class RemeshingTest : public ::testing::Test
{
protected:
  void SetUp() override
  {
    std::vector<MapInput> inputs{ icosphereInput(2, 0.0, { 1.0, 1.0, 1.0 }),
      icosphereInput(2, 0.4, { 1.5, 1.0, 0.7 }, 0.4) };
    setLandmarks(inputs[0], { { 0, 0, 1 } });
    setLandmarks(inputs[1], { { 0, 0, 1 } });
    this->surfaces =
      prepareInputs(inputs, landmarkVertices(inputs), SurfaceMapOptions().approximationSamples);
    for (PreparedInput& s : this->surfaces)
    {
      s.sizing.assign(s.points.size(), 0.25);
    }
    this->T = std::make_unique<CommonTriangulation>(this->surfaces, mapPairs(PairScheme::Star, 2));
    this->handlers = triangulationHandlers(*this->T);
    MapEnergyWeights& w = this->weights;
    w.barrier = 1e-3;
    w.mesh = 1.0;
    w.approximation = 100.0;
    w.map = 1.0;
    this->T->setTrackSamples(true);
    this->T->updateTargetLengths();
  }

  /// Closed 2-manifold of genus 0, certified on every sphere, every sample in
  /// exactly one face that contains it, landmarks kept, every vertex's lift
  /// (kept with its sphere point) that of its sphere point.
  void expectInvariants()
  {
    HalfedgeMesh& mesh = this->T->mesh();
    mesh.garbage_collection();
    long long boundary = 0;
    for (auto e : mesh.edges())
    {
      boundary += mesh.is_boundary(e) ? 1 : 0;
    }
    EXPECT_EQ(boundary, 0);
    EXPECT_EQ(static_cast<long long>(mesh.n_vertices()) - static_cast<long long>(mesh.n_edges()) +
        static_cast<long long>(mesh.n_faces()),
      2);
    const std::vector<std::array<int, 3>> triangles = faceTriangles(mesh);
    int landmarks = 0;
    for (auto v : mesh.vertices())
    {
      landmarks += this->T->landmark(v) >= 0 ? 1 : 0;
    }
    EXPECT_EQ(landmarks, 1);
    for (int i = 0; i < 2; ++i)
    {
      std::vector<Eigen::Vector3d> g(mesh.n_vertices());
      for (auto v : mesh.vertices())
      {
        g[v.idx()] = this->T->g(v, i);
      }
      for (auto v : mesh.vertices())
      {
        const Lift& lift = this->surfaces[i].lifts[this->T->liftTriangle(v, i)];
        EXPECT_EQ(this->T->vertex(v).lifted[i], lift(g[v.idx()])) << "vertex " << v.idx();
      }
      const BijectivityCertificate c = certifyBijective(g, triangles);
      EXPECT_TRUE(c.bijective) << c.reason;
      std::vector<int> count(this->surfaces[i].samples.spherePoints.size(), 0);
      for (auto f : mesh.faces())
      {
        for (int s : this->T->faceSamples(f, i))
        {
          ++count[s];
          const Eigen::Vector3d& q = this->surfaces[i].samples.spherePoints[s];
          const auto& t = triangles[f.idx()];
          EXPECT_GE(orient3dOrigin(g[t[0]], g[t[1]], q), 0);
          EXPECT_GE(orient3dOrigin(g[t[1]], g[t[2]], q), 0);
          EXPECT_GE(orient3dOrigin(g[t[2]], g[t[0]], q), 0);
        }
      }
      for (int c : count)
      {
        EXPECT_EQ(c, 1);
      }
    }
  }

  /// Applies `apply` to the first `count` edges (by index, from `first`) whose
  /// gain is finite and checks total energy change == gain.
  template<typename Gain, typename Apply>
  int checkEdits(Gain gain, Apply apply, int count)
  {
    int done = 0;
    for (int k = 0; done < count && k < static_cast<int>(this->T->mesh().n_edges()); k += 7)
    {
      const auto e = this->T->mesh().edge_handle(k);
      const double expected = gain(e);
      if (!std::isfinite(expected))
      {
        continue;
      }
      const double before = this->totalEnergy();
      EXPECT_TRUE(apply(this->T->mesh().edge_handle(k)));
      const double after = this->totalEnergy();
      EXPECT_NEAR(before - after, expected, 1e-9 * std::abs(before)) << "edge " << k;
      this->expectInvariants();
      ++done;
    }
    return done;
  }

  /// The energy under the fixture's weights.
  MapEnergy energy() const { return MapEnergy(*this->T, this->weights); }
  double totalEnergy() const { return this->energy().total(); }

  std::vector<PreparedInput> surfaces;
  std::unique_ptr<CommonTriangulation> T;
  MapEnergyWeights weights;
  EditHandlers handlers;
};
} // namespace

TEST_F(RemeshingTest, InitialStateSatisfiesTheInvariants)
{
  this->expectInvariants();
}

TEST_F(RemeshingTest, SplitChangesTheEnergyByItsLocalGain)
{
  const int done =
    this->checkEdits([&](OpenMesh::EdgeHandle e) { return splitGain(this->energy(), e); },
      [&](OpenMesh::EdgeHandle e)
      { return applySplit(*this->T, this->energy(), this->handlers, e, Always); },
      6);
  EXPECT_EQ(done, 6);
}

TEST_F(RemeshingTest, CollapseChangesTheEnergyByItsLocalGain)
{
  const int done = this->checkEdits([&](OpenMesh::EdgeHandle e)
    { return collapseGain(this->energy(), this->T->mesh().halfedge_handle(e, 0)); },
    [&](OpenMesh::EdgeHandle e)
    {
      return applyCollapse(
        *this->T, this->energy(), this->handlers, this->T->mesh().halfedge_handle(e, 0), Always);
    },
    6);
  EXPECT_EQ(done, 6);
}

TEST_F(RemeshingTest, FlipChangesTheEnergyByItsLocalGain)
{
  const int done =
    this->checkEdits([&](OpenMesh::EdgeHandle e) { return flipGain(this->energy(), e); },
      [&](OpenMesh::EdgeHandle e)
      { return applyFlip(*this->T, this->energy(), this->handlers, e, Always); },
      6);
  EXPECT_EQ(done, 6);
}

TEST_F(RemeshingTest, EachEditRunsTheHandlersOfItsKindWithTheFacesItMade)
{
  // A split makes the 4 faces around the new vertex, a flip 2; a collapse
  // the faces around the kept vertex. Only the edit's own kind's handlers run.
  std::vector<std::pair<char, std::size_t>> calls;
  EditHandlers counting = this->handlers;
  counting.split.push_back([&](const EditedFaces& f) { calls.emplace_back('s', f.faces.size()); });
  counting.collapse.push_back(
    [&](const EditedFaces& f) { calls.emplace_back('c', f.faces.size()); });
  counting.flip.push_back([&](const EditedFaces& f) { calls.emplace_back('f', f.faces.size()); });
  HalfedgeMesh& mesh = this->T->mesh();
  auto first = [&](auto gain) -> OpenMesh::EdgeHandle
  {
    for (auto e : mesh.edges())
    {
      if (!mesh.status(e).deleted() && std::isfinite(gain(e)))
      {
        return e;
      }
    }
    return OpenMesh::EdgeHandle();
  };
  const auto s = first([&](OpenMesh::EdgeHandle e) { return splitGain(this->energy(), e); });
  ASSERT_TRUE(applySplit(*this->T, this->energy(), counting, s, Always));
  const auto f = first([&](OpenMesh::EdgeHandle e) { return flipGain(this->energy(), e); });
  ASSERT_TRUE(applyFlip(*this->T, this->energy(), counting, f, Always));
  const auto c = first([&](OpenMesh::EdgeHandle e)
    { return collapseGain(this->energy(), mesh.halfedge_handle(e, 0)); });
  const auto kept = mesh.to_vertex_handle(mesh.halfedge_handle(c, 0));
  ASSERT_TRUE(
    applyCollapse(*this->T, this->energy(), counting, mesh.halfedge_handle(c, 0), Always));
  ASSERT_EQ(calls.size(), 3u);
  EXPECT_EQ(calls[0], std::make_pair('s', std::size_t(4)));
  EXPECT_EQ(calls[1], std::make_pair('f', std::size_t(2)));
  EXPECT_EQ(calls[2].first, 'c');
  EXPECT_EQ(calls[2].second, static_cast<std::size_t>(mesh.valence(kept)));
  this->expectInvariants();
}

TEST_F(RemeshingTest, NoEditTouchesALandmarkEdgeOrJoinsTwoLandmarks)
{
  HalfedgeMesh& mesh = this->T->mesh();
  for (auto h : mesh.halfedges())
  {
    if (this->T->landmark(mesh.from_vertex_handle(h)) >= 0 ||
      this->T->landmark(mesh.to_vertex_handle(h)) >= 0)
    {
      EXPECT_FALSE(std::isfinite(collapseGain(this->energy(), h)));
    }
  }
  // Make two landmarks opposite an edge: a flip must not join them.
  const auto e = mesh.edge_handle(0);
  const auto h = mesh.halfedge_handle(e, 0);
  const auto x = mesh.to_vertex_handle(mesh.next_halfedge_handle(h));
  const auto y = mesh.to_vertex_handle(mesh.next_halfedge_handle(mesh.opposite_halfedge_handle(h)));
  this->T->setLandmark(x, 7);
  this->T->setLandmark(y, 8);
  EXPECT_FALSE(std::isfinite(flipGain(this->energy(), e)));
}

TEST_F(RemeshingTest, MovedPointsWrittenBackKeepTheInvariants)
{
  CommonTriangulation::Snapshot snapshot;
  SpherePoints points;
  this->T->snapshot(snapshot, points, true, this->weights);
  Eigen::VectorXd step(points.numberOfVariables());
  for (Eigen::Index k = 0; k < step.size(); ++k)
  {
    step[k] = 2e-3 * std::sin(0.7 * static_cast<double>(k));
  }
  const std::vector<Eigen::Vector3d> start = points.positions();
  points.retract(step, 1.0);
  ASSERT_TRUE(this->T->update(snapshot, points));
  this->T->writeBack(snapshot, points);
  int moved = 0;
  for (auto v : this->T->mesh().vertices())
  {
    moved += this->T->g(v, 1) != start[snapshot.vertices + v.idx()] ? 1 : 0;
  }
  EXPECT_GT(moved, 0);
  this->expectInvariants();
}

TEST_F(RemeshingTest, InvertedCornersAreTheCornersOfInvertedTriangles)
{
  // Moving one point of embedding 1 onto the far side of the sphere inverts
  // the triangles around it there, and only those: their corners, and the
  // update() that the line search runs refuses the trial.
  CommonTriangulation::Snapshot snapshot;
  SpherePoints points;
  this->T->snapshot(snapshot, points, false, this->weights);
  EXPECT_TRUE(this->T->invertedCorners(snapshot, points).empty());
  const int moved = snapshot.vertices + snapshot.triangles[0][0];
  std::vector<Eigen::Vector3d> positions = points.positions();
  positions[moved] = -positions[moved];
  points.setPositions(positions);
  const std::vector<int> corners = this->T->invertedCorners(snapshot, points);
  ASSERT_FALSE(corners.empty());
  EXPECT_TRUE(std::is_sorted(corners.begin(), corners.end()));
  EXPECT_TRUE(std::binary_search(corners.begin(), corners.end(), moved));
  std::set<int> expected;
  for (const auto& t : snapshot.embeddedTriangles[1])
  {
    if (orient3dOrigin(positions[t[0]], positions[t[1]], positions[t[2]]) <= 0)
    {
      expected.insert(t.begin(), t.end());
    }
  }
  EXPECT_EQ(std::vector<int>(expected.begin(), expected.end()), corners);
  for (const int c : corners)
  {
    EXPECT_GE(c, snapshot.vertices) << "embedding 0 did not move";
  }
  EXPECT_FALSE(this->T->update(snapshot, points));
}

TEST_F(RemeshingTest, RoundLowersTheEnergyAndKeepsInvariants)
{
  const double before = this->totalEnergy();
  const RemeshingResult r = remesh(*this->T, this->energy());
  EXPECT_GT(r.splits + r.collapses + r.flips, 0);
  EXPECT_GT(r.gain, 0.0);
  // The round's edits were chosen with cached face energies: the total must
  // still drop by exactly the sum of their gains.
  EXPECT_NEAR(before - this->totalEnergy(), r.gain, 1e-9 * std::abs(before));
  this->expectInvariants();
}

TEST_F(RemeshingTest, BarrierIsRaisedWhereATrialInvertsAndEditsStartAfresh)
{
  CommonTriangulation::Snapshot snapshot;
  SpherePoints points;
  this->T->snapshot(snapshot, points, false, this->weights);
  EXPECT_TRUE(snapshot.barrierScales[0].empty()) << "raise off: one weight";
  this->weights.barrierRaise = 4.0;
  this->T->snapshot(snapshot, points, false, this->weights);
  ASSERT_EQ(snapshot.barrierScales[1].size(), snapshot.triangles.size());
  for (int i = 0; i < 2; ++i)
  {
    for (const double s : snapshot.barrierScales[i])
    {
      EXPECT_EQ(s, 1.0);
    }
  }

  // A point of embedding 1 on the far side of the sphere inverts the
  // triangles around it there; raised more often than the cap allows.
  const int moved = snapshot.vertices + snapshot.triangles[0][0];
  std::vector<Eigen::Vector3d> positions = points.positions();
  positions[moved] = -positions[moved];
  points.setPositions(positions);
  std::vector<char> inverted(snapshot.triangles.size(), 0);
  for (std::size_t t = 0; t < inverted.size(); ++t)
  {
    const auto& c = snapshot.embeddedTriangles[1][t];
    inverted[t] = orient3dOrigin(positions[c[0]], positions[c[1]], positions[c[2]]) <= 0;
  }
  ASSERT_GT(std::count(inverted.begin(), inverted.end(), 1), 0);
  for (int k = 0; k < CommonTriangulation::MaxBarrierRaises + 2; ++k)
  {
    this->T->raiseBarrier(snapshot, points, this->weights.barrierRaise);
  }
  const double top = std::pow(4.0, CommonTriangulation::MaxBarrierRaises);
  this->T->snapshot(snapshot, points, false, this->weights); // the mesh's points: nothing moved
  for (std::size_t t = 0; t < inverted.size(); ++t)
  {
    EXPECT_EQ(snapshot.barrierScales[0][t], 1.0) << "embedding 0 did not invert";
    EXPECT_EQ(snapshot.barrierScales[1][t], inverted[t] ? top : 1.0) << "triangle " << t;
  }
  // A flip of a raised triangle's edge makes two new triangles: unraised.
  HalfedgeMesh& mesh = this->T->mesh();
  OpenMesh::FaceHandle kept;
  bool flipped = false;
  for (std::size_t t = 0; t < inverted.size() && !flipped; ++t)
  {
    const auto f = mesh.face_handle(static_cast<int>(t));
    for (auto h : mesh.fh_range(f))
    {
      const auto other = mesh.opposite_face_handle(h);
      if (inverted[t] && inverted[other.idx()] &&
        applyFlip(*this->T, this->energy(), this->handlers, mesh.edge_handle(h), Always))
      {
        kept = mesh.face_handle(h);
        flipped = true;
        break;
      }
    }
  }
  ASSERT_TRUE(flipped);
  this->T->snapshot(snapshot, points, false, this->weights);
  int raised = 0;
  for (std::size_t t = 0; t < inverted.size(); ++t)
  {
    raised += snapshot.barrierScales[1][t] == top ? 1 : 0;
  }
  EXPECT_EQ(raised, std::count(inverted.begin(), inverted.end(), 1) - 2);
  EXPECT_EQ(snapshot.barrierScales[1][kept.idx()], 1.0);
}
