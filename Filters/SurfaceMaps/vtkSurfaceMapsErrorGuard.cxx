#include "vtkSurfaceMapsErrorGuard.h"

#include "base/Aborted.h"
#include "base/Error.h"

#include "vtkAlgorithm.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkInformation.h"
#include "vtkInformationIntegerKey.h"
#include "vtkInformationStringKey.h"
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
  const vtkSurfaceMapsErrorGuard::Report& report,
  const std::exception& e,
  const std::function<void()>& clearOutputs)
{
  clearOutputs();
  return vtkSurfaceMapsErrorGuard::Fail(self, report.ErrorCode, report.Prefix + e.what());
}

} // namespace

vtkInformationKeyMacro(vtkSurfaceMapsErrorGuard, LAST_ERROR_MESSAGE, String);
vtkInformationKeyMacro(vtkSurfaceMapsErrorGuard, NUMBER_OF_REPORTS, Integer);

vtkSurfaceMapsErrorGuard::Policy vtkSurfaceMapsErrorGuard::WithPrefix(const std::string& prefix)
{
  Policy policy;
  policy.InputError.Prefix = prefix;
  policy.NoResultError.Prefix = prefix;
  policy.OtherError.Prefix = prefix;
  return policy;
}

int vtkSurfaceMapsErrorGuard::Fail(vtkAlgorithm* self,
  unsigned long code,
  const std::string& message)
{
  vtkInformation* info = self->GetInformation();
  info->Set(LAST_ERROR_MESSAGE(), message.c_str());
  info->Set(NUMBER_OF_REPORTS(), NumberOfReports(self) + 1);
  ErrorCodeAccess::Set(self, code == vtkErrorCode::NoError ? vtkErrorCode::UnknownError : code);
  vtkErrorWithObjectMacro(self, << message);
  return 0;
}

const char* vtkSurfaceMapsErrorGuard::LastErrorMessage(const vtkAlgorithm* algorithm)
{
  // vtkAlgorithm::GetInformation is not const; reading does not change it.
  vtkInformation* info =
    algorithm ? const_cast<vtkAlgorithm*>(algorithm)->GetInformation() : nullptr;
  const char* message = info ? info->Get(LAST_ERROR_MESSAGE()) : nullptr;
  return message ? message : "";
}

int vtkSurfaceMapsErrorGuard::NumberOfReports(vtkAlgorithm* algorithm)
{
  vtkInformation* info = algorithm->GetInformation();
  return info->Has(NUMBER_OF_REPORTS()) ? info->Get(NUMBER_OF_REPORTS()) : 0;
}

int vtkSurfaceMapsErrorGuard::Run(vtkAlgorithm* self,
  const Policy& policy,
  const std::function<int()>& body,
  const std::function<void()>& clearOutputs)
{
  ErrorCodeAccess::Set(self, vtkErrorCode::NoError);
  self->GetInformation()->Remove(LAST_ERROR_MESSAGE());
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
    return fail(self, report, e, clearOutputs);
  }
  catch (const std::exception& e)
  {
    return fail(self, policy.OtherError, e, clearOutputs);
  }
}
