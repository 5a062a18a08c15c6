#include "slOBJFormat.h"

#include "slPointDeduplication.h"

#include <algorithm>
#include <atomic>
#include <charconv>
#include <cmath>
#include <condition_variable>
#include <cstring>
#include <exception>
#include <limits>
#include <mutex>
#include <thread>

namespace
{
/// One parsed line's cursor; every parse function returns false on anything
/// outside the accepted subset.
struct Cursor
{
  const char* at;
  const char* end; // the line's end, '\r' excluded

  void skipBlanks()
  {
    while (this->at < this->end && (*this->at == ' ' || *this->at == '\t'))
    {
      ++this->at;
    }
  }
  bool atSeparator() const { return this->at == this->end || *this->at == ' ' || *this->at == '\t'; }

  bool number(float& value)
  {
    this->skipBlanks();
    const auto r = std::from_chars(this->at, this->end, value, std::chars_format::general);
    if (r.ec != std::errc() || !std::isfinite(value))
    {
      return false;
    }
    this->at = r.ptr;
    return this->atSeparator();
  }
  bool index(std::int64_t& value)
  {
    const auto r = std::from_chars(this->at, this->end, value);
    if (r.ec != std::errc() || value <= 0 || value > std::numeric_limits<int>::max())
    {
      return false;
    }
    this->at = r.ptr;
    return true;
  }
  bool done()
  {
    this->skipBlanks();
    return this->at == this->end;
  }
};

enum Form
{
  Unknown = -1,
  V = 0,
  VT = 1,
  VN = 2,
  VTN = 3
};

/// Reads a face's corners into @p corners (v, vt, vn; 0 where absent).
bool face(Cursor& c, int& form, std::vector<std::int64_t>& corners, std::int64_t& count)
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
  return count >= 3;
}

void append(std::string& out, double value, bool isDouble)
{
  char buffer[40];
  const auto r = isDouble ? std::to_chars(buffer, buffer + sizeof(buffer), value)
                          : std::to_chars(buffer, buffer + sizeof(buffer), static_cast<float>(value));
  out.append(buffer, r.ptr);
}

void appendIndex(std::string& out, std::int64_t value)
{
  char buffer[24];
  const auto r = std::to_chars(buffer, buffer + sizeof(buffer), value);
  out.append(buffer, r.ptr);
}

/// The @p keyword lines of tuples [@p begin, @p end) of @p values.
void tuples(std::string& out, const char* keyword, const slValuesView& values, std::int64_t begin, std::int64_t end,
  int components)
{
  for (std::int64_t i = begin; i < end; ++i)
  {
    out += keyword;
    for (int k = 0; k < components; ++k)
    {
      out += ' ';
      append(out, values[static_cast<std::size_t>(i * components + k)], values.isDouble);
    }
    out += '\n';
  }
}
} // namespace

namespace
{
/// What one stretch of whole lines holds.
struct Chunk
{
  std::vector<float> v, vt, vn;
  std::vector<std::int64_t> corners;     // v index - 1 per corner
  std::vector<std::int32_t> t, n;        // vt and vn index per corner, when the form has them (see sameIndex)
  std::vector<std::int64_t> faceCorners; // corners per face
  int form = Unknown;
  bool ok = true;
  // Every corner so far names its v index for vt and vn too (the common
  // case, "f 1//1 2//2 3//3"): t and n are then left empty, which saves
  // writing, joining and faulting in 8 bytes per corner, until spelt out.
  bool sameIndex = true;

  /// Fills t and n from the corners' v indices, for the form @p hasT,
  /// @p hasN; from then on every corner's t and n are kept.
  void spellOut(bool hasT, bool hasN)
  {
    if (!this->sameIndex)
    {
      return;
    }
    this->sameIndex = false;
    for (std::int64_t a : this->corners)
    {
      if (hasT)
      {
        this->t.push_back(static_cast<std::int32_t>(a + 1));
      }
      if (hasN)
      {
        this->n.push_back(static_cast<std::int32_t>(a + 1));
      }
    }
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
      ok = c.number(x) && c.number(y) && c.number(z) && c.done();
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
      std::int64_t count = 0;
      corners.clear();
      ok = face(c, chunk.form, corners, count);
      const bool hasT = chunk.form == VT || chunk.form == VTN, hasN = chunk.form == VN || chunk.form == VTN;
      for (std::size_t k = 0; ok && k < corners.size(); k += 3)
      {
        const bool same = (!hasT || corners[k + 1] == corners[k]) && (!hasN || corners[k + 2] == corners[k]);
        if (!(chunk.sameIndex && same))
        {
          chunk.spellOut(hasT, hasN); // before this corner joins the corners spelt out
          if (hasT)
          {
            chunk.t.push_back(static_cast<std::int32_t>(corners[k + 1]));
          }
          if (hasN)
          {
            chunk.n.push_back(static_cast<std::int32_t>(corners[k + 2]));
          }
        }
        chunk.corners.push_back(corners[k] - 1);
      }
      chunk.faceCorners.push_back(count);
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
} // namespace

bool slParseOBJ(const char* text, std::size_t size, bool merge, slMeshArrays& mesh, int threads)
{
  // Lines split into one stretch per thread: indices are absolute, so the
  // stretches parse independently and are joined in order.
  const std::size_t parts = static_cast<std::size_t>(std::max(1, std::min(threads, 64)));
  std::vector<Chunk> chunks(size < (1u << 20) ? 1 : parts);
  std::vector<const char*> bounds{ text };
  for (std::size_t k = 1; k < chunks.size(); ++k)
  {
    const char* at = std::max(bounds.back(), text + size / chunks.size() * k);
    const char* newline = static_cast<const char*>(std::memchr(at, '\n', static_cast<std::size_t>(text + size - at)));
    bounds.push_back(newline ? newline + 1 : text + size);
  }
  bounds.push_back(text + size);
  std::vector<std::thread> workers;
  for (std::size_t k = 1; k < chunks.size(); ++k)
  {
    workers.emplace_back(parseLines, bounds[k], bounds[k + 1], std::ref(chunks[k]));
  }
  parseLines(bounds[0], bounds[1], chunks[0]);
  for (std::thread& w : workers)
  {
    w.join();
  }
  int form = Unknown;
  for (const Chunk& c : chunks)
  {
    if (!c.ok || (c.form != Unknown && form != Unknown && c.form != form))
    {
      return false;
    }
    form = c.form == Unknown ? form : c.form;
  }
  const bool hasT = form == VT || form == VTN, hasN = form == VN || form == VTN;
  // t and n are kept per corner only if some corner names another index.
  const bool sameIndex = std::all_of(chunks.begin(), chunks.end(), [](const Chunk& c) { return c.sameIndex; });
  if (!sameIndex)
  {
    for (Chunk& c : chunks)
    {
      c.spellOut(hasT, hasN);
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

  const std::int64_t nv = static_cast<std::int64_t>(v.size() / 3), nt = static_cast<std::int64_t>(vt.size() / 2),
                     nn = static_cast<std::int64_t>(vn.size() / 3);
  if (form == Unknown || (!hasT && nt > 0) || (!hasN && nn > 0))
  {
    return false;
  }
  const std::size_t cornerCount = mesh.connectivity.size();
  bool same = true; // every corner names one index for v, vt and vn
  for (std::size_t k = 0; k < cornerCount; ++k)
  {
    const std::int64_t a = mesh.connectivity[k];
    if (a >= nv)
    {
      return false;
    }
    if (sameIndex)
    {
      continue; // t and n are a + 1: checked against nt and nn below
    }
    if ((hasT && t[k] > nt) || (hasN && n[k] > nn))
    {
      return false;
    }
    same = same && (!hasT || t[k] == a + 1) && (!hasN || n[k] == a + 1);
  }
  if (same && ((hasT && nt != nv) || (hasN && nn != nv)))
  {
    return false; // vtkOBJReader's arrays would not match its points
  }

  // The points vtkOBJReader makes: the v list, or one per corner.
  if (same)
  {
    mesh.points = std::move(v);
    mesh.tcoords = std::move(vt);
    mesh.normals = std::move(vn);
  }
  else
  {
    mesh.points.resize(3 * cornerCount);
    mesh.tcoords.resize(hasT ? 2 * cornerCount : 0);
    mesh.normals.resize(hasN ? 3 * cornerCount : 0);
    for (std::size_t k = 0; k < cornerCount; ++k)
    {
      const std::size_t a = static_cast<std::size_t>(mesh.connectivity[k]);
      std::memcpy(&mesh.points[3 * k], &v[3 * a], 3 * sizeof(float));
      if (hasT)
      {
        std::memcpy(&mesh.tcoords[2 * k], &vt[2 * static_cast<std::size_t>(t[k] - 1)], 2 * sizeof(float));
      }
      if (hasN)
      {
        std::memcpy(&mesh.normals[3 * k], &vn[3 * static_cast<std::size_t>(n[k] - 1)], 3 * sizeof(float));
      }
      mesh.connectivity[k] = static_cast<std::int64_t>(k);
    }
  }
  if (merge)
  {
    slDeduplicatePoints(mesh);
  }
  return true;
}

namespace
{
/// The "f" lines of polygons [@p begin, @p end) of @p mesh, each corner's
/// index repeated for vt and vn.
void faces(const slMeshView& mesh, std::int64_t begin, std::int64_t end, std::string& out)
{
  // v, v/vt, v//vn or v/vt/vn, all of one index.
  const char* separator = mesh.tcoords.data ? "/" : "//";
  const int repeats = (mesh.tcoords.data ? 1 : 0) + (mesh.normals.data ? 1 : 0);
  const std::size_t digits = std::to_string(mesh.numberOfPoints).size();
  const std::size_t corners = static_cast<std::size_t>(
    mesh.offsets[static_cast<std::size_t>(end)] - mesh.offsets[static_cast<std::size_t>(begin)]);
  out.reserve(static_cast<std::size_t>(end - begin) * 2 + corners * (digits + 2) * static_cast<std::size_t>(1 + repeats));
  for (std::int64_t p = begin; p < end; ++p)
  {
    out += 'f';
    for (std::int64_t k = mesh.offsets[static_cast<std::size_t>(p)]; k < mesh.offsets[static_cast<std::size_t>(p + 1)]; ++k)
    {
      const std::int64_t index = mesh.connectivity[static_cast<std::size_t>(k)] + 1;
      out += ' ';
      appendIndex(out, index);
      for (int r = 0; r < repeats; ++r)
      {
        out += separator;
        appendIndex(out, index);
      }
    }
    out += '\n';
  }
}
} // namespace

void slFormatOBJ(const slMeshView& mesh, const std::function<void(const char*, std::size_t)>& sink, int threads)
{
  // The file in pieces of at most 256k lines (v, vn, vt, then f), formatted
  // on @p threads threads, each taking the next piece. This thread hands
  // the pieces to the sink in order as soon as each is ready, and formats
  // one itself while the next is not: writing overlaps formatting, and the
  // file is never whole in memory (nor copied into one string).
  struct Piece
  {
    int kind; // 0 v, 1 vn, 2 vt, 3 f
    std::int64_t begin, end;
    std::string text;
    bool ready;
  };
  std::vector<Piece> pieces;
  const std::int64_t step = 1 << 18;
  const std::int64_t counts[] = { mesh.numberOfPoints, mesh.normals.data ? mesh.numberOfPoints : 0,
    mesh.tcoords.data ? mesh.numberOfPoints : 0, mesh.numberOfPolygons };
  for (int kind = 0; kind < 4; ++kind)
  {
    for (std::int64_t begin = 0; begin < counts[kind]; begin += step)
    {
      pieces.push_back(Piece{ kind, begin, std::min(counts[kind], begin + step), std::string(), false });
    }
  }
  // Pieces formatted ahead of the writer wait in memory: at most `window`
  // of them past the next to write.
  const std::size_t window = 2 * static_cast<std::size_t>(std::max(threads, 1));
  std::mutex lock;
  std::condition_variable changed;
  std::size_t written = 0; // pieces handed to the sink (under lock)
  bool stop = false;       // a piece or the sink failed (under lock)
  std::exception_ptr failure;
  std::atomic<std::size_t> next{ 0 };
  // Texts already written, kept for the next pieces: memory the kernel
  // has given once is refilled instead of fresh pages being zeroed for
  // every piece.
  std::vector<std::string> spare;
  const auto format = [&](std::size_t k) {
    Piece& piece = pieces[k];
    {
      std::lock_guard<std::mutex> guard(lock);
      if (!spare.empty())
      {
        piece.text.swap(spare.back());
        spare.pop_back();
      }
    }
    if (piece.kind == 3)
    {
      faces(mesh, piece.begin, piece.end, piece.text);
    }
    else
    {
      static const char* const keywords[] = { "v", "vn", "vt" };
      const slValuesView& values = piece.kind == 0 ? mesh.points : piece.kind == 1 ? mesh.normals : mesh.tcoords;
      piece.text.reserve(static_cast<std::size_t>(piece.end - piece.begin) * 40);
      tuples(piece.text, keywords[piece.kind], values, piece.begin, piece.end, piece.kind == 2 ? 2 : 3);
    }
    std::lock_guard<std::mutex> guard(lock);
    piece.ready = true;
    changed.notify_all();
  };
  const auto fail = [&](std::exception_ptr error) {
    std::lock_guard<std::mutex> guard(lock);
    if (!failure)
    {
      failure = error;
    }
    stop = true;
    changed.notify_all();
  };
  auto work = [&] {
    try
    {
      for (std::size_t k = next++; k < pieces.size(); k = next++)
      {
        {
          std::unique_lock<std::mutex> guard(lock);
          changed.wait(guard, [&] { return stop || k < written + window; });
          if (stop)
          {
            return;
          }
        }
        format(k);
      }
    }
    catch (...)
    {
      fail(std::current_exception());
    }
  };
  std::vector<std::thread> workers;
  for (int t = 1; t < threads; ++t)
  {
    workers.emplace_back(work);
  }
  try
  {
    while (written < pieces.size())
    {
      std::unique_lock<std::mutex> guard(lock);
      if (stop)
      {
        break;
      }
      if (pieces[written].ready)
      {
        guard.unlock();
        Piece& piece = pieces[written];
        sink(piece.text.data(), piece.text.size());
        piece.text.clear();
        guard.lock();
        spare.push_back(std::move(piece.text));
        ++written;
        changed.notify_all();
        continue;
      }
      guard.unlock();
      const std::size_t k = next++;
      if (k < pieces.size())
      {
        format(k);
        continue;
      }
      guard.lock();
      changed.wait(guard, [&] { return stop || pieces[written].ready; });
    }
  }
  catch (...)
  {
    fail(std::current_exception());
  }
  for (std::thread& w : workers)
  {
    w.join();
  }
  if (failure)
  {
    std::rethrow_exception(failure);
  }
}
