#include "FilterTestData.h"
#include "vtkSurfaceMeshReader.h"
#include "vtkSurfaceMeshValidator.h"

#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkTable.h"
#include "vtkVariant.h"

#include <gtest/gtest.h>

#include <string>

namespace
{
using filtertest::read;

const std::string Data = SURFACEMAPS_DATA_DIR;

} // namespace

TEST(SurfaceMeshValidator, OneRowPerInput)
{
  vtkNew<vtkSurfaceMeshValidator> validator;
  validator->AddInputDataObject(read("ellipsoid.obj"));
  validator->AddInputDataObject(read("bad/torus.obj"));
  validator->AddInputDataObject(read("limbs.ply"));
  validator->Update();
  vtkTable* table = validator->GetOutput();
  ASSERT_EQ(table->GetNumberOfRows(), 3);
  EXPECT_FALSE(validator->GetAllValid());

  EXPECT_EQ(table->GetValueByName(0, "Valid").ToInt(), 1);
  EXPECT_EQ(table->GetValueByName(0, "Points").ToInt(), 642);
  EXPECT_EQ(table->GetValueByName(0, "Edges").ToInt(), 1920);
  EXPECT_EQ(table->GetValueByName(0, "Genus").ToInt(), 0);
  EXPECT_EQ(table->GetValueByName(0, "Input").ToString(), Data + "/ellipsoid.obj");
  EXPECT_EQ(table->GetValueByName(0, "Defects").ToString(), "");

  EXPECT_EQ(table->GetValueByName(1, "Valid").ToInt(), 0);
  EXPECT_EQ(table->GetValueByName(1, "Genus").ToInt(), 1);
  EXPECT_NE(table->GetValueByName(1, "Defects").ToString().find("has genus 1"), std::string::npos);

  EXPECT_EQ(table->GetValueByName(2, "Valid").ToInt(), 1);
  EXPECT_GT(table->GetValueByName(2, "MinAngle").ToDouble(), 10.0);
}

TEST(SurfaceMeshValidator, AllValid)
{
  vtkNew<vtkSurfaceMeshValidator> validator;
  validator->Update();
  EXPECT_FALSE(validator->GetAllValid()); // nothing to validate is not success
  validator->AddInputDataObject(read("ellipsoid.obj"));
  validator->AddInputDataObject(read("blob.off"));
  validator->Update();
  EXPECT_TRUE(validator->GetAllValid());
}

TEST(SurfaceMeshValidator, LandmarkCorrespondence)
{
  vtkNew<vtkSurfaceMeshValidator> validator;
  validator->AddInputDataObject(read("ellipsoid.obj", "ellipsoid.pinned"));
  validator->AddInputDataObject(read("blob.vtp"));
  validator->AddInputDataObject(read("limbs.ply", "bad/five_landmarks.pinned"));
  validator->Update();
  vtkTable* table = validator->GetOutput();
  EXPECT_EQ(table->GetValueByName(0, "Landmarks").ToInt(), 4);
  EXPECT_EQ(table->GetValueByName(1, "Landmarks").ToInt(), 4);
  EXPECT_EQ(table->GetValueByName(2, "Landmarks").ToInt(), 5);
  EXPECT_EQ(table->GetValueByName(0, "Valid").ToInt(), 1);
  EXPECT_EQ(table->GetValueByName(1, "Valid").ToInt(), 1);
  EXPECT_EQ(table->GetValueByName(2, "Valid").ToInt(), 0);
  EXPECT_NE(table->GetValueByName(2, "Defects").ToString().find("landmark counts do not match"),
    std::string::npos);

  validator->CheckLandmarkCorrespondenceOff();
  validator->Update();
  EXPECT_TRUE(validator->GetAllValid());
}
