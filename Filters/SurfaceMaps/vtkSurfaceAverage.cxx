#include "vtkSurfaceAverage.h"

#include "vtkSurfaceMapsCombination.h"
#include "vtkSurfaceMapsConversion.h"
#include "vtkSurfaceMapsErrorGuard.h"

#include "base/Aborted.h"
#include "statistics/Procrustes.h"

#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkSurfaceAverage);

struct vtkSurfaceAverage::vtkInternals
{
  vtkSurfaceMapsCombination::IndexedValues Weights; // explicitly set weights; 1 elsewhere
};

namespace
{

// The input weights normalised to sum 1; throws std::invalid_argument unless
// finite, >= 0 and not all 0.
std::vector<double> normalisedWeights(vtkSurfaceAverage* self,
  const std::vector<vtkPolyData*>& inputs)
{
  const int n = static_cast<int>(inputs.size());
  std::vector<double> weights(n);
  double total = 0.0;
  for (int i = 0; i < n; ++i)
  {
    weights[i] = self->GetInputWeight(i);
    if (!(weights[i] >= 0.0) || !std::isfinite(weights[i]))
    {
      std::ostringstream text;
      text << "the weight of " << vtkSurfaceMapsCombination::Name(inputs[i], "input", i) << " is "
           << weights[i] << "; weights must be finite and >= 0";
      throw std::invalid_argument(text.str());
    }
    total += weights[i];
  }
  if (!(total > 0.0))
  {
    throw std::invalid_argument("the input weights sum to 0");
  }
  for (double& w : weights)
  {
    w /= total;
  }
  return weights;
}

// The generalized Procrustes alignment of the inputs (the mean's frame and
// why vtkProcrustesAlignmentFilter is not used: see alignProcrustes and the
// class documentation).
template<typename Report>
surfacemaps::ProcrustesResult alignInputs(const std::vector<vtkPolyData*>& inputs,
  const std::vector<double>& weights,
  int alignMode,
  Report& report)
{
  std::vector<surfacemaps::ShapePoints> shapes;
  for (vtkPolyData* input : inputs)
  {
    shapes.push_back(vtkSurfaceMapsCombination::Points(input));
  }
  surfacemaps::ProcrustesOptions options;
  options.kind = vtkSurfaceMapsCombination::AlignmentOf(alignMode);
  options.progress = [&report](double fraction)
  { report(0.9 * fraction, "Aligning the inputs"); };
  return surfacemaps::alignProcrustes(
    shapes, weights, vtkSurfaceMapsCombination::Triangles(inputs[0]), options);
}

} // namespace

vtkSurfaceAverage::vtkSurfaceAverage()
  : Internals(new vtkInternals)
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(1);
}

vtkSurfaceAverage::~vtkSurfaceAverage() = default;

void vtkSurfaceAverage::SetInputWeight(int i, double weight)
{
  if (i < 0)
  {
    vtkErrorMacro(<< "input weight index " << i << " is negative");
    return;
  }
  if (this->Internals->Weights.Set(i, weight))
  {
    this->Modified();
  }
}

double vtkSurfaceAverage::GetInputWeight(int i)
{
  return this->Internals->Weights.Get(i, 1.0);
}

void vtkSurfaceAverage::RemoveAllInputWeights()
{
  if (this->Internals->Weights.Clear())
  {
    this->Modified();
  }
}

int vtkSurfaceAverage::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  info->Set(vtkAlgorithm::INPUT_IS_REPEATABLE(), 1);
  return 1;
}

int vtkSurfaceAverage::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  output->Initialize();
  const std::vector<vtkPolyData*> inputs = vtkSurfaceMapsConversion::PolyDataOf(inputVector[0]);
  auto report = [this](double fraction, const char* text)
  {
    this->SetProgressText(text);
    this->UpdateProgress(fraction);
    if (this->GetAbortExecute())
    {
      throw surfacemaps::Aborted();
    }
  };

  vtkSurfaceMapsErrorGuard::Policy policy;
  policy.AbortedOutputs = outputVector;
  return vtkSurfaceMapsErrorGuard::Run(
    this,
    policy,
    [&]
    {
      vtkSurfaceMapsCombination::CheckPresent(inputs, "input");
      const std::vector<double> weights = normalisedWeights(this, inputs);
      report(0.0, "Checking the connectivity");
      vtkSurfaceMapsCombination::CheckSameConnectivity(inputs, "input");
      const surfacemaps::ProcrustesResult alignment =
        alignInputs(inputs, weights, this->AlignMode, report);
      report(0.9, "Averaging");
      vtkSurfaceMapsCombination::Combine(inputs, weights, alignment.transforms, 0, this, output);
      vtkSurfaceMapsCombination::AddAlignmentFields(
        output, alignment, this->AlignMode == ALIGN_SIMILARITY);
      vtkSurfaceMapsCombination::AddField(output, "AverageWeight", 1, weights);
      report(1.0, "Done");
      return 1;
    },
    [output] { output->Initialize(); });
}

void vtkSurfaceAverage::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "AlignMode: " << this->AlignMode << "\n";
  os << indent << "InputWeights:";
  this->Internals->Weights.Print(os, "(all 1)");
  os << "\n";
}
