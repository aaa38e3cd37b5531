#include "vtkSurfaceShapeStatistics.h"

#include "vtkSurfaceMapsCombination.h"
#include "vtkSurfaceMapsConversion.h"
#include "vtkSurfaceMapsErrorGuard.h"
#include "vtkSurfaceMapsExecutive.h"

#include "base/Aborted.h"
#include "statistics/Procrustes.h"
#include "statistics/ShapeModes.h"

#include "vtkDoubleArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <stdexcept>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkSurfaceShapeStatistics);

namespace
{

vtkSmartPointer<vtkDoubleArray> pointArray(const char* name, int components, vtkIdType tuples)
{
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(tuples);
  return array;
}

// The output: input 0's cells at `points`, the spread and the modes as point
// data, the PCA's figures as field data.
void fillOutput(vtkPolyData* first,
  const surfacemaps::ShapePoints& points,
  const surfacemaps::ShapeModesResult& statistics,
  vtkPolyData* output)
{
  const vtkIdType np = static_cast<vtkIdType>(points.size());
  vtkNew<vtkPoints> xyz;
  xyz->SetDataTypeToDouble();
  xyz->SetNumberOfPoints(np);
  for (vtkIdType v = 0; v < np; ++v)
  {
    xyz->SetPoint(v, points[v].data());
  }
  output->CopyStructure(first);
  output->SetPoints(xyz);

  auto spread = pointArray("StandardDeviation", 1, np);
  for (vtkIdType v = 0; v < np; ++v)
  {
    spread->SetValue(v, statistics.standardDeviation[v]);
  }
  output->GetPointData()->AddArray(spread);
  output->GetPointData()->SetActiveScalars("StandardDeviation");
  const int k = static_cast<int>(statistics.modes.size());
  for (int m = 0; m < k; ++m)
  {
    auto mode = pointArray(("Mode_" + std::to_string(m + 1)).c_str(), 3, np);
    for (vtkIdType v = 0; v < np; ++v)
    {
      mode->SetTuple(v, statistics.modes[m][v].data());
    }
    output->GetPointData()->AddArray(mode);
  }

  const int n = static_cast<int>(statistics.scores.rows());
  std::vector<double> scores;
  for (int i = 0; i < n; ++i)
  {
    for (int m = 0; m < k; ++m)
    {
      scores.push_back(statistics.scores(i, m));
    }
  }
  vtkSurfaceMapsCombination::AddField(output, "Variance", 1, statistics.variances);
  vtkSurfaceMapsCombination::AddField(
    output, "ExplainedVarianceFraction", 1, statistics.explainedFractions);
  vtkSurfaceMapsCombination::AddField(output, "TotalVariance", 1, { statistics.totalVariance });
  if (k > 0)
  {
    vtkSurfaceMapsCombination::AddField(output, "Scores", k, scores);
  }
}

} // namespace

vtkSurfaceShapeStatistics::vtkSurfaceShapeStatistics()
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(1);
}

vtkSurfaceShapeStatistics::~vtkSurfaceShapeStatistics() = default;

int vtkSurfaceShapeStatistics::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  info->Set(vtkAlgorithm::INPUT_IS_REPEATABLE(), 1);
  return 1;
}

int vtkSurfaceShapeStatistics::RequestData(vtkInformation*,
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
      if (inputs.size() < 2)
      {
        throw std::invalid_argument("shape statistics need at least 2 inputs, not " +
          std::to_string(inputs.size()));
      }
      report(0.0, "Checking the connectivity");
      vtkSurfaceMapsCombination::CheckSameConnectivity(inputs, "input");

      std::vector<surfacemaps::ShapePoints> shapes;
      for (vtkPolyData* input : inputs)
      {
        shapes.push_back(vtkSurfaceMapsCombination::Points(input));
      }
      surfacemaps::ProcrustesOptions options;
      options.kind = vtkSurfaceMapsCombination::AlignmentOf(this->AlignMode);
      options.progress = [&report](double fraction)
      { report(0.8 * fraction, "Aligning the inputs"); };
      const surfacemaps::ProcrustesResult alignment = surfacemaps::alignProcrustes(shapes,
        std::vector<double>(shapes.size(), 1.0),
        vtkSurfaceMapsCombination::Triangles(inputs[0]),
        options);
      for (std::size_t i = 0; i < shapes.size(); ++i)
      {
        for (Eigen::Vector3d& x : shapes[i])
        {
          x = alignment.transforms[i].apply(x);
        }
      }

      report(0.8, "Principal modes");
      surfacemaps::ShapeModesOptions pca;
      pca.modes = this->NumberOfModes;
      const surfacemaps::ShapeModesResult statistics =
        surfacemaps::principalModes(shapes, alignment.vertexWeights, pca);
      const int k = static_cast<int>(statistics.modes.size());
      if (this->Mode > k)
      {
        throw std::invalid_argument("Mode " + std::to_string(this->Mode) +
          " is not computed: there are " + std::to_string(k) + " modes (NumberOfModes " +
          std::to_string(this->NumberOfModes) + ", at most N - 1 = " +
          std::to_string(inputs.size() - 1) + " for " + std::to_string(inputs.size()) +
          " inputs)");
      }
      fillOutput(inputs[0],
        surfacemaps::shapeAlongMode(statistics, this->Mode - 1, this->Coefficient),
        statistics,
        output);
      vtkSurfaceMapsCombination::AddAlignmentFields(
        output, alignment, this->AlignMode == ALIGN_SIMILARITY);
      report(1.0, "Done");
      return 1;
    },
    [output] { output->Initialize(); });
}

const char* vtkSurfaceShapeStatistics::GetLastErrorMessage() const
{
  return vtkSurfaceMapsErrorGuard::LastErrorMessage(this);
}

vtkExecutive* vtkSurfaceShapeStatistics::CreateDefaultExecutive()
{
  return vtkSurfaceMapsExecutive::New();
}

void vtkSurfaceShapeStatistics::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "AlignMode: " << this->AlignMode << "\n";
  os << indent << "NumberOfModes: " << this->NumberOfModes << "\n";
  os << indent << "Mode: " << this->Mode << "\n";
  os << indent << "Coefficient: " << this->Coefficient << "\n";
}
