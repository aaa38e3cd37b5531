/**
 * @class   vtkSurfaceMapsCombination
 * @brief   Linear combinations of meshes with identical connectivity (private).
 *
 * Shared by vtkSurfaceAverage (weighted mean after alignment) and
 * vtkSurfaceSequenceInterpolator (linear or cubic Hermite blend of keyframes):
 * both compute sum_i c_i x_i over N meshes that share their cells. The
 * connectivity check, the meshes as engine shapes and the alignment's field
 * data also serve vtkSurfaceShapeStatistics.
 *
 * Point-data rules (the same for both filters):
 * - "SourceCellId", "SourceBarycentric", "SpherePosition" and the active
 *   normals are dropped: they describe where a vertex lies on one input (or
 *   its surface orientation), which a blend of positions does not carry over
 *   (recompute normals with vtkPolyDataNormals).
 * - "Landmarks" is input 0's.
 * - Other arrays with the same name, type and number of components on every
 *   input go the way the filter's rule says
 *   (vtkSurfaceArrayTransferAlgorithm::ResolveArrayTransferMode; by default
 *   integer arrays categorical, floating-point ones continuous):
 *   categorical ones are the reference input's values (input 0 for the
 *   average, the keyframe nearest in time for the interpolator); continuous
 *   ones are combined component-wise with the same coefficients, in double
 *   precision, into an array of that type (integers rounded and clamped to
 *   the type's range); the active vectors are first rotated by each input's
 *   transform.
 * - Arrays missing on some input, or of a different type or shape there, and
 *   arrays that are not numeric are dropped.
 * Cell data and field data are not passed.
 */
#ifndef vtkSurfaceMapsCombination_h
#define vtkSurfaceMapsCombination_h

#include "statistics/Procrustes.h"

#include <Eigen/Core>

#include "vtkIOStream.h"

#include <array>
#include <map>
#include <string>
#include <vector>

class vtkPolyData;
class vtkSurfaceArrayTransferAlgorithm;

class vtkSurfaceMapsCombination
{
public:
  /// Throws std::invalid_argument "no <what>" when `inputs` is empty and
  /// "<what> k is not a vtkPolyData" for the first missing one.
  static void CheckPresent(const std::vector<vtkPolyData*>& inputs, const char* what);

  /// Values set per index (input weights, keyframe times); an index that was
  /// not set takes a default its owner supplies.
  class IndexedValues
  {
  public:
    /// Sets value i; false when it already had this value (nothing changed).
    bool Set(int i, double value);
    /// Value i, or `fallback` when it was not set.
    double Get(int i, double fallback) const;
    /// Removes every value; false when there were none.
    bool Clear();
    /// " i: v" for every value set, or " " + `whenEmpty`.
    void Print(ostream& os, const char* whenEmpty) const;

  private:
    std::map<int, double> Values;
  };

  /// x -> Scale * Rotation * x + Translation.
  using Similarity = surfacemaps::Similarity;

  /// The points of `mesh`, vertex by vertex.
  static surfacemaps::ShapePoints Points(vtkPolyData* mesh);

  /// The polygons of `mesh` as triangles (fans).
  static std::vector<std::array<int, 3>> Triangles(vtkPolyData* mesh);

  /// Adds the generalized Procrustes alignment as field data: "AlignmentRMS"
  /// (one value per input), "AlignmentTransform" (one 12-component tuple per
  /// input: the 3x4 matrix [s_i R_i | t_i], row by row) and, when
  /// `withScale`, "AlignmentScale" (s_i).
  static void AddAlignmentFields(vtkPolyData* output,
    const surfacemaps::ProcrustesResult& alignment,
    bool withScale);

  /// Adds the double array `name` with `values` (tuples of `components`) to
  /// the field data of `output`.
  static void AddField(vtkPolyData* output,
    const char* name,
    int components,
    const std::vector<double>& values);

  /// The engine's alignment for ALIGN_NONE (0), ALIGN_RIGID (1) or
  /// ALIGN_SIMILARITY (2), the modes of vtkSurfaceAverage and
  /// vtkSurfaceShapeStatistics.
  static surfacemaps::AlignmentKind AlignmentOf(int alignMode);

  /// "<kind> <index>", followed by " (<FileName>)" when the mesh carries one.
  static std::string Name(vtkPolyData* mesh, const std::string& kind, int index);

  /// Throws std::invalid_argument naming the first mesh (as `kind` i) whose
  /// number of points or cells differs from mesh 0's, and where; also the
  /// first mesh with a cell using a vertex index outside its points (64-bit
  /// ids included) or a point with non-finite coordinates.
  static void CheckSameConnectivity(const std::vector<vtkPolyData*>& meshes,
    const std::string& kind);

  /// output = mesh 0's cells with points sum_i c_i T_i(x_i) and the point
  /// arrays described above, categorical ones from mesh `reference`, each
  /// array's mode from `modes`. `transforms` is empty (identity) or one per
  /// mesh. Meshes with coefficient 0 do not contribute continuous values.
  static void Combine(const std::vector<vtkPolyData*>& meshes,
    const std::vector<double>& coefficients,
    const std::vector<Similarity>& transforms,
    int reference,
    vtkSurfaceArrayTransferAlgorithm* modes,
    vtkPolyData* output);
};

#endif
