// SurfaceMaps engine: procedural meshes (tests, initial embeddings, examples).
#pragma once

#include "mesh/PolygonMesh.h"

namespace surfacemaps
{

/// Regular tetrahedron inscribed in the unit sphere, outward orientation.
PolygonMesh makeTetrahedron();

/// Regular octahedron with vertices on the unit axes, outward orientation.
PolygonMesh makeOctahedron();

/// Unit icosphere: the icosahedron subdivided `level` times, vertices projected
/// onto the sphere; 10 * 4^level + 2 vertices, outward orientation.
PolygonMesh makeIcosphere(int level);

/// Torus of major radius R and minor radius r, `majorSegments` x `minorSegments`
/// quads split into triangles (genus 1).
PolygonMesh makeTorus(int majorSegments, int minorSegments, double R = 1.0, double r = 0.35);

} // namespace surfacemaps
