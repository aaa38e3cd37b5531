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
 * and up to 150 in all while some triangle's share of the sphere is below a
 * hundredth of its share of the mesh's area (the exact map of a surface map
 * would inherit such a squeezed triangle).
 * The result is certified with exact orientation predicates and a degree
 * check. If certification fails (or some triangles end up nearly collapsed,
 * distortion above 100, at the end or at a level of the first attempt) the
 * embedding is retried with a 100x stronger
 * barrier, then with the barrier alone; of certified attempts that are all
 * too distorted the least distorted one is kept; if none certifies the
 * filter reports an error and produces no output. "EmbeddingAttempt" says
 * which attempt won.
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

  ///@{
  /**
   * Total weight of the barriers (orientation and edge length), spread over
   * the triangles, against the distortion (whose minimum is 1). Default 0.1,
   * range [1e-6, 1e3]. Smaller values give lower distortion but stiffer
   * optimisation.
   */
  vtkSetClampMacro(BarrierWeight, double, 1e-6, 1e3);
  vtkGetMacro(BarrierWeight, double);
  ///@}

  ///@{
  /**
   * Newton iterations on the whole mesh after each reinsertion level, below
   * and above 1 000 vertices. Defaults 20 and 5, range [0, 1000].
   */
  vtkSetClampMacro(LevelIterations, int, 0, 1000);
  vtkGetMacro(LevelIterations, int);
  vtkSetClampMacro(LargeLevelIterations, int, 0, 1000);
  vtkGetMacro(LargeLevelIterations, int);
  ///@}

  ///@{
  /**
   * Newton iterations on the full mesh at the end. Default 50, range [0, 10000]
   * (more while a triangle is squeezed on the sphere, see above).
   * They stop earlier once a Newton step would lower the energy by less than
   * FinalTolerance times its value (default 1e-6, range [0, 1]).
   */
  vtkSetClampMacro(FinalIterations, int, 0, 10000);
  vtkGetMacro(FinalIterations, int);
  vtkSetClampMacro(FinalTolerance, double, 0.0, 1.0);
  vtkGetMacro(FinalTolerance, double);
  ///@}

  ///@{
  /**
   * Optional reference embedding (port 1) whose landmarks this embedding is
   * rotated onto; see the class description.
   */
  void SetReferenceConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }
  void SetReferenceData(vtkDataObject* data) { this->SetInputData(1, data); }
  ///@}

protected:
  vtkSphereEmbeddingFilter();
  int FillInputPortInformation(int port, vtkInformation* info) override;
  ~vtkSphereEmbeddingFilter() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  bool OutputPointsOnSphere = false;
  double BarrierWeight = 0.1;
  int LevelIterations = 20;
  int LargeLevelIterations = 5;
  int FinalIterations = 50;
  double FinalTolerance = 1e-6;

private:
  vtkSphereEmbeddingFilter(const vtkSphereEmbeddingFilter&) = delete;
  void operator=(const vtkSphereEmbeddingFilter&) = delete;
};

#endif
