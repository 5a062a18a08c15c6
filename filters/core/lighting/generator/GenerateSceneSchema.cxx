// Writes scene.schema.json, the JSON Schema of ShadeLab scene files, from the
// key tables (shadelab/SceneKeys.h, with LightingTables.h's models and light
// types): every key with its type, range and default. Run by the build
// (filters/core/lighting/CMakeLists.txt), which installs the result beside
// the shipped scenes.
//
// Defaults are what the scene writer writes for a default Scene, a default
// light of each type and a fitted camera, so they read as the writer spells
// them (0.1, not 0.10000000149011612).
#include "WriteGenerated.h"
#include "shadelab/SceneFile.h"
#include "shadelab/SceneKeys.h"
#include "shadelab/SceneLimits.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <string>

namespace
{
using json = nlohmann::ordered_json;
using namespace shadelab;

/// Sets the JSON Schema bound of one end of a range; an infinite end has none.
void bound(json& out, const char* closedName, const char* openName, double value, bool open)
{
  if (std::isfinite(value))
  {
    out[open ? openName : closedName] = value;
  }
}

/// The schema of @p key; @p written is the object as the scene writer writes
/// it with default values (a key it leaves out has no default).
template <typename Struct>
json keySchema(const SceneKey<Struct>& key, const json& written)
{
  json p = json::object();
  switch (key.kind)
  {
    case SceneKeyKind::Number:
      p["type"] = "number";
      bound(p, "minimum", "exclusiveMinimum", key.lo, key.openLo);
      // A bound by another key (edge <= cutoff) is not a JSON Schema range:
      // the reader checks it and the description says it.
      bound(p, "maximum", "exclusiveMaximum", key.upTo ? HUGE_VAL : key.hi, key.openHi);
      break;
    case SceneKeyKind::Colour:
      p["$ref"] = "#/$defs/color";
      break;
    case SceneKeyKind::Point:
      p["$ref"] = "#/$defs/vector";
      break;
    case SceneKeyKind::Direction:
      p["$ref"] = "#/$defs/direction";
      break;
    case SceneKeyKind::Coefficients:
      p["type"] = "array";
      p["items"] = { { "type", "number" } };
      bound(p["items"], "minimum", "exclusiveMinimum", key.lo, key.openLo);
      bound(p["items"], "maximum", "exclusiveMaximum", key.hi, key.openHi);
      p["minItems"] = 3;
      p["maxItems"] = 3;
      break;
    case SceneKeyKind::Text:
      p["type"] = "string";
      if (key.whenEmpty)
      {
        p["minLength"] = 1;
      }
      break;
    case SceneKeyKind::Space:
      p["enum"] = lightSpaceNames();
      break;
    case SceneKeyKind::Parameters:
      p["type"] = "object";
      p["additionalProperties"] = { { "oneOf",
        { { { "type", "number" } }, { { "type", "boolean" } }, { { "$ref", "#/$defs/color" } } } } };
      break;
  }
  if (key.what)
  {
    p["description"] = key.what;
  }
  if (key.kind != SceneKeyKind::Text && key.kind != SceneKeyKind::Parameters && written.contains(key.name))
  {
    p["default"] = written[key.name];
  }
  return p;
}

/// An object of the keys of @p keys that @p takes selects (after @p first).
template <typename Struct, typename Select>
json objectSchema(const std::vector<SceneKey<Struct>>& keys, const json& written, Select takes, json first = json::object())
{
  json properties = std::move(first);
  for (const SceneKey<Struct>& key : keys)
  {
    if (takes(key))
    {
      properties[key.name] = keySchema(key, written);
    }
  }
  return { { "type", "object" }, { "additionalProperties", false }, { "properties", properties } };
}

json schema()
{
  // One light of each type, in table order, and a fitted camera.
  Scene defaults;
  for (const LightTypeInfo& t : kLightTypes)
  {
    defaults.lights.push_back(defaultLight(t.type));
  }
  const json written = json::parse(sceneToJson(defaults));
  auto every = [](const auto&) { return true; };

  json defs = json::object();
  defs["pixels"] = { { "type", "integer" }, { "minimum", kMinImageSize }, { "maximum", kMaxImageSize } };
  defs["color"] = { { "description", "Linear RGB; components >= 0 (values above 1 are allowed: HDR), at most 1e6." },
    { "type", "array" }, { "items", { { "type", "number" }, { "minimum", 0 }, { "maximum", kMaxColourValue } } },
    { "minItems", 3 }, { "maxItems", 3 } };
  defs["vector"] = { { "type", "array" }, { "items", { { "type", "number" } } }, { "minItems", 3 }, { "maxItems", 3 } };
  defs["direction"] = { { "description", "Any non-zero length; normalised on use." }, { "$ref", "#/$defs/vector" } };
  defs["shading"] = { { "type", "object" }, { "additionalProperties", false },
    { "properties",
      { { "model", { { "enum", modelNames() }, { "default", written["shading"]["model"] } } },
        { "frequency", { { "enum", frequencyNames() }, { "default", written["shading"]["frequency"] } } } } } };
  defs["material"] = objectSchema(materialKeys(), written["material"], every);
  defs["brdf"] = objectSchema(brdfKeys(), json::object(), every);
  defs["brdf"]["required"] = { "file" };
  defs["camera"] = objectSchema(cameraKeys(), written["camera"], every);
  defs["camera"]["description"] = "Give position and focalPoint together, or neither: then the mesh is fitted in "
                                  "view and azimuth/elevation turn the camera.";
  json lightRefs = json::array();
  for (int i = 0; i < kLightTypeCount; ++i)
  {
    const LightTypeInfo& t = kLightTypes[i];
    const std::string def = std::string(t.name) + "Light";
    json light = objectSchema(lightKeys(), written["lights"][i],
      [&t](const SceneKey<SceneLight>& key) { return lightTakesKey(t.type, key); },
      json{ { "type", { { "const", t.name } } } });
    light["required"] = { "type" };
    defs[def] = light;
    lightRefs.push_back({ { "$ref", "#/$defs/" + def } });
  }

  json properties = json::object();
  properties["$schema"] = { { "type", "string" }, { "description", "Ignored; lets editors find this schema." } };
  properties["description"] = { { "type", "string" } };
  properties["imageSize"] = { { "description", "Width and height of rendered images, in pixels." },
    { "type", "array" }, { "prefixItems", { { { "$ref", "#/$defs/pixels" } }, { { "$ref", "#/$defs/pixels" } } } },
    { "minItems", 2 }, { "maxItems", 2 }, { "default", written["imageSize"] } };
  properties["background"] = { { "$ref", "#/$defs/color" }, { "default", written["background"] } };
  properties["shading"] = { { "$ref", "#/$defs/shading" } };
  properties["material"] = { { "$ref", "#/$defs/material" } };
  properties["brdf"] = { { "$ref", "#/$defs/brdf" } };
  properties["camera"] = { { "$ref", "#/$defs/camera" } };
  properties["lights"] = { { "type", "array" }, { "items", { { "oneOf", lightRefs } } } };

  json root = json::object();
  root["$schema"] = "https://json-schema.org/draft/2020-12/schema";
  root["$id"] = "https://shadelab.example/scene.schema.json";
  root["title"] = "ShadeLab scene";
  root["description"] = "Lights, material, camera, lighting model and shading frequency for ShadeLab. Every key is "
                        "optional; unknown keys are errors. Generated by the build from ShadeLab's key tables; see "
                        "docs/scene-format.md.";
  root["type"] = "object";
  root["additionalProperties"] = false;
  root["properties"] = properties;
  root["$defs"] = defs;
  return root;
}
} // namespace

int main(int argc, char** argv)
{
  if (argc != 2)
  {
    std::fprintf(stderr, "usage: %s OUTPUT.json\n", argv[0]);
    return 2;
  }
  return shadelab::generator::writeGenerated(argv[1], schema().dump(2) + "\n") ? 0 : 1;
}
