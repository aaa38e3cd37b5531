/**
 * @class   vtkSurfaceMeshValidator
 * @brief   Checks that surfaces are valid SurfaceMaps inputs and measures them.
 *
 * SurfaceMaps maps closed, 2-manifold, genus-0 triangle meshes onto each
 * other. This filter takes any number of vtkPolyData on its (repeatable)
 * input port and produces a vtkTable with one row per input:
 *
 * | column | meaning |
 * |---|---|
 * | Input | the "FileName" field-data string of the input, else "input i" |
 * | Valid | 1 if the input can be used as is |
 * | Points, Triangles, Edges | counts (Edges -1 if not determined) |
 * | Genus | genus of a closed, manifold, connected surface, else -1 |
 * | Components, BoundaryEdges, NonManifoldEdges, NonManifoldVertices | counts (-1 if not
 * determined) | | Area, BoundingBoxDiagonal | in the input's units | | MinAngle, MeanMinAngle |
 * smallest and mean per-triangle minimum angle, degrees | | Orientation | +1 outward normals, -1
 * inward, 0 unknown | | Landmarks | number of vertices with a "Landmarks" id >= 0 | | Defects | one
 * line per defect ("is not closed: 12 boundary edges (first: edge 4-17)") |
 *
 * Checked: triangles only, no missing/unused/duplicate vertices, finite
 * coordinates, no zero-area triangles, closed, manifold edges and vertices,
 * consistent orientation, one component, genus 0, and landmark ids unique
 * per input and (with CheckLandmarkCorrespondence) the same ids on every
 * input. Invalid inputs are not an execution error: the table says what is
 * wrong, and GetAllValid() sums it up.
 *
 * @warning Linear in the input size, single-threaded; a 100k-triangle mesh
 * takes a few tens of milliseconds.
 *
 * @sa vtkSurfaceMeshReader
 */
#ifndef vtkSurfaceMeshValidator_h
#define vtkSurfaceMeshValidator_h

#include "SurfaceMapsFiltersModule.h" // for export macro
#include "vtkTableAlgorithm.h"

class SURFACEMAPSFILTERS_EXPORT vtkSurfaceMeshValidator : public vtkTableAlgorithm
{
public:
  static vtkSurfaceMeshValidator* New();
  vtkTypeMacro(vtkSurfaceMeshValidator, vtkTableAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Triangles whose area is at most this fraction of the mesh's total area
   * count as zero-area. Default 1e-12, range [0, 1e-3].
   */
  vtkSetClampMacro(ZeroAreaFraction, double, 0.0, 1e-3);
  vtkGetMacro(ZeroAreaFraction, double);
  ///@}

  ///@{
  /**
   * Require the same landmark ids on every input (when any input has
   * landmarks). Default on.
   */
  vtkSetMacro(CheckLandmarkCorrespondence, bool);
  vtkGetMacro(CheckLandmarkCorrespondence, bool);
  vtkBooleanMacro(CheckLandmarkCorrespondence, bool);
  ///@}

  /**
   * After an update: true when every input is valid (and there is at least one).
   */
  vtkGetMacro(AllValid, bool);

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
  vtkSurfaceMeshValidator();
  ~vtkSurfaceMeshValidator() override = default;
  vtkExecutive* CreateDefaultExecutive() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double ZeroAreaFraction = 1e-12;
  bool CheckLandmarkCorrespondence = true;
  bool AllValid = false;

private:
  vtkSurfaceMeshValidator(const vtkSurfaceMeshValidator&) = delete;
  void operator=(const vtkSurfaceMeshValidator&) = delete;
};

#endif
