#include "slXMLStartTags.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <iterator>

namespace
{
bool isXMLSpace(char c)
{
  return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}

/// The end of the start tag that begins at @p at in @p text: the position
/// of its closing '>' outside quoted values (npos if the text ends first).
size_t tagEnd(const std::string& text, size_t at)
{
  char quote = 0;
  for (size_t i = at; i < text.size(); ++i)
  {
    const char c = text[i];
    if (quote)
    {
      quote = c == quote ? 0 : quote;
    }
    else if (c == '"' || c == '\'')
    {
      quote = c;
    }
    else if (c == '>')
    {
      return i;
    }
  }
  return std::string::npos;
}

/// @p value with its character references and predefined entities decoded
/// and each white space character made a space, as expat hands attribute
/// values to VTK's XML parser.
std::string xmlAttributeValue(const std::string& value)
{
  std::string out;
  // The first ';' at or after i, searched for again only once i has passed
  // it, so that a value of many '&' and no ';' is read once, not once per '&'.
  size_t nextSemicolon = value.find(';');
  for (size_t i = 0; i < value.size(); ++i)
  {
    const char c = value[i];
    if (c == '&' && nextSemicolon != std::string::npos && nextSemicolon < i)
    {
      nextSemicolon = value.find(';', i);
    }
    const size_t semicolon = c == '&' ? nextSemicolon : std::string::npos;
    if (semicolon == std::string::npos)
    {
      out += isXMLSpace(c) ? ' ' : c;
      continue;
    }
    const std::string entity = value.substr(i + 1, semicolon - i - 1);
    static const char* const names[][2] = { { "lt", "<" }, { "gt", ">" }, { "amp", "&" }, { "quot", "\"" },
      { "apos", "'" } };
    bool known = false;
    for (const auto& name : names)
    {
      if (entity == name[0])
      {
        out += name[1];
        known = true;
      }
    }
    if (!known && entity.size() > 1 && entity[0] == '#')
    {
      const bool hex = entity[1] == 'x';
      const unsigned long code = std::strtoul(entity.c_str() + (hex ? 2 : 1), nullptr, hex ? 16 : 10);
      // A character outside ASCII cannot be part of a number or of one of
      // VTK's keywords: '?' stands for it.
      out += code > 0 && code < 128 ? static_cast<char>(code) : '?';
      known = true;
    }
    if (!known)
    {
      out += value.substr(i, semicolon - i + 1);
    }
    i = semicolon;
  }
  return out;
}

/// The attributes of the start tag @p tag ("<Name" up to its '>'), read as
/// expat reads them: white space around '=', single or double quotes,
/// references decoded. Ends at the first thing expat would refuse (it then
/// refuses the file).
slXMLAttributes xmlAttributes(const std::string& tag)
{
  slXMLAttributes attributes;
  size_t i = 1;
  while (i < tag.size() && !isXMLSpace(tag[i]) && tag[i] != '/')
  {
    ++i; // the element's name
  }
  const auto skipSpace = [&] {
    while (i < tag.size() && isXMLSpace(tag[i]))
    {
      ++i;
    }
  };
  while (i < tag.size())
  {
    while (i < tag.size() && (isXMLSpace(tag[i]) || tag[i] == '/'))
    {
      ++i;
    }
    const size_t nameBegin = i;
    while (i < tag.size() && !isXMLSpace(tag[i]) && tag[i] != '=')
    {
      ++i;
    }
    const size_t nameEnd = i;
    skipSpace();
    if (i >= tag.size() || tag[i] != '=')
    {
      break;
    }
    ++i;
    skipSpace();
    const size_t close = i < tag.size() && (tag[i] == '"' || tag[i] == '\'') ? tag.find(tag[i], i + 1) : std::string::npos;
    if (close == std::string::npos)
    {
      break;
    }
    attributes.emplace_back(tag.substr(nameBegin, nameEnd - nameBegin), xmlAttributeValue(tag.substr(i + 1, close - i - 1)));
    i = close + 1;
  }
  return attributes;
}
} // namespace

std::vector<slXMLStartTag> slReadXMLStartTags(const std::string& text)
{
  std::vector<slXMLStartTag> tags;
  for (size_t at = text.find('<'); at != std::string::npos; at = text.find('<', at + 1))
  {
    // Comments, CDATA sections and processing instructions may hold any
    // character but their end marker, quotes and '<' included: skip them.
    static const char* const skipped[][2] = { { "<!--", "-->" }, { "<![CDATA[", "]]>" }, { "<?", "?>" } };
    const auto kind = std::find_if(std::begin(skipped), std::end(skipped),
      [&](const char* const* marks) { return text.compare(at, std::strlen(marks[0]), marks[0]) == 0; });
    if (kind != std::end(skipped))
    {
      at = text.find((*kind)[1], at + std::strlen((*kind)[0]));
      if (at == std::string::npos)
      {
        break;
      }
      continue;
    }
    // Elsewhere in a well-formed file '<' starts a tag, and its value quotes
    // and '>' close: where they do not, expat refuses the file. The next tag
    // starts after this one's end, so that no character is read twice.
    const size_t end = tagEnd(text, at);
    if (end == std::string::npos)
    {
      break;
    }
    size_t nameEnd = at + 1;
    while (nameEnd < end && !isXMLSpace(text[nameEnd]) && text[nameEnd] != '/')
    {
      ++nameEnd;
    }
    const std::string name = text.substr(at + 1, nameEnd - at - 1);
    const size_t begin = at;
    at = end;
    if (name.empty() || name[0] == '/' || name[0] == '!')
    {
      continue; // an end tag, or a declaration (DOCTYPE, ENTITY)
    }
    tags.push_back({ name, begin, end, xmlAttributes(text.substr(begin, end - begin)) });
    if (name == "AppendedData")
    {
      break;
    }
  }
  return tags;
}

const std::string* slFindXMLAttribute(const slXMLAttributes& attributes, const std::string& name)
{
  for (const auto& attribute : attributes)
  {
    if (attribute.first == name)
    {
      return &attribute.second;
    }
  }
  return nullptr;
}
