#include "shadelab/SceneFile.h"

#include "shadelab/AtomicFile.h"
#include "shadelab/BrdfAssignment.h"
#include "shadelab/InputFile.h"
#include "shadelab/PrintableText.h"
#include "shadelab/SceneKeys.h"
#include "shadelab/SceneLimits.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <set>
#include <sstream>
#include <vector>

namespace shadelab
{
namespace
{
using json = nlohmann::json;

std::string join(const std::vector<std::string>& items)
{
  std::string out;
  for (size_t i = 0; i < items.size(); ++i)
  {
    out += (i ? ", " : "") + ('"' + items[i] + '"');
  }
  return out;
}

std::string childPath(const std::string& parent, const std::string& key)
{
  return parent.empty() ? key : parent + "." + key;
}

/// The JSON value of one "name=value" assignment's value: true/false for
/// 0/1 is not told from a float 0/1 here, so numbers stay numbers and the
/// .brdf reader takes 0 and 1 for bools.
nlohmann::json assignmentValue(const std::string& value)
{
  if (value.find(',') != std::string::npos)
  {
    nlohmann::json rgb = nlohmann::json::array();
    std::istringstream parts(value);
    for (std::string part; std::getline(parts, part, ',');)
    {
      rgb.push_back(std::strtod(part.c_str(), nullptr));
    }
    return rgb;
  }
  if (value == "true" || value == "false")
  {
    return value == "true";
  }
  return std::strtod(value.c_str(), nullptr);
}

/// Reads one JSON document into a Scene, failing on the first problem with a
/// message that names the file and the key path.
class SceneReader
{
public:
  explicit SceneReader(std::string fileName)
    : File(std::move(fileName))
  {
  }

  Scene read(const json& root)
  {
    Scene scene;
    scene.sourceFile = this->File;
    this->expectObject(root, "", { "$schema", "description", "imageSize", "background", "shading",
                                   "material", "brdf", "camera", "lights" });
    if (root.contains("description"))
    {
      scene.description = this->string(root["description"], "description");
    }
    if (root.contains("imageSize"))
    {
      this->imageSize(root["imageSize"], "imageSize", scene);
    }
    if (root.contains("background"))
    {
      scene.background = this->color(root["background"], "background");
    }
    if (root.contains("shading"))
    {
      this->shading(root["shading"], "shading", scene);
    }
    if (root.contains("material"))
    {
      scene.material = this->material(root["material"], "material");
    }
    if (root.contains("brdf"))
    {
      scene.brdf = this->brdf(root["brdf"], "brdf");
    }
    if (root.contains("camera"))
    {
      scene.camera = this->camera(root["camera"], "camera");
    }
    if (root.contains("lights"))
    {
      const json& lights = root["lights"];
      if (!lights.is_array())
      {
        this->fail("lights", "expected an array of lights, got " + typeName(lights));
      }
      for (size_t i = 0; i < lights.size(); ++i)
      {
        scene.lights.push_back(this->light(lights[i], "lights[" + std::to_string(i) + "]"));
      }
    }
    return scene;
  }

  [[noreturn]] void fail(const std::string& path, const std::string& problem) const
  {
    throw Error(this->File + ": " + (path.empty() ? "(top level)" : path) + ": " + problem);
  }

private:
  std::string File;

  static std::string typeName(const json& value)
  {
    if (value.is_number())
    {
      return "a number";
    }
    if (value.is_string())
    {
      return "a string";
    }
    if (value.is_boolean())
    {
      return "a boolean";
    }
    if (value.is_null())
    {
      return "null";
    }
    return value.is_array() ? "an array" : "an object";
  }

  void expectObject(const json& value, const std::string& path, const std::set<std::string>& allowed) const
  {
    if (!value.is_object())
    {
      this->fail(path, "expected an object, got " + typeName(value));
    }
    for (const auto& item : value.items())
    {
      if (!allowed.count(item.key()))
      {
        this->fail(childPath(path, item.key()),
          "unknown key (allowed here: " + join(std::vector<std::string>(allowed.begin(), allowed.end())) +
            ")");
      }
    }
  }

  std::string string(const json& value, const std::string& path) const
  {
    if (!value.is_string())
    {
      this->fail(path, "expected a string, got " + typeName(value));
    }
    return value.get<std::string>();
  }

  /// A finite number in [lo, hi]; an open end is excluded when its flag is set.
  double number(const json& value, const std::string& path, double lo, double hi, bool openLo = false,
    bool openHi = false) const
  {
    if (!value.is_number())
    {
      this->fail(path, "expected a number, got " + typeName(value));
    }
    const double x = value.get<double>();
    const std::string problem = numberProblem(x, lo, hi, openLo, openHi);
    if (!problem.empty())
    {
      this->fail(path, problem);
    }
    return x;
  }

  glm::vec3 triple(const json& value, const std::string& path, const char* what, double lo, double hi = HUGE_VAL) const
  {
    if (!value.is_array() || value.size() != 3)
    {
      this->fail(path,
        std::string("expected ") + what + " of 3 numbers, got " +
          (value.is_array() ? std::to_string(value.size()) + " components" : typeName(value)));
    }
    glm::vec3 out;
    for (int i = 0; i < 3; ++i)
    {
      out[i] = static_cast<float>(
        this->number(value[i], path + "[" + std::to_string(i) + "]", lo, hi));
    }
    return out;
  }

  glm::vec3 color(const json& value, const std::string& path) const
  {
    return this->triple(value, path, "an RGB colour", 0.0, kMaxColourValue);
  }

  glm::vec3 point(const json& value, const std::string& path) const
  {
    return this->triple(value, path, "a point", -HUGE_VAL);
  }

  glm::vec3 direction(const json& value, const std::string& path) const
  {
    const glm::vec3 d = this->triple(value, path, "a direction", -HUGE_VAL);
    const std::string problem = directionProblem(d);
    if (!problem.empty())
    {
      this->fail(path, problem);
    }
    return d;
  }

  template <typename Enum>
  Enum choice(const json& value, const std::string& path, const std::vector<std::string>& names,
    bool (*parse)(const std::string&, Enum&)) const
  {
    Enum out{};
    if (!parse(this->string(value, path), out))
    {
      this->fail(path, "\"" + value.get<std::string>() + "\" is not one of " + join(names));
    }
    return out;
  }

  void imageSize(const json& value, const std::string& path, Scene& scene) const
  {
    if (!value.is_array() || value.size() != 2)
    {
      this->fail(path, "expected [width, height]");
    }
    for (int i = 0; i < 2; ++i)
    {
      const std::string itemPath = path + "[" + std::to_string(i) + "]";
      if (!value[i].is_number_integer())
      {
        this->fail(itemPath, "expected a whole number of pixels, got " + typeName(value[i]));
      }
      (i ? scene.height : scene.width) = static_cast<int>(this->number(value[i], itemPath, kMinImageSize, kMaxImageSize));
    }
  }

  void shading(const json& value, const std::string& path, Scene& scene) const
  {
    this->expectObject(value, path, { "model", "frequency" });
    if (value.contains("model"))
    {
      scene.model = this->choice(value["model"], childPath(path, "model"), modelNames(), &parseModelName);
    }
    if (value.contains("frequency"))
    {
      scene.frequency =
        this->choice(value["frequency"], childPath(path, "frequency"), frequencyNames(), &parseFrequencyName);
    }
  }

  /// Reads the keys of @p keys that @p takes selects from @p value into
  /// @p out, in table order (so that a bound is read before what it bounds).
  template <typename Struct, typename Select>
  void keys(const json& value, const std::string& path, const std::vector<SceneKey<Struct>>& keys, Struct& out,
    Select takes) const
  {
    for (const SceneKey<Struct>& key : keys)
    {
      if (!takes(key) || !value.contains(key.name))
      {
        continue;
      }
      const std::string p = childPath(path, key.name);
      const json& v = value[key.name];
      switch (key.kind)
      {
        case SceneKeyKind::Number:
          out.*(key.number) =
            static_cast<float>(this->number(v, p, key.lo, keyUpperLimit(key, out), key.openLo, key.openHi));
          break;
        case SceneKeyKind::Colour:
          out.*(key.vector) = this->color(v, p);
          break;
        case SceneKeyKind::Point:
          out.*(key.vector) = this->point(v, p);
          break;
        case SceneKeyKind::Direction:
          out.*(key.vector) = this->direction(v, p);
          break;
        case SceneKeyKind::Coefficients:
          if (!v.is_array() || v.size() != 3)
          {
            this->fail(p, "expected [c1, c2, c3] for min(1, 1/(c1 + c2 d + c3 d^2))");
          }
          out.*(key.vector) = this->triple(v, p, "[c1, c2, c3]", key.lo, key.hi);
          break;
        case SceneKeyKind::Text:
          out.*(key.text) = this->string(v, p);
          if (key.whenEmpty && (out.*(key.text)).empty())
          {
            this->fail(p, key.whenEmpty);
          }
          break;
        case SceneKeyKind::Space:
          out.*(key.space) = this->choice(v, p, lightSpaceNames(), &parseLightSpaceName);
          break;
        case SceneKeyKind::Parameters:
          out.*(key.parameters) = this->assignments(v, p);
          break;
      }
    }
  }

  /// {"name": 0.5, "flag": true, "tint": [1, 0, 0]} as "name=0.5", "flag=1",
  /// "tint=1,0,0": the .brdf reader checks names and ranges when the file is read.
  std::vector<std::string> assignments(const json& value, const std::string& path) const
  {
    if (!value.is_object())
    {
      this->fail(path, "expected an object of parameter values, got " + typeName(value));
    }
    std::vector<std::string> out;
    for (const auto& item : value.items())
    {
      const std::string p = childPath(path, item.key());
      const json& v = item.value();
      std::string text;
      if (v.is_boolean())
      {
        text = v.get<bool>() ? "1" : "0";
      }
      else if (v.is_number())
      {
        text = brdfNumberText(this->number(v, p, -HUGE_VAL, HUGE_VAL));
      }
      else if (v.is_array() && v.size() == 3)
      {
        for (int i = 0; i < 3; ++i)
        {
          text += (i ? "," : "") + brdfNumberText(this->number(v[i], p + "[" + std::to_string(i) + "]", 0.0, kMaxColourValue));
        }
      }
      else
      {
        this->fail(p, "expected a number, true/false or [r, g, b], got " + typeName(v));
      }
      out.push_back(item.key() + "=" + text);
    }
    return out;
  }

  /// The names of @p keys that @p takes selects, with @p extra.
  template <typename Struct, typename Select>
  static std::set<std::string> keyNames(
    const std::vector<SceneKey<Struct>>& keys, Select takes, std::set<std::string> extra = {})
  {
    for (const SceneKey<Struct>& key : keys)
    {
      if (takes(key))
      {
        extra.insert(key.name);
      }
    }
    return extra;
  }

  template <typename Struct>
  static bool every(const SceneKey<Struct>&)
  {
    return true;
  }

  SceneMaterial material(const json& value, const std::string& path) const
  {
    this->expectObject(value, path, keyNames(materialKeys(), every<SceneMaterial>));
    SceneMaterial m;
    this->keys(value, path, materialKeys(), m, every<SceneMaterial>);
    return m;
  }

  SceneBrdf brdf(const json& value, const std::string& path) const
  {
    this->expectObject(value, path, keyNames(brdfKeys(), every<SceneBrdf>));
    if (!value.contains("file"))
    {
      this->fail(path, "missing key \"file\" (the .brdf file)");
    }
    SceneBrdf b;
    this->keys(value, path, brdfKeys(), b, every<SceneBrdf>);
    return b;
  }

  SceneCamera camera(const json& value, const std::string& path) const
  {
    this->expectObject(value, path, keyNames(cameraKeys(), every<SceneCamera>));
    if (value.contains("position") != value.contains("focalPoint"))
    {
      this->fail(path, "give both position and focalPoint, or neither (then the mesh is fitted in view)");
    }
    SceneCamera c;
    this->keys(value, path, cameraKeys(), c, every<SceneCamera>);
    c.hasPosition = value.contains("position");
    if (c.hasPosition && !(glm::length(c.position - c.focalPoint) > 0.0f))
    {
      this->fail(childPath(path, "focalPoint"), "must differ from position");
    }
    return c;
  }

  SceneLight light(const json& value, const std::string& path) const
  {
    if (!value.is_object())
    {
      this->fail(path, "expected an object, got " + typeName(value));
    }
    if (!value.contains("type"))
    {
      this->fail(path, "missing key \"type\" (one of " + join(lightTypeNames()) + ")");
    }
    const LightType type = this->choice(value["type"], childPath(path, "type"), lightTypeNames(), &parseLightTypeName);
    auto takes = [type](const SceneKey<SceneLight>& key) { return lightTakesKey(type, key); };
    this->expectObject(value, path, keyNames(lightKeys(), takes, { "type" }));
    SceneLight l = defaultLight(type);
    this->keys(value, path, lightKeys(), l, takes);
    return l;
  }
};

/// Rejects duplicate keys, which nlohmann::json would silently collapse.
class DuplicateKeyCheck
{
public:
  explicit DuplicateKeyCheck(const SceneReader& reader)
    : Reader(reader)
    , Frames(std::make_shared<std::vector<Frame>>())
  {
  }

  bool operator()(int depth, json::parse_event_t event, json& parsed)
  {
    switch (event)
    {
      case json::parse_event_t::object_start:
      case json::parse_event_t::array_start:
        this->Frames->push_back({ event == json::parse_event_t::array_start, {}, "", 0 });
        break;
      case json::parse_event_t::key:
      {
        Frame& top = this->Frames->back();
        top.current = parsed.get<std::string>();
        if (!top.keys.insert(top.current).second)
        {
          this->Reader.fail(this->path(), "duplicate key");
        }
        break;
      }
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        this->Frames->pop_back();
        this->elementDone();
        break;
      case json::parse_event_t::value:
        this->elementDone();
        break;
    }
    (void)depth;
    return true;
  }

  /// The key path of the value being parsed ("lights[0].intensity").
  std::string path() const
  {
    std::string out;
    for (const Frame& f : *this->Frames)
    {
      out = f.isArray ? out + "[" + std::to_string(f.index) + "]" : childPath(out, f.current);
    }
    return out;
  }

private:
  struct Frame
  {
    bool isArray;
    std::set<std::string> keys;
    std::string current;
    size_t index;
  };
  const SceneReader& Reader;
  // Shared by the copies json::parse makes, so the caller still sees where
  // parsing stopped when a number throws.
  std::shared_ptr<std::vector<Frame>> Frames;

  void elementDone()
  {
    if (!this->Frames->empty() && this->Frames->back().isArray)
    {
      ++this->Frames->back().index;
    }
  }
};

/// A float as the shortest double that reads back to it (0.1f -> 0.1, not
/// 0.10000000149011612), so written files stay readable.
double tidy(float value)
{
  char text[32];
  std::snprintf(text, sizeof(text), "%.9g", static_cast<double>(value));
  for (int digits = 1; digits <= 9; ++digits)
  {
    char shorter[32];
    std::snprintf(shorter, sizeof(shorter), "%.*g", digits, static_cast<double>(value));
    if (std::strtof(shorter, nullptr) == value)
    {
      return std::strtod(shorter, nullptr);
    }
  }
  return std::strtod(text, nullptr);
}

json vec(const glm::vec3& v)
{
  return json::array({ tidy(v.x), tidy(v.y), tidy(v.z) });
}

/// The keys of @p keys that @p writes selects, with @p object's values
/// (empty texts left out).
template <typename Struct, typename Select>
json keysToJson(const std::vector<SceneKey<Struct>>& keys, const Struct& object, Select writes)
{
  json out = json::object();
  for (const SceneKey<Struct>& key : keys)
  {
    if (!writes(key))
    {
      continue;
    }
    switch (key.kind)
    {
      case SceneKeyKind::Number:
        out[key.name] = tidy(object.*(key.number));
        break;
      case SceneKeyKind::Colour:
      case SceneKeyKind::Point:
      case SceneKeyKind::Direction:
      case SceneKeyKind::Coefficients:
        out[key.name] = vec(object.*(key.vector));
        break;
      case SceneKeyKind::Text:
        if (!(object.*(key.text)).empty())
        {
          out[key.name] = object.*(key.text);
        }
        break;
      case SceneKeyKind::Space:
        out[key.name] = lightSpaceName(object.*(key.space));
        break;
      case SceneKeyKind::Parameters:
      {
        json values = json::object();
        for (const std::string& assignment : object.*(key.parameters))
        {
          const size_t equals = assignment.find('=');
          values[assignment.substr(0, equals)] =
            assignmentValue(equals == std::string::npos ? std::string() : assignment.substr(equals + 1));
        }
        out[key.name] = values;
        break;
      }
    }
  }
  return out;
}

} // namespace

Scene parseScene(const std::string& jsonText, const std::string& fileName)
{
  SceneReader reader(fileName);
  const DuplicateKeyCheck check(reader);
  json root;
  try
  {
    root = json::parse(jsonText, check);
  }
  catch (const json::out_of_range& e)
  {
    // A number beyond the double range (1e400): e.what() reads
    // "[json.exception.out_of_range.406] number overflow parsing '1e400'".
    const std::string what = e.what();
    const size_t quote = what.find('\'');
    const std::string number = quote == std::string::npos ? std::string() : what.substr(quote + 1, what.size() - quote - 2);
    reader.fail(check.path(), "the number " + number + " is beyond the range of a double");
  }
  catch (const json::parse_error& e)
  {
    // e.what() reads "[json.exception.parse_error.101] parse error at line L, column C: ...".
    std::string what = e.what();
    const size_t at = what.find("line ");
    const size_t colon = what.find(": ", at == std::string::npos ? 0 : at);
    std::string where = at == std::string::npos || colon == std::string::npos
      ? "byte " + std::to_string(e.byte)
      : what.substr(at, colon - at);
    std::string problem = colon == std::string::npos ? what : what.substr(colon + 2);
    // The problem quotes the bytes last read, which may be anything.
    throw Error(fileName + ": " + where + ": malformed JSON: " + printableText(problem, 200));
  }
  return reader.read(root);
}

Scene readSceneFile(const std::string& path)
{
  const std::string fileProblem = inputFileProblem(path, "a scene file");
  if (!fileProblem.empty())
  {
    throw Error(path + ": " + fileProblem);
  }
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    throw Error(path + ": cannot open scene file: " + openFailureReason(path));
  }
  std::stringstream text;
  text << in.rdbuf();
  if (in.bad())
  {
    throw Error(path + ": read error");
  }
  return parseScene(text.str(), path);
}

std::string sceneToJson(const Scene& scene)
{
  json root = json::object();
  if (!scene.description.empty())
  {
    root["description"] = scene.description;
  }
  root["imageSize"] = json::array({ scene.width, scene.height });
  root["background"] = vec(scene.background);
  root["shading"] = { { "model", modelName(scene.model) }, { "frequency", frequencyName(scene.frequency) } };

  root["material"] = keysToJson(materialKeys(), scene.material, [](const SceneKey<SceneMaterial>&) { return true; });
  if (!scene.brdf.file.empty())
  {
    root["brdf"] = keysToJson(brdfKeys(), scene.brdf, [](const SceneKey<SceneBrdf>&) { return true; });
  }
  // A placed camera is written with its position, a fitted one with its turns.
  const SceneCamera& c = scene.camera;
  root["camera"] = keysToJson(cameraKeys(), c, [&c](const SceneKey<SceneCamera>& key) {
    const std::string name = key.name;
    const bool placement = name == "position" || name == "focalPoint";
    const bool turn = name == "azimuth" || name == "elevation";
    return (!placement || c.hasPosition) && (!turn || !c.hasPosition);
  });

  json lights = json::array();
  for (const SceneLight& l : scene.lights)
  {
    json j = keysToJson(lightKeys(), l, [&l](const SceneKey<SceneLight>& key) { return lightTakesKey(l.type, key); });
    j["type"] = lightTypeName(l.type);
    lights.push_back(j);
  }
  root["lights"] = lights;
  return root.dump(2) + "\n";
}

void writeSceneFile(const Scene& scene, const std::string& path)
{
  writeFileAtomically(path, sceneToJson(scene));
}

} // namespace shadelab
