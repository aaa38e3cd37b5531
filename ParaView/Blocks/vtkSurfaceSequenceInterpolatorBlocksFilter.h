/**
 * @class   vtkSurfaceSequenceInterpolatorBlocksFilter
 * @brief   vtkSurfaceSequenceInterpolator whose keyframes may come as one composite (ParaView's).
 *
 * Interpolates over the surfaces of its input port flattened into one list
 * (connections in order, a composite's non-empty leaves in traversal order),
 * e.g. the blocks of vtkSurfaceMapBlocksFilter with PAIRS_SEQUENCE: surface k
 * is keyframe k. TIME_STEPS and TIME_RANGE need the number of keyframes
 * before the data is there: it is read from the inputs' announced blocks
 * (COMPOSITE_DATA_META_DATA, which vtkSurfaceMapBlocksFilter sets), else from
 * the data they hold now. Everything else is vtkSurfaceSequenceInterpolator's.
 *
 * @sa vtkSurfaceSequenceInterpolator vtkSurfaceMapBlocksFilter
 */
#ifndef vtkSurfaceSequenceInterpolatorBlocksFilter_h
#define vtkSurfaceSequenceInterpolatorBlocksFilter_h

#include "SurfaceMapsParaViewBlocksModule.h" // for export macro
#include "vtkSurfaceSequenceInterpolator.h"

class SURFACEMAPSPARAVIEWBLOCKS_EXPORT vtkSurfaceSequenceInterpolatorBlocksFilter
  : public vtkSurfaceSequenceInterpolator
{
public:
  static vtkSurfaceSequenceInterpolatorBlocksFilter* New();
  vtkTypeMacro(vtkSurfaceSequenceInterpolatorBlocksFilter, vtkSurfaceSequenceInterpolator);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkSurfaceSequenceInterpolatorBlocksFilter();
  ~vtkSurfaceSequenceInterpolatorBlocksFilter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkSurfaceSequenceInterpolatorBlocksFilter(
    const vtkSurfaceSequenceInterpolatorBlocksFilter&) = delete;
  void operator=(const vtkSurfaceSequenceInterpolatorBlocksFilter&) = delete;
};

#endif
