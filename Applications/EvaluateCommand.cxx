// surfacemap evaluate: distortion and approximation error of a map, for two
// meshes or for a map directory.
#include "Arguments.h"
#include "Commands.h"
#include "EvaluateMapDirectory.h"
#include "EvaluateMeshPair.h"
#include "Pictures.h"

#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

namespace surfacemap
{

const char* const EvaluateHelp =
  "usage: surfacemap evaluate SOURCE TARGET [--originals A B] [--output-dir DIR]\n"
  "                           [--pictures]\n"
  "       surfacemap evaluate MAPDIR [--inputs A B ...] [--output-dir DIR]\n"
  "                           [--pictures]\n"
  "\n"
  "Measures the map between two meshes of identical connectivity (for example\n"
  "the common triangulation lifted onto two inputs, or input A and input A\n"
  "mapped onto B), both centred and scaled to unit area: symmetric Dirichlet\n"
  "energy (1 for an isometry), area fractions with distortion max(s1, 1/s2)\n"
  "below 1.5 and 2, the largest distortion, minimum and mean minimum angles,\n"
  "and, when both carry SpherePosition, the exact bijectivity certificate.\n"
  "A SOURCE or TARGET (or a map's input 0) with zero-area triangles is refused\n"
  "(exit 2, naming the first): no distortion is defined on them.\n"
  "\n"
  "  --originals A B   the surfaces SOURCE and TARGET approximate: adds the\n"
  "                    Hausdorff figure H per side (largest distance of an\n"
  "                    original vertex to the approximation, in % of the\n"
  "                    original's bounding-box diagonal) and a two-sided\n"
  "                    distance (points sampled in the triangles of both\n"
  "                    surfaces, the same unit)\n"
  "  -o, --output-dir DIR\n"
  "                    also write DIR/summary.json, DIR/triangles.csv (per\n"
  "                    triangle s1, s2, distortion, unit areas) and\n"
  "                    DIR/distortion_curve.csv (area fraction below each\n"
  "                    distortion, the cumulative curve) and DIR/evaluated.vtp\n"
  "                    (SOURCE with the per-triangle figures as cell data);\n"
  "                    DIR is created if missing and checked for writing\n"
  "                    before anything is computed (both forms)\n"
  "  --pictures        also write PNGs into DIR (the first form needs\n"
  "                    --output-dir): DIR/distortion.png (SOURCE and TARGET\n"
  "                    side by side, each triangle coloured by its distortion,\n"
  "                    1 white to 3 and above dark red), DIR/checkerboard.png\n"
  "                    (a checkerboard of SOURCE's positions on both: on\n"
  "                    TARGET it shows how the map carries the squares) and\n"
  "                    DIR/distortion_curve.png (the cumulative curve).\n"
  "                    Rendered with VTK through OpenGL on the display, or\n"
  "                    without one on a virtual display (Xvfb, Debian package\n"
  "                    xvfb) started for the command and stopped at its end;\n"
  "                    with neither the command stops with exit code 2\n"
  "                    before computing\n"
  "\n"
  "The second form evaluates every map in MAPDIR, an output directory of\n"
  "'surfacemap map' (common_<i>.vtp, mapped_<i>.vtp, report.json), for each\n"
  "input j > 0 (j = 0 for a single input). Every file is checked against\n"
  "report.json and each common_<i>.vtp against embedding_<i>.vtp (T's sphere\n"
  "positions where the embedding puts their source points): a missing, stale,\n"
  "swapped, changed or rotated file is refused by name. Measured:\n"
  "  approximating map  common_0 -> common_j, H against inputs 0 and j\n"
  "  exact map          input 0 -> mapped_j (input 0 on input j), H against\n"
  "                     input j (and 0 against input 0 itself)\n"
  "  certificate        T's embeddings on the sphere (SpherePosition of\n"
  "                     common_0 and common_j), exact predicates and degree 1;\n"
  "                     the exact map is bijective through them\n"
  "The inputs are the files report.json names, or those given with\n"
  "  --inputs A B ...   one file per input, in the order of the map\n"
  "It writes, into --output-dir (default MAPDIR):\n"
  "  summary.json                        both maps' figures and the\n"
  "                                      certificate for every j\n"
  "  approximating_<j>_triangles.csv     per triangle figures, as above\n"
  "  approximating_<j>_distortion_curve.csv\n"
  "  approximating_<j>.vtp               common_j with the per-triangle\n"
  "                                      figures (cell data) and\n"
  "                                      SourcePosition: common_0's points,\n"
  "                                      centred, longest bounding-box side 2\n"
  "                                      (a checkerboard of it shows the map)\n"
  "  exact_<j>_triangles.csv, exact_<j>_distortion_curve.csv, exact_<j>.vtp\n"
  "                                      the same for input 0 -> mapped_j\n"
  "  with --pictures, for <kind> approximating (common_0 -> common_j) and\n"
  "  exact (input 0 -> mapped_j):\n"
  "  <kind>_<j>_distortion.png           as above, the map's two sides\n"
  "  <kind>_<j>_checkerboard.png         as above\n"
  "  distortion_curves_<j>.png           both maps' cumulative curves\n"
  "\n"
  "Exit code 0 on success, 2 for bad usage or input (also a directory that is\n"
  "not a map output, or no display nor Xvfb for --pictures), 3 when a map\n"
  "directory's certificate fails (its files are written all the same).\n";

namespace
{

struct EvaluateArguments
{
  std::vector<std::string> meshes, originals, inputs;
  std::string outputDir;
  bool pictures = false;
};

EvaluateArguments parseArguments(const std::vector<std::string>& args)
{
  EvaluateArguments parsed;
  bool inInputs = false;
  for (std::size_t i = 0; i < args.size(); ++i)
  {
    const std::string& a = args[i];
    if (isOption(a))
    {
      inInputs = false;
    }
    if (a == "--originals")
    {
      if (i + 2 >= args.size())
      {
        throw UsageError{ "--originals needs two files" };
      }
      parsed.originals = { args[i + 1], args[i + 2] };
      i += 2;
    }
    else if (a == "--inputs")
    {
      inInputs = true;
    }
    else if (isOutputDirOption(a))
    {
      parsed.outputDir = optionValue(args, i, "a directory");
    }
    else if (a == "--pictures")
    {
      parsed.pictures = true;
    }
    else if (isOption(a))
    {
      unknownOption(a);
    }
    else
    {
      (inInputs ? parsed.inputs : parsed.meshes).push_back(a);
    }
  }
  return parsed;
}

} // namespace

int runEvaluate(const std::vector<std::string>& args)
{
  const EvaluateArguments arguments = parseArguments(args);
  const std::vector<std::string>& meshes = arguments.meshes;
  if (arguments.pictures && meshes.size() == 2 && arguments.outputDir.empty())
  {
    throw UsageError{ "--pictures needs --output-dir DIR for two meshes (where the PNGs go)" };
  }
  if (arguments.pictures && !checkDisplayForPictures())
  {
    return ExitBadInput;
  }
  std::error_code ec;
  if (meshes.size() == 1 && !std::filesystem::exists(meshes[0], ec))
  {
    printError("cannot open '" + meshes[0] + "': no such file or directory");
    return ExitBadInput;
  }
  if (meshes.size() == 1 && std::filesystem::is_directory(meshes[0], ec))
  {
    if (!arguments.originals.empty())
    {
      throw UsageError{ "--originals is for two meshes; a map directory takes --inputs A B ..." };
    }
    return evaluateMapDirectory(
      meshes[0], arguments.inputs, arguments.outputDir, arguments.pictures);
  }
  if (meshes.size() != 2)
  {
    throw UsageError{ "evaluate takes two meshes, SOURCE and TARGET, or a map output directory" };
  }
  if (!arguments.inputs.empty())
  {
    throw UsageError{ "--inputs is for a map directory; two meshes take --originals A B" };
  }
  return evaluateMeshPair(meshes, arguments.originals, arguments.outputDir, arguments.pictures);
}

} // namespace surfacemap
