#ifndef slMeshReader_h
#define slMeshReader_h
/**
 * @class   slMeshReader
 * @brief   Reads a surface mesh from OBJ, PLY, STL, VTP, legacy VTK, OFF or glTF.
 *
 * slMeshReader picks the reader from the file name's extension (case
 * insensitive): .obj (vtkOBJReader, keeps texture coordinates and normals),
 * .ply (vtkPLYReader), .stl (vtkSTLReader), .vtp (vtkXMLPolyDataReader),
 * .vtk (vtkPolyDataReader; the file must hold polydata) and .off (ShadeLab's
 * own OFF parser, which keeps non-manifold faces and reports errors by line),
 * .gltf and .glb (vtkGLTFReader; every mesh primitive of the first scene,
 * with node transforms applied, appended into one polydata).
 *
 * OBJ and binary PLY files in the layouts most tools write (slOBJFormat.h,
 * slPLYFormat.h) are read by ShadeLab's own parsers instead, several times
 * faster, to exactly the mesh the VTK reader (and, for OBJ, the merging
 * below) gives; any other file goes to the checks and the VTK reader.
 *
 * vtkOBJReader emits one point per face corner. With MergeDuplicatePoints
 * on (the default), points equal in position and in every point-data value
 * (texture coordinates, normals) are merged again, so the mesh is connected
 * while texture and normal seams stay seams.
 *
 * The output is checked before it is passed on: a file that cannot be opened
 * or parsed, a mesh without polygons, or a point with a NaN or infinite
 * coordinate gives an error through vtkErrorMacro (one line, "FILE: problem"), an
 * empty output and a failed update (slUpdateOrThrow() gives the line back).
 *
 * @warning Only polygonal cells are required; vertices, lines and strips are
 * passed through as the underlying reader returns them.
 *
 * @sa vtkOBJReader vtkGLTFReader vtkPLYReader vtkSTLReader vtkXMLPolyDataReader
 */

#include "ShadeLabIOModule.h"

#include <vtkPolyDataAlgorithm.h>

#include <string>

class SHADELABIO_EXPORT slMeshReader : public vtkPolyDataAlgorithm
{
public:
  static slMeshReader* New();
  vtkTypeMacro(slMeshReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The file to read.
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /// Merge the per-corner points of OBJ files that are identical in position
  /// and all point data. On by default.
  vtkSetMacro(MergeDuplicatePoints, bool);
  vtkGetMacro(MergeDuplicatePoints, bool);
  vtkBooleanMacro(MergeDuplicatePoints, bool);
  ///@}

  /// True if the extension of @p fileName is one slMeshReader reads.
  static bool CanReadFile(const char* fileName);

  /// The extensions read, e.g. ".obj .ply .stl .vtp .vtk .off .gltf .glb".
  static const char* GetSupportedExtensions();

protected:
  slMeshReader();
  ~slMeshReader() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  slMeshReader(const slMeshReader&) = delete;
  void operator=(const slMeshReader&) = delete;

  /// vtkErrorMacro "FILE: @p problem"; false.
  bool Fail(const std::string& problem);

  char* FileName = nullptr;
  bool MergeDuplicatePoints = true;
};

#endif
