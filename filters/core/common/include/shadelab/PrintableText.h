#ifndef shadelab_PrintableText_h
#define shadelab_PrintableText_h
/**
 * @file PrintableText.h
 * @brief Bytes from a file made safe to quote in a one-line message.
 */

#include <string>

namespace shadelab
{

/// @p bytes with printable ASCII kept and every other byte (control
/// characters, escape sequences, non-ASCII) written as \xNN, cut after
/// @p maxBytes input bytes with "..." so a garbage file cannot flood or
/// colour a terminal.
std::string printableText(const std::string& bytes, size_t maxBytes = 40);

} // namespace shadelab

#endif
