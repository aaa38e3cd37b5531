// Failures a raw VTK pipeline can see: an upstream producer that fails, the
// error code and message of the module's algorithms, one message per failure.
#include "FilterTestData.h"
#include "vtkSphereEmbeddingFilter.h"
#include "vtkSurfaceMapFilter.h"
#include "vtkSurfaceMeshReader.h"

#include "vtkErrorCode.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkOutputWindow.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStringOutputWindow.h"
#include "vtkXMLPolyDataReader.h"

#include <gtest/gtest.h>

#include <string>

namespace
{
using filtertest::useShortSchedule;

const std::string Data = SURFACEMAPS_DATA_DIR;
const std::string Missing = Data + "/no_such_specimen.vtp";

// Everything VTK prints (errors, warnings) while the object lives.
class CapturedOutput
{
public:
  CapturedOutput()
    : Previous(vtkOutputWindow::GetInstance())
  {
    vtkOutputWindow::SetInstance(this->Window);
  }
  ~CapturedOutput() { vtkOutputWindow::SetInstance(this->Previous); }
  std::string Text() const { return this->Window->GetOutput(); }

private:
  vtkNew<vtkStringOutputWindow> Window;
  vtkSmartPointer<vtkOutputWindow> Previous;
};

bool contains(const std::string& text, const std::string& part)
{
  return text.find(part) != std::string::npos;
}

// Updates `map`, which must fail with InvalidInputError; the reason.
std::string invalidInputMessage(vtkSurfaceMapFilter* map)
{
  map->Update();
  EXPECT_EQ(
    map->GetErrorCode(), static_cast<unsigned long>(vtkSurfaceMapFilter::InvalidInputError));
  return map->GetLastErrorMessage();
}

} // namespace

TEST(PipelineErrors, MapFilterSeesAReaderThatFails)
{
  vtkNew<vtkXMLPolyDataReader> first, second;
  first->SetFileName((Data + "/blob.vtp").c_str());
  second->SetFileName((Data + "/blob.vtp").c_str());
  vtkNew<vtkSurfaceMapFilter> map;
  useShortSchedule(map);
  map->AddInputConnection(first->GetOutputPort());
  map->AddInputConnection(second->GetOutputPort());
  map->Update();
  ASSERT_EQ(map->GetErrorCode(), static_cast<unsigned long>(vtkErrorCode::NoError));
  ASSERT_GT(map->GetOutput(1)->GetNumberOfPoints(), 0);

  // The next specimen's file is missing: VTK never runs the map's
  // RequestData, yet the map must not look successful or keep the last map.
  second->SetFileName(Missing.c_str());
  {
    CapturedOutput output;
    map->Update();
  }
  EXPECT_EQ(
    map->GetErrorCode(), static_cast<unsigned long>(vtkSurfaceMapFilter::InvalidInputError));
  const std::string message = map->GetLastErrorMessage();
  EXPECT_TRUE(contains(message, "input 1 was not produced: vtkXMLPolyDataReader failed"))
    << message;
  EXPECT_TRUE(contains(message, Missing)) << message;
  for (int i = 0; i < 2; ++i)
  {
    EXPECT_EQ(map->GetOutput(i)->GetNumberOfPoints(), 0) << "output " << i;
  }

  second->SetFileName((Data + "/blob.vtp").c_str());
  map->Update();
  EXPECT_EQ(map->GetErrorCode(), static_cast<unsigned long>(vtkErrorCode::NoError));
  EXPECT_STREQ(map->GetLastErrorMessage(), "");
  EXPECT_GT(map->GetOutput(1)->GetNumberOfPoints(), 0);
}

TEST(PipelineErrors, ModuleReaderFailureReachesTheFilterDownstream)
{
  vtkNew<vtkSurfaceMeshReader> reader;
  reader->SetFileName(Missing.c_str());
  vtkNew<vtkSphereEmbeddingFilter> embedding;
  embedding->SetInputConnection(reader->GetOutputPort());
  CapturedOutput output;
  embedding->Update();

  EXPECT_NE(reader->GetErrorCode(), static_cast<unsigned long>(vtkErrorCode::NoError));
  const std::string reason = reader->GetLastErrorMessage();
  EXPECT_TRUE(contains(reason, Missing)) << reason;
  EXPECT_EQ(
    embedding->GetErrorCode(), static_cast<unsigned long>(vtkSurfaceMapFilter::InvalidInputError));
  const std::string message = embedding->GetLastErrorMessage();
  EXPECT_TRUE(
    contains(message, "input port 0 was not produced: vtkSurfaceMeshReader failed: " + reason))
    << message;
  EXPECT_EQ(embedding->GetOutput()->GetNumberOfPoints(), 0);
  // The reader reported its failure and the filter its own: no dumps of the
  // pipeline request on top.
  EXPECT_FALSE(contains(output.Text(), "returned failure for request")) << output.Text();
}

TEST(PipelineErrors, AnErrorTheFilterReportedIsPrintedOnce)
{
  vtkNew<vtkSurfaceMapFilter> map;
  map->AddInputData(filtertest::read("ellipsoid_coarse.stl"));
  map->AddInputData(filtertest::read("bad/hemisphere.obj"));
  CapturedOutput output;
  const std::string message = invalidInputMessage(map);
  EXPECT_TRUE(contains(message, "is not closed: ")) << message;
  // An open mesh without repeated points: not what vtkOBJReader makes.
  EXPECT_FALSE(contains(message, "vtkOBJReader")) << message;
  EXPECT_TRUE(contains(output.Text(), message)) << output.Text();
  EXPECT_FALSE(contains(output.Text(), "returned failure for request")) << output.Text();
}

TEST(PipelineErrors, TextureSeamsFromVtkOBJReaderPointToTheModuleReader)
{
  vtkNew<vtkOBJReader> reader;
  reader->SetFileName((Data + "/spot.obj").c_str());
  vtkNew<vtkSurfaceMapFilter> map;
  map->SetInputConnection(reader->GetOutputPort());
  CapturedOutput output;
  const std::string message = invalidInputMessage(map);
  EXPECT_TRUE(contains(message, "is not closed: ")) << message;
  EXPECT_TRUE(contains(message, "vtkOBJReader")) << message;
  EXPECT_TRUE(contains(message, "read it with vtkSurfaceMeshReader")) << message;
}
