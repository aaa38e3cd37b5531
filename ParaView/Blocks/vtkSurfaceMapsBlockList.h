/**
 * @class   vtkSurfaceMapsBlockList
 * @brief   The surfaces of a port as a flat list: what the composite adapters feed the filters.
 *
 * ParaView hands a filter one data object per connection, and SurfaceMaps'
 * map filter hands on N surfaces as one composite (one block per input). The
 * module's filters read their inputs as one information object per surface
 * (vtkSurfaceMapsConversion::PolyDataOf), so the adapters flatten each port
 * into such a vector: every connection in order, and for a composite
 * connection its non-empty leaves in traversal order. Private to the plugin's
 * module (private class, not wrapped).
 */
#ifndef vtkSurfaceMapsBlockList_h
#define vtkSurfaceMapsBlockList_h

#include "vtkSmartPointer.h"

#include <functional>
#include <string>
#include <vector>

class vtkAlgorithm;
class vtkDataObject;
class vtkInformation;
class vtkInformationVector;
class vtkMultiBlockDataSet;
class vtkPolyData;

class vtkSurfaceMapsBlockList
{
public:
  /**
   * Appends one information object (DATA_OBJECT set) per surface of `port`
   * to `flat` and its name to `names`: the "FileName" field-data string
   * (base name) of the surface, else the block's NAME, else "surface k".
   * A leaf that is not a vtkPolyData is an error reported on `self`
   * (vtkErrorWithObjectMacro, naming it and its type); returns false then.
   */
  static bool Flatten(vtkAlgorithm* self,
    vtkInformationVector* port,
    vtkInformationVector* flat,
    std::vector<std::string>& names);

  /**
   * The input port of a one-port adapter: repeatable, each connection a
   * vtkPolyData or a composite of them. Returns 1.
   */
  static int FillRepeatableBlocksPort(vtkInformation* info);

  /**
   * RequestData of a one-port adapter: flattens `port` (Flatten) and calls
   * `run` with the flat list as the wrapped filter's input vectors (the
   * superclass's RequestData); on a bad block empties output 0 and returns 0.
   */
  static int RequestFlattened(vtkAlgorithm* self,
    vtkInformationVector* port,
    vtkInformationVector* output,
    const std::function<int(vtkInformationVector**)>& run);

  /**
   * The number of surfaces the connection `info` will carry, known before
   * its data is there: the top-level blocks of its COMPOSITE_DATA_META_DATA
   * (vtkSurfaceMapBlocksFilter announces its N blocks there), else the
   * surfaces of the data object it holds now (1 for a plain data set).
   */
  static int CountSurfaces(vtkInformation* info);

  /**
   * `surfaces` as blocks of `output` (cleared first), block k named names[k].
   */
  static void Gather(const std::vector<vtkSmartPointer<vtkPolyData>>& surfaces,
    const std::vector<std::string>& names,
    vtkMultiBlockDataSet* output);

  /**
   * Appends surface `index` of `list` to `picked` (as one information
   * object); false, with an error on `self` naming `what` and the list's
   * length, when the list is shorter.
   */
  static bool Pick(vtkAlgorithm* self,
    vtkInformationVector* list,
    int index,
    const char* what,
    vtkInformationVector* picked);

  /** `n` empty vtkPolyData and an information vector holding them, for a filter's outputs. */
  static std::vector<vtkSmartPointer<vtkPolyData>> NewSurfaces(int n, vtkInformationVector* vector);
};

#endif
