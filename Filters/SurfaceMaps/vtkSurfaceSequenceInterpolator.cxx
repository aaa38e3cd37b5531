#include "vtkSurfaceSequenceInterpolator.h"

#include "vtkSurfaceMapsCombination.h"
#include "vtkSurfaceMapsConversion.h"
#include "vtkSurfaceMapsErrorGuard.h"

#include "base/Aborted.h"
#include "statistics/Procrustes.h"
#include "statistics/RotationBlend.h"

#include "vtkDataObject.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkSurfaceSequenceInterpolator);

struct vtkSurfaceSequenceInterpolator::vtkInternals
{
  vtkSurfaceMapsCombination::IndexedValues Times; // explicitly set times; t_k = k elsewhere

  // The keyframes' alignment and rotation blend depend on the keyframes and
  // the two settings only, not on the time: an animation reuses them.
  std::vector<std::pair<vtkPolyData*, vtkMTimeType>> PreparedFor;
  int PreparedAlignment = -1;
  int PreparedBlending = -1;
  surfacemaps::ProcrustesResult Alignment;
  std::unique_ptr<surfacemaps::RotationBlend> Blend; // null with BLEND_VERTICES

  // Alignment and Blend for these keyframes and settings, unless held.
  void Prepare(const std::vector<vtkPolyData*>& inputs, int alignment, int blending);
};

namespace
{

// The tangent (time derivative) at keyframe k as a combination of keyframes:
// the derivative of the parabola through three neighbouring keyframes (the
// secant with two keyframes).
std::vector<std::pair<int, double>> tangent(const std::vector<double>& t, int k)
{
  const int n = static_cast<int>(t.size());
  if (n == 2)
  {
    const double h = t[1] - t[0];
    return { { 0, -1.0 / h }, { 1, 1.0 / h } };
  }
  // d_j = (x_{j+1} - x_j) / h_j; the parabola through j-1, j, j+1 has the
  // derivative (a d_j + b d_{j-1}) / (a + b) at j (a = h_{j-1}, b = h_j),
  // (2a + b) d_0 / (a + b) - a d_1 / (a + b) at the first keyframe and the
  // mirror image at the last.
  if (k == 0)
  {
    const double a = t[1] - t[0], b = t[2] - t[1];
    const double f = (2.0 * a + b) / ((a + b) * a), g = a / ((a + b) * b);
    return { { 0, -f }, { 1, f + g }, { 2, -g } };
  }
  if (k == n - 1)
  {
    const double a = t[n - 2] - t[n - 3], b = t[n - 1] - t[n - 2];
    const double f = (2.0 * b + a) / ((a + b) * b), g = b / ((a + b) * a);
    return { { n - 1, f }, { n - 2, -f - g }, { n - 3, g } };
  }
  const double a = t[k] - t[k - 1], b = t[k + 1] - t[k];
  const double f = a / ((a + b) * b), g = b / ((a + b) * a);
  return { { k + 1, f }, { k, g - f }, { k - 1, -g } };
}

// Coefficients of the keyframes in the interpolated surface at `time`
// (within [t_0, t_{K-1}]): exactly one 1 and zeros at a keyframe time.
std::vector<double> coefficients(const std::vector<double>& t, double time, bool smooth)
{
  const int n = static_cast<int>(t.size());
  std::vector<double> c(n, 0.0);
  if (n == 1)
  {
    c[0] = 1.0;
    return c;
  }
  // Interval [t_k, t_{k+1}] with t_k <= time < t_{k+1} (the last one at t_{K-1}).
  int k = static_cast<int>(std::upper_bound(t.begin(), t.end(), time) - t.begin()) - 1;
  k = std::max(0, std::min(k, n - 2));
  const double h = t[k + 1] - t[k];
  const double u = (time - t[k]) / h;
  if (!smooth)
  {
    c[k] = 1.0 - u;
    c[k + 1] = u;
    return c;
  }
  const double u2 = u * u, u3 = u2 * u;
  c[k] += 2.0 * u3 - 3.0 * u2 + 1.0;
  c[k + 1] += -2.0 * u3 + 3.0 * u2;
  const double h10 = h * (u3 - 2.0 * u2 + u), h11 = h * (u3 - u2);
  for (const auto& [j, a] : tangent(t, k))
  {
    c[j] += h10 * a;
  }
  for (const auto& [j, a] : tangent(t, k + 1))
  {
    c[j] += h11 * a;
  }
  return c;
}

} // namespace

vtkSurfaceSequenceInterpolator::vtkSurfaceSequenceInterpolator()
  : Internals(new vtkInternals)
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(1);
}

vtkSurfaceSequenceInterpolator::~vtkSurfaceSequenceInterpolator() = default;

void vtkSurfaceSequenceInterpolator::SetKeyframeTime(int k, double time)
{
  if (k < 0)
  {
    vtkErrorMacro(<< "keyframe index " << k << " is negative");
    return;
  }
  if (this->Internals->Times.Set(k, time))
  {
    this->Modified();
  }
}

double vtkSurfaceSequenceInterpolator::GetKeyframeTime(int k)
{
  return this->Internals->Times.Get(k, static_cast<double>(k));
}

void vtkSurfaceSequenceInterpolator::RemoveAllKeyframeTimes()
{
  if (this->Internals->Times.Clear())
  {
    this->Modified();
  }
}

int vtkSurfaceSequenceInterpolator::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  info->Set(vtkAlgorithm::INPUT_IS_REPEATABLE(), 1);
  return 1;
}

namespace
{
// The times of the n keyframes; throws std::invalid_argument unless finite
// and strictly increasing.
std::vector<double> keyframeTimes(vtkSurfaceSequenceInterpolator* self, int n)
{
  std::vector<double> t(n);
  for (int k = 0; k < n; ++k)
  {
    t[k] = self->GetKeyframeTime(k);
    std::ostringstream text;
    if (!std::isfinite(t[k]))
    {
      text << "the time of keyframe " << k << " is " << t[k];
      throw std::invalid_argument(text.str());
    }
    if (k > 0 && !(t[k] > t[k - 1]))
    {
      text << "the time of keyframe " << k << " (" << t[k]
           << ") is not larger than that of keyframe " << k - 1 << " (" << t[k - 1]
           << "): keyframe times must be strictly increasing";
      throw std::invalid_argument(text.str());
    }
  }
  return t;
}

// The keyframe nearest to `time` (the earlier one at a midpoint): where
// categorical arrays come from.
int nearestKeyframe(const std::vector<double>& t, double time)
{
  int nearest = 0;
  for (int k = 1; k < static_cast<int>(t.size()); ++k)
  {
    if (std::abs(t[k] - time) < std::abs(t[nearest] - time))
    {
      nearest = k;
    }
  }
  return nearest;
}

} // namespace

// The alignment of the keyframes and, with BLEND_ROTATIONS, the blend of the
// aligned keyframes.
void vtkSurfaceSequenceInterpolator::vtkInternals::Prepare(const std::vector<vtkPolyData*>& inputs,
  int alignment,
  int blending)
{
  std::vector<std::pair<vtkPolyData*, vtkMTimeType>> key;
  for (vtkPolyData* input : inputs)
  {
    key.emplace_back(input, input->GetMTime());
  }
  if (key == this->PreparedFor && alignment == this->PreparedAlignment &&
    blending == this->PreparedBlending)
  {
    return;
  }
  this->PreparedFor.clear(); // nothing valid should this throw
  std::vector<surfacemaps::ShapePoints> shapes;
  for (vtkPolyData* input : inputs)
  {
    shapes.push_back(vtkSurfaceMapsCombination::Points(input));
  }
  const std::vector<std::array<int, 3>> triangles = vtkSurfaceMapsCombination::Triangles(inputs[0]);
  surfacemaps::ProcrustesOptions options;
  options.kind = vtkSurfaceMapsCombination::AlignmentOf(alignment);
  this->Alignment = surfacemaps::alignProcrustes(
    shapes, std::vector<double>(shapes.size(), 1.0), triangles, options);
  this->Blend.reset();
  if (blending == vtkSurfaceSequenceInterpolator::BLEND_ROTATIONS)
  {
    for (std::size_t k = 0; k < shapes.size(); ++k)
    {
      for (Eigen::Vector3d& p : shapes[k])
      {
        p = this->Alignment.transforms[k].apply(p);
      }
    }
    this->Blend = std::make_unique<surfacemaps::RotationBlend>(shapes, triangles);
  }
  this->PreparedFor = std::move(key);
  this->PreparedAlignment = alignment;
  this->PreparedBlending = blending;
}

namespace
{
// The requested time clamped into the keyframe range (the first keyframe's
// time when none is requested).
double clampedTime(const std::vector<double>& t, double requested)
{
  return std::isnan(requested) ? t.front() : std::max(t.front(), std::min(requested, t.back()));
}
} // namespace

int vtkSurfaceSequenceInterpolator::RequestInformation(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  outInfo->Remove(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
  outInfo->Remove(vtkStreamingDemandDrivenPipeline::TIME_RANGE());
  const int n = inputVector[0]->GetNumberOfInformationObjects();
  std::vector<double> t;
  try
  {
    t = keyframeTimes(this, n);
  }
  catch (const std::invalid_argument&)
  {
    return 1; // RequestData reports it and leaves the output empty
  }
  if (t.empty())
  {
    return 1;
  }
  std::vector<double> steps;
  for (int k = 0; k + 1 < n; ++k)
  {
    for (int j = 0; j < this->StepsPerInterval; ++j)
    {
      steps.push_back(t[k] + (t[k + 1] - t[k]) * j / this->StepsPerInterval);
    }
  }
  steps.push_back(t.back());
  outInfo->Set(
    vtkStreamingDemandDrivenPipeline::TIME_STEPS(), steps.data(), static_cast<int>(steps.size()));
  const double range[2] = { t.front(), t.back() };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
  return 1;
}

int vtkSurfaceSequenceInterpolator::RequestUpdateExtent(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector*)
{
  // The keyframes are static surfaces: our time is not theirs.
  for (int k = 0; k < inputVector[0]->GetNumberOfInformationObjects(); ++k)
  {
    inputVector[0]->GetInformationObject(k)->Remove(
      vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
  }
  return 1;
}

int vtkSurfaceSequenceInterpolator::RequestData(vtkInformation*,
  vtkInformationVector** inputVector,
  vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  output->Initialize();
  output->GetInformation()->Remove(vtkDataObject::DATA_TIME_STEP());
  const std::vector<vtkPolyData*> inputs = vtkSurfaceMapsConversion::PolyDataOf(inputVector[0]);
  const int n = static_cast<int>(inputs.size());
  const double requested = outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP())
    ? outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP())
    : this->TimeValue;

  vtkSurfaceMapsErrorGuard::Policy policy;
  policy.AbortedOutputs = outputVector;
  return vtkSurfaceMapsErrorGuard::Run(
    this,
    policy,
    [&]
    {
      vtkSurfaceMapsCombination::CheckPresent(inputs, "keyframe");
      const std::vector<double> t = keyframeTimes(this, n);
      this->SetProgressText("Interpolating");
      this->UpdateProgress(0.0);
      vtkSurfaceMapsCombination::CheckSameConnectivity(inputs, "keyframe");
      if (this->GetAbortExecute())
      {
        throw surfacemaps::Aborted();
      }

      const double time = clampedTime(t, requested);
      const std::vector<double> c =
        coefficients(t, time, this->InterpolationMode == INTERPOLATE_SMOOTH);
      this->Internals->Prepare(inputs, this->KeyframeAlignment, this->ShapeBlending);
      const surfacemaps::ProcrustesResult& alignment = this->Internals->Alignment;
      vtkSurfaceMapsCombination::Combine(
        inputs, c, alignment.transforms, nearestKeyframe(t, time), this, output);
      if (this->Internals->Blend)
      {
        const surfacemaps::ShapePoints x = this->Internals->Blend->blend(c);
        for (vtkIdType v = 0; v < static_cast<vtkIdType>(x.size()); ++v)
        {
          output->GetPoints()->SetPoint(v, x[v].data());
        }
      }
      if (this->KeyframeAlignment != ALIGN_NONE)
      {
        vtkSurfaceMapsCombination::AddAlignmentFields(
          output, alignment, this->KeyframeAlignment == ALIGN_SIMILARITY);
      }
      auto interpolated = vtkSmartPointer<vtkDoubleArray>::New();
      interpolated->SetName("InterpolationTime");
      interpolated->InsertNextValue(time);
      output->GetFieldData()->AddArray(interpolated);
      output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), requested);
      this->UpdateProgress(1.0);
      return 1;
    },
    [output] { output->Initialize(); });
}

void vtkSurfaceSequenceInterpolator::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "InterpolationMode: " << this->InterpolationMode << "\n";
  os << indent << "KeyframeAlignment: " << this->KeyframeAlignment << "\n";
  os << indent << "ShapeBlending: " << this->ShapeBlending << "\n";
  os << indent << "StepsPerInterval: " << this->StepsPerInterval << "\n";
  os << indent << "TimeValue: " << this->TimeValue << "\n";
  os << indent << "KeyframeTimes:";
  this->Internals->Times.Print(os, "(t_k = k)");
  os << "\n";
}
