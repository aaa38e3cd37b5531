// The command line: the geometric consistency of a map directory's files,
// which checksums cannot vouch for once report.json itself was edited.
//
// common_<j>.vtp holds, per vertex v of the common triangulation T, its
// position g_j(v) on sphere j ("SpherePosition") and where it lies on input j
// ("SourceCellId", "SourceBarycentric"), and embedding_<j>.vtp holds input j
// with its sphere embedding f_j ("SpherePosition"). The map found that point
// by locating g_j(v) in f_j (the ray 0 -> g_j(v) through the flat chord
// triangle), so f_j evaluated at the source point, normalised, is g_j(v) up to
// rounding. A rotated, mirrored, swapped or otherwise edited embedding or
// common file breaks that at (nearly) every vertex.
#pragma once

#include <string>
#include <vector>

namespace surfacemap
{

/// Largest distance on the unit sphere between g_j(v) and f_j at v's source
/// point that a map directory may show. A valid map's is rounding only (about
/// 1e-16 times the aspect ratio of the embedding's triangles); a rotation by
/// an angle a shows about a.
constexpr double MapSphereTolerance = 1e-6;

/// Checks that the files common_<j>.vtp of `inputs` in `directory` hold one
/// triangulation (points and triangles) and that each agrees with its
/// embedding_<j>.vtp as described above. Throws std::runtime_error naming the
/// files, the first vertex that disagrees and by how much. The files are
/// expected to be checked against report.json first (verifyMapFiles does).
void checkMapGeometry(const std::string& directory, const std::vector<int>& inputs);

} // namespace surfacemap
