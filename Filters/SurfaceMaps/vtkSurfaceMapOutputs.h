/**
 * @class   vtkSurfaceMapOutputs
 * @brief   vtkSurfaceMapFilter's outputs from a computed map (private).
 *
 * Builds the outputs of each OutputMode (see vtkSurfaceMapFilter): T lifted
 * onto every input, input k mapped onto every input, or every input with its
 * sphere embedding; their point, cell and field data. The inputs' point
 * arrays are carried continuous or categorical by the filter's rule
 * (vtkSurfaceArrayTransferAlgorithm).
 */
#ifndef vtkSurfaceMapOutputs_h
#define vtkSurfaceMapOutputs_h

#include "map/MapInput.h"
#include "map/SurfaceMap.h"

#include <vector>

class vtkPolyData;
class vtkSurfaceArrayTransferAlgorithm;

class vtkSurfaceMapOutputs
{
public:
  /// The map, its inputs as vtkPolyData and as the engine saw them, the
  /// embeddings' times (field data) and the filter whose array transfer
  /// modes say how the inputs' point arrays are carried.
  vtkSurfaceMapOutputs(const surfacemaps::SurfaceMapResult& map,
    const std::vector<vtkPolyData*>& inputs,
    const std::vector<surfacemaps::MapInput>& mapInputs,
    const std::vector<double>& embeddingSeconds,
    vtkSurfaceArrayTransferAlgorithm* arrayModes);

  /// Output i: T lifted onto input i.
  void CommonTriangulation(const std::vector<vtkPolyData*>& outputs) const;
  /// Output j: input k's mesh mapped onto input j by the exact map.
  void MappedInput(const std::vector<vtkPolyData*>& outputs, int k) const;
  /// Output i: input i with its sphere embedding f_i.
  void InputEmbeddings(const std::vector<vtkPolyData*>& outputs) const;

private:
  const surfacemaps::SurfaceMapResult& Map;
  const std::vector<vtkPolyData*>& Inputs;
  const std::vector<surfacemaps::MapInput>& MapInputs;
  const std::vector<double>& EmbeddingSeconds;
  vtkSurfaceArrayTransferAlgorithm* ArrayModes;
};

#endif
