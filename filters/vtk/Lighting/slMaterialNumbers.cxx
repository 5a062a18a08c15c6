#include "slMaterialNumbers.h"

#include "shadelab/SceneKeys.h"

#include <vtkObject.h>
#include <vtkSetGet.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <limits>
#include <string>

namespace
{
using MaterialKey = shadelab::SceneKey<shadelab::SceneMaterial>;

/// The number key named @p key, or null after reporting it as an error of @p self.
const MaterialKey* numberKey(vtkObject* self, const char* function, const char* key)
{
  std::string known;
  for (const MaterialKey& k : shadelab::materialKeys())
  {
    if (!k.number)
    {
      continue;
    }
    if (key && std::strcmp(k.name, key) == 0)
    {
      return &k;
    }
    known += (known.empty() ? "" : ", ") + std::string(k.name);
  }
  vtkErrorWithObjectMacro(self, << function << ": \"" << (key ? key : "(null)")
                                << "\" is not a number of the material (" << known << ")");
  return nullptr;
}
} // namespace

int slSetMaterialNumber(vtkObject* self, shadelab::SceneMaterial& material, const char* key, double value)
{
  const MaterialKey* k = numberKey(self, "SetMaterialParameter", key);
  if (!k)
  {
    return -1;
  }
  if (value != value)
  {
    vtkErrorWithObjectMacro(self, << "SetMaterialParameter: " << key << ": NaN is not a value");
    return -1;
  }
  const float clamped = static_cast<float>(std::clamp(value, k->lo, k->hi));
  float& field = material.*(k->number);
  if (field == clamped)
  {
    return 0;
  }
  field = clamped;
  return 1;
}

double slGetMaterialNumber(vtkObject* self, const shadelab::SceneMaterial& material, const char* key)
{
  const MaterialKey* k = numberKey(self, "GetMaterialParameter", key);
  return k ? static_cast<double>(material.*(k->number)) : std::numeric_limits<double>::quiet_NaN();
}

void slPrintMaterialNumbers(ostream& os, vtkIndent indent, const shadelab::SceneMaterial& material)
{
  for (const MaterialKey& k : shadelab::materialKeys())
  {
    if (k.number)
    {
      // Under the setter's name (key "roughnessX": SetRoughnessX), as
      // slLitFilter prints the same numbers.
      std::string setterName = k.name;
      setterName[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(setterName[0])));
      os << indent << setterName << ": " << material.*(k.number) << "\n";
    }
  }
}
