/**
 * @class   vtkSurfaceMapsErrorGuard
 * @brief   The module's one rule for failed updates (private).
 *
 * Every algorithm of the module runs the body of its RequestData through
 * Run(), so no exception leaves RequestData:
 * - surfacemaps::Aborted (the user aborted) is not an error: the outputs are
 *   cleared, marked DATA_NOT_GENERATED when the policy names them, and Run
 *   returns 1.
 * - an engine error (surfacemaps::Error: bad input, or no certified result)
 *   and any other std::exception (an internal failure) are errors: the
 *   outputs are cleared and Fail() reports the message with the error code
 *   the policy gives that kind (surfacemaps::ErrorKind, decided by the engine
 *   where it throws, not by the exception's type); Run returns 0.
 * Other exception types pass through. What differs between filters (message
 * prefixes, codes) is data in the Policy, not code in the filter.
 *
 * A failure always leaves a non-zero error code on the algorithm and its
 * reason in LastErrorMessage(), which every public class of the module
 * returns from GetLastErrorMessage(); Run clears both when an update starts.
 * The reason lives in the algorithm's own information object, so that
 * vtkSurfaceMapsExecutive can read it from any algorithm of the module
 * upstream and knows when the algorithm reported a failure itself.
 */
#ifndef vtkSurfaceMapsErrorGuard_h
#define vtkSurfaceMapsErrorGuard_h

#include "vtkErrorCode.h"

#include <functional>
#include <string>

class vtkAlgorithm;
class vtkInformationIntegerKey;
class vtkInformationStringKey;
class vtkInformationVector;

class vtkSurfaceMapsErrorGuard
{
public:
  /// The module's error codes: vtkSurfaceMapFilter::ErrorCodes and
  /// vtkSurfaceMapTransfer::ErrorCodes have these values.
  static constexpr unsigned long InvalidInputError = vtkErrorCode::UserError + 1;
  static constexpr unsigned long NotCertifiedError = vtkErrorCode::UserError + 2;

  /// How one kind of exception is reported.
  struct Report
  {
    std::string Prefix;                                   ///< put before the exception's message
    unsigned long ErrorCode = vtkErrorCode::UnknownError; ///< the filter's error code afterwards
  };

  /// What a filter reports for each kind of exception.
  struct Policy
  {
    Report InputError{ "", InvalidInputError };    ///< surfacemaps::ErrorKind::Input
    Report NoResultError{ "", NotCertifiedError }; ///< surfacemaps::ErrorKind::NoResult
    Report OtherError;                             ///< any other std::exception: internal
    /// Outputs marked DATA_NOT_GENERATED after an abort: VTK 9.1 would mark
    /// the empty outputs up to date (the ABORTED key arrives in 9.3), so the
    /// next Update would not run. Null: not marked.
    vtkInformationVector* AbortedOutputs = nullptr;
  };

  /// The default codes, every kind reported as `prefix` + the exception's
  /// message.
  static Policy WithPrefix(const std::string& prefix);

  /// Runs `body` and returns its value; or, when it throws, clears the
  /// outputs with `clearOutputs` and applies `policy` for `self` as above.
  static int Run(vtkAlgorithm* self,
    const Policy& policy,
    const std::function<int()>& body,
    const std::function<void()>& clearOutputs);

  /// Reports a failure of `self`: sets its error code to `code` (non-zero),
  /// keeps `message` as its last error message and passes it to
  /// vtkErrorMacro. Returns 0, RequestData's value for a failure.
  static int Fail(vtkAlgorithm* self, unsigned long code, const std::string& message);

  /// The reason of `algorithm`'s last failure reported through Fail (or Run);
  /// "" when its last update succeeded or it is not one of the module's.
  static const char* LastErrorMessage(const vtkAlgorithm* algorithm);

  /// How many failures `algorithm` has reported through Fail so far: a
  /// change across a call means the call reported its failure itself.
  static int NumberOfReports(vtkAlgorithm* algorithm);

private:
  static vtkInformationStringKey* LAST_ERROR_MESSAGE();
  static vtkInformationIntegerKey* NUMBER_OF_REPORTS();
};

#endif
