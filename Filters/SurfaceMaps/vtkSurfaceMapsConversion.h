/**
 * @class   vtkSurfaceMapsConversion
 * @brief   Translation between vtkPolyData and the SurfaceMaps engine meshes.
 *
 * The one place where VTK data meets the engine (private to the module).
 * Per-corner texture coordinates travel as the 6-component cell-data array
 * "CornerTCoords" (u0 v0 u1 v1 u2 v2 per triangle), per-corner normals (OBJ
 * `vn`) as the 9-component "CornerNormals" (x0 y0 z0 x1 ... z2 per triangle;
 * NaN at corners without one); landmarks as the int
 * point-data array "Landmarks" (-1 none).
 */
#ifndef vtkSurfaceMapsConversion_h
#define vtkSurfaceMapsConversion_h

#include "base/Log.h"
#include "mesh/HalfedgeMesh.h"
#include "mesh/MeshValidation.h"
#include "mesh/PolygonMesh.h"
#include "mesh/SurfacePoint.h"

#include "vtkSmartPointer.h"

#include <array>
#include <string>
#include <vector>

class vtkInformationVector;
class vtkPointData;
class vtkPolyData;

class vtkSurfaceMapsConversion
{
public:
  /// Every polygon of `input` (vertices, lines and strips are counted as
  /// non-polygon cells), with per-corner texture coordinates and normals if
  /// present ("CornerTCoords", "CornerNormals" on pure triangle data).
  static surfacemaps::PolygonMesh ToPolygonMesh(vtkPolyData* input);
  /// Points and polygons (and "CornerTCoords", "CornerNormals" when every face
  /// is a triangle and the mesh has per-corner values),
  /// with the mesh's point arrays (AddPointArrays).
  static vtkSmartPointer<vtkPolyData> ToPolyData(const surfacemaps::PolygonMesh& mesh);
  /// The mesh's point arrays as VTK arrays of their types on `output`'s point
  /// data; "Normals", "TCoords" and "RGB"/"RGBA" become the normals, texture
  /// coordinates and scalars, as VTK's PLY reader makes them.
  static void AddPointArrays(vtkPolyData* output, const surfacemaps::PolygonMesh& mesh);

  /// Half-edge mesh of a valid triangle mesh; throws std::invalid_argument otherwise.
  static surfacemaps::HalfedgeMesh ToHalfedgeMesh(vtkPolyData* input);
  static vtkSmartPointer<vtkPolyData> ToPolyData(const surfacemaps::HalfedgeMesh& mesh);

  /// The "SpherePosition" point array (3 components, one per point); empty if
  /// absent or of the wrong shape.
  static std::vector<Eigen::Vector3d> SpherePositions(vtkPolyData* input);

  /// The "Landmarks" point array as ids per vertex (-1 none); empty if absent.
  /// An array that is not one integer-valued component per point (values in
  /// int range) adds a defect (a sentence without the input's name) to
  /// `defects` and gives no ids.
  static std::vector<int> LandmarkIds(vtkPolyData* input, std::vector<std::string>& defects);

  /// An input as the engine sees it, with everything validation found.
  struct ValidatedInput
  {
    surfacemaps::PolygonMesh mesh;
    /// Statistics and defects of the mesh and of its "Landmarks" array.
    surfacemaps::MeshValidationResult validation;
    /// Per vertex (-1 none); empty when absent or defective.
    std::vector<int> landmarkIds;
  };

  /// The one input validation of the module (readers' output, every filter,
  /// the command line): the mesh (validateMesh with `options`) and, when
  /// options.requireSurface, its "Landmarks" array (shape, integer values,
  /// one vertex per id). Defects are sentences without the input's name.
  static ValidatedInput Validate(vtkPolyData* input,
    const surfacemaps::MeshValidationOptions& options = surfacemaps::MeshValidationOptions());

  /// Adds "SourceCellId" (the input triangle) and "SourceBarycentric" (the
  /// barycentric coordinates in it) of every surface point, one per point.
  static void AddSourcePoints(vtkPointData* pointData,
    const std::vector<surfacemaps::SurfacePoint>& points);

  /// Texture coordinates of `output`, whose vertex v lies at `points[v]` on
  /// `source` and whose triangles (`triangles`, in the order of its polys)
  /// receive the source's per-corner texture coordinates
  /// (PolygonMesh::cornerTexCoords):
  /// - the cell array "CornerTCoords" (6 components, u and v of each corner,
  ///   as vtkSurfaceMeshReader writes it), from
  ///   surfacemaps::transferCornerValues: no triangle spans a texture seam;
  /// - the point array "TCoords", the active texture coordinates: the corners
  ///   of each point's source triangle evaluated there. One value per vertex
  ///   cannot hold a seam: render through vtkSurfaceTextureSeamSplitter.
  /// Nothing when the source has no per-corner texture coordinates.
  static void SetCornerTCoords(vtkPolyData* output,
    const surfacemaps::PolygonMesh& source,
    const std::vector<std::array<int, 3>>& triangles,
    const std::vector<surfacemaps::SurfacePoint>& points);

  /// The vtkPolyData of every information object of `vector` (null where
  /// one holds no vtkPolyData): a repeatable port's inputs, or the outputs.
  static std::vector<vtkPolyData*> PolyDataOf(vtkInformationVector* vector);

  /// Engine messages into vtkLogger: warnings as WARNING, Info (a phase or
  /// round done) at VERBOSITY_1, Detail (an iteration) as TRACE.
  static surfacemaps::Logger EngineLog();

  /// Name for messages: the "FileName" field-data string if present, else "input <index>".
  static std::string InputName(vtkPolyData* input, int index);
};

#endif
