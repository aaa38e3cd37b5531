/**
 * @class   vtkSurfaceCheckerboardSource
 * @brief   The checkerboard texture maps are shown with: squares coloured by position.
 *
 * Produces a Size x Size RGB image (unsigned char scalars "Colours", origin
 * 0, spacing 1) of Squares x Squares squares. Every other square is
 * off-white; the others run through the hues along u (the image's x) and
 * from dark to light along v (y). A texture of it on a mesh shows stretch,
 * flips and seams of the texture coordinates, and, since no two coloured
 * squares look alike, where each part of the texture went: the command
 * line's transfer pictures and the Python package's
 * surfacemaps.render.checkerboard_texture use it. Wrap it in a vtkTexture
 * (interpolated, clamped at the edges) to render.
 *
 * @sa vtkSurfaceMapTransfer vtkSurfaceTextureSeamSplitter
 */
#ifndef vtkSurfaceCheckerboardSource_h
#define vtkSurfaceCheckerboardSource_h

#include "SurfaceMapsFiltersModule.h" // for export macro
#include "vtkImageAlgorithm.h"

class SURFACEMAPSFILTERS_EXPORT vtkSurfaceCheckerboardSource : public vtkImageAlgorithm
{
public:
  static vtkSurfaceCheckerboardSource* New();
  vtkTypeMacro(vtkSurfaceCheckerboardSource, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Squares along each side, at least 1 (default 16). */
  vtkSetClampMacro(Squares, int, 1, 4096);
  vtkGetMacro(Squares, int);
  ///@}

  ///@{
  /** Pixels along each side, at least 1 (default 512). */
  vtkSetClampMacro(Size, int, 1, 16384);
  vtkGetMacro(Size, int);
  ///@}

protected:
  vtkSurfaceCheckerboardSource();
  ~vtkSurfaceCheckerboardSource() override = default;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Squares = 16;
  int Size = 512;

private:
  vtkSurfaceCheckerboardSource(const vtkSurfaceCheckerboardSource&) = delete;
  void operator=(const vtkSurfaceCheckerboardSource&) = delete;
};

#endif
