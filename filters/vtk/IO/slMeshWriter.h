#ifndef slMeshWriter_h
#define slMeshWriter_h
/**
 * @class   slMeshWriter
 * @brief   Writes a surface mesh to VTP, PLY, OBJ, STL or legacy VTK, all or
 *          nothing.
 *
 * The format follows the file name's extension (case insensitive):
 * .vtp (vtkXMLPolyDataWriter, raw binary appended data compressed as
 * Compression says, keeps every array), .vtk
 * (vtkPolyDataWriter, binary, keeps every array), .ply (binary; point
 * normals and texture coordinates, written by slFormatPLY; a mesh with
 * colours (active scalars), vertices, lines or strips goes to vtkPLYWriter,
 * which keeps texture coordinates and RGB colours), .obj (point normals and
 * texture coordinates, written by slFormatOBJ with the fewest digits that
 * read back exactly; other meshes as above go to vtkOBJWriter), .stl
 * (vtkSTLWriter, binary; geometry only).
 *
 * The mesh is encoded in memory (OBJ piece by piece, each piece written as
 * it is ready); ShadeLab writes the bytes to a temporary file beside the
 * target, syncs it and renames it over the target:
 * a failure (a full disk included) never leaves a partial file nor destroys
 * an existing one. A failure is a vtkErrorMacro of one line naming the file
 * (and the system's reason, e.g. "No space left on device") and Write()
 * returning false (slCallOrThrow() gives the line back).
 *
 * VTP compression: LZ4 by default, about ten times faster to write than
 * zlib for about twice the size (bench/io/vtp_encoding.py;
 * docs/mesh-io.md has the figures).
 *
 * Caveats: ParaView 5.11 as Debian 12 ships it cannot read appended VTP
 * data, compressed or not (its VTK and Debian's libexpat; see
 * docs/paraview.md): convert to inline binary for it.
 *
 * @sa slMeshReader
 */

#include "ShadeLabIOModule.h"

#include <vtkPolyDataAlgorithm.h>

#include <string>

class SHADELABIO_EXPORT slMeshWriter : public vtkPolyDataAlgorithm
{
public:
  static slMeshWriter* New();
  vtkTypeMacro(slMeshWriter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The file to write.
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  /// VTP compression.
  enum Compressions
  {
    NONE = 0,
    LZ4 = 1,
    ZLIB = 2,
  };

  ///@{
  /// How .vtp data is compressed (default LZ4); other formats ignore it.
  vtkSetClampMacro(Compression, int, NONE, ZLIB);
  vtkGetMacro(Compression, int);
  ///@}

  /// "none", "lz4" or "zlib"; nullptr for another value.
  static const char* GetCompressionName(int compression);

  /// The Compressions value named @p name, or -1.
  static int GetCompressionByName(const std::string& name);

  /// Updates the input and writes it. True on success; false after
  /// vtkErrorMacro (also when the input's update failed).
  bool Write();

  /// True if slMeshWriter writes files with the extension of @p fileName.
  static bool CanWriteFile(const char* fileName);

  /// ".vtp .vtk .ply .obj .stl"
  static const char* GetSupportedExtensions();

protected:
  slMeshWriter();
  ~slMeshWriter() override;

  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  slMeshWriter(const slMeshWriter&) = delete;
  void operator=(const slMeshWriter&) = delete;

  /// Writes @p mesh to FileName. Throws shadelab::Error "FILE: problem".
  void WriteMesh(vtkPolyData* mesh);

  char* FileName = nullptr;
  int Compression = LZ4;
};

#endif
