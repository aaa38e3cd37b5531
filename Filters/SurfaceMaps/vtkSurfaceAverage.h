/**
 * @class   vtkSurfaceAverage
 * @brief   Weighted mean shape of N surfaces with identical connectivity, after alignment.
 *
 * Averages N >= 1 meshes that share their cells vertex by vertex, typically
 * the N outputs of vtkSurfaceMapFilter in its default COMMON_TRIANGULATION
 * mode (the common triangulation T lifted onto each input, in each input's
 * own coordinates): the mean shape of, e.g., the organ surfaces of one
 * developmental stage.
 *
 * The mean does not depend on the order of the inputs: generalized
 * Procrustes alignment (Gower 1975) aligns every input onto the current
 * mean, recomputes the mean and repeats until it stops moving (AlignMode).
 * Input i's alignment is the similarity x -> s_i R_i x + t_i (R_i a rotation,
 * never a reflection; s_i = 1 unless ALIGN_SIMILARITY) minimising the
 * area-weighted sum of squared distances sum_v A_v |s_i R_i x_iv + t_i - m_v|^2
 * to the mean m, with A_v a third of the area of the triangles around v,
 * averaged over the inputs with their weights (uniform when the inputs have
 * no area): the closed form of Umeyama (1991) via a 3x3 SVD. The output
 * points are the weighted mean m_v = sum_i w_i (s_i R_i x_iv + t_i) with the
 * input weights w_i normalised to sum 1.
 *
 * The frame of the mean is the same whatever the input order: with
 * ALIGN_SIMILARITY its size (area-weighted RMS distance to its centroid) is
 * the weighted mean of the inputs' sizes; it is placed by the rigid motion
 * that fits it best to the inputs as given (least sum_i w_i sum_v A_v
 * |m_v - x_iv|^2), so it lies where the inputs lie (for inputs already in one
 * frame, in that frame). That placement is ill-defined only when the inputs'
 * poses cancel out (e.g. a surface and its copy turned by half a turn, equal
 * weights). A single input of positive weight is the mean as given. Inputs of
 * weight 0 are aligned onto the mean but do not move it. Permuting the inputs
 * (with their weights) changes the mean only by rounding and the alignment's
 * convergence tolerance (far below 1e-9 of the bounding-box diagonal).
 *
 * vtkProcrustesAlignmentFilter is not used: it weighs every point alike (not
 * by area, so a finely meshed region would count more), has no input
 * weights, keeps the first input's frame and stops after 5 rounds at an
 * absolute tolerance, which leaves the result dependent on the input order.
 *
 * Inputs: port 0 is repeatable; input i is the (i+1)-th connection. Every
 * input must have input 0's number of points and exactly its cells (same
 * point ids in the same order); otherwise vtkErrorMacro names the input and
 * the first difference ("input 2 (b.obj) does not have the connectivity of
 * input 0: cell 17 has the points (3 4 5) instead of (3 5 4)") and the output
 * is empty.
 *
 * Output: input 0's cells with the averaged points. Point data, for arrays
 * present on every input with the same name, type and number of components
 * (others are dropped):
 * - continuous arrays (by default the floating-point ones) are averaged with
 *   the same weights (integers rounded); the active vectors are rotated by
 *   R_i first;
 * - categorical arrays (by default the integer ones: labels, region ids) are
 *   input 0's values, even where other inputs differ and whatever input 0's
 *   weight: a mean of labels is no label. SetArrayTransferMode chooses per
 *   array (see vtkSurfaceArrayTransferAlgorithm);
 * - "Landmarks" is input 0's (with the categorical arrays, the only output
 *   that depends on the input order);
 * - "SourceCellId", "SourceBarycentric" and "SpherePosition" (where a vertex
 *   lies on one input and on its sphere) and the active normals are dropped
 *   (recompute normals with vtkPolyDataNormals).
 * Cell data is not passed. Field data: "AlignmentRMS" (one value per input:
 * the area-weighted RMS distance sqrt(sum_v A_v |aligned x_iv - m_v|^2)
 * between the aligned input and the mean, in the output's units),
 * "AlignmentTransform" (one 12-component tuple per input: the 3x4 matrix
 * [s_i R_i | t_i] taking input i into the output's frame, row by row),
 * "AverageWeight" (the normalised weights) and, with ALIGN_SIMILARITY,
 * "AlignmentScale" (s_i per input).
 *
 * Errors: a negative or non-finite weight, weights summing to 0, or
 * connectivity that differs: vtkErrorMacro and an empty output. AbortExecute
 * set during the update (e.g. from a ProgressEvent observer) leaves the output
 * empty without an error.
 *
 * @warning Linear in N times the number of points per round of the alignment;
 * a few rounds for similar shapes, up to 200 (single-threaded, about a
 * millisecond per 10 000 vertices, input and round). Progress is reported
 * once per input and round, and AbortExecute is honoured there.
 *
 * @sa vtkSurfaceMapFilter vtkSurfaceSequenceInterpolator vtkSurfaceShapeStatistics
 * vtkProcrustesAlignmentFilter vtkSurfaceArrayTransferAlgorithm
 */
#ifndef vtkSurfaceAverage_h
#define vtkSurfaceAverage_h

#include "SurfaceMapsFiltersModule.h" // for export macro
#include "vtkSurfaceArrayTransferAlgorithm.h"

#include <memory> // for std::unique_ptr

class SURFACEMAPSFILTERS_EXPORT vtkSurfaceAverage : public vtkSurfaceArrayTransferAlgorithm
{
public:
  static vtkSurfaceAverage* New();
  vtkTypeMacro(vtkSurfaceAverage, vtkSurfaceArrayTransferAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** How each input is aligned onto the mean. */
  enum AlignModes
  {
    ALIGN_NONE = 0,      ///< as given
    ALIGN_RIGID = 1,     ///< rotation and translation
    ALIGN_SIMILARITY = 2 ///< rotation, translation and uniform scale
  };

  ///@{
  /**
   * ALIGN_NONE, ALIGN_RIGID (default) or ALIGN_SIMILARITY: the least-squares
   * (area-weighted) transformation of each input onto the mean, iterated
   * with the mean (generalized Procrustes). Reflections are never used.
   */
  vtkSetClampMacro(AlignMode, int, ALIGN_NONE, ALIGN_SIMILARITY);
  vtkGetMacro(AlignMode, int);
  void SetAlignModeToNone() { this->SetAlignMode(ALIGN_NONE); }
  void SetAlignModeToRigid() { this->SetAlignMode(ALIGN_RIGID); }
  void SetAlignModeToSimilarity() { this->SetAlignMode(ALIGN_SIMILARITY); }
  ///@}

  ///@{
  /**
   * Weight of input i in the mean (default 1 for every input). Weights must
   * be >= 0 with a positive sum (checked at update time: an error otherwise);
   * they are normalised to sum 1, and weight 0 leaves an input out of the mean
   * (it must still have the connectivity). Weights of indices beyond the
   * number of inputs are kept but unused. A negative index is ignored with an
   * error.
   */
  void SetInputWeight(int i, double weight);
  double GetInputWeight(int i);
  void RemoveAllInputWeights();
  ///@}

protected:
  vtkSurfaceAverage();
  ~vtkSurfaceAverage() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int AlignMode = ALIGN_RIGID;

private:
  vtkSurfaceAverage(const vtkSurfaceAverage&) = delete;
  void operator=(const vtkSurfaceAverage&) = delete;

  struct vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
