/**
 * @class   vtkSurfaceMapsExecutive
 * @brief   The executive of the module's algorithms (private): failures a pipeline can see.
 *
 * vtkCompositeDataPipeline (VTK's default executive), with two differences:
 * - When an input's producer fails (a reader whose file is missing, any
 *   upstream algorithm that returns failure), VTK never calls the
 *   algorithm's RequestData, so the algorithm would keep its error code 0
 *   and the previous update's outputs. Here the outputs are cleared and the
 *   algorithm reports the failure itself (vtkSurfaceMapsErrorGuard::Fail,
 *   InvalidInputError) naming the input and what failed upstream.
 * - A request the algorithm failed and reported itself (its message is in
 *   its GetLastErrorMessage()) is not followed by VTK's dump of the request:
 *   one message per failure.
 *
 * Every algorithm of the module creates this executive by default; an
 * application that sets another executive (ParaView does) keeps VTK's
 * behaviour for upstream failures, and the algorithm's own errors still set
 * its error code and message.
 */
#ifndef vtkSurfaceMapsExecutive_h
#define vtkSurfaceMapsExecutive_h

#include "vtkCompositeDataPipeline.h"

class vtkSurfaceMapsExecutive : public vtkCompositeDataPipeline
{
public:
  static vtkSurfaceMapsExecutive* New();
  vtkTypeMacro(vtkSurfaceMapsExecutive, vtkCompositeDataPipeline);

protected:
  vtkSurfaceMapsExecutive() = default;
  ~vtkSurfaceMapsExecutive() override = default;

  using vtkCompositeDataPipeline::ForwardUpstream;
  int ForwardUpstream(vtkInformation* request) override;
  int CallAlgorithm(vtkInformation* request,
    int direction,
    vtkInformationVector** inInfo,
    vtkInformationVector* outInfo) override;

private:
  vtkSurfaceMapsExecutive(const vtkSurfaceMapsExecutive&) = delete;
  void operator=(const vtkSurfaceMapsExecutive&) = delete;
};

#endif
