/**
 * @class   vtkSurfaceMapEvaluationBlocksFilter
 * @brief   vtkSurfaceMapEvaluation of two surfaces picked from a list (ParaView's evaluation).
 *
 * Port 0 (repeatable): surfaces of identical connectivity, flattened into one
 * list (connections in order, a composite's non-empty leaves in traversal
 * order), e.g. the blocks of vtkSurfaceMapBlocksFilter. Surface SourceIndex
 * is vtkSurfaceMapEvaluation's source P, surface TargetIndex its target Q.
 * Optional port 1 (repeatable): the original surfaces, flattened the same way
 * (e.g. the map's inputs); with them, originals SourceIndex and TargetIndex
 * give the Hausdorff figures. Output and errors are vtkSurfaceMapEvaluation's;
 * an index beyond a list is an error naming it.
 *
 * @sa vtkSurfaceMapEvaluation vtkSurfaceMapBlocksFilter
 */
#ifndef vtkSurfaceMapEvaluationBlocksFilter_h
#define vtkSurfaceMapEvaluationBlocksFilter_h

#include "SurfaceMapsParaViewBlocksModule.h" // for export macro
#include "vtkSurfaceMapEvaluation.h"

class SURFACEMAPSPARAVIEWBLOCKS_EXPORT vtkSurfaceMapEvaluationBlocksFilter
  : public vtkSurfaceMapEvaluation
{
public:
  static vtkSurfaceMapEvaluationBlocksFilter* New();
  vtkTypeMacro(vtkSurfaceMapEvaluationBlocksFilter, vtkSurfaceMapEvaluation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The surfaces compared: source P and target Q, indices into the flattened
   * list of port 0 (and of port 1's originals). Defaults 0 and 1, range
   * [0, VTK_INT_MAX].
   */
  vtkSetClampMacro(SourceIndex, int, 0, VTK_INT_MAX);
  vtkGetMacro(SourceIndex, int);
  vtkSetClampMacro(TargetIndex, int, 0, VTK_INT_MAX);
  vtkGetMacro(TargetIndex, int);
  ///@}

protected:
  vtkSurfaceMapEvaluationBlocksFilter();
  ~vtkSurfaceMapEvaluationBlocksFilter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int SourceIndex = 0;
  int TargetIndex = 1;

private:
  vtkSurfaceMapEvaluationBlocksFilter(const vtkSurfaceMapEvaluationBlocksFilter&) = delete;
  void operator=(const vtkSurfaceMapEvaluationBlocksFilter&) = delete;
};

#endif
