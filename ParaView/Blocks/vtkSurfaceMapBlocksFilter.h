/**
 * @class   vtkSurfaceMapBlocksFilter
 * @brief   vtkSurfaceMapFilter with one composite output: one block per input (ParaView's map).
 *
 * A ParaView proxy fixes its output ports when it is created, so it cannot
 * follow vtkSurfaceMapFilter's one output port per input. This subclass keeps
 * one output port, a vtkMultiBlockDataSet whose block i is what
 * vtkSurfaceMapFilter's output i would be (in every OutputMode), named after
 * input i (its "FileName" field data, else its block name). Its input port
 * takes any number of vtkPolyData and composite data sets, flattened into the
 * list of inputs (connections in order, a composite's non-empty leaves in
 * traversal order); a leaf that is not a vtkPolyData is an error. Every
 * setting, the kept map (switching OutputMode does not recompute), progress,
 * AbortExecute and the errors are vtkSurfaceMapFilter's.
 *
 * Preset: ParaView pushes every property of the proxy (each setting at
 * its table default unless changed), so a preset cannot be applied as
 * vtkSurfaceMapFilter::ApplyPreset does (once, overwritten by later Set
 * calls) without depending on the order the properties arrive in. Here the
 * preset is a property of its own, resolved when the map runs: a setting
 * the preset governs takes the preset's value while it is at its table
 * default, and a value changed away from the default wins over the preset
 * (as a command-line flag wins over --preset). Get<Name>()/GetSetting(i)
 * keep returning the values set; GetEffectiveSetting(i) is what the map
 * runs with.
 *
 * Its RequestInformation announces the N blocks in
 * COMPOSITE_DATA_META_DATA, so that downstream filters (the sequence
 * interpolator) know the number of surfaces before the map has run.
 *
 * @sa vtkSurfaceMapFilter vtkSurfaceAverageBlocksFilter
 */
#ifndef vtkSurfaceMapBlocksFilter_h
#define vtkSurfaceMapBlocksFilter_h

#include "SurfaceMapsParaViewBlocksModule.h" // for export macro
#include "vtkSurfaceMapFilter.h"

class SURFACEMAPSPARAVIEWBLOCKS_EXPORT vtkSurfaceMapBlocksFilter : public vtkSurfaceMapFilter
{
public:
  static vtkSurfaceMapBlocksFilter* New();
  vtkTypeMacro(vtkSurfaceMapBlocksFilter, vtkSurfaceMapFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The preset (vtkSurfaceMapFilter::Presets) filling in the settings it
   * governs that are at their table defaults, when the map runs. Default
   * PRESET_PAIR (the defaults themselves: no change). An unknown preset is
   * ignored with a vtkErrorMacro.
   */
  void SetPreset(int preset);
  vtkGetMacro(Preset, int);
  ///@}

  /**
   * Setting i's value the map runs with under Preset (see above); NaN for
   * an index out of range.
   */
  double GetEffectiveSetting(int i);

protected:
  vtkSurfaceMapBlocksFilter();
  ~vtkSurfaceMapBlocksFilter() override;

  void UpdateNumberOfOutputPorts() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Preset = PRESET_PAIR;

private:
  vtkSurfaceMapBlocksFilter(const vtkSurfaceMapBlocksFilter&) = delete;
  void operator=(const vtkSurfaceMapBlocksFilter&) = delete;
};

#endif
