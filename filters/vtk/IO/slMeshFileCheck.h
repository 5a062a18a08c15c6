#ifndef slMeshFileCheck_h
#define slMeshFileCheck_h
/**
 * @file slMeshFileCheck.h
 * @brief Checks a mesh file before a VTK 9.1 reader sees it.
 *
 * VTK's OBJ, PLY, STL, glTF, XML and legacy readers trust what a file says:
 * indices beyond the vertices, list counts beyond a line's values, a header's
 * element counts, buffer sizes and references. Some then read outside their
 * arrays, call exit(), allocate what the header claims, or silently load part
 * of the file. slMeshReader runs these checks first, so such a file gets one
 * line saying what is wrong instead. Each check reads the file once, without
 * allocating what its counts claim. Internal to ShadeLab::IO.
 */

#include <string>

/// The problem with the file @p fileName of extension @p ext (lower case,
/// with its dot) that would make VTK's reader crash, allocate without
/// bound, or read it wrongly, or "" when there is none (also for extensions
/// without a check). The problem does not name the file; it names the line,
/// element or byte where there is one.
std::string slMeshFileProblem(const std::string& fileName, const std::string& ext);

/// What a VTK dataset that is not a surface (a .vtu, or a legacy .vtk
/// file of an UNSTRUCTURED_GRID, ...) needs before ShadeLab can read it.
inline constexpr const char* kExtractSurfaceFirst =
  "extract its surface first (vtkDataSetSurfaceFilter, or ParaView's Extract Surface) and save it as .vtp";

/// The bytes of the file @p fileName, all of them, in one read ("" if it
/// does not open). The checks that need the whole file read it so.
std::string slReadWholeFile(const std::string& fileName);

/// The checks per format, on a file already known to open.
std::string slOBJProblem(const std::string& fileName);
std::string slPLYProblem(const std::string& fileName);
std::string slSTLProblem(const std::string& fileName);
std::string slGLTFProblem(const std::string& fileName, bool binary);
std::string slVTPProblem(const std::string& fileName);
std::string slLegacyVTKProblem(const std::string& fileName);

/// For a VTP file slVTPProblem() passed and VTK's reader then failed on: the
/// DataArray whose compressed data does not uncompress, and the block, or
/// "". VTK's compressors name neither; this uncompresses the data a second
/// time, so it runs only once VTK's reader has failed.
std::string slVTPDataProblem(const std::string& fileName);

#endif
