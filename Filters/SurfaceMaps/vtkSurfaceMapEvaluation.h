/**
 * @class   vtkSurfaceMapEvaluation
 * @brief   Distortion, approximation error and validity of a map between two meshes.
 *
 * Measures the piecewise linear map between two meshes of identical
 * connectivity, source P (input port 0) and target Q (input port 1), the way
 * SurfaceMaps reports every map (DESIGN.md section 6, after "Surface Maps via
 * Adaptive Triangulations", Schmidt, Pieper, Kobbelt, Eurographics 2023): both
 * meshes centred and scaled to unit area, per triangle the singular values
 * s1 >= s2 of the Jacobian between the two triangles in their own frames.
 *
 * Optional ports 2 and 3: the original surfaces that P and Q approximate. With
 * them the Hausdorff figure H (largest distance from an original vertex to the
 * approximating mesh, closest point, in percent of the original's bounding box
 * diagonal) is reported per side, and a two-sided distance: the larger of the
 * largest distances from points sampled in each mesh's triangles (vertices,
 * edge midpoints, centroids) to the other mesh, in the same unit.
 *
 * Output: the source mesh with cell data "SingularValueMax", "SingularValueMin",
 * "MaxStretch" (max(s1, 1/s2): the distortion of DESIGN.md section 6; named apart
 * from vtkSurfaceMapFilter's "Distortion", a symmetric Dirichlet density), "AreaSource", "AreaTarget" (unit-area areas), and
 * field data "SymmetricDirichlet" (1/4 sum area_Q (s1^2+s2^2) + area_P
 * (s1^-2+s2^-2); 1 for an isometry), "AreaBelow1.5", "AreaBelow2" (area fraction
 * of the source with distortion below 1.5 and 2), "MaxDistortion",
 * "DegenerateTriangles", "DistortionCurve" (201 pairs: distortion from 1 to 3,
 * area fraction of the source below it), "MinAngleSource", "MeanMinAngleSource",
 * "MinAngleTarget", "MeanMinAngleTarget" (degrees), "HausdorffSource",
 * "HausdorffTarget", "TwoSidedDistanceSource", "TwoSidedDistanceTarget"
 * (percent, when the originals are given), and, when both
 * meshes carry "SpherePosition", "Bijective" (1 if both embeddings are
 * certified with exact predicates) with "NonPositiveTriangles".
 *
 * Meshes whose connectivity differs are an error (the message says where);
 * the output is then empty.
 *
 * @warning Linear in the mesh size except the Hausdorff figure, which builds a
 * cell locator per side (n log n). Single-threaded.
 *
 * @sa vtkSphereEmbeddingFilter vtkSurfaceMeshValidator
 */
#ifndef vtkSurfaceMapEvaluation_h
#define vtkSurfaceMapEvaluation_h

#include "SurfaceMapsFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class SURFACEMAPSFILTERS_EXPORT vtkSurfaceMapEvaluation : public vtkPolyDataAlgorithm
{
public:
  static vtkSurfaceMapEvaluation* New();
  vtkTypeMacro(vtkSurfaceMapEvaluation, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Convenience: source (port 0), target (1), originals (2, 3; optional). */
  void SetSourceConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(0, output); }
  void SetTargetConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }
  void SetSourceOriginalConnection(vtkAlgorithmOutput* output)
  {
    this->SetInputConnection(2, output);
  }
  void SetTargetOriginalConnection(vtkAlgorithmOutput* output)
  {
    this->SetInputConnection(3, output);
  }
  ///@}

  /** The summary figures of the last update, by field-data name (NaN if absent). */
  double GetSummaryValue(const char* name);

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
  vtkSurfaceMapEvaluation();
  ~vtkSurfaceMapEvaluation() override = default;
  vtkExecutive* CreateDefaultExecutive() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkSurfaceMapEvaluation(const vtkSurfaceMapEvaluation&) = delete;
  void operator=(const vtkSurfaceMapEvaluation&) = delete;
};

#endif
