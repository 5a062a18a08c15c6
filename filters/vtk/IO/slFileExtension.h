#ifndef slFileExtension_h
#define slFileExtension_h
/**
 * @file slFileExtension.h
 * @brief File-name extension helpers shared by the ShadeLab readers and writers.
 */

#include <string>

/// The extension of @p fileName in lower case with its dot (".obj"), or "".
std::string slLowerExtension(const char* fileName);

/// True if @p extension appears in the space-separated @p list.
bool slExtensionInList(const std::string& extension, const char* list);

/// "" if the extension of @p fileName is in the space-separated @p list;
/// otherwise the reason, for a @p kind of file ("mesh", "image"):
/// `unsupported image format ".xyz" (supported: .png ...)` or
/// `no file extension to tell the image format (supported: .png ...)`.
std::string slFormatProblem(const char* fileName, const char* kind, const char* list);

#endif
