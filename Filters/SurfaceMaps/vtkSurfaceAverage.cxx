#include "vtkSurfaceAverage.h"

#include "vtkSurfaceMapsCombination.h"
#include "vtkSurfaceMapsConversion.h"
#include "vtkSurfaceMapsErrorGuard.h"

#include "base/Aborted.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdList.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <Eigen/Dense>

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

using Similarity = vtkSurfaceMapsCombination::Similarity;

std::vector<Eigen::Vector3d> pointsOf(vtkPolyData* mesh)
{
  std::vector<Eigen::Vector3d> points(mesh->GetNumberOfPoints());
  for (vtkIdType v = 0; v < mesh->GetNumberOfPoints(); ++v)
  {
    mesh->GetPoint(v, points[v].data());
  }
  return points;
}

// A third of the area of the triangles around each vertex (polygons as fans),
// normalised to sum 1; uniform when the mesh has no area.
std::vector<double> vertexAreas(vtkPolyData* mesh, const std::vector<Eigen::Vector3d>& x)
{
  std::vector<double> area(x.size(), 0.0);
  double total = 0.0;
  if (vtkCellArray* polys = mesh->GetPolys())
  {
    vtkNew<vtkIdList> ids;
    for (vtkIdType c = 0; c < polys->GetNumberOfCells(); ++c)
    {
      polys->GetCellAtId(c, ids);
      for (vtkIdType k = 1; k + 1 < ids->GetNumberOfIds(); ++k)
      {
        const vtkIdType t[3] = { ids->GetId(0), ids->GetId(k), ids->GetId(k + 1) };
        const double a = 0.5 * (x[t[1]] - x[t[0]]).cross(x[t[2]] - x[t[0]]).norm();
        for (vtkIdType v : t)
        {
          area[v] += a / 3.0;
        }
        total += a;
      }
    }
  }
  if (!(total > 0.0) || !std::isfinite(total))
  {
    return std::vector<double>(x.size(), x.empty() ? 0.0 : 1.0 / x.size());
  }
  for (double& a : area)
  {
    a /= total;
  }
  return area;
}

// The similarity (Umeyama 1991) minimising sum_v w_v |s R x_v + t - y_v|^2,
// det R = +1; s = 1 unless `withScale`. Weights sum to 1.
Similarity fitSimilarity(const std::vector<Eigen::Vector3d>& x,
  const std::vector<Eigen::Vector3d>& y,
  const std::vector<double>& w,
  bool withScale)
{
  Eigen::Vector3d mx = Eigen::Vector3d::Zero(), my = Eigen::Vector3d::Zero();
  for (std::size_t v = 0; v < x.size(); ++v)
  {
    mx += w[v] * x[v];
    my += w[v] * y[v];
  }
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  double varianceX = 0.0;
  for (std::size_t v = 0; v < x.size(); ++v)
  {
    const Eigen::Vector3d dx = x[v] - mx;
    covariance += w[v] * (y[v] - my) * dx.transpose();
    varianceX += w[v] * dx.squaredNorm();
  }
  Eigen::JacobiSVD<Eigen::Matrix3d> svd(covariance, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Vector3d sign(1.0, 1.0, 1.0);
  if (svd.matrixU().determinant() * svd.matrixV().determinant() < 0.0)
  {
    sign(2) = -1.0; // no reflection: flip the direction of the smallest singular value
  }
  Similarity s;
  s.Rotation = svd.matrixU() * sign.asDiagonal() * svd.matrixV().transpose();
  if (withScale && varianceX > 0.0)
  {
    s.Scale = svd.singularValues().dot(sign) / varianceX;
  }
  s.Translation = my - s.Scale * s.Rotation * mx;
  return s;
}

double weightedRms(const std::vector<Eigen::Vector3d>& x,
  const std::vector<Eigen::Vector3d>& y,
  const std::vector<double>& w,
  const Similarity& s)
{
  double sum = 0.0;
  for (std::size_t v = 0; v < x.size(); ++v)
  {
    sum += w[v] * (s.Scale * (s.Rotation * x[v]) + s.Translation - y[v]).squaredNorm();
  }
  return std::sqrt(sum);
}

void addField(vtkPolyData* output,
  const char* name,
  int components,
  const std::vector<double>& values)
{
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(static_cast<vtkIdType>(values.size()) / components);
  for (std::size_t k = 0; k < values.size(); ++k)
  {
    array->SetValue(static_cast<vtkIdType>(k), values[k]);
  }
  output->GetFieldData()->AddArray(array);
}

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

// The transform of every input onto input 0 (identity for input 0 and
// without alignment) and the area-weighted RMS distance it leaves.
struct Alignment
{
  std::vector<Similarity> Transforms;
  std::vector<double> RMS;
};

template<typename Report>
Alignment alignOntoFirst(const std::vector<vtkPolyData*>& inputs, int alignMode, Report& report)
{
  const int n = static_cast<int>(inputs.size());
  const std::vector<Eigen::Vector3d> reference = pointsOf(inputs[0]);
  const std::vector<double> areas = vertexAreas(inputs[0], reference);
  Alignment alignment{ std::vector<Similarity>(n), std::vector<double>(n, 0.0) };
  for (int i = 1; i < n; ++i)
  {
    report(static_cast<double>(i) / n, "Aligning the inputs");
    const std::vector<Eigen::Vector3d> x = pointsOf(inputs[i]);
    if (alignMode != vtkSurfaceAverage::ALIGN_NONE)
    {
      alignment.Transforms[i] =
        fitSimilarity(x, reference, areas, alignMode == vtkSurfaceAverage::ALIGN_SIMILARITY);
    }
    alignment.RMS[i] = weightedRms(x, reference, areas, alignment.Transforms[i]);
  }
  return alignment;
}

// The alignment and the weights as field data.
void addAlignmentFields(vtkPolyData* output,
  const Alignment& alignment,
  const std::vector<double>& weights,
  bool withScale)
{
  std::vector<double> matrices, scales;
  for (const Similarity& s : alignment.Transforms)
  {
    for (int r = 0; r < 3; ++r)
    {
      for (int c = 0; c < 3; ++c)
      {
        matrices.push_back(s.Scale * s.Rotation(r, c));
      }
      matrices.push_back(s.Translation(r));
    }
    scales.push_back(s.Scale);
  }
  addField(output, "AlignmentRMS", 1, alignment.RMS);
  addField(output, "AlignmentTransform", 12, matrices);
  addField(output, "AverageWeight", 1, weights);
  if (withScale)
  {
    addField(output, "AlignmentScale", 1, scales);
  }
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
  const int n = static_cast<int>(inputs.size());
  auto report = [this](double fraction, const char* text)
  {
    this->SetProgressText(text);
    this->UpdateProgress(fraction);
    if (this->GetAbortExecute())
    {
      throw surfacemaps::Aborted();
    }
  };

  vtkSurfaceMapsErrorGuard::Policy policy = vtkSurfaceMapsErrorGuard::MessageOnly();
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
      const Alignment alignment = alignOntoFirst(inputs, this->AlignMode, report);
      report(static_cast<double>(n) / (n + 1), "Averaging");
      vtkSurfaceMapsCombination::Combine(inputs, weights, alignment.Transforms, 0, this, output);
      addAlignmentFields(output, alignment, weights, this->AlignMode == ALIGN_SIMILARITY);
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
