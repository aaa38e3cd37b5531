/**
 * @class   vtkSurfaceArrayTransferAlgorithm
 * @brief   Superclass of the filters that carry point arrays onto other surfaces: continuous or
 * categorical.
 *
 * vtkSurfaceMapFilter (its outputs), vtkSurfaceMapTransfer, vtkSurfaceAverage
 * and vtkSurfaceSequenceInterpolator carry point arrays from their inputs onto
 * points that are not input vertices. Each point array goes one of two ways:
 * - continuous: interpolated (barycentric coordinates in the containing source
 *   triangle; the weighted mean or time blend in the average and the
 *   interpolator); integer values are rounded;
 * - categorical (labels, region ids): never a value the source does not have.
 *   Through a map, the value at the corner of the containing source triangle
 *   with the largest barycentric coordinate (the nearest corner; the first of
 *   equal ones); in vtkSurfaceAverage input 0's values, in
 *   vtkSurfaceSequenceInterpolator those of the keyframe nearest in time.
 *
 * The rule, the one place every such filter asks (ResolveArrayTransferMode):
 * an array named with SetArrayTransferMode goes that way; otherwise integer
 * arrays (char, short, int, long, id types, unsigned or not) are categorical
 * and floating-point arrays (float, double) continuous. Arrays that are not
 * numeric (e.g. vtkStringArray) are always categorical. Colours stored as
 * unsigned char are integers too: name them continuous if they should blend.
 *
 * The settings are ParaView-friendly: a name and an int mode per call, cleared
 * all at once, listed by index. Names that no input carries have no effect.
 * Changing them never recomputes a map (vtkSurfaceMapFilter reuses the one it
 * keeps).
 *
 * @sa vtkSurfaceMapFilter vtkSurfaceMapTransfer vtkSurfaceAverage
 * vtkSurfaceSequenceInterpolator
 */
#ifndef vtkSurfaceArrayTransferAlgorithm_h
#define vtkSurfaceArrayTransferAlgorithm_h

#include "SurfaceMapsFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <memory> // for std::unique_ptr

class vtkAbstractArray;

class SURFACEMAPSFILTERS_EXPORT vtkSurfaceArrayTransferAlgorithm : public vtkPolyDataAlgorithm
{
public:
  vtkAbstractTypeMacro(vtkSurfaceArrayTransferAlgorithm, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** How a point array is carried onto other points. */
  enum ArrayTransferModes
  {
    ARRAY_TRANSFER_BY_TYPE = 0,    ///< categorical for integer arrays, continuous for floating
    ARRAY_TRANSFER_CONTINUOUS = 1, ///< interpolated (integers rounded)
    ARRAY_TRANSFER_CATEGORICAL = 2 ///< a value of the source: the nearest corner's
  };

  ///@{
  /**
   * How the point array `name` is transferred: ARRAY_TRANSFER_CONTINUOUS,
   * ARRAY_TRANSFER_CATEGORICAL, or ARRAY_TRANSFER_BY_TYPE (the default for
   * every array: integer arrays categorical, floating-point ones continuous;
   * setting it removes the array's choice). A mode outside [0, 2] or a null or
   * empty name is ignored with an error. GetArrayTransferMode returns the
   * choice made for `name` (ARRAY_TRANSFER_BY_TYPE when none).
   */
  void SetArrayTransferMode(const char* name, int mode);
  int GetArrayTransferMode(const char* name);
  void SetArrayTransferModeToContinuous(const char* name)
  {
    this->SetArrayTransferMode(name, ARRAY_TRANSFER_CONTINUOUS);
  }
  void SetArrayTransferModeToCategorical(const char* name)
  {
    this->SetArrayTransferMode(name, ARRAY_TRANSFER_CATEGORICAL);
  }
  ///@}

  ///@{
  /**
   * Removes every array's choice: all arrays by type again.
   */
  void ClearArrayTransferModes();
  ///@}

  ///@{
  /**
   * The arrays with a choice, in name order: how many, and the i-th name
   * (nullptr outside [0, GetNumberOfArrayTransferModes())).
   */
  int GetNumberOfArrayTransferModes();
  const char* GetArrayTransferModeArrayName(int i);
  ///@}

  /**
   * The rule: ARRAY_TRANSFER_CONTINUOUS or ARRAY_TRANSFER_CATEGORICAL for
   * `array`, from the choice made for its name, else its type (see the class
   * documentation). A null array is categorical.
   */
  int ResolveArrayTransferMode(vtkAbstractArray* array);

  /** "continuous", "categorical" or "by type" for a mode value; nullptr for others. */
  static const char* GetArrayTransferModeAsString(int mode);

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
  vtkSurfaceArrayTransferAlgorithm();
  ~vtkSurfaceArrayTransferAlgorithm() override;
  vtkExecutive* CreateDefaultExecutive() override;

private:
  vtkSurfaceArrayTransferAlgorithm(const vtkSurfaceArrayTransferAlgorithm&) = delete;
  void operator=(const vtkSurfaceArrayTransferAlgorithm&) = delete;

  struct vtkArrayModes;
  std::unique_ptr<vtkArrayModes> ArrayModes;
};

#endif
