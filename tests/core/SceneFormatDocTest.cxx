// docs/scene-format.md against the key tables (SceneKeys.h): every key of a
// light, a material and a camera has its row, and the row states the key's
// kind, range, default and (lights) the types that take it as the tables
// do; the model row lists the lighting models. The doc is written for
// people, so this reads its notation: "0–10⁶", "(0, 90] degrees",
// "[0, cutoff]", "RGB in [0, 10⁶]", "≥ 0", "[0, 0, −1]", "0 (ambient lights: 1)".
#include "shadelab/SceneKeys.h"
#include "shadelab/SceneLimits.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

using namespace shadelab;

namespace
{
using Row = std::vector<std::string>;

std::string trimmed(const std::string& s)
{
  const size_t a = s.find_first_not_of(' '), b = s.find_last_not_of(' ');
  return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

/// The doc's rows "| a | b | ... |" whose first cell starts with a backtick,
/// as cells, with the doc's numbers in C notation (−1 -> -1, 10⁶ -> 1e6).
std::vector<Row> docRows()
{
  std::ifstream in(std::string(SHADELAB_DATA_DIR) + "/../docs/scene-format.md");
  std::stringstream text;
  text << in.rdbuf();
  std::string doc = std::regex_replace(text.str(), std::regex("\xE2\x88\x92"), "-");
  const char* const superscripts[] = { "\xE2\x81\xB0", "\xC2\xB9", "\xC2\xB2", "\xC2\xB3", "\xE2\x81\xB4",
    "\xE2\x81\xB5", "\xE2\x81\xB6", "\xE2\x81\xB7", "\xE2\x81\xB8", "\xE2\x81\xB9" };
  for (int d = 0; d < 10; ++d)
  {
    doc = std::regex_replace(doc, std::regex(std::string("10") + superscripts[d]), "1e" + std::to_string(d));
  }
  std::vector<Row> rows;
  std::istringstream lines(doc);
  std::string line;
  while (std::getline(lines, line))
  {
    if (line.rfind("| `", 0) != 0)
    {
      continue;
    }
    Row cells;
    size_t start = 1;
    for (size_t bar = line.find('|', start); bar != std::string::npos; bar = line.find('|', start))
    {
      cells.push_back(trimmed(line.substr(start, bar - start)));
      start = bar + 1;
    }
    rows.push_back(cells);
  }
  return rows;
}

/// The key names of a row's first cell: "`a`, `b`" -> a, b;
/// "`material.ambient/diffuse`" -> ambient, diffuse (with @p prefix
/// "material."; an empty prefix takes only names without a dot).
std::vector<std::string> keyNames(const std::string& cell, const std::string& prefix)
{
  std::vector<std::string> names;
  const std::regex quoted("`([^`]*)`");
  for (std::sregex_iterator i(cell.begin(), cell.end(), quoted), end; i != end; ++i)
  {
    std::string name = (*i)[1];
    if (name.rfind(prefix, 0) != 0 || (prefix.empty() && name.find('.') != std::string::npos))
    {
      continue;
    }
    std::istringstream parts(name.substr(prefix.size()));
    for (std::string part; std::getline(parts, part, '/');)
    {
      names.push_back(part);
    }
  }
  return names;
}

/// A range as the doc writes it.
struct DocRange
{
  bool found = false;
  double lo = -HUGE_VAL, hi = HUGE_VAL;
  bool openLo = false, openHi = false;
  std::string hiName; ///< "cutoff" in "[0, cutoff]"
};

DocRange rangeIn(const std::string& cell)
{
  DocRange r;
  std::smatch m;
  const std::string number = "(-?[0-9.]+(?:e[0-9]+)?)";
  if (std::regex_search(cell, m, std::regex("([\\[(])" + number + ", (?:" + number + "|([a-z]+))([\\])])")))
  {
    r.found = true;
    r.openLo = m[1] == "(";
    r.lo = std::stod(m[2]);
    r.hi = m[3].matched ? std::stod(m[3]) : HUGE_VAL;
    r.hiName = m[4];
    r.openHi = m[5] == ")";
  }
  else if (std::regex_search(cell, m, std::regex(number + "\xE2\x80\x93" + number)))
  {
    r.found = true;
    r.lo = std::stod(m[1]);
    r.hi = std::stod(m[2]);
  }
  else if (std::regex_search(cell, m, std::regex("\xE2\x89\xA5 " + number)))
  {
    r.found = true;
    r.lo = std::stod(m[1]);
  }
  return r;
}

/// The numbers of a default: "[0, 0, -1]" -> 0, 0, -1; "32" -> 32.
std::vector<double> numbersIn(const std::string& cell)
{
  std::vector<double> out;
  const std::regex number("-?[0-9.]+(?:e[0-9]+)?");
  for (std::sregex_iterator i(cell.begin(), cell.end(), number), end; i != end; ++i)
  {
    out.push_back(std::stod(i->str()));
  }
  return out;
}

/// The row states @p key's range in @p rangeCell and its value in @p object
/// as @p defaultCell.
template <typename Struct>
void expectRowStates(const SceneKey<Struct>& key, const std::vector<SceneKey<Struct>>& keys, const Struct& object,
  const std::string& rangeCell, const std::string& defaultCell)
{
  const DocRange r = rangeIn(rangeCell);
  switch (key.kind)
  {
    case SceneKeyKind::Number:
    case SceneKeyKind::Colour:
    case SceneKeyKind::Coefficients:
    {
      ASSERT_TRUE(r.found) << "no range in \"" << rangeCell << "\"";
      EXPECT_EQ(r.lo, key.lo) << rangeCell;
      EXPECT_EQ(r.openLo, key.openLo) << rangeCell;
      EXPECT_EQ(r.openHi, key.openHi) << rangeCell;
      if (key.upTo)
      {
        std::string bound;
        for (const SceneKey<Struct>& other : keys)
        {
          bound = other.number == key.upTo ? other.name : bound;
        }
        EXPECT_EQ(r.hiName, bound) << rangeCell;
      }
      else
      {
        EXPECT_EQ(r.hi, key.hi) << rangeCell;
      }
      break;
    }
    case SceneKeyKind::Direction:
      EXPECT_NE(rangeCell.find("non-zero"), std::string::npos) << rangeCell;
      break;
    case SceneKeyKind::Space:
      for (const std::string& name : lightSpaceNames())
      {
        EXPECT_NE(rangeCell.find("`" + name + "`"), std::string::npos) << rangeCell;
      }
      break;
    case SceneKeyKind::Point:
    case SceneKeyKind::Text:
    case SceneKeyKind::Parameters:
      break;
  }
  const std::vector<double> stated = numbersIn(defaultCell);
  if (key.number)
  {
    ASSERT_EQ(stated.size(), 1u) << defaultCell;
    EXPECT_EQ(static_cast<float>(stated[0]), object.*(key.number)) << defaultCell;
  }
  else if (key.vector && !(key.kind == SceneKeyKind::Point && stated.empty()))
  {
    // One number stands for three equal ones; a point may have no default.
    ASSERT_TRUE(stated.size() == 1 || stated.size() == 3) << defaultCell;
    for (int i = 0; i < 3; ++i)
    {
      EXPECT_EQ(static_cast<float>(stated[stated.size() == 1 ? 0 : i]), (object.*(key.vector))[i]) << defaultCell;
    }
  }
  else if (key.space)
  {
    EXPECT_EQ(defaultCell, std::string("`") + lightSpaceName(object.*(key.space)) + "`");
  }
}

/// The row of @p name among @p rows (first cells read with @p prefix), or null.
const Row* rowOf(const std::vector<Row>& rows, const std::string& name, const std::string& prefix, size_t* index)
{
  for (const Row& row : rows)
  {
    const std::vector<std::string> names = keyNames(row[0], prefix);
    for (size_t i = 0; i < names.size(); ++i)
    {
      if (names[i] == name)
      {
        *index = i;
        return &row;
      }
    }
  }
  return nullptr;
}

/// The @p index-th of a cell's " / "-separated values, or the cell.
std::string part(const std::string& cell, size_t index)
{
  std::vector<std::string> parts;
  size_t start = 0;
  for (size_t at = cell.find(" / "); at != std::string::npos; at = cell.find(" / ", start))
  {
    parts.push_back(cell.substr(start, at - start));
    start = at + 3;
  }
  parts.push_back(cell.substr(start));
  return parts.size() > 1 && index < parts.size() ? parts[index] : cell;
}
} // namespace

TEST(SceneFormatDoc, EveryLightKeyWithItsTypesRangeAndDefault)
{
  const std::vector<Row> rows = docRows();
  for (const SceneKey<SceneLight>& key : lightKeys())
  {
    SCOPED_TRACE(key.name);
    size_t index = 0;
    const Row* row = rowOf(rows, key.name, "", &index);
    ASSERT_NE(row, nullptr) << "no row for the light key";
    ASSERT_EQ(row->size(), 5u) << "| key | types | range | default | meaning |";
    const std::string& types = (*row)[1];
    // "0 (ambient lights: 1)": the default of every type, then one type's own.
    std::map<std::string, std::string> defaults;
    std::smatch own;
    const std::string& defaultCell = (*row)[3];
    const bool hasOwn = std::regex_search(defaultCell, own, std::regex(" \\(([a-z-]+) lights: (.*)\\)$"));
    for (const LightTypeInfo& t : kLightTypes)
    {
      SCOPED_TRACE(t.name);
      const bool listed = types == "all" || (types.rfind("not ", 0) == 0 ? types.substr(4) != t.name
                                                                           : std::regex_search(types,
                                                                               std::regex(std::string("\\b") + t.name + "\\b")));
      EXPECT_EQ(listed, lightTakesKey(t.type, key)) << "types: " << types;
      if (lightTakesKey(t.type, key))
      {
        const bool isOwn = hasOwn && own[1] == t.name;
        expectRowStates(key, lightKeys(), defaultLight(t.type), (*row)[2],
          isOwn ? std::string(own[2]) : hasOwn ? defaultCell.substr(0, static_cast<size_t>(own.position(0)))
                                               : defaultCell);
      }
    }
  }
}

namespace
{
/// Every key of @p keys has its row "| `PREFIXkey` | type, range | default | meaning |".
template <typename Struct>
void expectObjectRows(const std::vector<SceneKey<Struct>>& keys, const std::string& prefix)
{
  const std::vector<Row> rows = docRows();
  for (const SceneKey<Struct>& key : keys)
  {
    SCOPED_TRACE(prefix + key.name);
    size_t index = 0;
    const Row* row = rowOf(rows, key.name, prefix, &index);
    ASSERT_NE(row, nullptr) << "no row for the key";
    ASSERT_EQ(row->size(), 4u) << "| key | type, range | default | meaning |";
    expectRowStates(key, keys, Struct(), (*row)[1], part((*row)[2], index));
  }
}
} // namespace

TEST(SceneFormatDoc, EveryMaterialAndCameraKeyWithItsRangeAndDefault)
{
  expectObjectRows(materialKeys(), "material.");
  expectObjectRows(brdfKeys(), "brdf.");
  expectObjectRows(cameraKeys(), "camera.");
}

TEST(SceneFormatDoc, ModelRowListsTheModelsAndTheDefault)
{
  size_t index = 0;
  const std::vector<Row> rows = docRows();
  const Row* row = rowOf(rows, "model", "shading.", &index);
  ASSERT_NE(row, nullptr);
  std::string listed;
  for (const std::string& name : modelNames())
  {
    listed += (listed.empty() ? "`" : ", `") + name + "`";
  }
  EXPECT_EQ((*row)[1], listed);
  EXPECT_EQ((*row)[2], std::string("`") + modelName(Scene().model) + "`");
}
