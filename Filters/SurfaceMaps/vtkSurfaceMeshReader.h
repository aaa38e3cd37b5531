/**
 * @class   vtkSurfaceMeshReader
 * @brief   Reads a surface mesh (OBJ, OFF, PLY, STL, VTP, legacy VTK) and its landmarks.
 *
 * One reader for every mesh format SurfaceMaps accepts, chosen by the file
 * name's extension (case-insensitive): `.obj`, `.off`, `.ply`, `.stl`, `.vtp`,
 * `.vtk`. OBJ vertices follow the file's `v` lines (vtkOBJReader instead makes
 * one point per distinct v/vt/vn combination, which tears closed meshes open
 * along texture seams); per-corner texture coordinates are kept in the
 * 6-component cell array "CornerTCoords". OFF is read strictly (counts,
 * indices, numbers), and so is PLY (ASCII and binary; a face "texcoord" list
 * becomes "CornerTCoords"). STL points are merged. VTP and legacy VTK files
 * go through VTK's own readers.
 *
 * With LandmarkFileName set, the landmark file (one 0-based vertex index per
 * line, optionally prefixed `lk `, or SHREC `.vts` lines `index x y z`) becomes
 * the int point array "Landmarks": the k-th listed vertex gets id k, all others
 * -1. A VTP file may carry a "Landmarks" array itself.
 *
 * The output's field data holds the string array "FileName" so later filters
 * can name the mesh in their messages.
 *
 * Errors (missing, empty, truncated or malformed files, landmark indices out
 * of range) are reported with vtkErrorMacro naming the file, the line where
 * known, and the defect; the output is then empty. The reader does not judge
 * whether the mesh is a valid SurfaceMaps input: see vtkSurfaceMeshValidator.
 *
 * @sa vtkSurfaceMeshValidator
 */
#ifndef vtkSurfaceMeshReader_h
#define vtkSurfaceMeshReader_h

#include "SurfaceMapsFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

#include <memory> // for std::unique_ptr

class SURFACEMAPSFILTERS_EXPORT vtkSurfaceMeshReader : public vtkPolyDataAlgorithm
{
public:
  static vtkSurfaceMeshReader* New();
  vtkTypeMacro(vtkSurfaceMeshReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The mesh file. Required; no default.
   */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /**
   * Optional landmark file (`.pinned`, `.txt`, `.vts`). Default: none.
   */
  vtkSetStringMacro(LandmarkFileName);
  vtkGetStringMacro(LandmarkFileName);
  ///@}

  /**
   * True if the extension of `fileName` is one this reader handles.
   */
  static bool CanReadFile(const char* fileName);

  /**
   * The message of the last failed read, empty after a successful one.
   */
  const char* GetLastErrorMessage() const;

protected:
  vtkSurfaceMeshReader();
  ~vtkSurfaceMeshReader() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* FileName = nullptr;
  char* LandmarkFileName = nullptr;

private:
  vtkSurfaceMeshReader(const vtkSurfaceMeshReader&) = delete;
  void operator=(const vtkSurfaceMeshReader&) = delete;

  class vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif
