// surfacemap embed: bijective sphere embedding of one mesh.
#include "AlgorithmMessages.h"
#include "Arguments.h"
#include "AtomicFiles.h"
#include "Commands.h"
#include "MeshFiles.h"
#include "SettingFlags.h"
#include "Terminal.h"

#include "vtkSphereEmbeddingFilter.h"
#include "vtkSurfaceMapsSettings.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <cstdio>
#include <iostream>
#include <string>

namespace surfacemap
{

namespace
{

// True if `mesh` has a Landmarks array with at least one landmark (id >= 0).
bool hasLandmarks(vtkPolyData* mesh)
{
  vtkDataArray* ids = mesh->GetPointData()->GetArray("Landmarks");
  for (vtkIdType v = 0; ids && v < ids->GetNumberOfTuples(); ++v)
  {
    if (ids->GetComponent(v, 0) >= 0)
    {
      return true;
    }
  }
  return false;
}

} // namespace

namespace
{
const std::string EmbedHelpText =
  std::string("usage: surfacemap embed MESH -o OUT.vtp [--on-sphere] [--landmarks FILE]\n"
              "                        [--reference EMBEDDED.vtp] [SETTING ...]\n"
              "\n"
              "Computes a bijective embedding of MESH (closed, manifold, genus 0) on the\n"
              "unit sphere and writes MESH with the point array SpherePosition to OUT.vtp.\n"
              "The embedding is certified with exact orientation predicates.\n"
              "\n"
              "  -o, --output OUT.vtp  output file (VTK XML PolyData), written atomically;\n"
              "                        OUT.obj: an OBJ with the points and MESH's\n"
              "                        per-corner texture coordinates and normals, no\n"
              "                        arrays (with --on-sphere: MESH's texture on the\n"
              "                        sphere)\n"
              "  --on-sphere           put the output points on the sphere (for viewing);\n"
              "                        the original coordinates go to InputPosition\n"
              "  --landmarks FILE      landmark file carried along as the Landmarks array\n"
              "                        (formats below)\n"
              "  --reference FILE      an embedding written by this command (with landmarks):\n"
              "                        rotate the new embedding so that its landmarks come\n"
              "                        closest to the reference's\n"
              "\n"
              "Settings (surfacemap map computes its embeddings with their defaults):\n") +
  settingsHelp(vtkSurfaceMapsSettings::SPHERE_EMBEDDING_SETTINGS) +
  "\n"
  "Exit code 0 with a certified embedding, 2 for bad usage or input, 3 if no\n"
  "certified embedding was found.\n" +
  LandmarkFormatsHelp;
} // namespace

const char* const EmbedHelp = EmbedHelpText.c_str();

namespace
{

struct EmbedArguments
{
  std::string mesh, output, landmarks, reference;
  bool onSphere = false;
};

// The arguments; the settings' flags go to `embedding`.
EmbedArguments parseArguments(const std::vector<std::string>& args,
  vtkSphereEmbeddingFilter* embedding)
{
  EmbedArguments parsed;
  for (std::size_t i = 0; i < args.size(); ++i)
  {
    const std::string& a = args[i];
    if (a == "-o" || a == "--output" || a == "--landmarks" || a == "--reference")
    {
      std::string& file = a == "--landmarks" ? parsed.landmarks
        : a == "--reference"                 ? parsed.reference
                                             : parsed.output;
      file = optionValue(args, i, "a file name");
    }
    else if (a == "--on-sphere")
    {
      parsed.onSphere = true;
    }
    else if (parseSettingFlag(embedding, args, i))
    {
    }
    else if (isOption(a))
    {
      unknownOption(a);
    }
    else if (parsed.mesh.empty())
    {
      parsed.mesh = a;
    }
    else
    {
      throw UsageError{ "embed takes one mesh ('" + a + "' is a second one)" };
    }
  }
  if (parsed.mesh.empty())
  {
    throw UsageError{ "no mesh given" };
  }
  if (parsed.output.empty())
  {
    throw UsageError{ "no output file given (-o OUT.vtp)" };
  }
  return parsed;
}

// Sets the embedding `reference` (a file of this command) on `embedding`;
// false after printing why it cannot be used.
bool setReference(vtkSphereEmbeddingFilter* embedding,
  vtkPolyData* input,
  const std::string& reference)
{
  vtkSmartPointer<vtkPolyData> referenceMesh = readMesh(reference);
  if (!referenceMesh)
  {
    return false;
  }
  if (!referenceMesh->GetPointData()->GetArray("SpherePosition"))
  {
    printError(reference + " has no SpherePosition array (write it with surfacemap embed)");
    return false;
  }
  if (!hasLandmarks(input))
  {
    throw UsageError{ "--reference turns the embedding so that its landmarks come closest to "
                      "the reference's: give --landmarks (or a mesh with a Landmarks array)" };
  }
  embedding->SetReferenceData(referenceMesh);
  return true;
}

// Prints the embedding's figures and where it was written.
void printEmbedding(vtkPolyData* result, const EmbedArguments& arguments)
{
  auto value = [&](const char* name)
  {
    vtkDataArray* a = result->GetFieldData()->GetArray(name);
    return a ? a->GetTuple1(0) : 0.0;
  };
  std::printf("%s: certified bijective sphere embedding of %lld vertices\n",
    arguments.mesh.c_str(),
    static_cast<long long>(result->GetNumberOfPoints()));
  std::printf("  distortion (symmetric Dirichlet) %.4f, %d Newton iterations over %d levels, "
              "%.2f s\n",
    value("EmbeddingDistortion"),
    static_cast<int>(value("EmbeddingNewtonIterations")),
    static_cast<int>(value("EmbeddingLevels")),
    value("EmbeddingSeconds"));
  std::printf(
    "  smallest ratio of a triangle's share of the sphere to its share of the area %.3g\n",
    value("EmbeddingSmallestAreaRatio"));
  if (vtkDataArray* alignment = result->GetFieldData()->GetArray("LandmarkAlignmentError"))
  {
    std::printf("  rotated onto %s: landmarks %.4f rad (RMS) from the reference's\n",
      arguments.reference.c_str(),
      alignment->GetTuple1(0));
  }
  std::printf("  written to %s\n", arguments.output.c_str());
}

} // namespace

int runEmbed(const std::vector<std::string>& args)
{
  vtkNew<vtkSphereEmbeddingFilter> embedding;
  const EmbedArguments arguments = parseArguments(args, embedding);
  vtkSmartPointer<vtkPolyData> input = readValidMesh(arguments.mesh, arguments.landmarks);
  if (!input || !canWrite(arguments.output))
  {
    return ExitBadInput;
  }
  embedding->SetInputData(input);
  if (!arguments.reference.empty() && !setReference(embedding, input, arguments.reference))
  {
    return ExitBadInput;
  }
  embedding->SetOutputPointsOnSphere(arguments.onSphere);
  ErrorCapture errors(embedding);
  {
    ProgressBar bar(embedding);
    embedding->Update();
  }
  if (!errors.messages().empty() || embedding->GetOutput()->GetNumberOfPoints() == 0)
  {
    printErrors(errors.messages());
    return ExitNoCertifiedResult;
  }
  vtkPolyData* result = embedding->GetOutput();
  if (!succeeds([&] { writeMeshAtomically(result, arguments.output); }))
  {
    return ExitBadInput;
  }
  printEmbedding(result, arguments);
  return ExitOk;
}

} // namespace surfacemap
