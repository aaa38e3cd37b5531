/**
 * @class   vtkSurfaceMapTransfer
 * @brief   Carries point data from one input of a computed surface map to another.
 *
 * Samples the point arrays of one input of a bijective surface map (the
 * source, input `from`) onto the vertices of another (the target, input
 * `to`), through the map that vtkSurfaceMapFilter computed ("Surface Maps via
 * Adaptive Triangulations", Schmidt, Pieper, Kobbelt, Eurographics 2023),
 * from its saved outputs: no optimisation runs here. For every target vertex
 * v the exact map Phi = f_from^-1 o g_from o g_to^-1 o f_to gives a point of
 * the source: v's sphere point f_to(v) is located in the common
 * triangulation T's embedding g_to, the same barycentric coordinates are
 * taken on g_from (and normalised), and that sphere point is located in the
 * source's embedding f_from: a source triangle and barycentric coordinates,
 * where the source's arrays are read.
 *
 * Inputs (one vtkPolyData each, triangles only, all from the same map):
 * - port 0, target mesh: input `to` with the point array "SpherePosition" =
 *   f_to, its sphere embedding as the map used it (vtkSurfaceMapFilter's
 *   INPUT_EMBEDDINGS output `to`; `surfacemap map`'s embedding_<to>.vtp);
 * - port 1, source mesh: input `from` with "SpherePosition" = f_from and the
 *   arrays to transfer (embedding_<from>.vtp);
 * - port 2: T lifted onto the target, with "SpherePosition" = g_to
 *   (COMMON_TRIANGULATION output `to`, common_<to>.vtp);
 * - port 3: T lifted onto the source, with "SpherePosition" = g_from
 *   (common_<from>.vtp); its "SourceCellId", where present, is where point
 *   location on the source starts.
 *
 * Output: the target mesh (its points, triangles, cell data and field data)
 * with point data:
 * - the source's point arrays, keeping their names, types and their roles as
 *   active attributes: all of them except "SpherePosition", "Landmarks",
 *   "SourceCellId", "SourceBarycentric" and id-typed arrays, or those named
 *   with AddArrayName (any point array of the source). Each is continuous
 *   (interpolated with the barycentric coordinates; integers rounded) or
 *   categorical (the value at the corner of the source triangle with the
 *   largest barycentric coordinate, so never a value the source does not
 *   have): integer arrays categorical and floating-point ones continuous
 *   unless SetArrayTransferMode says otherwise (see
 *   vtkSurfaceArrayTransferAlgorithm);
 * - "SourceCellId" (the source triangle the vertex maps into) and
 *   "SourceBarycentric" (its barycentric coordinates there);
 * - "TCoords" (active texture coordinates) when the source carries per-corner
 *   texture coordinates (the 6-component cell array "CornerTCoords" of
 *   vtkSurfaceMeshReader): the corners of that source triangle interpolated
 *   with those barycentric coordinates; otherwise the source's active point
 *   texture coordinates, if any, are transferred (also when not named).
 * With per-corner texture coordinates on the source, the cell array
 * "CornerTCoords" (6 components) replaces the target's own: per triangle
 * corner, so that no triangle spans a texture seam
 * (surfacemaps::transferCornerValues). Render the texture through
 * vtkSurfaceTextureSeamSplitter, which gives each corner value its own point.
 * The target's own point arrays are not kept.
 *
 * Checks (errors name the port, the file from the "FileName" field data where
 * present, and the defect): every input is a non-empty triangle mesh with a
 * "SpherePosition" array of unit vectors (within 1e-6; used as given) that
 * is a certified bijective embedding (exact orientation of every triangle,
 * degree 1); ports 2 and 3 hold the same triangles; every named array
 * exists. Errors leave the output empty and set GetErrorCode() to
 * InvalidInputError. Inputs from different map runs cannot be detected and
 * give a wrong transfer.
 *
 * @warning Cost: point location on the sphere (a visibility walk, exact
 * predicates) for every target vertex in T and in the source, plus the
 * certification of the four embeddings: roughly linear in the sizes, about
 * 0.2 s for 100 000 target vertices. Single-threaded.
 *
 * @sa vtkSurfaceMapFilter vtkSurfaceArrayTransferAlgorithm
 */
#ifndef vtkSurfaceMapTransfer_h
#define vtkSurfaceMapTransfer_h

#include "SurfaceMapsFiltersModule.h" // for export macro
#include "vtkErrorCode.h"             // for the error codes
#include "vtkSurfaceArrayTransferAlgorithm.h"

#include <memory> // for std::unique_ptr
#include <string> // for std::string

class vtkPolyData;

class SURFACEMAPSFILTERS_EXPORT vtkSurfaceMapTransfer : public vtkSurfaceArrayTransferAlgorithm
{
public:
  static vtkSurfaceMapTransfer* New();
  vtkTypeMacro(vtkSurfaceMapTransfer, vtkSurfaceArrayTransferAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** Values of GetErrorCode() after a failed update. */
  enum ErrorCodes
  {
    InvalidInputError = vtkErrorCode::UserError + 1 ///< an input or array name cannot be used
  };

  ///@{
  /**
   * Convenience: target mesh (port 0), source mesh (1), T lifted onto the
   * target (2) and onto the source (3).
   */
  void SetTargetConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(0, output); }
  void SetSourceConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }
  void SetTargetCommonConnection(vtkAlgorithmOutput* output)
  {
    this->SetInputConnection(2, output);
  }
  void SetSourceCommonConnection(vtkAlgorithmOutput* output)
  {
    this->SetInputConnection(3, output);
  }
  ///@}

  ///@{
  /**
   * The source point arrays to transfer. None named (default): every point
   * array of the source except "SpherePosition", "Landmarks", "SourceCellId",
   * "SourceBarycentric" and id-typed arrays. A name the source does not have
   * is an error at the update.
   */
  void AddArrayName(const char* name);
  void RemoveAllArrayNames();
  int GetNumberOfArrayNames();
  const char* GetArrayName(int index);
  ///@}

  /**
   * Whether `mesh` has the connectivity of `reference`, as data saved from
   * the same mesh keeps it (e.g. a source mesh carrying other point arrays):
   * the same number of points and the same triangles in the same order, each
   * possibly starting at another corner. Returns "" when it has; otherwise
   * the first difference as words that follow the name of `mesh`, naming
   * `reference` by `referenceName`: "has 162 vertices, input 1 has 642",
   * "has 5 cells, input 1 has 4 triangles" (also for cells that are not
   * triangles) or "has triangle 5 as (0, 2, 1), input 1 has (0, 1, 2)".
   * `surfacemap transfer --source-data` and the Python package's
   * transfer(source_data=...) check with it.
   */
  static std::string DescribeConnectivityDifference(vtkPolyData* mesh,
    vtkPolyData* reference,
    const char* referenceName);

protected:
  vtkSurfaceMapTransfer();
  ~vtkSurfaceMapTransfer() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkSurfaceMapTransfer(const vtkSurfaceMapTransfer&) = delete;
  void operator=(const vtkSurfaceMapTransfer&) = delete;

  struct vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
