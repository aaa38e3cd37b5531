/**
 * @class   vtkSurfaceShapeStatisticsBlocksFilter
 * @brief   vtkSurfaceShapeStatistics whose inputs may come as one composite (for ParaView).
 *
 * The shape statistics (mean, modes, "StandardDeviation") of the surfaces of
 * its input port flattened into one list (connections in order, a
 * composite's non-empty leaves in traversal order), e.g. the blocks of
 * vtkSurfaceMapBlocksFilter in Common triangulation mode: surface k is
 * vtkSurfaceShapeStatistics' input k. Everything else is
 * vtkSurfaceShapeStatistics'; a leaf that is not a vtkPolyData is an error.
 *
 * @sa vtkSurfaceShapeStatistics vtkSurfaceMapBlocksFilter vtkSurfaceAverageBlocksFilter
 */
#ifndef vtkSurfaceShapeStatisticsBlocksFilter_h
#define vtkSurfaceShapeStatisticsBlocksFilter_h

#include "SurfaceMapsParaViewBlocksModule.h" // for export macro
#include "vtkSurfaceShapeStatistics.h"

class SURFACEMAPSPARAVIEWBLOCKS_EXPORT vtkSurfaceShapeStatisticsBlocksFilter
  : public vtkSurfaceShapeStatistics
{
public:
  static vtkSurfaceShapeStatisticsBlocksFilter* New();
  vtkTypeMacro(vtkSurfaceShapeStatisticsBlocksFilter, vtkSurfaceShapeStatistics);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkSurfaceShapeStatisticsBlocksFilter();
  ~vtkSurfaceShapeStatisticsBlocksFilter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkSurfaceShapeStatisticsBlocksFilter(const vtkSurfaceShapeStatisticsBlocksFilter&) = delete;
  void operator=(const vtkSurfaceShapeStatisticsBlocksFilter&) = delete;
};

#endif
