// Scene files: strict validation with one-line messages naming the file, the
// key path and the problem; and a lossless round trip.
#include "shadelab/BrdfAssignment.h"
#include "shadelab/DefaultScene.h"
#include "shadelab/SceneFile.h"
#include "shadelab/SceneKeys.h"
#include "shadelab/SceneLimits.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

using namespace shadelab;

namespace
{
/// The message parseScene() throws for @p text, or "" if it parses.
std::string errorFor(const std::string& text)
{
  try
  {
    parseScene(text, "bad.json");
  }
  catch (const Error& e)
  {
    return e.what();
  }
  return "";
}

std::string withLight(const std::string& lightBody)
{
  return R"({"lights": [{"type": "directional"}, )" + lightBody + "]}";
}
} // namespace

TEST(SceneFile, EmptyObjectGivesDefaults)
{
  const Scene scene = parseScene("{}", "empty.json");
  EXPECT_TRUE(scene.lights.empty());
  EXPECT_EQ(scene.model, ShadingModel::BlinnPhong);
  EXPECT_EQ(scene.frequency, ShadingFrequency::Phong);
  EXPECT_EQ(scene.sourceFile, "empty.json");
}

TEST(SceneFile, ReadsEveryField)
{
  const Scene s = parseScene(R"({
    "imageSize": [320, 240], "background": [0.1, 0.2, 0.3],
    "shading": {"model": "phong-normalized", "frequency": "gouraud"},
    "material": {"ambient": [0.1, 0.1, 0.1], "diffuse": [0.5, 0.6, 0.7], "specular": [1, 1, 1],
                 "emission": [0.2, 0, 0], "shininess": 64},
    "camera": {"position": [0, 0, 5], "focalPoint": [0, 0, 0], "viewUp": [0, 1, 0], "viewAngle": 40},
    "lights": [
      {"type": "spot", "position": [1, 2, 3], "direction": [0, 0, -1], "cutoff": 25, "exponent": 4,
       "edge": 5, "attenuation": [1, 0.1, 0.01], "intensity": 2, "diffuse": [1, 0.5, 0.25], "space": "camera"},
      {"type": "ambient", "ambient": [0.2, 0.2, 0.2]}
    ]})",
    "full.json");
  EXPECT_EQ(s.width, 320);
  EXPECT_EQ(s.height, 240);
  EXPECT_EQ(s.model, ShadingModel::PhongNormalized);
  EXPECT_EQ(s.frequency, ShadingFrequency::Gouraud);
  EXPECT_FLOAT_EQ(s.material.shininess, 64.0f);
  EXPECT_FLOAT_EQ(s.material.diffuse.y, 0.6f);
  EXPECT_TRUE(s.camera.hasPosition);
  EXPECT_FLOAT_EQ(s.camera.viewAngle, 40.0f);
  ASSERT_EQ(s.lights.size(), 2u);
  EXPECT_EQ(s.lights[0].type, LightType::Spot);
  EXPECT_EQ(s.lights[0].space, LightSpace::Camera);
  EXPECT_FLOAT_EQ(s.lights[0].cutoffDegrees, 25.0f);
  EXPECT_FLOAT_EQ(s.lights[0].edgeDegrees, 5.0f);
  EXPECT_FLOAT_EQ(s.lights[0].attenuation.z, 0.01f);
  EXPECT_EQ(s.lights[1].type, LightType::Ambient);
  EXPECT_EQ(s.lights[1].diffuse, glm::vec3(0.0f));
}

TEST(SceneFile, MalformedJSONNamesLineAndColumn)
{
  const std::string e = errorFor("{\n  \"background\": [0, 0, 0],\n  \"lights\": [ }\n");
  EXPECT_EQ(e.rfind("bad.json: line 3, column ", 0), 0u) << e;
  EXPECT_NE(e.find("malformed JSON"), std::string::npos) << e;
  EXPECT_EQ(e.find('\n'), std::string::npos) << "one line";
}

TEST(SceneFile, EmptyTextIsMalformed)
{
  EXPECT_NE(errorFor("").find("malformed JSON"), std::string::npos);
}

TEST(SceneFile, UnknownKeys)
{
  EXPECT_EQ(errorFor(R"({"lihgts": []})").rfind("bad.json: lihgts: unknown key (allowed here: ", 0), 0u);
  EXPECT_EQ(errorFor(R"({"material": {"shinyness": 3}})").rfind("bad.json: material.shinyness: unknown key", 0), 0u);
  // Keys that belong to another light type are unknown for this one.
  EXPECT_EQ(errorFor(withLight(R"({"type": "point", "cutoff": 20})")).rfind("bad.json: lights[1].cutoff: unknown key", 0),
    0u);
  EXPECT_EQ(errorFor(withLight(R"({"type": "ambient", "position": [0, 0, 0]})"))
              .rfind("bad.json: lights[1].position: unknown key", 0),
    0u);
}

TEST(SceneFile, DuplicateKeys)
{
  EXPECT_EQ(errorFor(R"({"lights": [{"type": "point", "position": [0,0,0], "position": [1,1,1]}]})"),
    "bad.json: lights[0].position: duplicate key");
  EXPECT_EQ(errorFor(R"({"background": [0,0,0], "background": [1,1,1]})"), "bad.json: background: duplicate key");
}

TEST(SceneFile, WrongTypes)
{
  EXPECT_EQ(errorFor(R"({"shading": {"model": 3}})"), "bad.json: shading.model: expected a string, got a number");
  EXPECT_EQ(errorFor(R"({"material": {"shininess": "high"}})"),
    "bad.json: material.shininess: expected a number, got a string");
  EXPECT_EQ(errorFor(R"({"lights": {"type": "point"}})"), "bad.json: lights: expected an array of lights, got an object");
  EXPECT_EQ(errorFor(R"({"material": {"diffuse": [1, true, 0]}})"),
    "bad.json: material.diffuse[1]: expected a number, got a boolean");
  EXPECT_EQ(errorFor(R"({"imageSize": [640.5, 480]})"),
    "bad.json: imageSize[0]: expected a whole number of pixels, got a number");
}

namespace
{
/// "\"a\", \"b\"": the valid names as the reader lists them.
std::string quoted(const std::vector<std::string>& names)
{
  std::string out;
  for (const std::string& name : names)
  {
    out += (out.empty() ? "\"" : ", \"") + name + "\"";
  }
  return out;
}
} // namespace

TEST(SceneFile, UnknownNames)
{
  ASSERT_EQ(quoted(modelNames()).rfind("\"lambert\", \"phong\", \"blinn-phong\", \"lambert-normalized\"", 0), 0u);
  EXPECT_EQ(errorFor(R"({"shading": {"model": "cook-torrance"}})"),
    "bad.json: shading.model: \"cook-torrance\" is not one of " + quoted(modelNames()));
  EXPECT_EQ(errorFor(withLight(R"({"type": "area"})")).rfind("bad.json: lights[1].type: \"area\" is not one of", 0), 0u);
  EXPECT_EQ(errorFor(withLight(R"({"position": [0, 0, 0]})")),
    "bad.json: lights[1]: missing key \"type\" (one of " + quoted(lightTypeNames()) + ")");
}

TEST(SceneFile, OutOfRangeValues)
{
  // { scene text, the error it gives }. The upper limits on colours and
  // intensities keep every product of them with the BRDF factors finite
  // in float (SceneLimits.h); every value must fit a float.
  const std::pair<std::string, std::string> cases[] = {
    { R"({"material": {"shininess": -1}})", "material.shininess: -1 is out of range [0, 100000]" },
    { withLight(R"({"type": "directional", "direction": [0, 0, 0]})"),
      "lights[1].direction: a direction must not have zero length" },
    { withLight(R"({"type": "spot", "cutoff": 0})"), "lights[1].cutoff: 0 is out of range (0, 90]" },
    { withLight(R"({"type": "spot", "cutoff": 90.5})"), "lights[1].cutoff: 90.5 is out of range (0, 90]" },
    { withLight(R"({"type": "spot", "cutoff": 20, "edge": 25})"), "lights[1].edge: 25 is out of range [0, 20]" },
    { withLight(R"({"type": "point", "attenuation": [1, -0.5, 0]})"),
      "lights[1].attenuation[1]: -0.5 is out of range [0, inf)" },
    { withLight(R"({"type": "point", "intensity": -2})"), "lights[1].intensity: -2 is out of range [0, 1e+06]" },
    { R"({"material": {"diffuse": [0.5, -0.1, 0]}})", "material.diffuse[1]: -0.1 is out of range [0, 1e+06]" },
    { withLight(R"({"type": "point", "intensity": 2e6})"), "lights[1].intensity: 2e+06 is out of range [0, 1e+06]" },
    { withLight(R"({"type": "point", "specular": [1, 1, 3e38]})"),
      "lights[1].specular[2]: 3e+38 is out of range [0, 1e+06]" },
    { R"({"material": {"emission": [1e39, 0, 0]}})", "material.emission[0]: 1e+39 is beyond the float range" },
    { withLight(R"({"type": "point", "position": [0, -1e39, 0]})"),
      "lights[1].position[1]: -1e+39 is beyond the float range" },
    { R"({"camera": {"viewAngle": 180}})", "camera.viewAngle: 180 is out of range (0, 180)" },
    { R"({"imageSize": [8, 480]})", "imageSize[0]: 8 is out of range [16, 8192]" },
  };
  for (const auto& c : cases)
  {
    EXPECT_EQ(errorFor(c.first), "bad.json: " + c.second) << c.first;
  }
}

TEST(SceneFile, WrongNumberOfComponents)
{
  EXPECT_EQ(errorFor(R"({"material": {"diffuse": [1, 0]}})"),
    "bad.json: material.diffuse: expected an RGB colour of 3 numbers, got 2 components");
  EXPECT_EQ(errorFor(R"({"background": [1, 0, 0, 1]})"),
    "bad.json: background: expected an RGB colour of 3 numbers, got 4 components");
  EXPECT_EQ(errorFor(withLight(R"({"type": "point", "position": 3})")),
    "bad.json: lights[1].position: expected a point of 3 numbers, got a number");
}

TEST(SceneFile, CameraNeedsPositionAndFocalPointTogether)
{
  EXPECT_EQ(errorFor(R"({"camera": {"position": [0, 0, 1]}})").rfind("bad.json: camera: give both position", 0), 0u);
  EXPECT_EQ(errorFor(R"({"camera": {"position": [1, 1, 1], "focalPoint": [1, 1, 1]}})"),
    "bad.json: camera.focalPoint: must differ from position");
}

TEST(SceneFile, MissingFile)
{
  try
  {
    readSceneFile("/nonexistent/scene.json");
    FAIL() << "expected shadelab::Error";
  }
  catch (const Error& e)
  {
    EXPECT_STREQ(e.what(), "/nonexistent/scene.json: cannot open scene file: No such file or directory");
  }
}

TEST(SceneFile, RoundTripIsLossless)
{
  Scene scene = defaultScene();
  scene.model = ShadingModel::BlinnPhongNormalized;
  scene.frequency = ShadingFrequency::Flat;
  scene.material.diffuseTexture = "wood.png";
  SceneLight spot;
  spot.type = LightType::Spot;
  spot.position = glm::vec3(1.5f, -2.0f, 3.25f);
  spot.cutoffDegrees = 17.5f;
  spot.edgeDegrees = 2.5f;
  spot.exponent = 3.0f;
  spot.attenuation = glm::vec3(1.0f, 0.25f, 0.0625f);
  scene.lights.push_back(spot);

  const std::string json = sceneToJson(scene);
  const Scene back = parseScene(json, "roundtrip.json");
  EXPECT_EQ(sceneToJson(back), json);
  ASSERT_EQ(back.lights.size(), scene.lights.size());
  EXPECT_EQ(back.lights.back().position, spot.position);
  EXPECT_EQ(back.lights.back().attenuation, spot.attenuation);
  EXPECT_EQ(back.model, scene.model);
  EXPECT_EQ(back.material.diffuseTexture, "wood.png");
}

TEST(SceneFile, BrdfFileAndParameters)
{
  // Values as "name=value" assignments, what `shadelab render --param` takes.
  const Scene s = parseScene(
    R"({"brdf": {"file": "ward.brdf", "parameters": {"alpha": 0.25, "iso": true, "tint": [1, 0.5, 0]}}})", "a.json");
  EXPECT_EQ(s.brdf.file, "ward.brdf");
  EXPECT_EQ(s.brdf.parameters, (std::vector<std::string>{ "alpha=0.25", "iso=1", "tint=1,0.5,0" }));
  const Scene back = parseScene(sceneToJson(s), "back.json");
  EXPECT_EQ(back.brdf.file, s.brdf.file);
  EXPECT_EQ(back.brdf.parameters, s.brdf.parameters);
  EXPECT_EQ(sceneToJson(back), sceneToJson(s));
  EXPECT_EQ(sceneToJson(Scene()).find("brdf"), std::string::npos) << "no brdf key without a file";

  EXPECT_EQ(errorFor(R"({"brdf": {"parameters": {}}})"), "bad.json: brdf: missing key \"file\" (the .brdf file)");
  EXPECT_EQ(errorFor(R"({"brdf": {"file": ""}})"), "bad.json: brdf.file: must name a .brdf file");
  EXPECT_EQ(errorFor(R"({"brdf": {"file": "a.brdf", "parameters": {"k": "x"}}})"),
    "bad.json: brdf.parameters.k: expected a number, true/false or [r, g, b], got a string");
  EXPECT_EQ(errorFor(R"({"brdf": {"file": "a.brdf", "parameters": {"c": [1, -1, 0]}}})").rfind(
              "bad.json: brdf.parameters.c[1]: ", 0),
    0u);
  EXPECT_EQ(errorFor(R"({"brdf": {"file": "a.brdf", "parameters": [1]}})"),
    "bad.json: brdf.parameters: expected an object of parameter values, got an array");
}

TEST(SceneFile, BrdfAssignmentsReadBackExactly)
{
  // What the pass, the viewer and the scene reader write is what the .brdf
  // reader takes, to the float: every kind, values with no short decimal.
  const BrdfFile file = parseBrdfText("::begin parameters\nfloat a 0 1 0.5\nbool b 0\ncolor c 0 0 0\n"
                                      "::end parameters\n::begin shader\nvec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y) { return c; }\n"
                                      "::end shader\n",
    "t.brdf");
  const std::vector<glm::vec3> values{ glm::vec3(1.0f / 3.0f), glm::vec3(1.0f),
    glm::vec3(0.1f, 2.0f / 7.0f, 1e-7f) };
  std::vector<std::string> assignments;
  for (size_t i = 0; i < values.size(); ++i)
  {
    assignments.push_back(brdfAssignment(file.parameters[i], values[i]));
  }
  EXPECT_EQ(assignments[1], "b=1");
  const std::vector<glm::vec3> back = brdfParameterValues(file, assignments);
  EXPECT_EQ(back[0].x, values[0].x);
  EXPECT_EQ(back[1].x, 1.0f);
  EXPECT_EQ(back[2], values[2]);
}

TEST(SceneFile, ShippedScenesAreValid)
{
  for (const char* name : { "default.json", "glow.json", "regression/all-lights.json", "regression/directional.json",
         "regression/point.json", "regression/spot.json", "regression/ambient.json", "regression/microfacet.json" })
  {
    const Scene s = readSceneFile(std::string(SHADELAB_DATA_DIR) + "/scenes/" + name);
    EXPECT_FALSE(s.lights.empty()) << name;
  }
}

TEST(SceneFile, SchemaListsExactlyTheKeysTheReaderAccepts)
{
  // The reader's "allowed here" list for each object, against the JSON Schema.
  std::ifstream in(SHADELAB_SCHEMA_FILE);
  ASSERT_TRUE(in.good());
  const nlohmann::json schema = nlohmann::json::parse(in);
  auto schemaKeys = [](const nlohmann::json& object) {
    std::string out;
    for (const auto& item : object["properties"].items())
    {
      out += (out.empty() ? "" : ", ") + ("\"" + item.key() + "\"");
    }
    return out; // nlohmann::json orders keys alphabetically, as std::set does
  };
  auto allowedIn = [](const std::string& message) {
    const size_t open = message.find("(allowed here: ");
    return open == std::string::npos ? message : message.substr(open + 15, message.size() - open - 16);
  };
  EXPECT_EQ(allowedIn(errorFor(R"({"zzz": 1})")), schemaKeys(schema));
  EXPECT_EQ(allowedIn(errorFor(R"({"shading": {"zzz": 1}})")), schemaKeys(schema["$defs"]["shading"]));
  EXPECT_EQ(allowedIn(errorFor(R"({"material": {"zzz": 1}})")), schemaKeys(schema["$defs"]["material"]));
  EXPECT_EQ(allowedIn(errorFor(R"({"camera": {"zzz": 1}})")), schemaKeys(schema["$defs"]["camera"]));
  EXPECT_EQ(allowedIn(errorFor(R"({"brdf": {"file": "a.brdf", "zzz": 1}})")), schemaKeys(schema["$defs"]["brdf"]));
  for (const LightTypeInfo& t : kLightTypes)
  {
    const std::string light = std::string(R"({"lights": [{"type": ")") + t.name + R"(", "zzz": 1}]})";
    EXPECT_EQ(allowedIn(errorFor(light)), schemaKeys(schema["$defs"][std::string(t.name) + "Light"])) << t.name;
  }
}

namespace
{
/// @p property with its "$ref" chain resolved; its own keys win.
nlohmann::json resolved(const nlohmann::json& schema, nlohmann::json property)
{
  while (property.contains("$ref"))
  {
    std::string ref = property["$ref"].get<std::string>();
    property.erase("$ref");
    nlohmann::json target = schema[nlohmann::json::json_pointer(ref.substr(1))];
    target.update(property);
    property = target;
  }
  return property;
}

nlohmann::json asJson(const glm::vec3& v)
{
  return nlohmann::json::array({ v.x, v.y, v.z });
}

/// The schema's default equals the field's default, as the reader stores it (float).
bool sameDefault(const nlohmann::json& schemaDefault, const nlohmann::json& value)
{
  if (schemaDefault.is_array() && value.is_array() && schemaDefault.size() == value.size())
  {
    for (size_t i = 0; i < value.size(); ++i)
    {
      if (static_cast<float>(schemaDefault[i].get<double>()) != value[i].get<float>())
      {
        return false;
      }
    }
    return true;
  }
  if (schemaDefault.is_number() && value.is_number())
  {
    return static_cast<float>(schemaDefault.get<double>()) == value.get<float>();
  }
  return schemaDefault == value;
}

/// The schema's entry for @p key (of an object whose defaults are @p object)
/// has the key's type, range and default.
template <typename Struct>
void expectSchemaMatches(
  const nlohmann::json& schema, const nlohmann::json& properties, const SceneKey<Struct>& key, const Struct& object,
  bool needsDefault, const std::string& where)
{
  SCOPED_TRACE(where + "." + key.name);
  ASSERT_TRUE(properties.contains(key.name));
  const nlohmann::json p = resolved(schema, properties[key.name]);
  auto expectBound = [&](const nlohmann::json& j, const char* closed, const char* open, double value, bool isOpen) {
    if (std::isinf(value))
    {
      EXPECT_FALSE(j.contains(closed) || j.contains(open)) << j.dump();
      return;
    }
    ASSERT_TRUE(j.contains(isOpen ? open : closed)) << j.dump();
    EXPECT_EQ(j[isOpen ? open : closed].get<double>(), value);
    EXPECT_FALSE(j.contains(isOpen ? closed : open));
  };
  nlohmann::json value;
  switch (key.kind)
  {
    case SceneKeyKind::Number:
      EXPECT_EQ(p["type"], "number");
      expectBound(p, "minimum", "exclusiveMinimum", key.lo, key.openLo);
      // A bound by another key (edge <= cutoff) is not a JSON Schema range.
      expectBound(p, "maximum", "exclusiveMaximum", key.upTo ? HUGE_VAL : key.hi, key.openHi);
      value = object.*(key.number);
      break;
    case SceneKeyKind::Colour:
    case SceneKeyKind::Point:
    case SceneKeyKind::Direction:
    case SceneKeyKind::Coefficients:
      EXPECT_EQ(p["type"], "array");
      EXPECT_EQ(p["minItems"], 3);
      EXPECT_EQ(p["maxItems"], 3);
      EXPECT_EQ(p["items"]["type"], "number");
      expectBound(p["items"], "minimum", "exclusiveMinimum", key.lo, key.openLo);
      expectBound(p["items"], "maximum", "exclusiveMaximum", key.hi, key.openHi);
      value = asJson(object.*(key.vector));
      break;
    case SceneKeyKind::Text:
      EXPECT_EQ(p["type"], "string");
      EXPECT_EQ(p.contains("minLength"), key.whenEmpty != nullptr);
      return; // texts have no default
    case SceneKeyKind::Space:
      EXPECT_EQ(p["enum"], nlohmann::json(lightSpaceNames()));
      value = lightSpaceName(object.*(key.space));
      break;
    case SceneKeyKind::Parameters:
      EXPECT_EQ(p["type"], "object");
      EXPECT_EQ(p["additionalProperties"]["oneOf"].size(), 3u) << p.dump();
      return; // the file's defaults hold for parameters not given
  }
  if (needsDefault)
  {
    ASSERT_TRUE(p.contains("default")) << p.dump();
  }
  if (p.contains("default"))
  {
    EXPECT_TRUE(sameDefault(p["default"], value)) << p["default"].dump() << " vs " << value.dump();
  }
}
} // namespace

TEST(SceneFile, SchemaTypesRangesAndDefaultsAreTheKeyTables)
{
  std::ifstream in(SHADELAB_SCHEMA_FILE);
  ASSERT_TRUE(in.good());
  const nlohmann::json schema = nlohmann::json::parse(in);
  const nlohmann::json& defs = schema["$defs"];
  for (const LightTypeInfo& t : kLightTypes)
  {
    const nlohmann::json& properties = defs[std::string(t.name) + "Light"]["properties"];
    EXPECT_EQ(properties["type"]["const"], t.name);
    for (const SceneKey<SceneLight>& key : lightKeys())
    {
      if (lightTakesKey(t.type, key))
      {
        expectSchemaMatches(schema, properties, key, defaultLight(t.type), true, t.name);
      }
      else
      {
        EXPECT_FALSE(properties.contains(key.name)) << t.name << " takes no " << key.name;
      }
    }
  }
  const nlohmann::json lightTypes = schema["properties"]["lights"]["items"]["oneOf"];
  ASSERT_EQ(lightTypes.size(), static_cast<size_t>(kLightTypeCount));
  for (int i = 0; i < kLightTypeCount; ++i)
  {
    EXPECT_EQ(lightTypes[i]["$ref"], std::string("#/$defs/") + kLightTypes[i].name + "Light");
  }
  for (const SceneKey<SceneMaterial>& key : materialKeys())
  {
    expectSchemaMatches(schema, defs["material"]["properties"], key, SceneMaterial(), true, "material");
  }
  for (const SceneKey<SceneBrdf>& key : brdfKeys())
  {
    expectSchemaMatches(schema, defs["brdf"]["properties"], key, SceneBrdf(), false, "brdf");
  }
  EXPECT_EQ(defs["brdf"]["required"], nlohmann::json::array({ "file" }));
  for (const SceneKey<SceneCamera>& key : cameraKeys())
  {
    // position and focalPoint have no default: without them the mesh is fitted.
    expectSchemaMatches(schema, defs["camera"]["properties"], key, SceneCamera(), key.kind != SceneKeyKind::Point,
      "camera");
  }
  const Scene defaults;
  EXPECT_EQ(defs["shading"]["properties"]["model"]["enum"], nlohmann::json(modelNames()));
  EXPECT_EQ(defs["shading"]["properties"]["model"]["default"], modelName(defaults.model));
  EXPECT_EQ(defs["shading"]["properties"]["frequency"]["enum"], nlohmann::json(frequencyNames()));
  EXPECT_EQ(defs["shading"]["properties"]["frequency"]["default"], frequencyName(defaults.frequency));
  EXPECT_EQ(defs["pixels"]["minimum"], kMinImageSize);
  EXPECT_EQ(defs["pixels"]["maximum"], kMaxImageSize);
  EXPECT_EQ(schema["properties"]["imageSize"]["default"], nlohmann::json::array({ defaults.width, defaults.height }));
  EXPECT_TRUE(sameDefault(schema["properties"]["background"]["default"], asJson(defaults.background)));
}
