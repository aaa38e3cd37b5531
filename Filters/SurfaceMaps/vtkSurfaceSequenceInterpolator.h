/**
 * @class   vtkSurfaceSequenceInterpolator
 * @brief   A surface that moves through K keyframe surfaces of identical connectivity over time.
 *
 * Interpolates between K >= 1 keyframe meshes that share
 * their cells, e.g. the outputs of vtkSurfaceMapFilter with
 * SetPairModeToSequence() (one common triangulation lifted onto the surfaces
 * of successive developmental stages), or stage averages (vtkSurfaceAverage)
 * mapped through one common triangulation. Keyframe k is placed at time t_k
 * (SetKeyframeTime; default t_k = k); the output is the surface at any time
 * in [t_0, t_{K-1}], following VTK's temporal pipeline: the output
 * information reports TIME_STEPS and TIME_RANGE, and the requested
 * UPDATE_TIME_STEP is produced (UpdateTimeStep(t), ParaView's animation, or
 * downstream temporal filters).
 *
 * InterpolationMode, the weights c_k(t) of the keyframes in time (written
 * below for BLEND_VERTICES, which weighs the points; BLEND_ROTATIONS weighs
 * each triangle's rotation vector and stretch the same way):
 * - INTERPOLATE_LINEAR: on [t_k, t_{k+1}], (1 - u) x_k + u x_{k+1} with
 *   u = (t - t_k) / (t_{k+1} - t_k). Continuous; the velocity jumps at the
 *   keyframes.
 * - INTERPOLATE_SMOOTH (default): piecewise-cubic Hermite interpolation, C1
 *   in time, with the tangent at keyframe k the derivative of the parabola
 *   through keyframes k - 1, k, k + 1 (through 0, 1, 2 at the first keyframe
 *   and K - 3, K - 2, K - 1 at the last), valid for non-uniform times. With
 *   BLEND_VERTICES and ALIGN_NONE it reproduces every vertex path that is a
 *   polynomial of degree <= 2 in t exactly; with two keyframes it equals the
 *   linear interpolation. Like every interpolating cubic it may overshoot
 *   between keyframes that change direction abruptly.
 * Both modes reproduce the keyframes exactly at the keyframe times (after
 * their alignment, below).
 *
 * What it assumes: the keyframes are one surface at successive times, vertex
 * v of every keyframe the same material point (one common triangulation),
 * and a change of pose between keyframes (an organ scanned turned, a mean
 * placed where its stage's specimens lay) is not part of the motion. So:
 * - KeyframeAlignment (default ALIGN_RIGID): the keyframes are first aligned
 *   onto their order-free mean (generalized Procrustes with area weights, as
 *   vtkSurfaceAverage: rotation and translation, plus a uniform scale with
 *   ALIGN_SIMILARITY, which also removes growth between keyframes); the
 *   output is in the mean's frame, which lies where the keyframes lie on
 *   average, and at t_k it is keyframe k moved by its transform. ALIGN_NONE
 *   takes the poses as given.
 * - ShapeBlending (default BLEND_ROTATIONS): what remains, genuine bending
 *   and turning of parts, is blended triangle by triangle in rotation (by
 *   angle) and stretch and integrated back into a surface (least squares),
 *   so a part that turns between keyframes keeps its length and thickness;
 *   a vertex-wise blend (BLEND_VERTICES) moves points along chords, which
 *   shortens and thins turning parts (a shape turned by 90 degrees keeps 71
 *   % of its width half-way, a tube bent into a half loop collapses). Both
 *   use the same coefficients in time. With BLEND_ROTATIONS a rigid turn
 *   between keyframes is interpolated as a rigid turn (the shorter way
 *   round); a part that turns by more than 180 degrees while the rest of the
 *   surface turns less (a tube bending into a loop) keeps turning the same
 *   way; keyframes that differ by stretch alone blend as with
 *   BLEND_VERTICES.
 *
 * Inputs: port 0 is repeatable; keyframe k is the (k+1)-th connection. Every
 * keyframe must have keyframe 0's number of points and exactly its cells;
 * otherwise vtkErrorMacro names the keyframe and the first difference, and
 * the output is empty. The keyframes are requested without a time (they are
 * static surfaces).
 *
 * Output: keyframe 0's cells with the interpolated points; point data under
 * vtkSurfaceAverage's rules, for arrays present on every keyframe with the
 * same name, type and components: continuous arrays (by default the
 * floating-point ones) interpolated with the same coefficients (integers
 * rounded); categorical arrays (by default the integer ones: labels) the
 * values of the keyframe nearest in time (the earlier one at a midpoint), so
 * they switch at the midpoints between keyframes; SetArrayTransferMode
 * chooses per array (see vtkSurfaceArrayTransferAlgorithm). "Landmarks" is
 * keyframe 0's; "SourceCellId", "SourceBarycentric", "SpherePosition" and the
 * active normals are dropped.
 * Continuous active vectors are rotated by each keyframe's alignment.
 * No cell data. Field data "InterpolationTime": the time actually
 * interpolated (the requested time clamped into [t_0, t_{K-1}]); unless
 * ALIGN_NONE, vtkSurfaceAverage's "AlignmentRMS" and "AlignmentTransform"
 * (one 12-component tuple per keyframe: [s_k R_k | t_k] row by row, onto the
 * output's frame) and, with ALIGN_SIMILARITY, "AlignmentScale". The output's
 * vtkDataObject::DATA_TIME_STEP is the requested time.
 *
 * Errors: keyframe times that are not strictly increasing (the message names
 * the first keyframe k with t_k <= t_{k-1}) or connectivity that differs:
 * vtkErrorMacro and an empty output (TIME_STEPS is then not reported).
 *
 * @warning Single-threaded. The alignment (a few Procrustes rounds over all
 * K keyframes) and, with BLEND_ROTATIONS, a polar decomposition per
 * triangle and keyframe and one sparse factorisation run when the keyframes
 * or these two settings change and are kept for later times; each update
 * is then linear in the number of points (one sparse solve with
 * BLEND_ROTATIONS; only the two or four keyframes around the time
 * contribute).
 *
 * @sa vtkSurfaceMapFilter vtkSurfaceAverage vtkTemporalInterpolator
 * vtkSurfaceArrayTransferAlgorithm
 */
#ifndef vtkSurfaceSequenceInterpolator_h
#define vtkSurfaceSequenceInterpolator_h

#include "SurfaceMapsFiltersModule.h" // for export macro
#include "vtkSurfaceArrayTransferAlgorithm.h"

#include <memory> // for std::unique_ptr

class SURFACEMAPSFILTERS_EXPORT vtkSurfaceSequenceInterpolator
  : public vtkSurfaceArrayTransferAlgorithm
{
public:
  static vtkSurfaceSequenceInterpolator* New();
  vtkTypeMacro(vtkSurfaceSequenceInterpolator, vtkSurfaceArrayTransferAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** How the surface moves between keyframes. */
  enum InterpolationModes
  {
    INTERPOLATE_LINEAR = 0, ///< piecewise linear in time
    INTERPOLATE_SMOOTH = 1  ///< piecewise cubic Hermite, C1 in time
  };

  ///@{
  /**
   * INTERPOLATE_LINEAR or INTERPOLATE_SMOOTH (default).
   */
  vtkSetClampMacro(InterpolationMode, int, INTERPOLATE_LINEAR, INTERPOLATE_SMOOTH);
  vtkGetMacro(InterpolationMode, int);
  void SetInterpolationModeToLinear() { this->SetInterpolationMode(INTERPOLATE_LINEAR); }
  void SetInterpolationModeToSmooth() { this->SetInterpolationMode(INTERPOLATE_SMOOTH); }
  ///@}

  /** How the keyframes are aligned to each other before they are blended. */
  enum KeyframeAlignments
  {
    ALIGN_NONE = 0,      ///< poses as given
    ALIGN_RIGID = 1,     ///< rotation and translation
    ALIGN_SIMILARITY = 2 ///< rotation, translation and uniform scale
  };

  ///@{
  /**
   * ALIGN_NONE, ALIGN_RIGID (default) or ALIGN_SIMILARITY: the least-squares
   * (area-weighted) transformation of every keyframe onto the keyframes'
   * common mean, applied before blending (see the class description).
   */
  vtkSetClampMacro(KeyframeAlignment, int, ALIGN_NONE, ALIGN_SIMILARITY);
  vtkGetMacro(KeyframeAlignment, int);
  void SetKeyframeAlignmentToNone() { this->SetKeyframeAlignment(ALIGN_NONE); }
  void SetKeyframeAlignmentToRigid() { this->SetKeyframeAlignment(ALIGN_RIGID); }
  void SetKeyframeAlignmentToSimilarity() { this->SetKeyframeAlignment(ALIGN_SIMILARITY); }
  ///@}

  /** How the points of the aligned keyframes are blended. */
  enum ShapeBlendings
  {
    BLEND_VERTICES = 0, ///< vertex by vertex: sum_k c_k x_k
    BLEND_ROTATIONS = 1 ///< triangle by triangle in rotation and stretch
  };

  ///@{
  /**
   * BLEND_VERTICES or BLEND_ROTATIONS (default): whether turning parts are
   * blended along chords or by angle (see the class description). Point
   * arrays are blended vertex by vertex either way.
   */
  vtkSetClampMacro(ShapeBlending, int, BLEND_VERTICES, BLEND_ROTATIONS);
  vtkGetMacro(ShapeBlending, int);
  void SetShapeBlendingToVertices() { this->SetShapeBlending(BLEND_VERTICES); }
  void SetShapeBlendingToRotations() { this->SetShapeBlending(BLEND_ROTATIONS); }
  ///@}

  ///@{
  /**
   * Time of keyframe k (default k for every keyframe without an explicit
   * time). The times of the connected keyframes must be strictly increasing
   * (checked at update time: an error otherwise). Times of indices beyond the
   * number of keyframes are kept but unused. A negative index is ignored with
   * an error.
   */
  void SetKeyframeTime(int k, double time);
  double GetKeyframeTime(int k);
  void RemoveAllKeyframeTimes();
  ///@}

  ///@{
  /**
   * Time steps reported per keyframe interval in TIME_STEPS: the keyframe
   * times plus StepsPerInterval - 1 evenly spaced times inside each interval,
   * so an animation that snaps to the time steps shows the motion. Default 1
   * (only the keyframes), range [1, 10000]. Any time in the range can be
   * requested regardless.
   */
  vtkSetClampMacro(StepsPerInterval, int, 1, 10000);
  vtkGetMacro(StepsPerInterval, int);
  ///@}

  ///@{
  /**
   * Time produced when the request carries no UPDATE_TIME_STEP (a plain
   * Update() before any time was requested downstream). Default 0 (keyframe
   * 0 with the default times); clamped into the keyframe range at update time.
   * Once a time was requested (UpdateTimeStep), the pipeline keeps requesting
   * it, so later plain updates use that time.
   */
  vtkSetMacro(TimeValue, double);
  vtkGetMacro(TimeValue, double);
  ///@}

protected:
  vtkSurfaceSequenceInterpolator();
  ~vtkSurfaceSequenceInterpolator() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int InterpolationMode = INTERPOLATE_SMOOTH;
  int KeyframeAlignment = ALIGN_RIGID;
  int ShapeBlending = BLEND_ROTATIONS;
  int StepsPerInterval = 1;
  double TimeValue = 0.0;

private:
  vtkSurfaceSequenceInterpolator(const vtkSurfaceSequenceInterpolator&) = delete;
  void operator=(const vtkSurfaceSequenceInterpolator&) = delete;

  struct vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
