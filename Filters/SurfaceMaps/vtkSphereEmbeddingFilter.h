/**
 * @class   vtkSphereEmbeddingFilter
 * @brief   Bijective embedding of a closed genus-0 surface on the unit sphere.
 *
 * Computes, for every vertex of a closed, manifold, genus-0 triangle mesh, a
 * point on the unit sphere such that the chord triangles of all input
 * triangles are positively oriented and cover the sphere exactly once: a
 * bijective map of the surface onto the sphere, the starting point of every
 * surface map in SurfaceMaps ("Surface Maps via Adaptive Triangulations",
 * Schmidt, Pieper, Kobbelt, Eurographics 2023, section on initial
 * embeddings). The distortion minimised is the area-weighted symmetric
 * Dirichlet energy between each input triangle and its chord triangle (both
 * meshes scaled to unit area), with log barriers keeping every triangle
 * positive and every spherical edge shorter than 140 degrees.
 *
 * Method: the mesh is decimated by half-edge collapses (quadric error order,
 * independent sets per level) to a tetrahedron, which is placed as a regular
 * tetrahedron; the collapses are undone level by level, each vertex placed
 * inside its one-ring's kernel and optimised locally, then the whole level by
 * a few projected-Newton steps; the final mesh gets up to FinalIterations,
 * and up to SqueezedFinalIterations in all while some triangle's share of
 * the sphere is below SqueezedAreaRatio times its share of the mesh's area
 * (the exact map of a surface map would inherit such a squeezed triangle).
 * The result is certified with exact orientation predicates and a degree
 * check. If certification fails (or some triangles end up nearly collapsed,
 * distortion above AcceptableDistortion, at the end or at a level of the
 * first attempt) the embedding is retried with a 100x stronger barrier, then
 * with the barrier alone; of certified attempts that are all too distorted
 * the least distorted one is kept; if none certifies the filter reports an
 * error and produces no output. "EmbeddingAttempt" says which attempt won.
 *
 * Settings: each setting below (all but OutputPointsOnSphere) is one entry of
 * the engine's list of settings (Core/settings/SettingList.def), which its
 * Set/Get macros, doc comment and member are written from. vtkSurfaceMapFilter
 * embeds every input it is not given an embedding for with the same defaults.
 * vtkSurfaceMapsSettings (table SPHERE_EMBEDDING_SETTINGS) lists them for
 * tools; GetSetting(i) and SetSetting(i) read and write them by index. A
 * setting outside its range at the update (NaN) is an error.
 *
 * Input: vtkPolyData, triangles only, closed, manifold, genus 0 (what
 * vtkSurfaceMeshValidator accepts). Invalid input is reported with the same
 * messages as the validator (naming the input's "FileName" field-data string
 * when present) and gives an empty output.
 *
 * Optional input port 1 (SetReferenceConnection / SetReferenceData): an already
 * embedded mesh with "SpherePosition" and "Landmarks" arrays. When both it and
 * the input carry landmarks with common ids, the new embedding is rotated
 * rigidly (a rotation keeps it bijective) so that its landmarks come as close
 * as possible to the reference's (least squares); field data
 * "LandmarkAlignmentError" gives the remaining RMS angle (radians).
 *
 * Output: the input mesh with the point array "SpherePosition" (3 doubles,
 * unit vectors). With OutputPointsOnSphere the points themselves are moved to
 * the sphere (for viewing) and the original coordinates are kept in the point
 * array "InputPosition". Field data: "EmbeddingDistortion" (symmetric
 * Dirichlet, 1 for an isometry), "EmbeddingEnergy", "EmbeddingNewtonIterations",
 * "EmbeddingLevels", "EmbeddingAttempt" (1 = default weights), "EmbeddingSeconds",
 * "EmbeddingSmallestAreaRatio" (over the triangles, the smallest ratio of a
 * triangle's share of the sphere to its share of the mesh's area; 1 for an
 * area-preserving embedding).
 *
 * @warning Cost grows a little faster than linearly with the vertex count:
 * about 0.7 s for 3 000 vertices and 3.5 s for 12 000 on two cores (see the
 * README's performance section). Derivative evaluation runs on all OpenMP
 * threads. Progress is reported per level; AbortExecute stops the filter
 * within one Newton iteration and leaves the output empty.
 *
 * @sa vtkSurfaceMeshValidator vtkSurfaceMeshReader
 */
#ifndef vtkSphereEmbeddingFilter_h
#define vtkSphereEmbeddingFilter_h

#include "SurfaceMapsFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class SURFACEMAPSFILTERS_EXPORT vtkSphereEmbeddingFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkSphereEmbeddingFilter* New();
  vtkTypeMacro(vtkSphereEmbeddingFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Move the output points onto the sphere (the original coordinates go to
   * the point array "InputPosition"). Default off: the output keeps the
   * input's geometry and carries the embedding in "SpherePosition".
   */
  vtkSetMacro(OutputPointsOnSphere, bool);
  vtkGetMacro(OutputPointsOnSphere, bool);
  vtkBooleanMacro(OutputPointsOnSphere, bool);
  ///@}

  // BEGIN SETTINGS
  // Written from Core/settings/SettingList.def by TestSettingHeaders
  // (SURFACEMAPS_UPDATE_SETTING_HEADERS=1 ctest -R SettingHeaders):
  // edit the list, not these lines.
  // clang-format off

  ///@{
  /** Total weight of the barriers (orientation and spherical edge length), spread evenly over
   * the triangles, against the distortion (whose minimum is 1): smaller values give a lower
   * distortion but a stiffer optimisation. The retry after a failed attempt multiplies it by
   * 100. Default 0.1, range 1e-6 to 1000. */
  vtkSetClampMacro(BarrierWeight, double, 1e-6, 1000.0);
  vtkGetMacro(BarrierWeight, double);
  ///@}

  ///@{
  /** Newton iterations on the whole current mesh after inserting a level, while the mesh has at
   * most 1 000 vertices; also the most a larger level gets when its insertion left the energy
   * far above the previous level's. Default 20, range 0 to 1000. */
  vtkSetClampMacro(LevelIterations, int, 0, 1000);
  vtkGetMacro(LevelIterations, int);
  ///@}

  ///@{
  /** Newton iterations after inserting a level once the mesh has more than 1 000 vertices.
   * Default 5, range 0 to 1000. */
  vtkSetClampMacro(LargeLevelIterations, int, 0, 1000);
  vtkGetMacro(LargeLevelIterations, int);
  ///@}

  ///@{
  /** A level's iterations stop once the decrease a Newton step expects (decrement^2 / 2) is
   * below this. Default 1e-5, range 0 to 1. */
  vtkSetClampMacro(LevelTolerance, double, 0.0, 1.0);
  vtkGetMacro(LevelTolerance, double);
  ///@}

  ///@{
  /** Newton iterations on each inserted vertex's own position, inside its one-ring's kernel.
   * Default 10, range 0 to 1000. */
  vtkSetClampMacro(LocalIterations, int, 0, 1000);
  vtkGetMacro(LocalIterations, int);
  ///@}

  ///@{
  /** Newton iterations on the input mesh at the end (more while a triangle is squeezed, see
   * SqueezedFinalIterations). Default 50, range 0 to 10000. */
  vtkSetClampMacro(FinalIterations, int, 0, 10000);
  vtkGetMacro(FinalIterations, int);
  ///@}

  ///@{
  /** The final iterations stop once the decrease a Newton step expects (decrement^2 / 2) is
   * below this (an absolute energy; the distortion's minimum is 1). Default 1e-5, range 0 to 1. */
  vtkSetClampMacro(FinalTolerance, double, 0.0, 1.0);
  vtkGetMacro(FinalTolerance, double);
  ///@}

  ///@{
  /** The final iterations go on, up to this many in all (and until FinalTolerance is met), while
   * some triangle's share of the sphere is below SqueezedAreaRatio times its share of the
   * input's area: the exact map of a surface map inherits such a triangle and squeezes or
   * stretches the input triangles that land in it as much. Default 150, range 0 to 100000. */
  vtkSetClampMacro(SqueezedFinalIterations, int, 0, 100000);
  vtkGetMacro(SqueezedFinalIterations, int);
  ///@}

  ///@{
  /** The ratio below which SqueezedFinalIterations counts a triangle as squeezed (0: no check).
   * Sound embeddings of real meshes have no triangle below 0.07; after 50 iterations a few
   * meshes still have triangles at 1e-4 to 1e-3 that more iterations remove. Default 0.01,
   * range 0 to 1. */
  vtkSetClampMacro(SqueezedAreaRatio, double, 0.0, 1.0);
  vtkGetMacro(SqueezedAreaRatio, double);
  ///@}

  ///@{
  /** An attempt whose final distortion (symmetric Dirichlet) exceeds this counts as failed and
   * the next attempt runs (a 100 times stronger barrier, then the barrier alone); if every
   * certified attempt exceeds it, the least distorted one is the result. The first attempt also
   * gives up at the first level whose distortion ends above it. A sound embedding's distortion
   * is of order 1 to 10; above 100 it is dominated by triangles squeezed thousands of times.
   * Default 100, range 1 to 1e12. */
  vtkSetClampMacro(AcceptableDistortion, double, 1.0, 1e12);
  vtkGetMacro(AcceptableDistortion, double);
  ///@}

  ///@{
  /** Largest tangent step of one vertex in a Newton step, as the tan of its angle (tan 75
   * degrees is 3.73); the whole step is scaled down to respect it. Default 3.732050807568877,
   * range 1e-6 to 1000. */
  vtkSetClampMacro(MaxVertexStep, double, 1e-6, 1000.0);
  vtkGetMacro(MaxVertexStep, double);
  ///@}
  // clang-format on
  // END SETTINGS

  ///@{
  /**
   * Setting i of vtkSurfaceMapsSettings' SPHERE_EMBEDDING_SETTINGS table (the
   * settings above, in the list's order) as a double (switches 0/1); set
   * clamps into the range like Set<Name>(). GetSetting returns NaN for an
   * index out of range; SetSetting ignores it.
   */
  double GetSetting(int i);
  void SetSetting(int i, double value);
  ///@}

  ///@{
  /**
   * Optional reference embedding (port 1) whose landmarks this embedding is
   * rotated onto; see the class description.
   */
  void SetReferenceConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }
  void SetReferenceData(vtkDataObject* data) { this->SetInputData(1, data); }
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
  vtkSphereEmbeddingFilter();
  int FillInputPortInformation(int port, vtkInformation* info) override;
  ~vtkSphereEmbeddingFilter() override = default;
  vtkExecutive* CreateDefaultExecutive() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  bool OutputPointsOnSphere = false;
  // BEGIN SETTING MEMBERS
  // clang-format off
  double BarrierWeight = 0.1;
  int LevelIterations = 20;
  int LargeLevelIterations = 5;
  double LevelTolerance = 1e-5;
  int LocalIterations = 10;
  int FinalIterations = 50;
  double FinalTolerance = 1e-5;
  int SqueezedFinalIterations = 150;
  double SqueezedAreaRatio = 0.01;
  double AcceptableDistortion = 100.0;
  double MaxVertexStep = 3.732050807568877;
  // clang-format on
  // END SETTING MEMBERS

private:
  vtkSphereEmbeddingFilter(const vtkSphereEmbeddingFilter&) = delete;
  void operator=(const vtkSphereEmbeddingFilter&) = delete;
};

#endif
