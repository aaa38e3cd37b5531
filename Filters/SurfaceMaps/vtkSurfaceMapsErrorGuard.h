/**
 * @class   vtkSurfaceMapsErrorGuard
 * @brief   The module's one rule for exceptions in RequestData (private).
 *
 * Every filter of the module runs the body of its RequestData through Run(),
 * so no exception leaves RequestData:
 * - surfacemaps::Aborted (the user aborted) is not an error: the outputs are
 *   cleared, marked DATA_NOT_GENERATED when the policy names them, and Run
 *   returns 1.
 * - an engine error (surfacemaps::Error: bad input, or no certified result)
 *   and any other std::exception (an internal failure) are errors: the
 *   outputs are cleared, the filter's error code is set and its
 *   vtkErrorMacro reports the message as the policy says for that kind
 *   (surfacemaps::ErrorKind, decided by the engine where it throws, not by
 *   the exception's type), and Run returns 0.
 * Other exception types pass through. What differs between filters (error
 * codes, message prefixes) is data in the Policy, not code in the filter.
 */
#ifndef vtkSurfaceMapsErrorGuard_h
#define vtkSurfaceMapsErrorGuard_h

#include <functional>
#include <string>

class vtkAlgorithm;
class vtkInformationVector;

class vtkSurfaceMapsErrorGuard
{
public:
  /// A Report::ErrorCode that leaves the filter's error code as it is.
  static constexpr unsigned long KeepErrorCode = ~0ul;

  /// How one kind of exception is reported.
  struct Report
  {
    std::string Prefix;                      ///< put before the exception's message
    unsigned long ErrorCode = KeepErrorCode; ///< the filter's error code afterwards
  };

  /// What a filter reports for each kind of exception. The defaults report
  /// the exception's message as it is and leave the error code alone.
  struct Policy
  {
    Report InputError;    ///< surfacemaps::ErrorKind::Input
    Report NoResultError; ///< surfacemaps::ErrorKind::NoResult
    Report OtherError;    ///< any other std::exception: an internal failure
    /// Outputs marked DATA_NOT_GENERATED after an abort: VTK 9.1 would mark
    /// the empty outputs up to date (the ABORTED key arrives in 9.3), so the
    /// next Update would not run. Null: not marked.
    vtkInformationVector* AbortedOutputs = nullptr;
    /// Receives the reported message before it is reported (for a filter
    /// that keeps its last error). Empty: nothing receives it.
    std::function<void(const std::string&)> KeepMessage;
  };

  /// Every kind reported as `prefix` + the exception's message, error code
  /// left alone.
  static Policy MessageOnly(const std::string& prefix = std::string());

  /// Runs `body` and returns its value; or, when it throws, clears the
  /// outputs with `clearOutputs` and applies `policy` for `self` as above.
  static int Run(vtkAlgorithm* self,
    const Policy& policy,
    const std::function<int()>& body,
    const std::function<void()>& clearOutputs);
};

#endif
