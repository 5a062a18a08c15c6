#include "slPointDeduplication.h"

#include <cstring>
#include <type_traits>

namespace
{
std::uint64_t hashBytes(const unsigned char* bytes, std::size_t n)
{
  std::uint64_t h = 1469598103934665603ull; // FNV-1a, then mixed
  for (std::size_t i = 0; i < n; ++i)
  {
    h = (h ^ bytes[i]) * 1099511628211ull;
  }
  h ^= h >> 29;
  h *= 0xbf58476d1ce4e5b9ull;
  return h ^ (h >> 32);
}
} // namespace

std::vector<std::int64_t> slUniqueRows(
  const unsigned char* rows, std::size_t rowBytes, std::size_t count, std::vector<std::int64_t>& newId)
{
  // Open addressing over a power-of-two table at most half full; a slot
  // holds the key's hash and 1 + its distinct row's number, so that rows
  // are compared only when their hashes agree.
  std::size_t size = 16;
  while (size < 2 * count)
  {
    size *= 2;
  }
  struct Slot
  {
    std::uint64_t hash;
    std::int64_t id; // 0: empty
  };
  std::vector<Slot> slots(size, Slot{ 0, 0 });
  std::vector<std::int64_t> kept;
  kept.reserve(count);
  newId.assign(count, 0);
  for (std::size_t i = 0; i < count; ++i)
  {
    const unsigned char* row = rows + i * rowBytes;
    const std::uint64_t hash = hashBytes(row, rowBytes);
    for (std::size_t s = hash & (size - 1);; s = (s + 1) & (size - 1))
    {
      Slot& slot = slots[s];
      if (slot.id == 0)
      {
        slot = Slot{ hash, static_cast<std::int64_t>(kept.size()) + 1 };
        newId[i] = static_cast<std::int64_t>(kept.size());
        kept.push_back(static_cast<std::int64_t>(i));
        break;
      }
      const std::int64_t id = slot.id - 1;
      if (slot.hash == hash &&
        std::memcmp(rows + static_cast<std::size_t>(kept[static_cast<std::size_t>(id)]) * rowBytes, row, rowBytes) == 0)
      {
        newId[i] = id;
        break;
      }
    }
  }
  return kept;
}

void slDeduplicatePoints(slMeshArrays& mesh, std::vector<std::int32_t>& keys)
{
  static_assert(sizeof(float) == sizeof(std::int32_t), "a key takes a value's place");
  const std::size_t n = mesh.points.size() / 3;
  const std::size_t width =
    3 + (mesh.normals.empty() ? 0 : 3) + (mesh.tcoords.empty() ? 0 : 2) + (keys.empty() ? 0 : 1);
  // The row of a point: its position, then its point data in the order
  // vtkOBJReader gives its arrays (texture coordinates, normals), then its
  // key.
  std::vector<float> rows(n * width);
  for (std::size_t i = 0; i < n; ++i)
  {
    float* row = &rows[i * width];
    std::memcpy(row, &mesh.points[3 * i], 3 * sizeof(float));
    std::size_t at = 3;
    if (!mesh.tcoords.empty())
    {
      std::memcpy(row + at, &mesh.tcoords[2 * i], 2 * sizeof(float));
      at += 2;
    }
    if (!mesh.normals.empty())
    {
      std::memcpy(row + at, &mesh.normals[3 * i], 3 * sizeof(float));
      at += 3;
    }
    if (!keys.empty())
    {
      std::memcpy(row + at, &keys[i], sizeof(std::int32_t));
    }
  }
  std::vector<std::int64_t> newId;
  const std::vector<std::int64_t> kept =
    slUniqueRows(reinterpret_cast<const unsigned char*>(rows.data()), width * sizeof(float), n, newId);
  if (kept.size() == n)
  {
    return;
  }
  auto gather = [&](auto& values, std::size_t components) {
    if (values.empty())
    {
      return;
    }
    using Value = typename std::decay_t<decltype(values)>::value_type;
    std::vector<Value> out(kept.size() * components);
    for (std::size_t k = 0; k < kept.size(); ++k)
    {
      std::memcpy(
        &out[k * components], &values[static_cast<std::size_t>(kept[k]) * components], components * sizeof(Value));
    }
    values.swap(out);
  };
  gather(mesh.points, 3);
  gather(mesh.normals, 3);
  gather(mesh.tcoords, 2);
  gather(keys, 1);
  for (std::int64_t& id : mesh.connectivity)
  {
    id = newId[static_cast<std::size_t>(id)];
  }
}
