// surfacemap statistics: mean shape, modes of variation and spread of a
// population of surfaces with one connectivity.
#include "AlgorithmMessages.h"
#include "Arguments.h"
#include "AtomicFiles.h"
#include "Commands.h"
#include "MapDirectory.h"
#include "MeshFiles.h"
#include "OutputDirectory.h"
#include "Pictures.h"
#include "StatisticsPictures.h"
#include "Terminal.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkSurfaceShapeStatistics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

namespace surfacemap
{

const char* const StatisticsHelp =
  "usage: surfacemap statistics MAPDIR --output-dir DIR [options]\n"
  "       surfacemap statistics MESH MESH [MESH ...] --output-dir DIR [options]\n"
  "\n"
  "Shape statistics of a population of surfaces with identical connectivity\n"
  "(vtkSurfaceShapeStatistics): generalized Procrustes alignment onto their\n"
  "mean (area-weighted; the mean does not depend on the order of the\n"
  "specimens), then the principal modes of variation. MAPDIR is an output\n"
  "directory of 'surfacemap map': its common_<i>.vtp, one per input its\n"
  "report.json lists (the common triangulation lifted onto each specimen),\n"
  "each checked against report.json and its embedding_<i>.vtp as 'evaluate'\n"
  "does (a missing, stale, swapped, changed or rotated file is refused by\n"
  "name).\n"
  "Otherwise give two or more meshes of one connectivity.\n"
  "\n"
  "Variances, scores and modes use the area-weighted inner product (vertex\n"
  "areas summing to 1) with 1/N: sqrt(variance) is the RMS displacement over\n"
  "the surface of one standard deviation along a mode, in the meshes' units.\n"
  "\n"
  "  -o, --output-dir DIR\n"
  "                     where to write (created if missing; checked for\n"
  "                     writing before computing)\n"
  "  --modes K          modes to compute (default 3, from 1 to 100; N\n"
  "                     specimens have at most N - 1)\n"
  "  --align MODE       rigid (default: size is part of the variation),\n"
  "                     similarity (also a uniform scale: shape alone) or none\n"
  "  --frames F         frames of each mode's animation, from -2 to +2\n"
  "                     standard deviations (default 9, from 2 to 1000)\n"
  "  --pictures         also write the PNGs below, rendered with VTK through\n"
  "                     OpenGL on the display, or without one on a virtual\n"
  "                     display (Xvfb, Debian package xvfb) started for the\n"
  "                     command and stopped at its end; with neither the\n"
  "                     command stops with exit code 2 before computing\n"
  "\n"
  "Writes, each file atomically, the frames and the files naming them put in\n"
  "place together at the end (an interrupted run leaves none of them):\n"
  "  DIR/mean.vtp                  the mean shape with the point arrays\n"
  "                                StandardDeviation (per vertex: RMS distance\n"
  "                                of the aligned specimens to the mean) and\n"
  "                                Mode_<m> (the modes as displacements)\n"
  "  DIR/mode_<m>.pvd              per mode m = 1..K: a ParaView animation of\n"
  "                                mean + c sqrt(variance_m) mode_m for c from\n"
  "                                -2 to +2 (the time value is c), its frames\n"
  "                                in DIR/mode_<m>/frame_<k>.vtp\n"
  "  DIR/scores.csv                per specimen: its file and its score on\n"
  "                                every mode (specimen ~ mean + sum of\n"
  "                                score_m mode_m), its alignment RMS\n"
  "  DIR/variance.csv              per mode: variance, standard deviation,\n"
  "                                explained and cumulative fraction\n"
  "  with --pictures:\n"
  "  DIR/explained_variance.png    bar chart of the explained variance\n"
  "  DIR/scores.png                the specimens' scores on modes 1 and 2\n"
  "  DIR/spread.png                the mean coloured by StandardDeviation\n"
  "\n"
  "Exit code 0 on success, 2 for bad usage or input (meshes of another\n"
  "connectivity, a directory that is no map output, no display nor Xvfb\n"
  "for --pictures), 1 for an internal error.\n";

namespace
{

struct StatisticsArguments
{
  std::vector<std::string> sources;
  std::string outputDir;
  int modes = 3;
  int align = vtkSurfaceShapeStatistics::ALIGN_RIGID;
  int frames = 9;
  bool pictures = false;
};

// Animation frames per mode: enough for any smooth animation, and a bound
// on what a mistyped number writes (1000 frames of a mode is 1000 files).
constexpr int MaxFrames = 1000;
// Modes: far more than a population's variation is read from, and with
// MaxFrames a bound of 100 000 frame files.
constexpr int MaxModes = 100;

int integerValue(const std::string& option, const std::string& text, int lowest, int highest)
{
  std::size_t used = 0;
  long long value = 0;
  try
  {
    value = std::stoll(text, &used);
  }
  catch (const std::exception&)
  {
    used = 0;
  }
  if (used != text.size() || value < lowest || value > highest)
  {
    throw UsageError{ option + " needs an integer from " + std::to_string(lowest) + " to " +
      std::to_string(highest) + ", not '" + text + "'" };
  }
  return static_cast<int>(value);
}

StatisticsArguments parseArguments(const std::vector<std::string>& args)
{
  StatisticsArguments parsed;
  for (std::size_t i = 0; i < args.size(); ++i)
  {
    const std::string& a = args[i];
    if (isOutputDirOption(a))
    {
      parsed.outputDir = optionValue(args, i, "a directory");
    }
    else if (a == "--modes")
    {
      parsed.modes = integerValue(a, optionValue(args, i, "a number"), 1, MaxModes);
    }
    else if (a == "--frames")
    {
      parsed.frames = integerValue(a, optionValue(args, i, "a number"), 2, MaxFrames);
    }
    else if (a == "--align")
    {
      const std::string& mode = optionValue(args, i, "rigid, similarity or none");
      if (mode == "rigid")
      {
        parsed.align = vtkSurfaceShapeStatistics::ALIGN_RIGID;
      }
      else if (mode == "similarity")
      {
        parsed.align = vtkSurfaceShapeStatistics::ALIGN_SIMILARITY;
      }
      else if (mode == "none")
      {
        parsed.align = vtkSurfaceShapeStatistics::ALIGN_NONE;
      }
      else
      {
        throw UsageError{ "--align is rigid, similarity or none, not '" + mode + "'" };
      }
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
      parsed.sources.push_back(a);
    }
  }
  if (parsed.sources.empty())
  {
    throw UsageError{ "statistics needs a map directory or two or more meshes" };
  }
  if (parsed.outputDir.empty())
  {
    throw UsageError{ "statistics needs --output-dir DIR" };
  }
  return parsed;
}

// The specimen files: a map directory's common_<i>.vtp (one per input its
// report.json lists, each checked against it as 'evaluate' does) or the
// meshes given. Throws std::runtime_error naming what is missing or wrong.
std::vector<std::string> specimenFiles(const std::vector<std::string>& sources)
{
  std::error_code ec;
  if (sources.size() != 1 || !std::filesystem::is_directory(sources[0], ec))
  {
    return sources;
  }
  const std::string& directory = sources[0];
  const int n = mapInputCount(directory);
  std::vector<std::string> names, files;
  for (int i = 0; i < n; ++i)
  {
    names.push_back(mapFileName("common", i));
    files.push_back(directory + "/" + names.back());
  }
  verifyMapFiles(directory, names);
  return files;
}

std::vector<double> fieldValues(vtkPolyData* mesh, const char* name)
{
  std::vector<double> values;
  vtkDataArray* array = mesh->GetFieldData()->GetArray(name);
  for (vtkIdType k = 0; array && k < array->GetNumberOfValues(); ++k)
  {
    values.push_back(array->GetComponent(
      k / array->GetNumberOfComponents(), static_cast<int>(k % array->GetNumberOfComponents())));
  }
  return values;
}

std::string csvNumber(double value)
{
  std::ostringstream text;
  text << std::setprecision(12) << value;
  return text.str();
}

// A CSV field: quoted when it holds a comma, a quote or a line break.
std::string csvText(const std::string& text)
{
  if (text.find_first_of(",\"\n\r") == std::string::npos)
  {
    return text;
  }
  std::string quoted = "\"";
  for (char c : text)
  {
    quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  }
  return quoted + "\"";
}

std::string varianceTable(vtkPolyData* mean)
{
  const std::vector<double> variances = fieldValues(mean, "Variance");
  const std::vector<double> fractions = fieldValues(mean, "ExplainedVarianceFraction");
  std::ostringstream csv;
  csv << "mode,variance,standard_deviation,explained_fraction,cumulative_fraction\n";
  double cumulative = 0.0;
  for (std::size_t m = 0; m < variances.size(); ++m)
  {
    cumulative += fractions[m];
    csv << m + 1 << "," << csvNumber(variances[m]) << "," << csvNumber(std::sqrt(variances[m]))
        << "," << csvNumber(fractions[m]) << "," << csvNumber(cumulative) << "\n";
  }
  return csv.str();
}

std::string scoresTable(vtkPolyData* mean, const std::vector<std::string>& files, int modes)
{
  const std::vector<double> scores = fieldValues(mean, "Scores");
  const std::vector<double> rms = fieldValues(mean, "AlignmentRMS");
  std::ostringstream csv;
  csv << "specimen,file";
  for (int m = 1; m <= modes; ++m)
  {
    csv << ",mode_" << m;
  }
  csv << ",alignment_rms\n";
  for (std::size_t i = 0; i < files.size(); ++i)
  {
    csv << i << "," << csvText(files[i]);
    for (int m = 0; m < modes; ++m)
    {
      csv << "," << csvNumber(scores[i * modes + m]);
    }
    csv << "," << csvNumber(rms[i]) << "\n";
  }
  return csv.str();
}

// mode_<m>.pvd and its frames mode_<m>/frame_<k>.vtp.
void writeModeAnimation(vtkSurfaceShapeStatistics* statistics,
  ErrorCapture& errors,
  const std::string& dir,
  int mode,
  int frames)
{
  const std::string stem = "mode_" + std::to_string(mode);
  std::filesystem::create_directories(dir + "/" + stem);
  const int digits = std::max(3, static_cast<int>(std::to_string(frames - 1).size()));
  std::ostringstream pvd;
  pvd << "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
         "  <Collection>\n";
  statistics->SetMode(mode);
  for (int k = 0; k < frames; ++k)
  {
    const double c = -2.0 + 4.0 * k / (frames - 1);
    statistics->SetCoefficient(c);
    statistics->Update();
    if (!errors.messages().empty() || statistics->GetOutput()->GetNumberOfPoints() == 0)
    {
      throw std::invalid_argument(errors.messages().empty()
          ? "no shape along mode " + std::to_string(mode)
          : errors.messages().front());
    }
    std::ostringstream frame;
    frame << stem << "/frame_" << std::setw(digits) << std::setfill('0') << k << ".vtp";
    writePolyDataAtomically(statistics->GetOutput(), dir + "/" + frame.str());
    pvd << "    <DataSet timestep=\"" << csvNumber(c) << "\" group=\"\" part=\"0\" file=\""
        << frame.str() << "\"/>\n";
  }
  pvd << "  </Collection>\n</VTKFile>\n";
  writeFileAtomically(dir + "/" + stem + ".pvd", pvd.str());
}

} // namespace

namespace
{

// The specimens' files (those given or those a map directory names) and
// their meshes; false after printing why one cannot be read.
bool readSpecimens(const StatisticsArguments& arguments,
  std::vector<std::string>& files,
  std::vector<vtkSmartPointer<vtkPolyData>>& meshes)
{
  if (!succeeds([&] { files = specimenFiles(arguments.sources); }))
  {
    return false;
  }
  if (files.size() < 2)
  {
    throw UsageError{ "statistics needs two or more meshes (or a map directory of two or more "
                      "inputs), not " +
      std::to_string(files.size()) };
  }
  for (const std::string& file : files)
  {
    meshes.push_back(readMesh(file));
    if (!meshes.back())
    {
      return false;
    }
  }
  return true;
}

// Prints the total variance and each mode's.
void printModes(vtkPolyData* mean, std::size_t specimens)
{
  const std::vector<double> variances = fieldValues(mean, "Variance");
  const std::vector<double> fractions = fieldValues(mean, "ExplainedVarianceFraction");
  std::printf("statistics of %d specimens, %lld vertices: total variance %.6g\n",
    static_cast<int>(specimens),
    static_cast<long long>(mean->GetNumberOfPoints()),
    fieldValues(mean, "TotalVariance").at(0));
  for (std::size_t m = 0; m < variances.size(); ++m)
  {
    std::printf("  mode %d: variance %.6g (sd %.6g), %.1f%% of the total\n",
      static_cast<int>(m + 1),
      variances[m],
      std::sqrt(variances[m]),
      100.0 * fractions[m]);
  }
}

// Writes mean.vtp, each mode's animation, scores.csv, variance.csv and, with
// --pictures, the pictures into the output directory. Throws
// std::runtime_error naming a file that cannot be written.
//
// Everything but the pictures is written into a staging directory first and
// moved into place at the end, frames before the files naming them: an
// interrupted run (a signal, a full disk, a failed frame) leaves no frames
// without mode_<m>.pvd, scores.csv and variance.csv, and no index file
// without its frames.
void writeResults(vtkSurfaceShapeStatistics* statistics,
  ErrorCapture& errors,
  vtkPolyData* mean,
  const std::vector<std::string>& files,
  const StatisticsArguments& arguments)
{
  const std::vector<double> fractions = fieldValues(mean, "ExplainedVarianceFraction");
  const int modes = static_cast<int>(fractions.size());
  const std::string& dir = arguments.outputDir;
  StagingDirectory staging(dir, "statistics");
  std::vector<std::string> frames, indexes;
  for (int m = 1; m <= modes; ++m)
  {
    writeModeAnimation(statistics, errors, staging.path(), m, arguments.frames);
    frames.push_back("mode_" + std::to_string(m));
    indexes.push_back("mode_" + std::to_string(m) + ".pvd");
  }
  writePolyDataAtomically(mean, staging.path() + "/mean.vtp");
  writeFileAtomically(staging.path() + "/scores.csv", scoresTable(mean, files, modes));
  writeFileAtomically(staging.path() + "/variance.csv", varianceTable(mean));
  std::vector<std::string> order = frames;
  order.push_back("mean.vtp");
  order.insert(order.end(), indexes.begin(), indexes.end());
  order.push_back("scores.csv");
  order.push_back("variance.csv");
  staging.publish(order);
  if (arguments.pictures)
  {
    writeExplainedVariancePicture(fractions, dir + "/explained_variance.png");
    writeScoresPicture(fieldValues(mean, "Scores"), modes, dir + "/scores.png");
    writeSpreadPicture(mean, dir + "/spread.png");
  }
}

} // namespace

int runStatistics(const std::vector<std::string>& args)
{
  const StatisticsArguments arguments = parseArguments(args);
  if (arguments.pictures && !checkDisplayForPictures())
  {
    return ExitBadInput;
  }
  std::vector<std::string> files;
  std::vector<vtkSmartPointer<vtkPolyData>> meshes;
  std::string created;
  if (!readSpecimens(arguments, files, meshes) ||
    !prepareOutputDirectory(arguments.outputDir, "variance.csv", created))
  {
    return ExitBadInput;
  }
  vtkNew<vtkSurfaceShapeStatistics> statistics;
  statistics->SetNumberOfModes(arguments.modes);
  statistics->SetAlignMode(arguments.align);
  for (vtkPolyData* mesh : meshes)
  {
    statistics->AddInputData(mesh);
  }
  ErrorCapture errors(statistics);
  {
    ProgressBar progress(statistics);
    statistics->Update();
  }
  if (!errors.messages().empty() || statistics->GetOutput()->GetNumberOfPoints() == 0)
  {
    printErrors(errors.messages());
    removeCreatedDirectory(created); // nothing written into it
    return ExitBadInput;
  }
  vtkNew<vtkPolyData> mean;
  mean->DeepCopy(statistics->GetOutput());
  printModes(mean, files.size());
  if (!succeeds([&] { writeResults(statistics, errors, mean, files, arguments); }))
  {
    return ExitBadInput;
  }
  std::printf("  written to %s: mean.vtp, mode_<m>.pvd (m <= %d) with mode_<m>/frame_<k>.vtp, "
              "scores.csv, variance.csv%s\n",
    arguments.outputDir.c_str(),
    static_cast<int>(fieldValues(mean, "Variance").size()),
    arguments.pictures ? ", explained_variance.png, scores.png, spread.png" : "");
  return ExitOk;
}

} // namespace surfacemap
