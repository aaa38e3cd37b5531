/**
 * @class   vtkSurfaceTextureSeamSplitter
 * @brief   Splits a triangle mesh along its texture seams so that one texture coordinate per point renders it.
 *
 * Texture coordinates per triangle corner (the 6-component cell array
 * "CornerTCoords": u and v of corners 0, 1, 2, as vtkSurfaceMeshReader reads
 * OBJ `vt` and PLY `texcoord`, and as vtkSurfaceMapFilter and
 * vtkSurfaceMapTransfer carry them onto other meshes) can differ at a vertex
 * shared by triangles on both sides of a seam. VTK renders one texture
 * coordinate per point, so a mesh whose points carry a single value shows,
 * along every seam, triangles stretched across the texture atlas. This filter
 * gives every point one copy per distinct corner value (exact comparison;
 * corners without a value, NaN, count as one value), so the active point
 * texture coordinates are exactly the corners' values.
 *
 * Output: the input's points followed by the copies, the triangles (same order,
 * same cell data) using the copies, every point array copied onto the copies,
 * and the point arrays
 * - "TCoords" (active texture coordinates): each point's corner value (points
 *   used by no triangle keep the input's active texture coordinates, or NaN);
 * - "OriginalPointId" (vtkIdType): the input point each output point copies.
 * An input without "CornerTCoords" passes through unchanged, with
 * "OriginalPointId" the identity. Vertices, lines and strips pass through on
 * the original points. Errors (polygons that are not triangles, a
 * "CornerTCoords" array that is not 6 components per cell) leave the output
 * empty.
 *
 * @sa vtkSurfaceMeshReader vtkSurfaceMapTransfer vtkSurfaceMapFilter
 */
#ifndef vtkSurfaceTextureSeamSplitter_h
#define vtkSurfaceTextureSeamSplitter_h

#include "SurfaceMapsFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class SURFACEMAPSFILTERS_EXPORT vtkSurfaceTextureSeamSplitter : public vtkPolyDataAlgorithm
{
public:
  static vtkSurfaceTextureSeamSplitter* New();
  vtkTypeMacro(vtkSurfaceTextureSeamSplitter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Why the last update failed: the reason its error message gave, also when
   * an input's producer failed upstream (then it names the input and what
   * failed). Empty after a successful update. After a failure GetErrorCode()
   * is vtkSurfaceMapFilter::InvalidInputError (an input cannot be used, or
   * was not produced), NotCertifiedError, or vtkErrorCode::UnknownError (an
   * internal error), and the outputs are empty.
   */
  const char* GetLastErrorMessage() const;

protected:
  vtkSurfaceTextureSeamSplitter() = default;
  ~vtkSurfaceTextureSeamSplitter() override = default;
  vtkExecutive* CreateDefaultExecutive() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkSurfaceTextureSeamSplitter(const vtkSurfaceTextureSeamSplitter&) = delete;
  void operator=(const vtkSurfaceTextureSeamSplitter&) = delete;
};

#endif
