/**
 * @class   vtkSurfaceMeshValidatorBlocksFilter
 * @brief   vtkSurfaceMeshValidator whose inputs may come as one composite (ParaView's validator).
 *
 * Checks the surfaces of its input port flattened into one list (connections
 * in order, a composite's non-empty leaves in traversal order): one table
 * row per surface, as vtkSurfaceMeshValidator's. A leaf that is not a
 * vtkPolyData is an error (the validator's table is for surfaces).
 *
 * @sa vtkSurfaceMeshValidator vtkSurfaceMapBlocksFilter
 */
#ifndef vtkSurfaceMeshValidatorBlocksFilter_h
#define vtkSurfaceMeshValidatorBlocksFilter_h

#include "SurfaceMapsParaViewBlocksModule.h" // for export macro
#include "vtkSurfaceMeshValidator.h"

class SURFACEMAPSPARAVIEWBLOCKS_EXPORT vtkSurfaceMeshValidatorBlocksFilter
  : public vtkSurfaceMeshValidator
{
public:
  static vtkSurfaceMeshValidatorBlocksFilter* New();
  vtkTypeMacro(vtkSurfaceMeshValidatorBlocksFilter, vtkSurfaceMeshValidator);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkSurfaceMeshValidatorBlocksFilter();
  ~vtkSurfaceMeshValidatorBlocksFilter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkSurfaceMeshValidatorBlocksFilter(const vtkSurfaceMeshValidatorBlocksFilter&) = delete;
  void operator=(const vtkSurfaceMeshValidatorBlocksFilter&) = delete;
};

#endif
