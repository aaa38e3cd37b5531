/**
 * @class   vtkSurfaceMapFilter
 * @brief   Bijective map between N closed genus-0 surfaces via an adaptive common triangulation.
 *
 * Computes a continuous, bijective map between N >= 1 closed, manifold, genus-0
 * triangle meshes, represented by one common triangulation T with a sphere
 * embedding per input ("Surface Maps via Adaptive Triangulations", Schmidt,
 * Pieper, Kobbelt, Eurographics 2023). Each input gets a fixed bijective
 * embedding f_i on the unit sphere; T carries N embeddings g_i and is optimised
 * by edge splits, collapses, flips and projected-Newton steps (barriers, map
 * distortion, mesh quality, approximation, landmarks) in a landmark, a coarse
 * and a fine phase. Every result is certified bijective with exact predicates.
 *
 * Inputs: port 0 is repeatable; input i is the (i+1)-th connection. Triangles
 * only, closed, manifold, genus 0 (what vtkSurfaceMeshValidator accepts).
 * Optional point arrays:
 * - "Landmarks" (int, id >= 0 at landmark vertices, -1 elsewhere): the same id
 *   on two inputs means the two vertices correspond; every input must carry
 *   the same ids. Landmarks mirroring input 0's (a mirrored mesh or the
 *   other side's list) draw a warning naming both inputs; the map runs.
 * - "Sizing" (1 component): target edge length in the input's own units
 *   (see SizingMode); without it, sizing follows the curvature.
 * - "SpherePosition" (3 components): a precomputed bijective sphere embedding
 *   (e.g. from vtkSphereEmbeddingFilter), verified with exact predicates and
 *   used instead of computing one here (with the sphere embedding's default
 *   settings, which are vtkSphereEmbeddingFilter's defaults: one list holds
 *   both). Every embedding is first rotated rigidly onto input 0's: by
 *   the landmarks, or without them by a search (LandmarkFreeAlignment).
 * Port 1 (optional, repeatable): an existing map of port 0's first M inputs
 * (its M COMMON_TRIANGULATION outputs; those inputs carry its
 * INPUT_EMBEDDINGS "SpherePosition") to add the others to, its maps kept
 * (surfacemaps::addToSurfaceMap; RefinementRounds 0 and MaxError 0).
 *
 * Outputs: one output port per input connection, following the connections
 * at once (GetOutputPort(i) can be connected before the first Update); with
 * no input, one empty port.
 *
 * OutputMode COMMON_TRIANGULATION (default): output i is T lifted onto input i,
 * in input i's original coordinates; all outputs share the same triangles.
 * Point data: "SpherePosition" (g_i, unit vectors, in the frame of input i's
 * embedding after the landmark rotation), "SourceCellId" (triangle of
 * input i containing the vertex), "SourceBarycentric" (its barycentric
 * coordinates in that triangle), "Landmarks" (id per T vertex, -1 none), and
 * every other point array of input i read there (its own "Landmarks",
 * "Sizing", "SpherePosition" and global ids are not): continuous arrays
 * interpolated with those barycentric coordinates (integers rounded),
 * categorical ones (integer arrays unless SetArrayTransferMode says
 * otherwise, vtkSurfaceArrayTransferAlgorithm) from the triangle's corner
 * with the largest barycentric coordinate, so no output holds a value its
 * input does not have; changing the modes does not recompute the map.
 *
 * OutputMode MAPPED_INPUT: output j is the mesh of
 * input k = MappedInput mapped onto input j by the exact map (k's
 * connectivity, vertex v at Phi_kj(v) on input j): for transferring data
 * between inputs and for measuring the exact map. Point data:
 * "SourceCellId", "SourceBarycentric" (where on input j), "Landmarks" (input
 * k's ids) and input j's point arrays read there, continuous or categorical
 * as above; cell data: input k's (same cells). Output k is input k itself.
 *
 * Texture coordinates (both modes above): an input's per-corner texture
 * coordinates (cell array "CornerTCoords" of vtkSurfaceMeshReader) are
 * carried per corner too, no triangle spanning a seam
 * (surfacemaps::transferCornerValues), plus the point array "TCoords"
 * interpolated where each point lies; to render, split the output with
 * vtkSurfaceTextureSeamSplitter. Active point texture coordinates are
 * carried like any point array (the corner ones take precedence).
 *
 * OutputMode INPUT_EMBEDDINGS: output i is input i unchanged (points, cells,
 * point and cell data) with the point array "SpherePosition" set to its sphere
 * embedding f_i as the map used it (rotated onto input 0's frame), the frame
 * of T's "SpherePosition": with T lifted on inputs i and j, what
 * vtkSurfaceMapTransfer needs to carry data from i to j later.
 *
 * Cell data (modes COMMON_TRIANGULATION and MAPPED_INPUT): "Distortion", the
 * per-triangle symmetric Dirichlet energy of the map from output r to output i
 * (r = 0, or MappedInput), both centred and at unit area, divided by the
 * triangle's mean area (A_0 + A_i) / 2:
 *   Distortion = (A_i (s1^2 + s2^2) + A_0 (s1^-2 + s2^-2)) / (2 (A_0 + A_i)),
 * 1 where locally isometric (+inf if degenerate); its mean weighted by the
 * mean areas is vtkSurfaceMapEvaluation's "SymmetricDirichlet". Output r: 1.
 *
 * Field data (every output): "InputIndex"; "Bijective" (1: every embedding g_i
 * of T certified with exact predicates and degree 1), "SphericalDegree" (of
 * this output's g_i); "CommonVertices", "CommonTriangles" (size of T);
 * "Energy" (final weighted energy), "BarrierEnergy", "MeshEnergy",
 * "ApproximationEnergy", "MapEnergy" (its terms, unweighted);
 * "LandmarkError" (largest distance of a kept landmark from its input
 * vertex, input units: 0 when exact); "SetAsideLandmarks" (the ids the
 * guide check set aside, LandmarksAsGuides); "MapSeconds" (the map alone),
 * "EmbeddingSeconds" (one value per input, 0 for a given embedding); one
 * tuple per phase that ran: "PhaseName" (string:
 * landmarks, coarse, fine, refine, bound), "PhaseIterations", "PhaseConverged" (0: stopped at
 * its iteration cap, which is normal), "PhaseStalledIterations" (iterations
 * whose line search failed or cut its first trial by more than 100 times: a
 * kink held the step back), "PhaseEnergy", "PhaseVertices",
 * "PhaseSplits", "PhaseCollapses", "PhaseFlips", "PhaseLandmarkError",
 * "PhaseSeconds", "PhaseRemeshSeconds", "PhaseDerivativeSeconds",
 * "PhaseSolveSeconds", "PhaseLineSearchSeconds"; and input i's own field data
 * (e.g. its "FileName").
 *
 * Errors: invalid input (named by index and file name, with the defect and
 * where), landmark ids that do not correspond, a "SpherePosition" that is not
 * a bijective embedding, an input whose producer failed, or a map that
 * cannot be certified: vtkErrorMacro, every output empty, GetErrorCode()
 * says which (InvalidInputError, NotCertifiedError, vtkErrorCode::UnknownError)
 * and GetLastErrorMessage() why; in a loop over files, check GetErrorCode()
 * after Update(). AbortExecute set during the update (e.g. from a
 * ProgressEvent observer) stops within one iteration, outputs empty, no error.
 *
 * Settings: every setting of the map (all but SizingMode, NumberOfThreads,
 * OutputMode, MappedInput and the array transfer modes of the superclass,
 * which only shape the outputs) is one entry of the engine's list of
 * settings (Core/settings/SettingList.def), which its Set/Get macros (clamped
 * to its range), doc comment and member below are written from. A setting
 * outside its range at the update (NaN) is an InvalidInputError.
 * GetSettingName(i), ... and vtkSurfaceMapsSettings list them for tools.
 *
 * Switching OutputMode or MappedInput reuses the map of the last update.
 *
 * @warning Cost: the sphere embeddings (vtkSphereEmbeddingFilter: about 0.7 s
 * for 3 000 vertices) plus the optimisation, dominated by the fine phase,
 * roughly linear in the size of T and of the inputs' approximation samples.
 * Derivatives and remeshing candidates are evaluated on all OpenMP threads.
 * Progress once per iteration (the phase in the progress text), where
 * AbortExecute is honoured. The last map (a few times the size of the
 * outputs) is kept until the next update.
 *
 * @sa vtkSphereEmbeddingFilter vtkSurfaceMapEvaluation vtkSurfaceMeshValidator
 * vtkSurfaceMapTransfer vtkSurfaceArrayTransferAlgorithm
 */
#ifndef vtkSurfaceMapFilter_h
#define vtkSurfaceMapFilter_h

#include "SurfaceMapsFiltersModule.h" // for export macro
#include "vtkErrorCode.h"             // for the error codes
#include "vtkSurfaceArrayTransferAlgorithm.h"

#include <memory> // for std::unique_ptr

class SURFACEMAPSFILTERS_EXPORT vtkSurfaceMapFilter : public vtkSurfaceArrayTransferAlgorithm
{
public:
  static vtkSurfaceMapFilter* New();
  vtkTypeMacro(vtkSurfaceMapFilter, vtkSurfaceArrayTransferAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** Whose distortion the map-distortion term measures: input pairs, or each
   * input against the inputs' mean shape. */
  enum PairModes
  {
    PAIRS_STAR = 0,     ///< (0, i) for every i > 0
    PAIRS_SEQUENCE = 1, ///< (i, i + 1)
    PAIRS_CYCLE = 2,    ///< (i, i + 1) and (N - 1, 0)
    PAIRS_ALL = 3,      ///< every pair
    PAIRS_MEAN = 4      ///< each input against the inputs' mean shape
  };

  /** What the outputs carry. */
  enum OutputModes
  {
    COMMON_TRIANGULATION = 0, ///< output i: T lifted onto input i
    MAPPED_INPUT = 1,         ///< output j: input MappedInput mapped onto input j
    INPUT_EMBEDDINGS = 2      ///< output i: input i with its embedding f_i
  };

  /** Where the target edge lengths come from. */
  enum SizingModes
  {
    SIZING_ARRAY_OR_CURVATURE = 0, ///< the "Sizing" point array where present, else curvature
    SIZING_CURVATURE = 1           ///< always curvature (any "Sizing" array is ignored)
  };

  /** What values a setting takes (GetSettingType). */
  enum SettingTypes
  {
    SETTING_REAL = 0,   ///< a number in [minimum, maximum]
    SETTING_COUNT = 1,  ///< a whole number in [minimum, maximum]
    SETTING_SWITCH = 2, ///< 0 or 1
    SETTING_CHOICE = 3  ///< an index into GetSettingChoices
  };

  /** Values of GetErrorCode() after a failed update. */
  enum ErrorCodes
  {
    InvalidInputError = vtkErrorCode::UserError + 1, ///< an input cannot be used
    NotCertifiedError = vtkErrorCode::UserError + 2  ///< no certified bijective map
  };

  // BEGIN SETTINGS
  // Written from Core/settings/SettingList.def by TestSettingHeaders
  // (SURFACEMAPS_UPDATE_SETTING_HEADERS=1 ctest -R SettingHeaders):
  // edit the list, not these lines.
  // clang-format off

  ///@{
  /** Whose map distortion is minimised with three or more inputs: the pairs (0, i), (i, i+1),
   * (i, i+1) and (N-1, 0), or every pair; or mean: each input against the inputs' mean shape,
   * triangle by triangle (no input privileged; time linear in N). With all and mean the map
   * does not depend on the order of the inputs (they are mapped most typical first). Default
   * star. */
  vtkSetClampMacro(PairMode, int, 0, 4);
  vtkGetMacro(PairMode, int);
  void SetPairModeToStar() { this->SetPairMode(0); }
  void SetPairModeToSequence() { this->SetPairMode(1); }
  void SetPairModeToCycle() { this->SetPairMode(2); }
  void SetPairModeToAll() { this->SetPairMode(3); }
  void SetPairModeToMean() { this->SetPairMode(4); }
  ///@}

  ///@{
  /** Iteration cap of the landmark phase (barrier and landmark terms only; runs only with
   * landmarks; 0 skips it). One iteration: improving splits, collapses, flips, one Newton step.
   * Default 100, range 0 to 100000. */
  vtkSetClampMacro(LandmarkIterations, int, 0, 100000);
  vtkGetMacro(LandmarkIterations, int);
  ///@}

  ///@{
  /** Weight of the landmark term in the landmark phase. Default 1e6, range 0 to 1e12. */
  vtkSetClampMacro(LandmarkWeight, double, 0.0, 1e12);
  vtkGetMacro(LandmarkWeight, double);
  ///@}

  ///@{
  /** Weight of the bijectivity barrier in the landmark phase. Default 1, range 1e-12 to 1e6. */
  vtkSetClampMacro(LandmarkBarrierWeight, double, 1e-12, 1e6);
  vtkGetMacro(LandmarkBarrierWeight, double);
  ///@}

  ///@{
  /** Distance on the sphere below which every landmark counts as reached. Default 0.0001, range
   * 0 to 1. */
  vtkSetClampMacro(LandmarkTolerance, double, 0.0, 1.0);
  vtkGetMacro(LandmarkTolerance, double);
  ///@}

  ///@{
  /** Once the landmarks are reached, go on with Newton steps and flips only until the landmark
   * phase converges, so the barrier relaxes T around the moved landmarks; off: end the phase as
   * soon as they are reached. Default on. */
  vtkSetClampMacro(RelaxLandmarkPhase, bool, false, true);
  vtkGetMacro(RelaxLandmarkPhase, bool);
  vtkBooleanMacro(RelaxLandmarkPhase, bool);
  ///@}

  ///@{
  /** After the landmark phase, snap T's landmark vertices exactly onto their input vertices and
   * lock them; off: release them to the optimisation. Default on. */
  vtkSetClampMacro(KeepLandmarks, bool, false, true);
  vtkGetMacro(KeepLandmarks, bool);
  vtkBooleanMacro(KeepLandmarks, bool);
  ///@}

  ///@{
  /** Without landmarks, turn each input's sphere embedding onto the first's by a search over
   * rotations, keeping the one under which the initial map is most nearly a rigid motion (a
   * warning names the input when two distinct rotations fit almost equally well); off: the
   * embeddings as computed, in no particular rotation to each other. Default on. */
  vtkSetClampMacro(LandmarkFreeAlignment, bool, false, true);
  vtkGetMacro(LandmarkFreeAlignment, bool);
  vtkBooleanMacro(LandmarkFreeAlignment, bool);
  ///@}

  ///@{
  /** Treat the landmarks as a guess: a short map without landmarks first confirms those whose
   * partner lies within LandmarkGuideTolerance of where the shapes put it; they bind the map,
   * the others are left free, and each of those the map does not find within the tolerance
   * (swapped, on the wrong finger or leg, far off) is set aside with a warning. Costs about one
   * coarse phase more. Off: every landmark binds the map. Default off. */
  vtkSetClampMacro(LandmarksAsGuides, bool, false, true);
  vtkGetMacro(LandmarksAsGuides, bool);
  vtkBooleanMacro(LandmarksAsGuides, bool);
  ///@}

  ///@{
  /** With landmarks as guides: how far (in % of the input's bounding-box diagonal) a landmark's
   * partner may lie from where a map puts it. Default 5, range 0.01 to 100. */
  vtkSetClampMacro(LandmarkGuideTolerance, double, 0.01, 100.0);
  vtkGetMacro(LandmarkGuideTolerance, double);
  ///@}

  ///@{
  /** Iteration cap of the coarse phase (0 skips it). A phase also ends when no edit lowers the
   * energy and the Newton decrement is below DecrementTolerance. Default 50, range 0 to 100000. */
  vtkSetClampMacro(CoarseIterations, int, 0, 100000);
  vtkGetMacro(CoarseIterations, int);
  ///@}

  ///@{
  /** Approximation error eps of the coarse phase (unit-area units): approximation weight
   * 1/eps^2, and the error the curvature sizing aims at. Default 0.01, range 1e-6 to 1. */
  vtkSetClampMacro(CoarseError, double, 1e-6, 1.0);
  vtkGetMacro(CoarseError, double);
  ///@}

  ///@{
  /** Weight of the bijectivity barrier in the coarse phase. Default 0.001, range 1e-12 to 1e6. */
  vtkSetClampMacro(CoarseBarrierWeight, double, 1e-12, 1e6);
  vtkGetMacro(CoarseBarrierWeight, double);
  ///@}

  ///@{
  /** Iteration cap of the fine phase (0 skips it, and the refinement with it). Default 50, range
   * 0 to 100000. */
  vtkSetClampMacro(FineIterations, int, 0, 100000);
  vtkGetMacro(FineIterations, int);
  ///@}

  ///@{
  /** Approximation error eps of the fine phase (unit-area units): approximation weight 1/eps^2
   * and the curvature sizing's error; smaller values give a larger T. Default 0.001, range 1e-6
   * to 1. */
  vtkSetClampMacro(TargetError, double, 1e-6, 1.0);
  vtkGetMacro(TargetError, double);
  ///@}

  ///@{
  /** Weight of the bijectivity barrier in the fine phase and after it. Default 1e-6, range 1e-12
   * to 1e6. */
  vtkSetClampMacro(FineBarrierWeight, double, 1e-12, 1e6);
  vtkGetMacro(FineBarrierWeight, double);
  ///@}

  ///@{
  /** From the fine phase on, the barrier weight of a triangle of T that inverts on a sphere at a
   * Newton step's full step is multiplied by this (at most three times), so the next steps see
   * the wall they ran into; 1: the same weight for every triangle. Default 4, range 1 to 1000. */
  vtkSetClampMacro(FineBarrierRaise, double, 1.0, 1000.0);
  vtkGetMacro(FineBarrierRaise, double);
  ///@}

  ///@{
  /** Weight of the mesh-quality term (coarse phase on). Default 0.5, range 0 to 1e6. */
  vtkSetClampMacro(MeshWeight, double, 0.0, 1e6);
  vtkGetMacro(MeshWeight, double);
  ///@}

  ///@{
  /** Weight of the coverage term (coarse phase on): per triangle of T and input, its lifted area
   * against the input area its sphere triangle covers; keeps T's triangles from being slivers
   * on one sphere over a fold of the surface, where the exact map squeezes. Default 0.1, range
   * 0 to 1e6. */
  vtkSetClampMacro(CoverageWeight, double, 0.0, 1e6);
  vtkGetMacro(CoverageWeight, double);
  ///@}

  ///@{
  /** Weight of the map-distortion term (coarse phase on): more, a lower distortion. Default 1,
   * range 0 to 1e6. */
  vtkSetClampMacro(MapWeight, double, 0.0, 1e6);
  vtkGetMacro(MapWeight, double);
  ///@}

  ///@{
  /** Weight of the surface-approximation term (coarse phase on): more, a T and an exact map
   * closer to the inputs. Default 0.25, range 0 to 1e6. */
  vtkSetClampMacro(ApproximationWeight, double, 0.0, 1e6);
  vtkGetMacro(ApproximationWeight, double);
  ///@}

  ///@{
  /** After the fine phase, rounds that shrink the sizing around input triangles whose exact-map
   * distortion exceeds a threshold, then iterate again with the fine phase's settings; rounds
   * stop when no triangle exceeds it (0: off). Default 1, range 0 to 100. */
  vtkSetClampMacro(RefinementRounds, int, 0, 100);
  vtkGetMacro(RefinementRounds, int);
  ///@}

  ///@{
  /** Iterations of each refinement round (at most FineIterations). Default 10, range 1 to
   * 100000. */
  vtkSetClampMacro(RefinementIterations, int, 1, 100000);
  vtkGetMacro(RefinementIterations, int);
  ///@}

  ///@{
  /** The first round's threshold on the exact map's distortion max(s1, 1/s2) of an input
   * triangle: T gets more vertices where the map is distorted. Default 1.4, range 1 to 1e12. */
  vtkSetClampMacro(RefinementDistortion, double, 1.0, 1e12);
  vtkGetMacro(RefinementDistortion, double);
  ///@}

  ///@{
  /** The later rounds' threshold: while the exact map squeezes an input triangle inside a T
   * triangle (which T's own map cannot see) beyond this, another round of iterations runs, with
   * the sizing as it is. Default 10, range 1 to 1e12. */
  vtkSetClampMacro(SqueezeDistortion, double, 1.0, 1e12);
  vtkGetMacro(SqueezeDistortion, double);
  ///@}

  ///@{
  /** Bounds the first round's refinement: with a fraction `area` of an input above the threshold
   * the sizing there shrinks by 1/sqrt(1 + growth/area), at most by half (0: the round only
   * iterates). Default 0.25, range 0 to 1e12. */
  vtkSetClampMacro(RefinementGrowth, double, 0.0, 1e12);
  vtkGetMacro(RefinementGrowth, double);
  ///@}

  ///@{
  /** Error-bounded remeshing: the largest distance allowed between an input vertex and its base
   * point on T, as a fraction of the input's bounding-box diagonal; refined until met, then
   * optimised with the bound as a barrier and certified on every vertex (0: off). The filter's
   * field data "BaseDistance" and "ErrorBound" give it per input; a bound that cannot be met
   * leaves no certified map. Default 0, range 0 to 1. */
  vtkSetClampMacro(MaxError, double, 0.0, 1.0);
  vtkGetMacro(MaxError, double);
  ///@}

  ///@{
  /** Rounds of refinement towards MaxError at most; a vertex still beyond the bound after them
   * is an error (one only beyond BoundMargin of it goes on to the bound phase). Default 8,
   * range 0 to 100. */
  vtkSetClampMacro(BoundRefinementRounds, int, 0, 100);
  vtkGetMacro(BoundRefinementRounds, int);
  ///@}

  ///@{
  /** Iterations of each refinement round towards MaxError. Default 10, range 0 to 100000. */
  vtkSetClampMacro(BoundRefinementIterations, int, 0, 100000);
  vtkGetMacro(BoundRefinementIterations, int);
  ///@}

  ///@{
  /** Refinement towards MaxError goes on while a vertex is beyond this fraction of the bound, so
   * that the barrier starts finite. Default 0.9, range 0.01 to 1. */
  vtkSetClampMacro(BoundMargin, double, 0.01, 1.0);
  vtkGetMacro(BoundMargin, double);
  ///@}

  ///@{
  /** Iterations with the hard bound as a barrier when MaxError is set. Default 20, range 0 to
   * 100000. */
  vtkSetClampMacro(BoundIterations, int, 0, 100000);
  vtkGetMacro(BoundIterations, int);
  ///@}

  ///@{
  /** Vertex budget of T, checked after every remeshing: a map whose T would grow beyond it ends
   * without a certified result, naming the phase, so that a target error or bound finer than
   * the budget allows cannot run for ever (0: 20 times the largest input's vertex count, at
   * least 20 000). Default 0, range 0 to 1000000000. */
  vtkSetClampMacro(MaxVertices, int, 0, 1000000000);
  vtkGetMacro(MaxVertices, int);
  ///@}

  ///@{
  /** Input vertices per input the approximation term uses at most (an evenly spread subsample of
   * larger inputs; every vertex with MaxError). Default 50000, range 1 to 1000000000. */
  vtkSetClampMacro(ApproximationSamples, int, 1, 1000000000);
  vtkGetMacro(ApproximationSamples, int);
  ///@}

  ///@{
  /** Smallest edge length of the curvature sizing, and the smallest a Sizing array may ask for
   * (unit-area units; a smaller one is an input error). Default 0.001, range 1e-9 to 1e9. */
  vtkSetClampMacro(MinEdgeLength, double, 1e-9, 1e9);
  vtkGetMacro(MinEdgeLength, double);
  ///@}

  ///@{
  /** Largest edge length of the curvature sizing (unit-area units). Default 100, range 1e-9 to
   * 1e9. */
  vtkSetClampMacro(MaxEdgeLength, double, 1e-9, 1e9);
  vtkGetMacro(MaxEdgeLength, double);
  ///@}

  ///@{
  /** A phase has converged when no edit lowers the energy and the Newton decrement sqrt(-d.g) is
   * below this. Default 0.0001, range 0 to 1. */
  vtkSetClampMacro(DecrementTolerance, double, 0.0, 1.0);
  vtkGetMacro(DecrementTolerance, double);
  ///@}

  ///@{
  /** Largest tangent step of one point in a Newton step, as the tan of its angle (tan 10 degrees
   * is 0.176); the whole step is scaled down to respect it, never clamped per point. Default
   * 0.17632698070846498, range 1e-6 to 1000. */
  vtkSetClampMacro(MaxPointStep, double, 1e-6, 1000.0);
  vtkGetMacro(MaxPointStep, double);
  ///@}

  ///@{
  /** From this many inputs on, each Newton system is solved by conjugate gradients
   * preconditioned with every sphere embedding's own block (time linear in the number of
   * inputs) instead of one Cholesky factorisation of all embeddings together (whose cost grows
   * with the cube of the number of inputs); 0: always the factorisation. Default 4, range 0 to
   * 1000000. */
  vtkSetClampMacro(BlockSolveInputs, int, 0, 1000000);
  vtkGetMacro(BlockSolveInputs, int);
  ///@}
  // clang-format on
  // END SETTINGS

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
   * The settings table for tools (command lines, GUIs), the same as
   * vtkSurfaceMapsSettings' MAP_SETTINGS table: setting i's property
   * name (Set<Name>/Get<Name>), command-line flag (without "--"; for a
   * switch the flag that turns it on, GetSettingOffFlag the one that turns it
   * off, else nullptr), choices ("star|sequence|..." for SETTING_CHOICE,
   * else nullptr), documentation, topic (the group a GUI shows it in, e.g.
   * "Landmark phase"; settings of one topic are consecutive), SettingTypes
   * value, range and default.
   * Indices outside [0, GetNumberOfSettings()) give nullptr or NaN.
   */
  static int GetNumberOfSettings();
  static const char* GetSettingName(int i);
  static const char* GetSettingFlag(int i);
  static const char* GetSettingOffFlag(int i);
  static const char* GetSettingChoices(int i);
  static const char* GetSettingDocumentation(int i);
  static const char* GetSettingTopic(int i);
  static int GetSettingType(int i);
  static double GetSettingMinimum(int i);
  static double GetSettingMaximum(int i);
  static double GetSettingDefault(int i);
  /** Setting i's value from `text` as vtkSurfaceMapsSettings::Parse; false if none. */
  static bool ParseSettingValue(int i, const char* text, double* value);
  ///@}

  /** Named sets of settings for kinds of study (ApplyPreset). */
  enum Presets
  {
    PRESET_PAIR = 0,      ///< two surfaces, the finest map: the defaults
    PRESET_POPULATION = 1 ///< many surfaces, one coarser T for statistics
  };

  ///@{
  /**
   * Sets the settings a preset governs (GetPresetDocumentation(p) names
   * them with their values) and leaves every other setting as it is;
   * PRESET_PAIR restores those settings' defaults, so presets undo each
   * other. Set<Name>() after it overrides single settings. A preset is not
   * itself a setting: GetSetting/PrintSelf show the values it set.
   * SetScheduleToPopulation() is ApplyPreset(PRESET_POPULATION): for 10 to 50
   * specimens in one map (star pairs), a T of about a thousand vertices or
   * less, time per iteration linear in the number of inputs. An unknown
   * preset is ignored with a vtkErrorMacro.
   */
  void ApplyPreset(int preset);
  void SetScheduleToPair() { this->ApplyPreset(PRESET_PAIR); }
  void SetScheduleToPopulation() { this->ApplyPreset(PRESET_POPULATION); }
  static int GetNumberOfPresets();
  /** "pair", "population"; nullptr out of range. */
  static const char* GetPresetName(int preset);
  /** What the preset is for, then "Sets Name value, ...". nullptr out of range. */
  static const char* GetPresetDocumentation(int preset);
  ///@}

  ///@{
  /**
   * Setting i's value as a double (switches 0/1, choices their index); set
   * clamps into the range like Set<Name>(). GetSetting returns NaN for an
   * index out of range; SetSetting ignores it.
   */
  double GetSetting(int i);
  void SetSetting(int i, double value);
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

  /**
   * Called whenever the input connections change: one output port per input
   * connection (at least one). A subclass that gathers every map output into
   * one port (ParaView's composite map) overrides it to keep its ports.
   */
  virtual void UpdateNumberOfOutputPorts();

  // BEGIN SETTING MEMBERS
  // clang-format off
  int PairMode = 0;
  int LandmarkIterations = 100;
  double LandmarkWeight = 1e6;
  double LandmarkBarrierWeight = 1.0;
  double LandmarkTolerance = 0.0001;
  bool RelaxLandmarkPhase = true;
  bool KeepLandmarks = true;
  bool LandmarkFreeAlignment = true;
  bool LandmarksAsGuides = false;
  double LandmarkGuideTolerance = 5.0;
  int CoarseIterations = 50;
  double CoarseError = 0.01;
  double CoarseBarrierWeight = 0.001;
  int FineIterations = 50;
  double TargetError = 0.001;
  double FineBarrierWeight = 1e-6;
  double FineBarrierRaise = 4.0;
  double MeshWeight = 0.5;
  double CoverageWeight = 0.1;
  double MapWeight = 1.0;
  double ApproximationWeight = 0.25;
  int RefinementRounds = 1;
  int RefinementIterations = 10;
  double RefinementDistortion = 1.4;
  double SqueezeDistortion = 10.0;
  double RefinementGrowth = 0.25;
  double MaxError = 0.0;
  int BoundRefinementRounds = 8;
  int BoundRefinementIterations = 10;
  double BoundMargin = 0.9;
  int BoundIterations = 20;
  int MaxVertices = 0;
  int ApproximationSamples = 50000;
  double MinEdgeLength = 0.001;
  double MaxEdgeLength = 100.0;
  double DecrementTolerance = 0.0001;
  double MaxPointStep = 0.17632698070846498;
  int BlockSolveInputs = 4;
  // clang-format on
  // END SETTING MEMBERS
  int SizingMode = SIZING_ARRAY_OR_CURVATURE;
  int OutputMode = COMMON_TRIANGULATION;
  int MappedInput = 0;
  int NumberOfThreads = 0;

private:
  vtkSurfaceMapFilter(const vtkSurfaceMapFilter&) = delete;
  void operator=(const vtkSurfaceMapFilter&) = delete;

  struct vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
