// Writes a ParaView state file (.pvsm) of a SurfaceMaps pipeline on the
// bundled meshes, for the README's screenshot: ParaView's GUI opens it with
// the plugin loaded (`paraview --state=FILE`; see .ci/paraview-screenshot.sh).
// Built in the plugin build; writing the state through the server manager
// keeps the file valid for this ParaView, which a hand-written one would not
// be. Needs a display (the render view is created); paths in the state are
// relative to the working directory, so run it from the repository's root.
//
// Usage: WriteSurfaceMapsState PLUGIN_FILE OUTPUT.pvsm
//
// The pipeline: two meshes with corresponding landmarks (ellipsoid, blob) ->
// Surface Map -> Surface Average and Surface Sequence Interpolator; Surface
// Map Evaluation of the blob against the ellipsoid (per-triangle stretch).
// Shown side by side: the inputs in the back row; the evaluation, the average
// and the interpolator at t = 0.5 (half-way from the ellipsoid to the blob)
// with T's edges in the front row.
#include "vtkDataObject.h"
#include "vtkInitializationHelper.h"
#include "vtkNew.h"
#include "vtkProcessModule.h"
#include "vtkSMPVRepresentationProxy.h"
#include "vtkSMParaViewPipelineControllerWithRendering.h"
#include "vtkSMPluginManager.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMProxyManager.h"
#include "vtkSMRenderViewProxy.h"
#include "vtkSMSession.h"
#include "vtkSMSessionProxyManager.h"
#include "vtkSMSourceProxy.h"
#include "vtkSMViewProxy.h"
#include "vtkSmartPointer.h"

#include <iostream>
#include <stdexcept>
#include <string>

namespace
{
struct Scene
{
  vtkSMSessionProxyManager* Manager;
  vtkSMParaViewPipelineControllerWithRendering* Controller;
  vtkSMRenderViewProxy* View;

  vtkSmartPointer<vtkSMSourceProxy> New(const char* group, const char* name)
  {
    vtkSmartPointer<vtkSMSourceProxy> proxy;
    proxy.TakeReference(vtkSMSourceProxy::SafeDownCast(this->Manager->NewProxy(group, name)));
    if (!proxy)
    {
      throw std::runtime_error(std::string("no proxy ") + group + "/" + name);
    }
    this->Controller->PreInitializeProxy(proxy);
    return proxy;
  }

  void Register(vtkSMSourceProxy* proxy, const char* label)
  {
    proxy->UpdateVTKObjects();
    this->Controller->PostInitializeProxy(proxy);
    this->Controller->RegisterPipelineProxy(proxy, label);
  }

  // Shows `proxy` at `position`; colours by the cell array `cells` when
  // given; `edges` draws the triangles.
  void Show(vtkSMSourceProxy* proxy, double x, double y, const char* cells, bool edges)
  {
    vtkSMProxy* representation = this->Controller->Show(proxy, 0, this->View);
    const double position[3] = { x, y, 0.0 };
    vtkSMPropertyHelper(representation, "Position").Set(position, 3);
    vtkSMPropertyHelper(representation, "Representation")
      .Set(edges ? "Surface With Edges" : "Surface");
    if (cells)
    {
      vtkSMPVRepresentationProxy::SetScalarColoring(representation, cells, vtkDataObject::CELL);
      vtkSMPVRepresentationProxy::RescaleTransferFunctionToDataRange(representation, false);
      vtkSMPVRepresentationProxy::SetScalarBarVisibility(representation, this->View, true);
    }
    else
    {
      vtkSMPVRepresentationProxy::SetScalarColoring(representation, nullptr, 0);
    }
    representation->UpdateVTKObjects();
  }
};

// The proxies of the pipeline (see the top of the file).
struct Pipeline
{
  vtkSmartPointer<vtkSMSourceProxy> Readers[2];
  vtkSmartPointer<vtkSMSourceProxy> Map;
  vtkSmartPointer<vtkSMSourceProxy> Average;
  vtkSmartPointer<vtkSMSourceProxy> Sequence;
  vtkSmartPointer<vtkSMSourceProxy> Evaluation;
};

// The render view, registered and assigned to a layout: the GUI shows the
// views of the state's layouts only.
vtkSmartPointer<vtkSMProxy> newRenderView(vtkSMSessionProxyManager* manager,
  vtkSMParaViewPipelineControllerWithRendering* controller)
{
  vtkSmartPointer<vtkSMProxy> viewProxy;
  viewProxy.TakeReference(manager->NewProxy("views", "RenderView"));
  controller->InitializeProxy(viewProxy);
  controller->RegisterViewProxy(viewProxy, "RenderView1");
  controller->AssignViewToLayout(vtkSMViewProxy::SafeDownCast(viewProxy));
  return viewProxy;
}

Pipeline buildPipeline(Scene& scene)
{
  Pipeline pipeline;
  const char* files[2] = { "Data/ellipsoid.obj", "Data/blob.off" };
  const char* landmarks[2] = { "Data/ellipsoid.pinned", "Data/blob.vts" };
  const char* labels[2] = { "ellipsoid.obj", "blob.off" };
  for (int i = 0; i < 2; ++i)
  {
    pipeline.Readers[i] = scene.New("sources", "SurfaceMeshReader");
    vtkSMPropertyHelper(pipeline.Readers[i], "FileName").Set(files[i]);
    vtkSMPropertyHelper(pipeline.Readers[i], "LandmarkFileName").Set(landmarks[i]);
    scene.Register(pipeline.Readers[i], labels[i]);
  }
  pipeline.Map = scene.New("filters", "SurfaceMap");
  for (auto& reader : pipeline.Readers)
  {
    vtkSMPropertyHelper(pipeline.Map, "Input").Add(reader, 0);
  }
  scene.Register(pipeline.Map, "SurfaceMap");

  pipeline.Average = scene.New("filters", "SurfaceAverage");
  vtkSMPropertyHelper(pipeline.Average, "Input").Set(pipeline.Map, 0);
  scene.Register(pipeline.Average, "SurfaceAverage");

  pipeline.Sequence = scene.New("filters", "SurfaceSequenceInterpolator");
  vtkSMPropertyHelper(pipeline.Sequence, "Input").Set(pipeline.Map, 0);
  vtkSMPropertyHelper(pipeline.Sequence, "StepsPerInterval").Set(10);
  scene.Register(pipeline.Sequence, "SurfaceSequenceInterpolator");

  pipeline.Evaluation = scene.New("filters", "SurfaceMapEvaluation");
  vtkSMPropertyHelper(pipeline.Evaluation, "Input").Set(pipeline.Map, 0);
  vtkSMPropertyHelper(pipeline.Evaluation, "SourceIndex").Set(1);
  vtkSMPropertyHelper(pipeline.Evaluation, "TargetIndex").Set(0);
  scene.Register(pipeline.Evaluation, "SurfaceMapEvaluation");
  return pipeline;
}

// The inputs in the back row; the evaluation, the average and the
// interpolator with T's edges in the front row.
void showPipeline(Scene& scene, const Pipeline& pipeline)
{
  const double spacing = 3.5;
  for (int i = 0; i < 2; ++i)
  {
    scene.Show(pipeline.Readers[i], (i - 0.5) * spacing, spacing, nullptr, false);
  }
  scene.Show(pipeline.Evaluation, -spacing, 0.0, "MaxStretch", true);
  scene.Show(pipeline.Average, 0.0, 0.0, nullptr, true);
  scene.Show(pipeline.Sequence, spacing, 0.0, nullptr, true);
}

// Builds and shows the pipeline at t = 0.5 and writes its state to `output`;
// the exit status.
int writeState(Scene& scene, vtkSMSession* session, const char* output)
{
  try
  {
    const Pipeline pipeline = buildPipeline(scene);
    showPipeline(scene, pipeline);
    vtkSMProxy* animation = scene.Controller->FindAnimationScene(session);
    vtkSMPropertyHelper(animation, "AnimationTime").Set(0.5);
    animation->UpdateVTKObjects();
    scene.View->ResetCamera();
    scene.View->StillRender();
    if (!scene.Manager->SaveXMLState(output))
    {
      std::cerr << "cannot write " << output << "\n";
      return 1;
    }
  }
  catch (const std::exception& e)
  {
    std::cerr << e.what() << "\n";
    return 1;
  }
  return 0;
}
} // namespace

int main(int argc, char* argv[])
{
  if (argc != 3)
  {
    std::cerr << "usage: " << argv[0] << " PLUGIN_FILE OUTPUT.pvsm\n";
    return 2;
  }
  vtkInitializationHelper::SetLoadSettingsFilesDuringInitialization(false);
  // ParaView parses its own options: give it the program name only (and the
  // terminating null its logger insists on).
  char* programOnly[2] = { argv[0], nullptr };
  if (!vtkInitializationHelper::Initialize(1, programOnly, vtkProcessModule::PROCESS_CLIENT))
  {
    std::cerr << "cannot initialise ParaView's engine\n";
    return 1;
  }
  int status = 0;
  {
    vtkNew<vtkSMSession> session;
    vtkProcessModule::GetProcessModule()->RegisterSession(session);
    vtkNew<vtkSMParaViewPipelineControllerWithRendering> controller;
    controller->InitializeSession(session);
    if (!vtkSMProxyManager::GetProxyManager()->GetPluginManager()->LoadLocalPlugin(argv[1]))
    {
      std::cerr << "cannot load the plugin " << argv[1] << "\n";
      return 1;
    }
    vtkSMSessionProxyManager* manager = session->GetSessionProxyManager();
    const vtkSmartPointer<vtkSMProxy> viewProxy = newRenderView(manager, controller);
    Scene scene{ manager, controller, vtkSMRenderViewProxy::SafeDownCast(viewProxy) };
    status = writeState(scene, session, argv[2]);
    vtkProcessModule::GetProcessModule()->UnRegisterSession(session);
  }
  vtkInitializationHelper::Finalize();
  return status;
}
