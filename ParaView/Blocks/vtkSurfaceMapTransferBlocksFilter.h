/**
 * @class   vtkSurfaceMapTransferBlocksFilter
 * @brief   vtkSurfaceMapTransfer between two inputs of a map, from its composite outputs.
 *
 * Port 0: the map's inputs with their sphere embeddings (a
 * vtkSurfaceMapBlocksFilter in INPUT_EMBEDDINGS mode), port 1: T lifted onto
 * each input (one in COMMON_TRIANGULATION mode, same inputs and settings),
 * each flattened into a list (connections in order, a composite's non-empty
 * leaves in traversal order). Carries the point arrays of input SourceIndex
 * onto the vertices of input TargetIndex: vtkSurfaceMapTransfer with target
 * mesh = embeddings[TargetIndex], source mesh = embeddings[SourceIndex] and
 * their lifts common[TargetIndex], common[SourceIndex]. Output, settings and
 * errors are vtkSurfaceMapTransfer's; an index beyond a list is an error
 * naming it.
 *
 * @sa vtkSurfaceMapTransfer vtkSurfaceMapBlocksFilter
 */
#ifndef vtkSurfaceMapTransferBlocksFilter_h
#define vtkSurfaceMapTransferBlocksFilter_h

#include "SurfaceMapsParaViewBlocksModule.h" // for export macro
#include "vtkSurfaceMapTransfer.h"

class SURFACEMAPSPARAVIEWBLOCKS_EXPORT vtkSurfaceMapTransferBlocksFilter
  : public vtkSurfaceMapTransfer
{
public:
  static vtkSurfaceMapTransferBlocksFilter* New();
  vtkTypeMacro(vtkSurfaceMapTransferBlocksFilter, vtkSurfaceMapTransfer);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The input whose point arrays are carried (SourceIndex, default 1) and the
   * input that receives them (TargetIndex, default 0), indices into both
   * lists. Range [0, VTK_INT_MAX].
   */
  vtkSetClampMacro(SourceIndex, int, 0, VTK_INT_MAX);
  vtkGetMacro(SourceIndex, int);
  vtkSetClampMacro(TargetIndex, int, 0, VTK_INT_MAX);
  vtkGetMacro(TargetIndex, int);
  ///@}

protected:
  vtkSurfaceMapTransferBlocksFilter();
  ~vtkSurfaceMapTransferBlocksFilter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int SourceIndex = 1;
  int TargetIndex = 0;

private:
  vtkSurfaceMapTransferBlocksFilter(const vtkSurfaceMapTransferBlocksFilter&) = delete;
  void operator=(const vtkSurfaceMapTransferBlocksFilter&) = delete;
};

#endif
