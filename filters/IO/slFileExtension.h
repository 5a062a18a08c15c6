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

#endif
