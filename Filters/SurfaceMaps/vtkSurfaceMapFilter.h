/**
 * @class   vtkSurfaceMapFilter
 * @brief   Bijective map between N closed genus-0 surfaces via an adaptive common triangulation.
 *
 * Computes a continuous, bijective map between N >= 1 closed, manifold, genus-0
 * triangle meshes, represented by one common triangulation T with a sphere
 * embedding per input ("Surface Maps via Adaptive Triangulations", Schmidt,
 * Pieper, Kobbelt, Eurographics 2023). Each input gets a fixed bijective
 * embedding f_i on the unit sphere; T carries N embeddings g_i and is optimised
 * by edge splits, collapses, flips and projected-Newton steps on an energy of
 * bijectivity barriers, map distortion (symmetric Dirichlet over a set of input
 * pairs), mesh quality, surface approximation and landmarks, in three phases:
 * landmarks (only with landmarks), coarse (error CoarseError), fine (error
 * TargetError). Every result is certified bijective with exact predicates; a
 * run that cannot certify is an error.
 *
 * Inputs: port 0 is repeatable; input i is the (i+1)-th connection. Triangles
 * only, closed, manifold, genus 0 (what vtkSurfaceMeshValidator accepts).
 * Optional point arrays:
 * - "Landmarks" (int, id >= 0 at landmark vertices, -1 elsewhere): the same id
 *   on two inputs means the two vertices correspond; every input must carry
 *   the same ids.
 * - "Sizing" (1 component): target edge length in the input's own units
 *   (see SizingMode); without it, sizing follows the curvature.
 * - "SpherePosition" (3 components): a precomputed bijective sphere embedding
 *   (e.g. from vtkSphereEmbeddingFilter), verified with exact predicates and
 *   used instead of computing one here (with vtkSphereEmbeddingFilter's
 *   default settings). With landmarks, every embedding is first rotated
 *   rigidly onto input 0's by the landmarks.
 *
 * Outputs: one output port per input connection; the number of output ports
 * follows the connections at once (also right after AddInputConnection, so
 * GetOutputPort(i) can be connected before the first Update). With no input
 * there is still one (empty) output port.
 *
 * OutputMode COMMON_TRIANGULATION (default): output i is T lifted onto input i,
 * in input i's original coordinates; all outputs share the same triangles.
 * Point data: "SpherePosition" (g_i, unit vectors, in the frame of input i's
 * embedding after the landmark rotation), "SourceCellId" (triangle of
 * input i containing the vertex), "SourceBarycentric" (its barycentric
 * coordinates in that triangle), "Landmarks" (id per T vertex, -1 none), and
 * every other point array of input i interpolated with those barycentric
 * coordinates (its own "Landmarks", "Sizing" and "SpherePosition" are not).
 *
 * OutputMode MAPPED_INPUT (also MAPPED_FIRST_INPUT): output j is the mesh of
 * input k = MappedInput mapped onto input j by the exact map (k's
 * connectivity, vertex v at Phi_kj(v) on input j): for transferring data
 * between inputs and for measuring the exact map. Point data:
 * "SourceCellId", "SourceBarycentric" (where on input j), "Landmarks" (input
 * k's ids) and input j's point arrays interpolated; cell data: input k's (same
 * cells). Output k is input k itself.
 *
 * Texture coordinates (both modes above): when input i carries per-corner
 * texture coordinates (the 6-component cell array "CornerTCoords" of
 * vtkSurfaceMeshReader), output i gets the point array "TCoords" (active
 * texture coordinates): the corner values of the input triangle the point
 * lies in ("SourceCellId"), interpolated with "SourceBarycentric", so texture
 * seams stay sharp. Active point texture coordinates of an input are
 * interpolated like any point array (the corner ones take precedence).
 *
 * OutputMode INPUT_EMBEDDINGS: output i is input i unchanged (points, cells,
 * point and cell data) with the point array "SpherePosition" set to its sphere
 * embedding f_i as the map used it (inputs 1.. rotated onto input 0's frame
 * by the landmarks): the frame of the common triangulation's own
 * "SpherePosition" arrays. With T lifted on inputs i and j, these are what
 * vtkSurfaceMapTransfer needs to carry data from input i to input j later.
 * No "Distortion"; field data as below.
 *
 * Cell data (modes COMMON_TRIANGULATION and MAPPED_INPUT): "Distortion", the
 * symmetric Dirichlet energy of the piecewise linear map from output r to
 * output i per triangle (r = 0, or MappedInput in MAPPED_INPUT mode): with both
 * meshes centred and scaled to unit area, s1 >= s2 the singular values of the
 * triangle's Jacobian and A_0, A_i its unit-area areas on output 0 and
 * output i,
 *   Distortion = (A_i (s1^2 + s2^2) + A_0 (s1^-2 + s2^-2)) / (2 (A_0 + A_i)),
 * i.e. the per-triangle term 1/4 (A_i (s1^2 + s2^2) + A_0 (s1^-2 + s2^-2)) of
 * the map's energy divided by the triangle's mean area (A_0 + A_i) / 2: 1 for a
 * locally isometric triangle, larger otherwise (+inf if degenerate), and its
 * mean weighted by (A_0 + A_i) / 2 is the map's whole symmetric Dirichlet
 * energy (vtkSurfaceMapEvaluation's "SymmetricDirichlet"). Output r: all 1.
 *
 * Field data (every output): "InputIndex"; "Bijective" (1: every embedding g_i
 * of T certified with exact predicates and degree 1), "SphericalDegree" (of
 * this output's g_i); "CommonVertices", "CommonTriangles" (size of T);
 * "Energy" (final weighted energy), "BarrierEnergy", "MeshEnergy",
 * "ApproximationEnergy", "MapEnergy" (its terms, unweighted);
 * "LandmarkError" (largest distance of a kept landmark from its input
 * vertex, input units: 0 when exact); "MapSeconds" (the map alone),
 * "EmbeddingSeconds" (one value per input, 0 for a given embedding); one
 * tuple per phase that ran: "PhaseName" (string:
 * landmarks, coarse, fine), "PhaseIterations", "PhaseConverged" (0: stopped at
 * its iteration cap, which is normal), "PhaseEnergy", "PhaseVertices",
 * "PhaseSplits", "PhaseCollapses", "PhaseFlips", "PhaseLandmarkError",
 * "PhaseSeconds", "PhaseRemeshSeconds", "PhaseDerivativeSeconds",
 * "PhaseSolveSeconds", "PhaseLineSearchSeconds"; and input i's own field data
 * (e.g. its "FileName").
 *
 * Errors: invalid input (named by index and file name, with the defect and
 * where: "input 1 (a.obj) is not closed: 12 boundary edges"), landmark ids
 * that do not correspond, a "SpherePosition" array that is not a bijective
 * embedding, or a map that cannot be certified: vtkErrorMacro, every output
 * empty, and GetErrorCode() says which (InvalidInputError, NotCertifiedError,
 * vtkErrorCode::UnknownError for anything else). AbortExecute set during the
 * update (e.g. from a ProgressEvent observer) stops within one iteration and
 * leaves every output empty without an error.
 *
 * Switching OutputMode or MappedInput after an update reuses the computed map
 * as long as the inputs and every other setting are unchanged (the filter
 * keeps the last map for that), so every kind of output costs one
 * computation.
 *
 * @warning Cost: the sphere embeddings (see vtkSphereEmbeddingFilter: about
 * 0.7 s for 3 000 vertices, 3.5 s for 12 000) plus the optimisation,
 * dominated by the fine phase, whose iterations cost roughly linear time in
 * the size of T and of the inputs' approximation samples (about 1 s in all
 * for two 642-vertex inputs with 3 coarse and 3 fine iterations).
 * Derivatives and remeshing candidates are evaluated on all OpenMP threads.
 * Progress is reported once per iteration with the phase in the progress
 * text; AbortExecute is honoured there. The filter keeps the last map (T
 * with its N embeddings and lifts, a few times the size of the outputs)
 * until the next update.
 *
 * @sa vtkSphereEmbeddingFilter vtkSurfaceMapEvaluation vtkSurfaceMeshValidator
 * vtkSurfaceMapTransfer
 */
#ifndef vtkSurfaceMapFilter_h
#define vtkSurfaceMapFilter_h

#include "SurfaceMapsFiltersModule.h" // for export macro
#include "vtkErrorCode.h"             // for the error codes
#include "vtkPolyDataAlgorithm.h"

#include <memory> // for std::unique_ptr

class SURFACEMAPSFILTERS_EXPORT vtkSurfaceMapFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkSurfaceMapFilter* New();
  vtkTypeMacro(vtkSurfaceMapFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** Which input pairs the map-distortion term measures. */
  enum PairModes
  {
    PAIRS_STAR = 0,     ///< (0, i) for every i > 0
    PAIRS_SEQUENCE = 1, ///< (i, i + 1)
    PAIRS_CYCLE = 2,    ///< (i, i + 1) and (N - 1, 0)
    PAIRS_ALL = 3       ///< every pair
  };

  /** What the outputs carry. */
  enum OutputModes
  {
    COMMON_TRIANGULATION = 0,         ///< output i: T lifted onto input i
    MAPPED_INPUT = 1,                 ///< output j: input MappedInput mapped onto input j
    INPUT_EMBEDDINGS = 2,             ///< output i: input i with its embedding f_i
    MAPPED_FIRST_INPUT = MAPPED_INPUT ///< MAPPED_INPUT (with MappedInput 0)
  };

  /** Where the target edge lengths come from. */
  enum SizingModes
  {
    SIZING_ARRAY_OR_CURVATURE = 0, ///< the "Sizing" point array where present, else curvature
    SIZING_CURVATURE = 1           ///< always curvature (any "Sizing" array is ignored)
  };

  /** Values of GetErrorCode() after a failed update. */
  enum ErrorCodes
  {
    InvalidInputError = vtkErrorCode::UserError + 1, ///< an input cannot be used
    NotCertifiedError = vtkErrorCode::UserError + 2  ///< no certified bijective map
  };

  ///@{
  /**
   * Approximation error eps of the fine phase, in unit-area units (each input
   * centred and scaled to unit area): the surface-approximation weight is
   * 1/eps^2 and the curvature sizing aims at this error. Default 1e-3 (the
   * paper's), range [1e-6, 1]. Smaller values give larger T.
   */
  vtkSetClampMacro(TargetError, double, 1e-6, 1.0);
  vtkGetMacro(TargetError, double);
  ///@}

  ///@{
  /**
   * Approximation error eps of the coarse phase, unit-area units. Default
   * 1e-2, range [1e-6, 1]; normally larger than TargetError.
   */
  vtkSetClampMacro(CoarseError, double, 1e-6, 1.0);
  vtkGetMacro(CoarseError, double);
  ///@}

  ///@{
  /**
   * Iteration caps of the three phases (one iteration: all improving splits,
   * collapses and flips, then one Newton step). A phase ends earlier when no
   * edit lowers the energy and the Newton decrement is below
   * DecrementTolerance. Defaults 100 (landmarks), 50 (coarse), 50 (fine),
   * range [0, 100000]; 0 skips the phase. The landmark phase only runs when
   * the inputs carry landmarks.
   */
  vtkSetClampMacro(LandmarkIterations, int, 0, 100000);
  vtkGetMacro(LandmarkIterations, int);
  vtkSetClampMacro(CoarseIterations, int, 0, 100000);
  vtkGetMacro(CoarseIterations, int);
  vtkSetClampMacro(FineIterations, int, 0, 100000);
  vtkGetMacro(FineIterations, int);
  ///@}

  ///@{
  /**
   * Weight of the bijectivity barrier in the landmark, coarse and fine
   * phases. Defaults 1, 1e-3 and 1e-6, range [1e-12, 1e6]. Larger values keep
   * triangles further from degenerating on the spheres at the cost of
   * distortion.
   */
  vtkSetClampMacro(LandmarkBarrierWeight, double, 1e-12, 1e6);
  vtkGetMacro(LandmarkBarrierWeight, double);
  vtkSetClampMacro(CoarseBarrierWeight, double, 1e-12, 1e6);
  vtkGetMacro(CoarseBarrierWeight, double);
  vtkSetClampMacro(FineBarrierWeight, double, 1e-12, 1e6);
  vtkGetMacro(FineBarrierWeight, double);
  ///@}

  ///@{
  /**
   * Weights of the mesh-quality, map-distortion and surface-approximation
   * terms (coarse and fine phases). Defaults 0.5, 1 and 0.25, range [0, 1e6].
   * The paper's weights are all 1; with our approximation term (which fits
   * T closer to the inputs than the reference implementation's: Hausdorff
   * 0.14 % where it reaches 0.25-0.47 % on shrec 61 <-> 248) these defaults
   * gave lower distortion on both shared benchmark pairs and both builds
   * (README, "Surface map"). More map weight: lower distortion; more
   * approximation weight: T and the exact map closer to the inputs.
   */
  vtkSetClampMacro(MeshWeight, double, 0.0, 1e6);
  vtkGetMacro(MeshWeight, double);
  vtkSetClampMacro(MapWeight, double, 0.0, 1e6);
  vtkGetMacro(MapWeight, double);
  vtkSetClampMacro(ApproximationWeight, double, 0.0, 1e6);
  vtkGetMacro(ApproximationWeight, double);
  ///@}

  ///@{
  /**
   * Landmark phase: weight of the landmark term (default 1e6, range [0, 1e12])
   * and the distance on the sphere below which every landmark counts as
   * reached, ending the phase (default 1e-4, range [0, 1]).
   */
  vtkSetClampMacro(LandmarkWeight, double, 0.0, 1e12);
  vtkGetMacro(LandmarkWeight, double);
  vtkSetClampMacro(LandmarkTolerance, double, 0.0, 1.0);
  vtkGetMacro(LandmarkTolerance, double);
  ///@}

  ///@{
  /**
   * Once every landmark is reached, go on in the landmark phase with Newton
   * steps and flips only (no splits or collapses) until it converges or
   * reaches LandmarkIterations (default on): the barrier relaxes T's
   * embeddings around the moved landmarks, a smoother start for the
   * distortion phases. Off: the phase ends as soon as the landmarks are
   * reached.
   */
  vtkSetMacro(RelaxLandmarkPhase, bool);
  vtkGetMacro(RelaxLandmarkPhase, bool);
  vtkBooleanMacro(RelaxLandmarkPhase, bool);
  ///@}

  ///@{
  /**
   * After the landmark phase, lock the landmark vertices of T, snapped exactly
   * onto their input vertices (on), or release them to the optimisation
   * (off). Default on.
   */
  vtkSetMacro(KeepLandmarks, bool);
  vtkGetMacro(KeepLandmarks, bool);
  vtkBooleanMacro(KeepLandmarks, bool);
  ///@}

  ///@{
  /**
   * Which input pairs the map distortion measures: PAIRS_STAR (default),
   * PAIRS_SEQUENCE, PAIRS_CYCLE or PAIRS_ALL. Irrelevant for two inputs.
   */
  vtkSetClampMacro(PairMode, int, PAIRS_STAR, PAIRS_ALL);
  vtkGetMacro(PairMode, int);
  void SetPairModeToStar() { this->SetPairMode(PAIRS_STAR); }
  void SetPairModeToSequence() { this->SetPairMode(PAIRS_SEQUENCE); }
  void SetPairModeToCycle() { this->SetPairMode(PAIRS_CYCLE); }
  void SetPairModeToAll() { this->SetPairMode(PAIRS_ALL); }
  ///@}

  ///@{
  /**
   * Error-bounded remeshing: the largest distance allowed between an input
   * vertex and its base point on T (the point of T that the map assigns to
   * it), as a fraction of that input's bounding-box diagonal. Default 0
   * (off), range [0, 1]. After the fine phase the sizing is refined around
   * the vertices that are too far (rounds of 10 iterations, at most 8), then
   * BoundIterations iterations run with the bound as a barrier instead of the
   * soft approximation term. The bound is certified on every input vertex
   * (every vertex is an approximation sample then); a bound that cannot be
   * met is an error ("no certified map"). Field data: "BaseDistance" and
   * "ErrorBound" per input, in the input's units.
   */
  vtkSetClampMacro(MaxError, double, 0.0, 1.0);
  vtkGetMacro(MaxError, double);
  ///@}

  ///@{
  /**
   * Iterations with the hard bound when MaxError is set. Default 20,
   * range [0, 100000].
   */
  vtkSetClampMacro(BoundIterations, int, 0, 100000);
  vtkGetMacro(BoundIterations, int);
  ///@}

  ///@{
  /**
   * Refinement where the exact map is distorted: after the fine phase, up to
   * RefinementRounds rounds (default 3, range [0, 100]; 0 off) of
   * RefinementIterations more iterations (default 10, range [1, 100000]; at
   * most FineIterations) with the fine phase's settings, each after
   * shrinking the sizing around the input triangles whose exact-map
   * distortion max(s1, 1/s2) exceeds a threshold. The first round uses RefinementDistortion (default 1.4, range
   * [1, 1e12]) and gives T more vertices where the map is distorted; with a
   * fraction `area` of an input above it, the sizing there shrinks by
   * 1 / sqrt(1 + RefinementGrowth / area), but at most by half
   * (RefinementGrowth default 0.25, range [0, 1e12]; 0: the round only
   * iterates). The later rounds use SqueezeDistortion (default 10, range
   * [1, 1e12]) and halve the sizing: they repair input triangles that the
   * exact map squeezes inside a T triangle, where it follows the two sphere
   * embeddings, which T's own map cannot see. No round runs when no
   * triangle is that distorted, nor without a fine phase (FineIterations 0).
   * RefinementDistortion 10 refines only squeezes, as before 2026-11-23.
   */
  vtkSetClampMacro(RefinementRounds, int, 0, 100);
  vtkGetMacro(RefinementRounds, int);
  vtkSetClampMacro(RefinementIterations, int, 1, 100000);
  vtkGetMacro(RefinementIterations, int);
  vtkSetClampMacro(RefinementDistortion, double, 1.0, 1e12);
  vtkGetMacro(RefinementDistortion, double);
  vtkSetClampMacro(RefinementGrowth, double, 0.0, 1e12);
  vtkGetMacro(RefinementGrowth, double);
  vtkSetClampMacro(SqueezeDistortion, double, 1.0, 1e12);
  vtkGetMacro(SqueezeDistortion, double);
  ///@}

  ///@{
  /**
   * Newton steps of the coarse and fine phases that the line search cuts
   * below a tenth are solved again up to KinkRetries times with the points
   * held that make the energy leave its model (an approximation sample
   * crossing into a T triangle that is tiny on the sphere). Default 0 (off),
   * range [0, 10]; each retry costs a factorisation.
   */
  vtkSetClampMacro(KinkRetries, int, 0, 10);
  vtkGetMacro(KinkRetries, int);
  ///@}

  ///@{
  /**
   * Input vertices per input the approximation term uses at most (an evenly
   * spread subsample of larger inputs). Default 50000, range [1, 1e9].
   */
  vtkSetClampMacro(ApproximationSamples, int, 1, 1000000000);
  vtkGetMacro(ApproximationSamples, int);
  ///@}

  ///@{
  /**
   * Target edge lengths: SIZING_ARRAY_OR_CURVATURE (default) uses an input's
   * "Sizing" point array where present and curvature elsewhere;
   * SIZING_CURVATURE always uses curvature.
   */
  vtkSetClampMacro(SizingMode, int, SIZING_ARRAY_OR_CURVATURE, SIZING_CURVATURE);
  vtkGetMacro(SizingMode, int);
  void SetSizingModeToArrayOrCurvature() { this->SetSizingMode(SIZING_ARRAY_OR_CURVATURE); }
  void SetSizingModeToCurvature() { this->SetSizingMode(SIZING_CURVATURE); }
  ///@}

  ///@{
  /**
   * Clamp of the curvature sizing's edge lengths, unit-area units. Defaults
   * 1e-3 and 100, range [1e-9, 1e9].
   */
  vtkSetClampMacro(MinEdgeLength, double, 1e-9, 1e9);
  vtkGetMacro(MinEdgeLength, double);
  vtkSetClampMacro(MaxEdgeLength, double, 1e-9, 1e9);
  vtkGetMacro(MaxEdgeLength, double);
  ///@}

  ///@{
  /**
   * A phase has converged when no edit lowers the energy and the Newton
   * decrement sqrt(-d.g) is below this. Default 1e-4, range [0, 1].
   */
  vtkSetClampMacro(DecrementTolerance, double, 0.0, 1.0);
  vtkGetMacro(DecrementTolerance, double);
  ///@}

  ///@{
  /**
   * OpenMP threads for this filter's updates (sphere embeddings and map).
   * Default 0: OpenMP's default (OMP_NUM_THREADS, else all cores). The map
   * does not depend on it (deterministic for any thread count), only the
   * time does; e.g. an MPI rank that started with one thread can use the
   * cores of ranks that have finished. Changing it does not recompute the
   * map. Range [0, 1024].
   */
  vtkSetClampMacro(NumberOfThreads, int, 0, 1024);
  vtkGetMacro(NumberOfThreads, int);
  ///@}

  ///@{
  /**
   * COMMON_TRIANGULATION (default): output i is T lifted onto input i.
   * MAPPED_INPUT: output j is input MappedInput mapped onto input j
   * (SetOutputModeToMappedFirstInput() also sets MappedInput to 0).
   * INPUT_EMBEDDINGS: output i is input i with its sphere embedding f_i.
   * Changing only this setting does not recompute the map.
   */
  vtkSetClampMacro(OutputMode, int, COMMON_TRIANGULATION, INPUT_EMBEDDINGS);
  vtkGetMacro(OutputMode, int);
  void SetOutputModeToCommonTriangulation() { this->SetOutputMode(COMMON_TRIANGULATION); }
  void SetOutputModeToMappedInput() { this->SetOutputMode(MAPPED_INPUT); }
  void SetOutputModeToMappedFirstInput()
  {
    this->SetMappedInput(0);
    this->SetOutputMode(MAPPED_INPUT);
  }
  void SetOutputModeToInputEmbeddings() { this->SetOutputMode(INPUT_EMBEDDINGS); }
  ///@}

  ///@{
  /**
   * The input whose mesh the MAPPED_INPUT outputs carry onto every input.
   * Default 0, range [0, number of inputs - 1] (a larger value is an error at
   * the update in that mode). Changing it does not recompute the map.
   */
  vtkSetClampMacro(MappedInput, int, 0, VTK_INT_MAX);
  vtkGetMacro(MappedInput, int);
  ///@}

  ///@{
  /**
   * Connections of the repeatable input port 0. They keep the number of
   * output ports equal to the number of input connections (at least one).
   */
  void SetInputConnection(int port, vtkAlgorithmOutput* input) override;
  void SetInputConnection(vtkAlgorithmOutput* input) override;
  void AddInputConnection(int port, vtkAlgorithmOutput* input) override;
  void AddInputConnection(vtkAlgorithmOutput* input) override;
  void RemoveInputConnection(int port, vtkAlgorithmOutput* input) override;
  void RemoveInputConnection(int port, int idx) override;
  void RemoveAllInputConnections(int port) override;
  ///@}

protected:
  vtkSurfaceMapFilter();
  ~vtkSurfaceMapFilter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  void SetNumberOfInputConnections(int port, int n) override;

  double TargetError = 1e-3;
  double CoarseError = 1e-2;
  int LandmarkIterations = 100;
  int CoarseIterations = 50;
  int FineIterations = 50;
  double LandmarkBarrierWeight = 1.0;
  double CoarseBarrierWeight = 1e-3;
  double FineBarrierWeight = 1e-6;
  double MeshWeight = 0.5;
  double MapWeight = 1.0;
  double ApproximationWeight = 0.25;
  double LandmarkWeight = 1e6;
  double LandmarkTolerance = 1e-4;
  bool RelaxLandmarkPhase = true;
  bool KeepLandmarks = true;
  int PairMode = PAIRS_STAR;
  double MaxError = 0.0;
  int BoundIterations = 20;
  int RefinementRounds = 3;
  int RefinementIterations = 10;
  double RefinementDistortion = 1.4;
  double RefinementGrowth = 0.25;
  double SqueezeDistortion = 10.0;
  int KinkRetries = 0;
  int ApproximationSamples = 50000;
  int SizingMode = SIZING_ARRAY_OR_CURVATURE;
  double MinEdgeLength = 1e-3;
  double MaxEdgeLength = 100.0;
  double DecrementTolerance = 1e-4;
  int OutputMode = COMMON_TRIANGULATION;
  int MappedInput = 0;
  int NumberOfThreads = 0;

private:
  /// Prints the settings (with `all` false only those that change the map,
  /// the key of the kept map).
  void PrintSettings(ostream& os, vtkIndent indent, bool all);

  vtkSurfaceMapFilter(const vtkSurfaceMapFilter&) = delete;
  void operator=(const vtkSurfaceMapFilter&) = delete;

  /// One output port per input connection (at least one).
  void UpdateNumberOfOutputPorts();

  struct vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
