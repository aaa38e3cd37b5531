/**
 * @class   vtkSurfaceShapeStatistics
 * @brief   Mean shape, principal modes of variation and per-vertex spread of N surfaces with identical connectivity.
 *
 * Statistics of a population of N >= 2 meshes that share their cells vertex
 * by vertex, typically the outputs of vtkSurfaceMapFilter (the common
 * triangulation lifted onto each specimen): the point distribution model of
 * Cootes et al. (1995) over the whole surface.
 *
 * 1. Alignment: generalized Procrustes alignment of all inputs with equal
 *    weights, exactly as vtkSurfaceAverage does it (AlignMode; area-weighted;
 *    the same order-free frame), so the mean here is vtkSurfaceAverage's
 *    mean of the same inputs.
 * 2. PCA of the aligned shapes in the area-weighted inner product
 *    <u, w> = sum_v A_v u_v . w_v (A_v: a third of the area of the triangles
 *    around v, averaged over the inputs, normalised to sum 1), through the
 *    N x N Gram matrix of the deviations from the mean (N is small, the
 *    points many). Second moments use 1/N. Area weighting makes the figures
 *    independent of how finely each region is meshed: sqrt(Variance) is the
 *    RMS displacement over the surface of one standard deviation along the
 *    mode, in the inputs' length unit.
 *
 * Output (port 0): input 0's cells with the points
 * mean + Coefficient * sqrt(variance_m) * mode_m for m = Mode (Coefficient 0
 * gives the mean: sliders for ParaView) and the point arrays:
 * - "StandardDeviation": per vertex, sqrt of the mean squared distance of
 *   the aligned inputs to the mean (in length units);
 * - "Mode_1" ... "Mode_k": the modes as displacement vectors (3 components),
 *   unit norm in the inner product above (sum_v A_v |u_v|^2 = 1); the sign is
 *   chosen so that the largest coordinate is positive.
 * Field data: "Variance" and "ExplainedVarianceFraction" (one value per
 * mode: variance / TotalVariance), "TotalVariance" (the sum over all N - 1
 * modes = sum_v A_v StandardDeviation_v^2), "Scores" (N tuples of k
 * components: <aligned x_i - mean, mode_m>, so x_i ~ mean + sum_m score_im
 * mode_m and the variance of a mode is the mean of its squared scores),
 * "AlignmentRMS", "AlignmentTransform" (and "AlignmentScale") as in
 * vtkSurfaceAverage. Input point arrays are not passed.
 *
 * k = min(NumberOfModes, N - 1). A mode of variance 0 (e.g. identical inputs)
 * has zero vectors and scores.
 *
 * Errors (vtkErrorMacro, empty output): fewer than 2 inputs, connectivity
 * that differs (the message of vtkSurfaceAverage, naming the input and the
 * first difference), or Mode above k. AbortExecute leaves the output empty
 * without an error.
 *
 * @warning Alignment: linear in N times the number of points per round; PCA:
 * N^2 times the number of points for the Gram matrix (a second for 50
 * inputs of 100 000 points). Single-threaded. Progress per input and
 * alignment round, where AbortExecute is honoured.
 *
 * vtkPCAAnalysisFilter is not used: it weighs every point alike (a finely
 * meshed region would dominate the modes) and expects already aligned
 * inputs, which vtkProcrustesAlignmentFilter would align in input 0's frame.
 *
 * @sa vtkSurfaceAverage vtkSurfaceMapFilter vtkPCAAnalysisFilter
 */
#ifndef vtkSurfaceShapeStatistics_h
#define vtkSurfaceShapeStatistics_h

#include "SurfaceMapsFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"


class SURFACEMAPSFILTERS_EXPORT vtkSurfaceShapeStatistics : public vtkPolyDataAlgorithm
{
public:
  static vtkSurfaceShapeStatistics* New();
  vtkTypeMacro(vtkSurfaceShapeStatistics, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** How the inputs are aligned onto their mean (as in vtkSurfaceAverage). */
  enum AlignModes
  {
    ALIGN_NONE = 0,      ///< as given
    ALIGN_RIGID = 1,     ///< rotation and translation
    ALIGN_SIMILARITY = 2 ///< rotation, translation and uniform scale
  };

  ///@{
  /**
   * ALIGN_NONE, ALIGN_RIGID (default: size stays part of the variation) or
   * ALIGN_SIMILARITY (shape alone): generalized Procrustes alignment of the
   * inputs before the PCA.
   */
  vtkSetClampMacro(AlignMode, int, ALIGN_NONE, ALIGN_SIMILARITY);
  vtkGetMacro(AlignMode, int);
  void SetAlignModeToNone() { this->SetAlignMode(ALIGN_NONE); }
  void SetAlignModeToRigid() { this->SetAlignMode(ALIGN_RIGID); }
  void SetAlignModeToSimilarity() { this->SetAlignMode(ALIGN_SIMILARITY); }
  ///@}

  ///@{
  /**
   * Modes computed, k (default 3, 1 to 1000); at most N - 1 come out.
   */
  vtkSetClampMacro(NumberOfModes, int, 1, 1000);
  vtkGetMacro(NumberOfModes, int);
  ///@}

  ///@{
  /**
   * The mode the output moves along, 1-based (default 1, 1 to 1000; it must
   * be at most the number of modes computed).
   */
  vtkSetClampMacro(Mode, int, 1, 1000);
  vtkGetMacro(Mode, int);
  ///@}

  ///@{
  /**
   * Standard deviations along Mode (default 0: the mean; -10 to 10): the
   * output is mean + Coefficient * sqrt(variance) * mode.
   */
  vtkSetClampMacro(Coefficient, double, -10.0, 10.0);
  vtkGetMacro(Coefficient, double);
  ///@}

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
  vtkSurfaceShapeStatistics();
  ~vtkSurfaceShapeStatistics() override;
  vtkExecutive* CreateDefaultExecutive() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int AlignMode = ALIGN_RIGID;
  int NumberOfModes = 3;
  int Mode = 1;
  double Coefficient = 0.0;

private:
  vtkSurfaceShapeStatistics(const vtkSurfaceShapeStatistics&) = delete;
  void operator=(const vtkSurfaceShapeStatistics&) = delete;
};

#endif
