// The `surfacemap` command line: pieces shared by the commands.
#pragma once

#include "vtkSmartPointer.h"

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

class vtkAlgorithm;
class vtkObject;
class vtkPolyData;

namespace surfacemap
{

/// Collects the messages of a VTK algorithm's ErrorEvents (or another event
/// that carries a message, such as WarningEvent), without VTK's
/// source-location prefix, so commands can print them their own way.
class ErrorCapture
{
public:
  explicit ErrorCapture(vtkAlgorithm* algorithm, unsigned long event = 0 /* ErrorEvent */);
  ~ErrorCapture();
  ErrorCapture(const ErrorCapture&) = delete;
  ErrorCapture& operator=(const ErrorCapture&) = delete;

  const std::vector<std::string>& messages() const { return this->Messages; }

private:
  static void callback(vtkObject*, unsigned long, void* self, void* text);
  vtkAlgorithm* Algorithm;
  unsigned long Tag = 0;
  std::vector<std::string> Messages;
};

/// Prints the warnings of an algorithm (vtkWarningMacro) on stderr as they
/// come, "surfacemap: warning: <message>", while this object lives.
class WarningPrinter
{
public:
  explicit WarningPrinter(vtkAlgorithm* algorithm);
  ~WarningPrinter();
  WarningPrinter(const WarningPrinter&) = delete;
  WarningPrinter& operator=(const WarningPrinter&) = delete;

private:
  static void callback(vtkObject*, unsigned long, void*, void* text);
  vtkAlgorithm* Algorithm;
  unsigned long Tag = 0;
};

/// A progress bar on stderr while an algorithm runs, only if stderr is a
/// terminal.
class ProgressBar
{
public:
  explicit ProgressBar(vtkAlgorithm* algorithm);
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

private:
  static void callback(vtkObject*, unsigned long, void* self, void*);
  vtkAlgorithm* Algorithm;
  unsigned long Tag = 0;
  bool Shown = false;
};

/// True for an argument that starts with '-': an option, never a file.
bool isOption(const std::string& argument);

/// The value after the option args[i], advancing i to it; throws UsageError
/// "<option> needs <what>" when the arguments end first.
const std::string& optionValue(const std::vector<std::string>& args,
  std::size_t& i,
  const char* what = "a value");

/// Throws UsageError "unknown option '<argument>'".
[[noreturn]] void unknownOption(const std::string& argument);

/// Prints every message with printError, in order.
void printErrors(const std::vector<std::string>& messages);

/// Runs `step`; if it throws std::runtime_error (a file that cannot be read,
/// created or written), prints the message and returns false, for the
/// caller to exit with ExitBadInput. Other exceptions pass.
bool succeeds(const std::function<void()>& step);

/// Measures the map source -> target (equal connectivity) with
/// vtkSurfaceMapEvaluation; originals (for the Hausdorff figures) may be null.
/// Returns the evaluated source with the per-triangle arrays and the summary
/// field data; throws std::invalid_argument with the evaluation's message.
vtkSmartPointer<vtkPolyData> measureMap(vtkPolyData* source,
  vtkPolyData* target,
  vtkPolyData* sourceOriginal,
  vtkPolyData* targetOriginal);

/// The names of measureMap's summary figures, in the order they are printed.
const std::vector<const char*>& evaluationSummaryNames();

/// A summary figure of measureMap's result, NaN if absent.
double summaryValue(vtkPolyData* result, const char* name);

/// The landmark file formats, for the help of every command with --landmarks
/// (indented by 2, lines of at most 78 characters).
extern const char* const LandmarkFormatsHelp;

/// Prints "surfacemap: warning: <message>" on stderr.
void printWarning(const std::string& message);

/// One line on the landmarks of `mesh` (read by vtkSurfaceMeshReader from
/// `landmarks`) that were given as points and snapped to vertices: how many,
/// the largest snap distance, absolute and in % of the bounding-box diagonal;
/// empty when none was a point.
std::string landmarkSnapSummary(vtkPolyData* mesh, const std::string& landmarks);

/// The snapped landmarks of `mesh` as a JSON list of { id, vertex, distance,
/// percent_of_diagonal }, "null" when none was a point.
std::string landmarkSnapJson(vtkPolyData* mesh);

/// Reads a mesh with vtkSurfaceMeshReader; on failure prints the reason and
/// returns null. Landmarks given as points: the reader's warnings (a point
/// far from every vertex) go to stderr and landmarkSnapSummary to stdout.
/// `sizing` names a sizing file (vtkSurfaceMeshReader::SetSizingFileName).
vtkSmartPointer<vtkPolyData> readMesh(const std::string& path,
  const std::string& landmarks = "",
  const std::string& sizing = "");

/// Reads a mesh (and optional landmark file) with vtkSurfaceMeshReader and
/// validates it; on failure prints the reasons and returns null.
vtkSmartPointer<vtkPolyData> readValidMesh(const std::string& path, const std::string& landmarks);

/// The input files a map directory's report.json (`report`) names, in
/// order. Throws std::runtime_error naming the file and what is wrong with it
/// (missing, not JSON, no inputs).
std::vector<std::string> mapReportInputs(const std::string& report);

/// True if `path` is a regular file (false on any error).
bool isFile(const std::string& path);

/// The name of an output file of 'surfacemap map' for input i:
/// <stem>_<i>.vtp (stem common, mapped or embedding).
std::string mapFileName(const char* stem, int i);

/// Creates `directory` (with its parents) if missing and checks that the file
/// `probe` can be written in it. Throws std::runtime_error naming what failed.
void createOutputDirectory(const std::string& directory, const std::string& probe);

/// createOutputDirectory before a computation: false after printing why
/// (for the caller to exit with ExitBadInput). `created` receives the
/// outermost directory it had to create (empty if none), for
/// removeCreatedDirectory when no result comes out.
bool prepareOutputDirectory(const std::string& directory,
  const std::string& probe,
  std::string& created);

/// Removes `created` (from prepareOutputDirectory) with everything in it; nothing if empty.
void removeCreatedDirectory(const std::string& created);

/// Throws std::runtime_error naming `path` if no file can be created there
/// (checked before long computations whose result would be lost).
void checkWritable(const std::string& path);
/// True if a file can be created at `path`; otherwise prints why (as
/// checkWritable's message) and returns false, for the caller to exit with
/// ExitBadInput.
bool canWrite(const std::string& path);

/// `value` as a JSON number (10 significant digits); null if not finite,
/// since JSON has no infinity or NaN.
std::string jsonNumber(double value);

/// `text` as a quoted JSON string (quotes, backslashes and control
/// characters escaped).
std::string jsonString(const std::string& text);

/// Makes SIGINT and SIGTERM remove the temporary files being written before
/// the process ends, and ignores SIGXFSZ so a file size limit is a reported
/// write error. Call once at the start of main.
void installSignalHandlers();

/// While it lives, SIGINT and SIGTERM remove the files of `directory` that a
/// map writes (report.json, common_/mapped_/embedding_<i>.vtp, temporary
/// *.tmp.* files) and then the directory if that left it empty; any other
/// file stays, and with it the directory. For a map being written beside
/// the directory it will replace, and for the replaced map's files.
class InterruptCleanup
{
public:
  explicit InterruptCleanup(const std::string& directory);
  ~InterruptCleanup();
  InterruptCleanup(const InterruptCleanup&) = delete;
  InterruptCleanup& operator=(const InterruptCleanup&) = delete;

private:
  int Slot = -1;
};

/// While it lives, SIGINT and SIGTERM first rename `moved` back to
/// `original` (before any InterruptCleanup runs). The rename fails, and
/// changes nothing, while `original` exists: only the moment between moving
/// a directory away and moving its replacement in is undone.
class InterruptRestore
{
public:
  InterruptRestore(const std::string& moved, const std::string& original);
  ~InterruptRestore();
  InterruptRestore(const InterruptRestore&) = delete;
  InterruptRestore& operator=(const InterruptRestore&) = delete;

private:
  bool Registered = false;
};

/// Writes `content` to a temporary name beside `path`, checks every write,
/// fsync, close and the size on disk, then renames it. On any failure the
/// temporary file is removed and std::runtime_error names `path`.
void writeFileAtomically(const std::string& path, const std::string& content);

/// Writes VTK XML PolyData (also checking the writer's own error code)
/// through writeFileAtomically, so a failed or interrupted write never leaves
/// a half-written file. Throws std::runtime_error naming the file on failure.
void writePolyDataAtomically(vtkPolyData* data, const std::string& path);

/// Writes the triangles of `data` as Wavefront OBJ through
/// writeFileAtomically: `v` per point, and, from the cell arrays
/// "CornerTCoords" (6 components) and "CornerNormals" (9), one `vt` / `vn`
/// per distinct corner value with faces `f v/vt/vn` (`v/vt`, `v//vn`, `v`),
/// so texture seams and sharp normals stay exact; a face with a non-finite
/// corner value goes without that attribute. OBJ holds no other data: other
/// point and cell arrays are not written.
void writeObjAtomically(vtkPolyData* data, const std::string& path);

/// writeObjAtomically for a path ending in .obj (any case), else
/// writePolyDataAtomically.
void writeMeshAtomically(vtkPolyData* data, const std::string& path);

} // namespace surfacemap
