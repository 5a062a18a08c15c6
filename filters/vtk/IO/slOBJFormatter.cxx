#include "slOBJFormat.h"

#include <algorithm>
#include <atomic>
#include <charconv>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace
{
/// @p value with the fewest digits that read back to it, as a double or,
/// unless @p isDouble, as a float.
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
  try
  {
    // A thread that cannot start (no memory for its stack) leaves the
    // pieces to the others: this thread formats too.
    workers.reserve(static_cast<std::size_t>(std::max(threads - 1, 0)));
    for (int t = 1; t < threads; ++t)
    {
      workers.emplace_back(work);
    }
  }
  catch (const std::exception&)
  {
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
