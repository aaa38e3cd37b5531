/**
 * @class   vtkSurfaceMeshReader
 * @brief   Reads a surface mesh (OBJ, OFF, PLY, STL, VTP, legacy VTK) and its landmarks.
 *
 * One reader for every mesh format SurfaceMaps accepts, chosen by the file
 * name's extension (case-insensitive): `.obj`, `.off`, `.ply`, `.stl`, `.vtp`,
 * `.vtk`. OBJ vertices follow the file's `v` lines (vtkOBJReader instead makes
 * one point per distinct v/vt/vn combination, which tears closed meshes open
 * along texture seams); per-corner texture coordinates are kept in the
 * 6-component cell array "CornerTCoords" (u0 v0 u1 v1 u2 v2 per triangle) and
 * per-corner normals (`vn`, referenced as `f v/t/n` or `f v//n`) in the
 * 9-component cell array "CornerNormals" (x0 y0 z0 x1 y1 z1 x2 y2 z2, as the
 * file gives them, not normalised); a corner without one is NaN, and a file
 * whose faces use no texture coordinates (normals) has no such array. Both
 * need every face to be a triangle. An OBJ file with line or point elements
 * (`l`, `p`) is refused, as any input with lines or vertices is. OFF is read strictly (counts,
 * indices, numbers), and so is PLY (ASCII and binary; a face "texcoord" list
 * becomes "CornerTCoords"). STL points are merged. VTP and legacy VTK files
 * go through VTK's own readers.
 *
 * With LandmarkFileName set, the landmark file becomes the int point array
 * "Landmarks" (landmark id at landmark vertices, -1 elsewhere). Formats, by
 * extension: one 0-based vertex index per line, optionally prefixed `lk `
 * (`.pinned`, `.txt`), SHREC `.vts` lines `index x y z` (the index is used) or
 * `x y z` / `-1 x y z` (a point: the index is missing); `.csv` lines `x,y,z`
 * or `x,y,z,id` (or columns named by a header line); 3D Slicer markups
 * `.fcsv` (columns id,x,y,z,...) and `.mrk.json`
 * (markups[0].controlPoints[i].position, optional id and label). The k-th
 * landmark gets id k unless the file gives integer ids. A landmark given as a
 * point becomes the closest vertex (vtkStaticPointLocator); the field data
 * then holds, per such landmark in file order, "LandmarkSnapId",
 * "LandmarkSnapVertex" and "LandmarkSnapDistance" (input units), and a
 * warning (vtkWarningMacro) names each point farther than 1 % of the
 * bounding-box diagonal from its vertex. A VTP file may carry a "Landmarks"
 * array itself.
 *
 * With SizingFileName set, the sizing file (one target edge length per
 * vertex per line, in the mesh's units; finite, positive, exactly one per
 * vertex) becomes the double point array "Sizing" that vtkSurfaceMapFilter
 * uses instead of curvature.
 *
 * The output's field data holds the string array "FileName" so later filters
 * can name the mesh in their messages.
 *
 * Errors (missing, empty, truncated or malformed files, landmark indices out
 * of range, sizing files with the wrong count or a value that is not a
 * positive length) are reported with vtkErrorMacro naming the file, the line where
 * known, and the defect; the output is then empty. The reader does not judge
 * whether the mesh is a valid SurfaceMaps input: see vtkSurfaceMeshValidator.
 *
 * @sa vtkSurfaceMeshValidator
 */
#ifndef vtkSurfaceMeshReader_h
#define vtkSurfaceMeshReader_h

#include "SurfaceMapsFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

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
   * Optional landmark file (`.pinned`, `.txt`, `.vts`, `.csv`, `.fcsv`,
   * `.mrk.json`). Default: none.
   */
  vtkSetStringMacro(LandmarkFileName);
  vtkGetStringMacro(LandmarkFileName);
  ///@}

  ///@{
  /**
   * Optional sizing file (one target edge length per vertex per line).
   * Default: none.
   */
  vtkSetStringMacro(SizingFileName);
  vtkGetStringMacro(SizingFileName);
  ///@}

  /**
   * True if the extension of `fileName` is one this reader handles.
   */
  static bool CanReadFile(const char* fileName);

  /**
   * Why the last update failed: the reason its error message gave, also when
   * an input's producer failed upstream (then it names the input and what
   * failed). Empty after a successful update. After a failure GetErrorCode()
   * is vtkSurfaceMapFilter::InvalidInputError (an input cannot be used, or
   * was not produced), NotCertifiedError, or vtkErrorCode::UnknownError (an
   * internal error), and the outputs are empty.
   */
  const char* GetLastErrorMessage() const;

protected:
  vtkSurfaceMeshReader();
  ~vtkSurfaceMeshReader() override;
  vtkExecutive* CreateDefaultExecutive() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* FileName = nullptr;
  char* LandmarkFileName = nullptr;
  char* SizingFileName = nullptr;

private:
  vtkSurfaceMeshReader(const vtkSurfaceMeshReader&) = delete;
  void operator=(const vtkSurfaceMeshReader&) = delete;
};

#endif
