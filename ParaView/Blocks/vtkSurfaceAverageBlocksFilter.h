/**
 * @class   vtkSurfaceAverageBlocksFilter
 * @brief   vtkSurfaceAverage whose inputs may come as one composite (ParaView's average).
 *
 * Averages the surfaces of its input port flattened into one list
 * (connections in order, a composite's non-empty leaves in traversal order),
 * e.g. the blocks of vtkSurfaceMapBlocksFilter: surface k is
 * vtkSurfaceAverage's input k (InputWeight k, reference frame of surface 0).
 * Everything else is vtkSurfaceAverage's; a leaf that is not a vtkPolyData is
 * an error.
 *
 * @sa vtkSurfaceAverage vtkSurfaceMapBlocksFilter
 */
#ifndef vtkSurfaceAverageBlocksFilter_h
#define vtkSurfaceAverageBlocksFilter_h

#include "SurfaceMapsParaViewBlocksModule.h" // for export macro
#include "vtkSurfaceAverage.h"

class SURFACEMAPSPARAVIEWBLOCKS_EXPORT vtkSurfaceAverageBlocksFilter : public vtkSurfaceAverage
{
public:
  static vtkSurfaceAverageBlocksFilter* New();
  vtkTypeMacro(vtkSurfaceAverageBlocksFilter, vtkSurfaceAverage);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkSurfaceAverageBlocksFilter();
  ~vtkSurfaceAverageBlocksFilter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkSurfaceAverageBlocksFilter(const vtkSurfaceAverageBlocksFilter&) = delete;
  void operator=(const vtkSurfaceAverageBlocksFilter&) = delete;
};

#endif
