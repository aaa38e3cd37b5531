#include "vtkSurfaceCheckerboardSource.h"

#include "vtkDataObject.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>

vtkStandardNewMacro(vtkSurfaceCheckerboardSource);

vtkSurfaceCheckerboardSource::vtkSurfaceCheckerboardSource()
{
  this->SetNumberOfInputPorts(0);
}

int vtkSurfaceCheckerboardSource::RequestInformation(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  vtkInformation* info = outputVector->GetInformationObject(0);
  const int extent[6] = { 0, this->Size - 1, 0, this->Size - 1, 0, 0 };
  info->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  vtkDataObject::SetPointDataActiveScalarInfo(info, VTK_UNSIGNED_CHAR, 3);
  return 1;
}

int vtkSurfaceCheckerboardSource::RequestData(vtkInformation*,
  vtkInformationVector**,
  vtkInformationVector* outputVector)
{
  vtkImageData* image = vtkImageData::GetData(outputVector);
  const int size = this->Size;
  const int squares = this->Squares;
  // The whole image whatever extent was asked for: it is small, and a
  // texture needs all of it.
  image->SetExtent(0, size - 1, 0, size - 1, 0, 0);
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetName("Colours");
  colours->SetNumberOfComponents(3);
  colours->SetNumberOfTuples(static_cast<vtkIdType>(size) * size);
  const double cell = static_cast<double>(size) / squares;
  for (int y = 0; y < size; ++y)
  {
    const int j = static_cast<int>(y / cell);
    for (int x = 0; x < size; ++x)
    {
      const int i = static_cast<int>(x / cell);
      double rgb[3] = { 245.0 / 255.0, 245.0 / 255.0, 240.0 / 255.0 };
      if ((i + j) % 2 == 0)
      {
        vtkMath::HSVToRGB(static_cast<double>(i) / squares, 0.75,
          0.35 + 0.6 * j / std::max(squares - 1, 1), rgb, rgb + 1, rgb + 2);
      }
      for (int c = 0; c < 3; ++c)
      {
        colours->SetValue(3 * (static_cast<vtkIdType>(y) * size + x) + c,
          static_cast<unsigned char>(255.0 * rgb[c]));
      }
    }
  }
  image->GetPointData()->SetScalars(colours);
  return 1;
}

void vtkSurfaceCheckerboardSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Squares: " << this->Squares << "\n";
  os << indent << "Size: " << this->Size << "\n";
}
