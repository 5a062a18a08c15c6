#include "slOBJFormat.h"

#include "slPointDeduplication.h"
#include "slTextParsing.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <unordered_map>
#include <utility>

namespace
{
/// One parsed line's cursor; every parse function returns false on anything
/// outside the accepted subset.
using Cursor = slTextCursor;

/// The form of an element's corners: bit 1 set if they name a vt, bit 2 a vn.
enum Form
{
  Unknown = -1,
  V = 0,
  VT = 1,
  VN = 2,
  VTN = 3,
  Mixed = 4 // faces of several forms
};

/// Reads an element's corners, all of one form, into @p corners (v, vt,
/// vn; 0 where absent) and that form into @p form.
bool element(Cursor& c, int& form, std::vector<std::int64_t>& corners, std::int64_t& count)
{
  count = 0;
  for (c.skipBlanks(); c.at < c.end; c.skipBlanks())
  {
    std::int64_t v = 0, t = 0, n = 0;
    if (!c.index(v))
    {
      return false;
    }
    int here = V;
    if (c.at < c.end && *c.at == '/')
    {
      ++c.at;
      if (c.at < c.end && *c.at == '/')
      {
        ++c.at;
        if (!c.index(n))
        {
          return false;
        }
        here = VN;
      }
      else
      {
        if (!c.index(t))
        {
          return false;
        }
        here = VT;
        if (c.at < c.end && *c.at == '/')
        {
          ++c.at;
          if (!c.index(n))
          {
            return false;
          }
          here = VTN;
        }
      }
    }
    if (!c.atSeparator() || (form != Unknown && form != here))
    {
      return false;
    }
    form = here;
    corners.push_back(v);
    corners.push_back(t);
    corners.push_back(n);
    ++count;
  }
  return count >= 1;
}

/// The first word of the rest of the line (empty if none), as vtkOBJReader
/// reads a "usemtl" or "mtllib" name (sscanf "%s", a stream's >>). False if
/// the rest holds a control byte other than a tab, which VTK would take for
/// white space where this parser does not.
bool firstWord(Cursor& c, std::string& word)
{
  if (std::find_if(c.at, c.end, [](char b) { return static_cast<unsigned char>(b) < 0x20 && b != '\t'; }) != c.end)
  {
    return false;
  }
  c.skipBlanks();
  const char* start = c.at;
  while (c.at < c.end && *c.at != ' ' && *c.at != '\t')
  {
    ++c.at;
  }
  word.assign(start, c.at);
  return true;
}

} // namespace

namespace
{
/// What one stretch of whole lines holds.
struct Chunk
{
  std::vector<float> v, vt, vn;
  std::vector<std::int64_t> corners;     // v index - 1 per face corner
  std::vector<std::int32_t> t, n;        // vt and vn index per face corner, 0 for none (see sameIndex)
  std::vector<std::int64_t> faceCorners; // corners per face
  // "l" and "p" elements: v index - 1 per corner, corners per element.
  std::vector<std::int64_t> lineIds, lineSizes, vertexIds, vertexSizes;
  std::int64_t lineTexture = 0; // the largest vt index of an "l" corner (checked, then ignored as VTK does)
  int form = Unknown;           // the faces' one form, or Mixed
  int given = 0;                // the Form bits some face has
  int everyFace = VTN;          // the Form bits every face has
  int kept = 0;                 // which of t (bit 1) and n (bit 2) are filled, once spelt out
  bool ok = true;
  // What vtkOBJReader makes of groups and materials: the place of each "g"
  // and "usemtl" line as the number of faces before it in this stretch, the
  // "mtllib" lines' names, and the first face of plain "v" corners (VTK's
  // material "NO_MATERIAL").
  std::vector<std::int64_t> groups;
  std::vector<std::pair<std::int64_t, std::string>> materials;
  std::vector<std::string> libraries;
  std::int64_t firstPlainFace = -1;
  // Every face so far has one form, and every corner names its v index for
  // vt and vn too (the common case, "f 1//1 2//2 3//3"): t and n are then
  // left empty, which saves writing, joining and faulting in 8 bytes per
  // corner, until spelt out.
  bool sameIndex = true;

  /// Fills t and n (those @p keep names) from the corners' v indices and
  /// the faces' one form; from then on every corner's t and n are kept.
  void spellOut(int keep)
  {
    if (!this->sameIndex)
    {
      return;
    }
    this->sameIndex = false;
    this->kept = keep;
    const int has = this->form == Unknown ? V : this->form;
    for (std::int64_t a : this->corners)
    {
      if (keep & VT)
      {
        this->t.push_back(has & VT ? static_cast<std::int32_t>(a + 1) : 0);
      }
      if (keep & VN)
      {
        this->n.push_back(has & VN ? static_cast<std::int32_t>(a + 1) : 0);
      }
    }
  }

  /// Adds, spelt out, the arrays among t and n that @p keep names and no
  /// face so far needed: zero for every corner.
  void widen(int keep)
  {
    if ((keep & VT) && !(this->kept & VT))
    {
      this->t.assign(this->corners.size(), 0);
    }
    if ((keep & VN) && !(this->kept & VN))
    {
      this->n.assign(this->corners.size(), 0);
    }
    this->kept |= keep;
  }
};

/// Parses the whole lines in [@p begin, @p end) into @p chunk.
void parseLines(const char* begin, const char* end, Chunk& chunk)
{
  std::vector<std::int64_t> corners;
  for (const char* line = begin; line < end;)
  {
    const char* next = static_cast<const char*>(std::memchr(line, '\n', static_cast<std::size_t>(end - line)));
    next = next ? next : end;
    const char* lineEnd = next > line && next[-1] == '\r' ? next - 1 : next;
    const std::size_t lineLength = static_cast<std::size_t>(lineEnd - line);
    if (lineLength > 1000 || std::find(line, lineEnd, '\0') != lineEnd)
    {
      chunk.ok = false;
      return;
    }
    Cursor c{ line, lineEnd };
    line = next + 1;
    c.skipBlanks();
    if (c.at == c.end || *c.at == '#')
    {
      continue;
    }
    const char* keyword = c.at;
    while (c.at < c.end && *c.at != ' ' && *c.at != '\t')
    {
      ++c.at;
    }
    const std::size_t length = static_cast<std::size_t>(c.at - keyword);
    float x = 0, y = 0, z = 0;
    bool ok = true;
    if (length == 1 && keyword[0] == 'v')
    {
      // Numbers after x, y, z (a vertex colour r g b, a weight w) are
      // read and dropped: vtkOBJReader reads the first three and ignores
      // the rest of the line.
      ok = c.number(x) && c.number(y) && c.number(z);
      for (float ignored = 0; ok && !c.done();)
      {
        ok = c.number(ignored);
      }
      chunk.v.insert(chunk.v.end(), { x, y, z });
    }
    else if (length == 2 && keyword[0] == 'v' && keyword[1] == 'n')
    {
      ok = c.number(x) && c.number(y) && c.number(z) && c.done();
      chunk.vn.insert(chunk.vn.end(), { x, y, z });
    }
    else if (length == 2 && keyword[0] == 'v' && keyword[1] == 't')
    {
      ok = c.number(x) && c.number(y) && c.done();
      chunk.vt.insert(chunk.vt.end(), { x, y });
    }
    else if (length == 1 && keyword[0] == 'f')
    {
      int here = Unknown;
      std::int64_t count = 0;
      corners.clear();
      ok = element(c, here, corners, count) && count >= 3;
      // Faces may differ in form ("f 1//1 2//1 3//1" beside "f 1 2 4"):
      // t and n then hold 0 for the corners of faces without them.
      chunk.form = chunk.form == Unknown ? here : chunk.form;
      const bool sameForm = chunk.form == here;
      const int keep = chunk.given | here;
      for (std::size_t k = 0; ok && k < corners.size(); k += 3)
      {
        const bool same =
          sameForm && (!(here & VT) || corners[k + 1] == corners[k]) && (!(here & VN) || corners[k + 2] == corners[k]);
        if (!(chunk.sameIndex && same))
        {
          chunk.spellOut(keep); // before this corner joins the corners spelt out
          chunk.widen(keep);
          if (keep & VT)
          {
            chunk.t.push_back(static_cast<std::int32_t>(corners[k + 1]));
          }
          if (keep & VN)
          {
            chunk.n.push_back(static_cast<std::int32_t>(corners[k + 2]));
          }
        }
        chunk.corners.push_back(corners[k] - 1);
      }
      chunk.form = sameForm ? here : Mixed;
      chunk.given = keep;
      chunk.everyFace &= here;
      if (here == V && chunk.firstPlainFace < 0)
      {
        chunk.firstPlainFace = static_cast<std::int64_t>(chunk.faceCorners.size());
      }
      chunk.faceCorners.push_back(count);
    }
    else if (length == 1 && (keyword[0] == 'l' || keyword[0] == 'p'))
    {
      // As vtkOBJReader reads them: "l" corners v or v/vt (the vt unused),
      // "p" corners v; VTK's lines and vertex cells.
      const bool line = keyword[0] == 'l';
      int here = Unknown;
      std::int64_t count = 0;
      corners.clear();
      ok = element(c, here, corners, count) && count >= (line ? 2 : 1) && (here == V || (line && here == VT));
      for (std::size_t k = 0; ok && k < corners.size(); k += 3)
      {
        (line ? chunk.lineIds : chunk.vertexIds).push_back(corners[k] - 1);
        chunk.lineTexture = std::max(chunk.lineTexture, corners[k + 1]);
      }
      (line ? chunk.lineSizes : chunk.vertexSizes).push_back(count);
    }
    else if (length == 1 && (keyword[0] == 'o' || keyword[0] == 's'))
    {
      // Object names and smoothing groups: vtkOBJReader ignores them.
    }
    else if (length == 1 && keyword[0] == 'g')
    {
      chunk.groups.push_back(static_cast<std::int64_t>(chunk.faceCorners.size())); // the names do not matter
    }
    else if (length == 6 && std::memcmp(keyword, "usemtl", 6) == 0)
    {
      // vtkOBJReader copies the name into a char[100].
      std::string name;
      ok = firstWord(c, name) && !name.empty() && name.size() <= 99;
      chunk.materials.emplace_back(static_cast<std::int64_t>(chunk.faceCorners.size()), std::move(name));
    }
    else if (length == 6 && std::memcmp(keyword, "mtllib", 6) == 0)
    {
      std::string name;
      ok = firstWord(c, name);
      chunk.libraries.push_back(std::move(name));
    }
    else
    {
      ok = false;
    }
    if (!ok)
    {
      chunk.ok = false;
      return;
    }
  }
}

template <typename T>
std::vector<T> joined(std::vector<Chunk>& chunks, std::vector<T> Chunk::*member)
{
  std::size_t total = 0;
  for (const Chunk& c : chunks)
  {
    total += (c.*member).size();
  }
  std::vector<T> out;
  out.reserve(total);
  for (Chunk& c : chunks)
  {
    out.insert(out.end(), (c.*member).begin(), (c.*member).end());
    std::vector<T>().swap(c.*member);
  }
  return out;
}

/// vtkOBJReader's "GroupIds" from the places of the "g" lines (faces before
/// each, in order): it counts them from -1 and raises the count to 0 at the
/// first face, so a face has the number of "g" lines before it, less one if
/// one comes before the first face. Empty when every face has 0. False if
/// VTK's int count would overflow.
bool groupIds(const std::vector<std::int64_t>& places, std::int64_t faces, std::vector<float>& ids)
{
  ids.clear();
  if (places.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
  {
    return false;
  }
  if (faces == 0)
  {
    return true; // declined later
  }
  const std::size_t first = !places.empty() && places[0] == 0 ? 1 : 0;
  if (std::upper_bound(places.begin(), places.end(), faces - 1) - places.begin() == static_cast<std::ptrdiff_t>(first))
  {
    return true; // no "g" line between faces: all 0
  }
  ids.resize(static_cast<std::size_t>(faces));
  std::size_t before = 0; // "g" lines before face f
  for (std::int64_t f = 0; f < faces; ++f)
  {
    while (before < places.size() && places[before] <= f)
    {
      ++before;
    }
    // As VTK converts its int count.
    ids[static_cast<std::size_t>(f)] = static_cast<float>(static_cast<int>(before - first));
  }
  return true;
}

/// vtkOBJReader 9.1's name for the material it gives, once, to the first
/// face of plain "v" corners.
const std::string noMaterial = "NO_MATERIAL";

/// vtkOBJReader's texture coordinates where no face corner gives one.
const float noTCoords[2] = { -1.0f, -1.0f };

/// A "usemtl" line or the first face of plain "v" corners: the faces before
/// it, and its material's name.
using MaterialStart = std::pair<std::int64_t, const std::string*>;

/// vtkOBJReader's "MaterialIds", "MaterialNames" and "MaterialLibraries"
/// from @p starts, the places (faces before each) and names of the "usemtl"
/// lines and of the first face of plain "v" corners, in file order: each
/// starts its material at its place (the last of one place wins), the faces
/// before the first have id 0, and ids number the names in order of first
/// appearance. There are materials unless no name or only NO_MATERIAL
/// appears.
void materialIds(const std::vector<MaterialStart>& starts, std::int64_t faces,
  std::vector<std::string> libraries, slOBJAttributes& attributes)
{
  std::unordered_map<std::string, std::int32_t> idOf;
  std::vector<std::string> names;
  std::vector<std::pair<std::int64_t, std::int32_t>> idFrom; // (first face, id), by face
  for (const auto& start : starts)
  {
    const auto known = idOf.emplace(*start.second, static_cast<std::int32_t>(names.size()));
    if (known.second)
    {
      names.push_back(*start.second);
    }
    if (!idFrom.empty() && idFrom.back().first == start.first)
    {
      idFrom.back().second = known.first->second;
    }
    else
    {
      idFrom.emplace_back(start.first, known.first->second);
    }
  }
  if (names.empty() || (names.size() == 1 && names[0] == noMaterial))
  {
    return;
  }
  attributes.materialIds.assign(static_cast<std::size_t>(faces), 0);
  for (std::size_t k = 0; k < idFrom.size(); ++k)
  {
    const std::int64_t end = k + 1 < idFrom.size() ? std::min(idFrom[k + 1].first, faces) : faces;
    std::fill(attributes.materialIds.begin() + std::min(idFrom[k].first, faces),
      attributes.materialIds.begin() + end, idFrom[k].second);
  }
  attributes.materialNames = std::move(names);
  attributes.materialLibraries = std::move(libraries);
}

/// vtkOBJReader 9.1's texture coordinate arrays, from the "usemtl" lines
/// @p lines in file order: one per name, else one named "TCoords", named in
/// attributes.tcoordsNames in the order of VTK's
/// std::unordered_map<std::string, vtkFloatArray*>, into which it emplaces
/// the names in order of first appearance (its order depends only on the
/// names and that sequence: std::hash<std::string> is the same on every
/// run). Fills @p arrayFrom with the array of each face, (first face,
/// array) by face: that of the "usemtl" line before it, and, before the
/// first, that of the file's last (VTK's name buffer still holds it from
/// the pass that made the arrays). False if an array would be named
/// "Normals" (VTK's normals then replace it).
bool tcoordsArrays(const std::vector<MaterialStart>& lines, slOBJAttributes& attributes,
  std::vector<std::pair<std::int64_t, std::int32_t>>& arrayFrom)
{
  std::unordered_map<std::string, std::int32_t> arrays;
  for (const MaterialStart& line : lines)
  {
    arrays.emplace(*line.second, 0);
  }
  if (arrays.empty())
  {
    arrays.emplace("TCoords", 0);
  }
  for (auto& array : arrays)
  {
    array.second = static_cast<std::int32_t>(attributes.tcoordsNames.size());
    attributes.tcoordsNames.push_back(array.first);
  }
  arrayFrom.assign(1, { 0, arrays.at(lines.empty() ? std::string("TCoords") : *lines.back().second) });
  for (const MaterialStart& line : lines)
  {
    arrayFrom.emplace_back(line.first, arrays.at(*line.second));
  }
  return arrays.count("Normals") == 0;
}

/// Fills @p attributes from the stretches' "g", "usemtl" and "mtllib" lines
/// and first faces of plain "v" corners, given whether faces have texture
/// coordinates (@p textured), and then @p tcoordsFrom with the texture
/// coordinate array of each face (tcoordsArrays). False where vtkOBJReader
/// 9.1 gives what this parser does not: texture coordinates of a material
/// named "Normals" (which VTK's normals then replace); materials beside "l"
/// and "p" elements (VTK's "MaterialIds" then has a value per face only,
/// and slMeshReader refuses the file).
bool attributesOf(const std::vector<Chunk>& chunks, bool textured, slOBJAttributes& attributes,
  std::vector<std::pair<std::int64_t, std::int32_t>>& tcoordsFrom)
{
  bool elements = false; // "l" or "p"
  std::vector<std::int64_t> groups;
  std::vector<MaterialStart> starts, lines; // with and without NO_MATERIAL
  std::vector<std::string> libraries;
  bool plainFaceSeen = false;
  std::int64_t faces = 0; // before the stretch
  for (const Chunk& c : chunks)
  {
    for (std::int64_t place : c.groups)
    {
      groups.push_back(faces + place);
    }
    // The file's first face of plain "v" corners starts its material after
    // the "usemtl" lines before it.
    const std::int64_t plainFace = plainFaceSeen ? -1 : c.firstPlainFace;
    plainFaceSeen = plainFaceSeen || plainFace >= 0;
    bool plainFaceNoted = plainFace < 0;
    const auto notePlainFace = [&] {
      starts.emplace_back(faces + plainFace, &noMaterial);
      plainFaceNoted = true;
    };
    for (const auto& m : c.materials)
    {
      if (!plainFaceNoted && m.first > plainFace)
      {
        notePlainFace();
      }
      starts.emplace_back(faces + m.first, &m.second);
      lines.emplace_back(faces + m.first, &m.second);
    }
    if (!plainFaceNoted)
    {
      notePlainFace();
    }
    libraries.insert(libraries.end(), c.libraries.begin(), c.libraries.end());
    elements = elements || !c.lineSizes.empty() || !c.vertexSizes.empty();
    faces += static_cast<std::int64_t>(c.faceCorners.size());
  }
  if ((textured && !tcoordsArrays(lines, attributes, tcoordsFrom)) || !groupIds(groups, faces, attributes.groupIds))
  {
    return false;
  }
  materialIds(starts, faces, std::move(libraries), attributes);
  return attributes.materialIds.empty() || !elements;
}

/// Which of vtkOBJReader's texture coordinate arrays hold the value of each
/// vt: those of the faces that name it (@p arrayFrom, (first face, array)
/// by face; @p t, the vt index of each face corner, 0 for none, or, if
/// @p sameIndex, every corner's v index), and none for a vt (-1, -1), which
/// every array holds alike. Numbers the sets of arrays in
/// attributes.tcoordsSets in order of first appearance by vt index, the
/// empty one first, and returns the set of each vt index (0: none).
std::vector<std::int32_t> vtSets(const slMeshArrays& mesh, const std::vector<std::int32_t>& t, bool sameIndex,
  const std::vector<float>& vt, const std::vector<std::pair<std::int64_t, std::int32_t>>& arrayFrom,
  slOBJAttributes& attributes)
{
  const std::size_t nt = vt.size() / 2, arrays = attributes.tcoordsNames.size(), words = (arrays + 63) / 64;
  std::vector<std::uint64_t> masks((nt + 1) * words);
  std::size_t from = 0;
  const std::size_t faces = mesh.offsets.size() - 1;
  for (std::size_t f = 0; f < faces; ++f)
  {
    while (from + 1 < arrayFrom.size() && static_cast<std::size_t>(arrayFrom[from + 1].first) <= f)
    {
      ++from;
    }
    const auto a = static_cast<std::size_t>(arrayFrom[from].second);
    const std::uint64_t bit = std::uint64_t(1) << (a % 64);
    for (auto k = static_cast<std::size_t>(mesh.offsets[f]); k < static_cast<std::size_t>(mesh.offsets[f + 1]); ++k)
    {
      const auto tk = static_cast<std::size_t>(sameIndex ? mesh.connectivity[k] + 1 : t[k]);
      masks[tk * words + a / 64] |= tk > 0 ? bit : 0;
    }
  }
  std::vector<std::int32_t> setOf(nt + 1);
  std::unordered_map<std::string, std::int32_t> ids;
  attributes.tcoordsSets.clear();
  for (std::size_t i = 0; i <= nt; ++i)
  {
    std::uint64_t* mask = &masks[i * words];
    if (i > 0 && std::memcmp(&vt[2 * (i - 1)], noTCoords, sizeof(noTCoords)) == 0)
    {
      std::fill(mask, mask + words, 0);
    }
    // Neighbouring vt mostly have one set: only a change is looked up.
    if (i > 0 && std::equal(mask, mask + words, mask - words))
    {
      setOf[i] = setOf[i - 1];
      continue;
    }
    const auto known = ids.emplace(std::string(reinterpret_cast<const char*>(mask), words * sizeof(std::uint64_t)),
      static_cast<std::int32_t>(attributes.tcoordsSets.size()));
    if (known.second)
    {
      std::vector<bool> set(arrays);
      for (std::size_t a = 0; a < arrays; ++a)
      {
        set[a] = (mask[a / 64] >> (a % 64)) & 1;
      }
      attributes.tcoordsSets.push_back(std::move(set));
    }
    setOf[i] = known.first->second;
  }
  return setOf;
}
} // namespace

bool slParseOBJ(
  const char* text, std::size_t size, bool merge, slMeshArrays& mesh, slOBJAttributes& attributes, int threads)
{
  // A UTF-8 byte order mark (some Windows editors write one) is not part of
  // the first line's keyword.
  if (size >= 3 && std::memcmp(text, "\xEF\xBB\xBF", 3) == 0)
  {
    text += 3;
    size -= 3;
  }
  // Lines split into one stretch per thread: indices are absolute, so the
  // stretches parse independently and are joined in order.
  std::vector<Chunk> chunks(slTextStretchCount(size, threads));
  const std::vector<const char*> bounds = slLineStretches(text, size, chunks.size());
  slRunEach(chunks.size(), [&](std::size_t k) { parseLines(bounds[k], bounds[k + 1], chunks[k]); });
  int given = 0, everyFace = VTN;
  std::int64_t lineTexture = 0;
  for (const Chunk& c : chunks)
  {
    if (!c.ok)
    {
      return false;
    }
    given |= c.given;
    everyFace &= c.everyFace;
    lineTexture = std::max(lineTexture, c.lineTexture);
  }
  const bool hasT = (given & VT) != 0, hasN = (given & VN) != 0;
  attributes = slOBJAttributes();
  std::vector<std::pair<std::int64_t, std::int32_t>> tcoordsFrom;
  if (!attributesOf(chunks, hasT, attributes, tcoordsFrom))
  {
    return false;
  }
  // t and n are kept per corner only if some corner names another index,
  // or some faces have no vt (t then tells the corners with one from them).
  const bool sameIndex = std::all_of(chunks.begin(), chunks.end(), [](const Chunk& c) { return c.sameIndex; }) &&
    (!hasT || (everyFace & VT));
  if (!sameIndex)
  {
    for (Chunk& c : chunks)
    {
      c.spellOut(given);
      c.widen(given);
    }
  }
  std::vector<float> v = joined(chunks, &Chunk::v), vt = joined(chunks, &Chunk::vt), vn = joined(chunks, &Chunk::vn);
  std::vector<std::int32_t> t = joined(chunks, &Chunk::t), n = joined(chunks, &Chunk::n);
  mesh = slMeshArrays();
  mesh.connectivity = joined(chunks, &Chunk::corners);
  const std::vector<std::int64_t> faceCorners = joined(chunks, &Chunk::faceCorners);
  mesh.offsets.resize(faceCorners.size() + 1);
  mesh.offsets[0] = 0;
  for (std::size_t f = 0; f < faceCorners.size(); ++f)
  {
    mesh.offsets[f + 1] = mesh.offsets[f] + faceCorners[f];
  }
  // The lines' and vertex cells' ids follow the faces' (slMeshArrays).
  const std::size_t cornerCount = mesh.connectivity.size();
  for (std::vector<std::int64_t> Chunk::*ids : { &Chunk::lineIds, &Chunk::vertexIds })
  {
    const std::vector<std::int64_t> more = joined(chunks, ids);
    mesh.connectivity.insert(mesh.connectivity.end(), more.begin(), more.end());
  }
  mesh.lineSizes = joined(chunks, &Chunk::lineSizes);
  mesh.vertexSizes = joined(chunks, &Chunk::vertexSizes);
  const bool elements = mesh.connectivity.size() > cornerCount; // "l" or "p"

  const std::int64_t nv = static_cast<std::int64_t>(v.size() / 3), nt = static_cast<std::int64_t>(vt.size() / 2),
                     nn = static_cast<std::int64_t>(vn.size() / 3);
  if (faceCorners.empty() || (!hasT && nt > 0) || (!hasN && nn > 0) || lineTexture > nt)
  {
    return false;
  }
  bool sameT = true, sameN = true; // every corner naming a vt (vn) names its v index
  for (std::size_t k = 0; k < mesh.connectivity.size(); ++k)
  {
    const std::int64_t a = mesh.connectivity[k];
    if (a >= nv)
    {
      return false;
    }
    if (sameIndex || k >= cornerCount)
    {
      continue; // t and n are 0 or a + 1: checked against nt and nn below
    }
    if ((hasT && t[k] > nt) || (hasN && n[k] > nn))
    {
      return false;
    }
    sameT = sameT && (!hasT || t[k] == 0 || t[k] == a + 1);
    sameN = sameN && (!hasN || n[k] == 0 || n[k] == a + 1);
  }
  // The points vtkOBJReader makes: the v list, or one per corner when a vt
  // or vn index differs from its v index. Normals per corner need a vn at
  // every corner: every face has one, and there is no "l" or "p" element
  // (vtkOBJReader 9.1 drops such faces and elements instead). Where some
  // point would have no normal, the normals are left out: the programs
  // compute them.
  const bool normalsPerCorner = (everyFace & VN) && !elements;
  bool normals = hasN && (sameN || normalsPerCorner);
  const bool same = sameT && (sameN || !normals);
  normals = normals && (same || normalsPerCorner);
  if (same && ((hasT && nt != nv) || (normals && nn != nv)))
  {
    return false; // vtkOBJReader's arrays would not match its points
  }
  // A point's texture coordinates, and which of vtkOBJReader's arrays hold
  // them, follow from its vt; the set of each point is needed only where
  // not every point with texture coordinates has the same.
  const std::vector<std::int32_t> setOf =
    hasT ? vtSets(mesh, t, sameIndex, vt, tcoordsFrom, attributes) : std::vector<std::int32_t>();
  const bool pointSets = attributes.tcoordsSets.size() > 2;
  if (same)
  {
    if (hasT)
    {
      // vtkOBJReader gives a point its vt through a face corner naming
      // one, and (-1, -1) to the points no such corner names.
      for (std::size_t i = 0; i < static_cast<std::size_t>(nv); ++i)
      {
        if (setOf[i + 1] == 0)
        {
          vt[2 * i] = vt[2 * i + 1] = -1.0f;
        }
      }
      if (pointSets)
      {
        attributes.pointTCoordsSets.assign(setOf.begin() + 1, setOf.end());
      }
    }
    mesh.points = std::move(v);
    mesh.tcoords = std::move(vt);
    mesh.normals = normals ? std::move(vn) : std::vector<float>();
  }
  else
  {
    const std::size_t total = mesh.connectivity.size();
    mesh.points.resize(3 * total);
    mesh.tcoords.resize(hasT ? 2 * total : 0);
    mesh.normals.resize(normals ? 3 * total : 0);
    attributes.pointTCoordsSets.resize(pointSets ? total : 0);
    for (std::size_t k = 0; k < total; ++k)
    {
      const std::size_t a = static_cast<std::size_t>(mesh.connectivity[k]);
      std::memcpy(&mesh.points[3 * k], &v[3 * a], 3 * sizeof(float));
      if (hasT)
      {
        const std::int32_t tk = k < cornerCount ? t[k] : 0;
        std::memcpy(
          &mesh.tcoords[2 * k], tk > 0 ? &vt[2 * static_cast<std::size_t>(tk - 1)] : noTCoords, 2 * sizeof(float));
        if (pointSets)
        {
          attributes.pointTCoordsSets[k] = setOf[static_cast<std::size_t>(tk)];
        }
      }
      if (normals)
      {
        std::memcpy(&mesh.normals[3 * k], &vn[3 * static_cast<std::size_t>(n[k] - 1)], 3 * sizeof(float));
      }
      mesh.connectivity[k] = static_cast<std::int64_t>(k);
    }
  }
  if (merge)
  {
    slDeduplicatePoints(mesh, attributes.pointTCoordsSets);
  }
  return true;
}

void slOBJTCoordsArray(
  const slOBJAttributes& attributes, std::size_t a, const float* tcoords, std::size_t points, float* out)
{
  std::vector<char> holds; // by set
  for (const std::vector<bool>& set : attributes.tcoordsSets)
  {
    holds.push_back(set[a]);
  }
  const std::vector<std::int32_t>& sets = attributes.pointTCoordsSets;
  for (std::size_t p = 0; p < points; ++p)
  {
    const float u = tcoords[2 * p], v = tcoords[2 * p + 1];
    const std::size_t s = !sets.empty() ? static_cast<std::size_t>(sets[p])
                                        : std::memcmp(&tcoords[2 * p], noTCoords, sizeof(noTCoords)) != 0 ? 1 : 0;
    const bool held = s < holds.size() && holds[s];
    out[2 * p] = held ? u : noTCoords[0];
    out[2 * p + 1] = held ? v : noTCoords[1];
  }
}
