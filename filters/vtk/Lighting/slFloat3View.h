#ifndef slFloat3View_h
#define slFloat3View_h
/**
 * @file slFloat3View.h
 * @brief Internal: read access to a 3-component vtkDataArray as glm::vec3,
 * without a copy when it already holds floats (the fast path of the lighting
 * loops), converted once otherwise. Not wrapped.
 */

#include <vtkDataArray.h>
#include <vtkFloatArray.h>

#include <glm/glm.hpp>

#include <vector>

namespace shadelab
{

class Float3View
{
public:
  explicit Float3View(vtkDataArray* array)
  {
    auto* floats = vtkFloatArray::SafeDownCast(array);
    if (floats && floats->GetNumberOfComponents() == 3)
    {
      this->Data = floats->GetPointer(0);
      return;
    }
    const vtkIdType n = array->GetNumberOfTuples();
    this->Copy.resize(static_cast<size_t>(3 * n));
    for (vtkIdType i = 0; i < n; ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        this->Copy[static_cast<size_t>(3 * i + c)] = static_cast<float>(array->GetComponent(i, c));
      }
    }
    this->Data = this->Copy.data();
  }

  /// xyz of every tuple, contiguous.
  const float* data() const { return this->Data; }

  glm::vec3 operator[](vtkIdType i) const
  {
    const float* p = this->Data + 3 * i;
    return glm::vec3(p[0], p[1], p[2]);
  }

private:
  const float* Data = nullptr;
  std::vector<float> Copy;
};

} // namespace shadelab

#endif
