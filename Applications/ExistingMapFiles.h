// The command line: `surfacemap map --add-to DIR`, the map in DIR that new
// inputs are added to (its files checked, its settings, its inputs).
#pragma once

#include "Json.h"

#include "vtkSmartPointer.h"

#include <string>
#include <vector>

class vtkPolyData;
class vtkSurfaceMapFilter;

namespace surfacemap
{

/// The help entry of --add-to (indented like `map`'s other options).
extern const char* const AddToHelp;

/// The value of "--add-to DIR" in `args`, "" without one; UsageError when
/// it is given twice or without a directory.
std::string addToDirectory(const std::vector<std::string>& args);

/// What `map --add-to` reuses of an existing map.
struct ExistingMapFiles
{
  std::string directory;
  /// Its report.json.
  Json::Value report;
  /// Per input j: embedding_<j>.vtp (input j with the embedding the map
  /// used; field data only "FileName") and common_<j>.vtp (T on input j).
  std::vector<vtkSmartPointer<vtkPolyData>> embeddings, common;
};

/// Reads the map in `directory` after checking every common_<j> and
/// embedding_<j> against its report.json and each other (verifyMapFiles),
/// and sets its settings (report.json's "settings") on `map`, so that flags
/// given after override them. Throws std::runtime_error naming the file and
/// its defect.
ExistingMapFiles readExistingMap(const std::string& directory, vtkSurfaceMapFilter* map);

/// The report of the map with the existing map's inputs added first:
/// report["inputs"][j] for j < M becomes the existing report's entry (its
/// files), "added_to" records the directory, its map id and M, and a
/// missing "preset" is the existing map's.
void mergeExistingReport(Json::Value& report, const ExistingMapFiles& existing);

/// The existing map's input files, for the names of the specimens.
std::vector<std::string> existingInputFiles(const ExistingMapFiles& existing);

} // namespace surfacemap
