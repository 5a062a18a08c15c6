#ifndef slXMLStartTags_h
#define slXMLStartTags_h
/**
 * @file slXMLStartTags.h
 * @brief The start tags of a VTK XML file, read as expat reads them.
 *
 * The VTP check reads the counts and array headers that VTK's XML reader
 * will allocate for, so it must see the same attributes expat hands to VTK:
 * values in single or double quotes, white space around '=', character
 * references decoded, and nothing inside comments, CDATA sections or
 * processing instructions. Internal to ShadeLab::IO.
 */

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

/// A start tag's attributes: names and values, in the tag's order.
using slXMLAttributes = std::vector<std::pair<std::string, std::string>>;

/// One start tag: the element's name, where the tag begins ('<') and ends
/// (its closing '>'), and its attributes.
struct slXMLStartTag
{
  std::string name;
  size_t begin = 0;
  size_t end = 0;
  slXMLAttributes attributes;
};

/// The start tags of @p text in order, up to and including the first
/// "AppendedData" one (the raw data after it is not markup). Comments,
/// CDATA sections, processing instructions and end tags are skipped. Stops
/// at a tag that does not close within @p text (expat refuses such a file).
/// Linear in the size of @p text.
std::vector<slXMLStartTag> slReadXMLStartTags(const std::string& text);

/// The value of attribute @p name among @p attributes, or null.
const std::string* slFindXMLAttribute(const slXMLAttributes& attributes, const std::string& name);

#endif
