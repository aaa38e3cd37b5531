#include "vtkSurfaceMapsErrorGuard.h"

#include "base/Aborted.h"
#include "base/Error.h"

#include "vtkAlgorithm.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"

#include <exception>
#include <stdexcept>

namespace
{

// vtkAlgorithm::SetErrorCode is protected. A class derived from vtkAlgorithm
// may take its address, and the member pointer applies to any algorithm.
struct ErrorCodeAccess : public vtkAlgorithm
{
  static void Set(vtkAlgorithm* algorithm, unsigned long code)
  {
    (algorithm->*&ErrorCodeAccess::SetErrorCode)(code);
  }
};

int fail(vtkAlgorithm* self,
  const vtkSurfaceMapsErrorGuard::Policy& policy,
  const vtkSurfaceMapsErrorGuard::Report& report,
  const std::exception& e,
  const std::function<void()>& clearOutputs)
{
  const std::string message = report.Prefix + e.what();
  if (policy.KeepMessage)
  {
    policy.KeepMessage(message);
  }
  clearOutputs();
  if (report.ErrorCode != vtkSurfaceMapsErrorGuard::KeepErrorCode)
  {
    ErrorCodeAccess::Set(self, report.ErrorCode);
  }
  vtkErrorWithObjectMacro(self, << message);
  return 0;
}

} // namespace

vtkSurfaceMapsErrorGuard::Policy vtkSurfaceMapsErrorGuard::MessageOnly(const std::string& prefix)
{
  Policy policy;
  policy.InputError.Prefix = prefix;
  policy.NoResultError.Prefix = prefix;
  policy.OtherError.Prefix = prefix;
  return policy;
}

int vtkSurfaceMapsErrorGuard::Run(vtkAlgorithm* self,
  const Policy& policy,
  const std::function<int()>& body,
  const std::function<void()>& clearOutputs)
{
  try
  {
    return body();
  }
  catch (const surfacemaps::Aborted&)
  {
    clearOutputs();
    if (vtkInformationVector* outputs = policy.AbortedOutputs)
    {
      for (int i = 0; i < outputs->GetNumberOfInformationObjects(); ++i)
      {
        outputs->GetInformationObject(i)->Set(vtkDemandDrivenPipeline::DATA_NOT_GENERATED(), 1);
      }
    }
    return 1;
  }
  catch (const surfacemaps::Error& e)
  {
    const Report& report =
      e.kind() == surfacemaps::ErrorKind::Input ? policy.InputError : policy.NoResultError;
    return fail(self, policy, report, e, clearOutputs);
  }
  catch (const std::exception& e)
  {
    return fail(self, policy, policy.OtherError, e, clearOutputs);
  }
}
