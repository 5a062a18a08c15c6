#ifndef slPassObjectMap_h
#define slPassObjectMap_h
/**
 * @file slPassObjectMap.h
 * @brief A map from VTK objects slLightingPass does not own to values it
 * keeps for them, which forgets freed objects. Internal to
 * ShadeLab::RenderPasses.
 *
 * Apart from the pass because it knows nothing of lighting: the pass keeps
 * four such maps (mappers, shader programs, properties, renderers).
 */

#include <vtkWeakPointer.h>

#include <cstddef>
#include <iterator>
#include <map>
#include <utility>

/// Values the pass keeps per object it does not own (mappers, shader
/// programs, properties, renderers), by address. An entry holds a weak
/// pointer to its object: once the object is freed, the entry is not found,
/// even by a new object at the same address. Entries of freed objects are
/// dropped when an insertion finds the map past twice its size after the
/// last sweep: a long-running program that makes and frees many actors
/// keeps it within about twice the number of live objects, at an amortised
/// constant cost per insertion.
template <typename Object, typename Value>
class slPassObjectMap
{
public:
  /// The value of @p object, or null if it has none (or is not the object
  /// the entry at its address was made for).
  const Value* Find(Object* object) const
  {
    const auto entry = this->Entries.find(object);
    return entry != this->Entries.end() && entry->second.first == object ? &entry->second.second : nullptr;
  }

  /// Gives @p object the value @p value (in place of a freed object's).
  const Value& Insert(Object* object, const Value& value)
  {
    if (this->Entries.size() > 2 * this->SizeAfterSweep)
    {
      for (auto entry = this->Entries.begin(); entry != this->Entries.end();)
      {
        entry = entry->second.first ? std::next(entry) : this->Entries.erase(entry);
      }
      this->SizeAfterSweep = this->Entries.size();
    }
    auto& entry = this->Entries[object];
    entry = { object, value };
    return entry.second;
  }

  /// Calls @p f(object, value) for every entry whose object is alive.
  template <typename Function>
  void ForEachLive(Function f) const
  {
    for (const auto& entry : this->Entries)
    {
      if (Object* object = entry.second.first.GetPointer())
      {
        f(object, entry.second.second);
      }
    }
  }

  void Clear()
  {
    this->Entries.clear();
    this->SizeAfterSweep = 0;
  }

  size_t Size() const { return this->Entries.size(); }

private:
  std::map<Object*, std::pair<vtkWeakPointer<Object>, Value>> Entries;
  size_t SizeAfterSweep = 0;
};

#endif
