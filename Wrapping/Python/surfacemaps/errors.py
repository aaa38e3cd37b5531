"""How the module's VTK algorithms report to Python: the package's exceptions and warning class, and
the update that turns an algorithm's error and warning events into them."""

import warnings

from vtkmodules.vtkCommonCore import vtkCommand


class InputError(ValueError):
    """A mesh or landmark file cannot be used; the message says why and where."""


class MapError(RuntimeError):
    """No certified bijective map was found (or the computation failed otherwise)."""


class SurfaceMapsWarning(UserWarning):
    """Valid but suspect input, e.g. landmarks that are the mirror image of the first mesh's."""


def _error_observer(algorithm):
    """Turn the algorithm's ErrorEvents into a list of messages (instead of VTK's output window).

    Returns the list and the observer's tag (for RemoveObserver)."""
    messages = []

    def on_error(obj, event, text=None):
        messages.append(text.split("): ", 1)[-1].strip() if text else "unknown error")

    on_error.CallDataType = "string0"
    return messages, algorithm.AddObserver(vtkCommand.ErrorEvent, on_error)


def _collect_errors(algorithm):
    """The algorithm's error messages from now on, as a list that fills as they come."""
    return _error_observer(algorithm)[0]


def _macro_text(text, default):
    """The message of a vtkErrorMacro/vtkWarningMacro text, without file, line and object."""
    return text.split("): ", 1)[-1].strip() if text else default


def _update(algorithm, errors=None):
    """algorithm.Update() with the error itself as the only message.

    When RequestData fails, VTK's executive adds its own error ("Algorithm ...
    returned failure for request: ..." and the whole request) through the
    output window; here it is observed for this update only and dropped when
    the algorithm reported why (its ErrorEvents fill `errors`), else appended
    to `errors` so that the caller raises it. The algorithm's warnings become
    Python warnings (SurfaceMapsWarning)."""
    executive = algorithm.GetExecutive()
    pipeline_errors = []

    def on_pipeline_error(obj, event, text=None):
        pipeline_errors.append(_macro_text(text, "pipeline error"))

    def on_warning(obj, event, text=None):
        warnings.warn(_macro_text(text, "unknown warning"), SurfaceMapsWarning, stacklevel=4)

    on_pipeline_error.CallDataType = "string0"
    on_warning.CallDataType = "string0"
    tags = [(executive, executive.AddObserver(vtkCommand.ErrorEvent, on_pipeline_error)),
            (algorithm, algorithm.AddObserver(vtkCommand.WarningEvent, on_warning))]
    try:
        algorithm.Update()
    finally:
        for obj, tag in tags:
            obj.RemoveObserver(tag)
    if errors is not None and not errors:
        errors.extend(pipeline_errors)
