// glTF 2.0 (.gltf and .glb): every buffer exists and holds its byteLength,
// every view lies in its buffer, every accessor in its view, and every index
// into buffers, views, accessors, meshes, nodes, skins, textures, images and
// samplers names an existing one, with no node its own ancestor.
// vtkGLTFReader follows all of these unchecked.
#include "slMeshFileCheck.h"

#include "shadelab/PrintableText.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <functional>
#include <vector>

namespace
{
using json = nlohmann::json;

/// Thrown with the one-line problem.
struct Problem
{
  std::string text;
};

[[noreturn]] void fail(const std::string& text)
{
  throw Problem{ text };
}

const json& member(const json& object, const char* key)
{
  static const json none;
  return object.is_object() && object.contains(key) ? object[key] : none;
}

/// A non-negative integer @p key of @p object (or @p fallback when absent).
unsigned long long count(const json& object, const char* key, const std::string& where, unsigned long long fallback = 0)
{
  const json& value = member(object, key);
  if (value.is_null())
  {
    return fallback;
  }
  if (!value.is_number_unsigned())
  {
    fail(where + "." + key + " is not a non-negative integer");
  }
  return value.get<unsigned long long>();
}

/// The file an external @p uri (a string, not data:) of @p where names in
/// @p folder; fails unless it is a regular file, which VTK then reads whole
/// (a FIFO hung the image reader, a device never ends).
std::filesystem::path externalFile(const std::filesystem::path& folder, const json& uri, const std::string& where)
{
  const std::filesystem::path path = folder / uri.get<std::string>();
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error))
  {
    const bool exists = std::filesystem::exists(path, error);
    fail(where + ".uri: " + (exists ? "not a regular file" : "no file") + " \"" +
      shadelab::printableText(uri.get<std::string>(), 200) + "\"");
  }
  return path;
}

const json& list(const json& root, const char* key)
{
  static const json empty = json::array();
  const json& value = member(root, key);
  if (value.is_null())
  {
    return empty;
  }
  if (!value.is_array())
  {
    fail(std::string(key) + " is not an array");
  }
  return value;
}

/// Checks that @p object's @p key, when present, indexes @p array (named @p arrayName).
void reference(const json& object, const char* key, const json& array, const char* arrayName, const std::string& where)
{
  if (member(object, key).is_null())
  {
    return;
  }
  const unsigned long long i = count(object, key, where);
  if (i >= array.size())
  {
    fail(where + "." + key + " = " + std::to_string(i) + " names no " + arrayName + " (there are " +
      std::to_string(array.size()) + ")");
  }
}

std::string at(const char* array, size_t i)
{
  return std::string(array) + "[" + std::to_string(i) + "]";
}

int componentSize(unsigned long long type)
{
  switch (type)
  {
    case 5120:
    case 5121:
      return 1;
    case 5122:
    case 5123:
      return 2;
    case 5125:
    case 5126:
      return 4;
    default:
      return 0;
  }
}

int componentCount(const std::string& type)
{
  static const std::pair<const char*, int> types[] = { { "SCALAR", 1 }, { "VEC2", 2 }, { "VEC3", 3 }, { "VEC4", 4 },
    { "MAT2", 4 }, { "MAT3", 9 }, { "MAT4", 16 } };
  for (const auto& t : types)
  {
    if (type == t.first)
    {
      return t.second;
    }
  }
  return 0;
}

/// Bytes a base64 data URI decodes to.
unsigned long long dataURIBytes(const std::string& uri)
{
  const size_t comma = uri.find(',');
  if (comma == std::string::npos || uri.find(";base64") == std::string::npos)
  {
    return 0;
  }
  unsigned long long chars = uri.size() - comma - 1;
  while (chars > 0 && uri[comma + chars] == '=')
  {
    --chars;
  }
  return chars * 3 / 4;
}

void checkDocument(const json& root, const std::filesystem::path& folder, long long binChunk)
{
  if (!root.is_object())
  {
    fail("the JSON is not an object");
  }
  const json& buffers = list(root, "buffers");
  const json& views = list(root, "bufferViews");
  const json& accessors = list(root, "accessors");
  const json& meshes = list(root, "meshes");
  const json& nodes = list(root, "nodes");
  const json& scenes = list(root, "scenes");
  const json& skins = list(root, "skins");
  const json& images = list(root, "images");
  const json& textures = list(root, "textures");
  const json& samplers = list(root, "samplers");
  const json& materials = list(root, "materials");
  const json& cameras = list(root, "cameras");

  std::vector<unsigned long long> bufferBytes;
  for (size_t i = 0; i < buffers.size(); ++i)
  {
    const std::string where = at("buffers", i);
    const unsigned long long bytes = count(buffers[i], "byteLength", where);
    const json& uri = member(buffers[i], "uri");
    unsigned long long available = 0;
    if (uri.is_null())
    {
      if (i != 0 || binChunk < 0)
      {
        fail(where + " has no uri and there is no GLB binary chunk for it");
      }
      available = static_cast<unsigned long long>(binChunk);
    }
    else if (!uri.is_string())
    {
      fail(where + ".uri is not a string");
    }
    else if (uri.get<std::string>().rfind("data:", 0) == 0)
    {
      available = dataURIBytes(uri.get<std::string>());
    }
    else
    {
      std::error_code error;
      available = std::filesystem::file_size(externalFile(folder, uri, where), error);
    }
    if (available < bytes)
    {
      fail(where + " holds " + std::to_string(available) + " bytes, its byteLength is " + std::to_string(bytes));
    }
    bufferBytes.push_back(bytes);
  }

  std::vector<unsigned long long> viewBytes, viewStride;
  for (size_t i = 0; i < views.size(); ++i)
  {
    const std::string where = at("bufferViews", i);
    if (member(views[i], "buffer").is_null())
    {
      fail(where + " has no buffer");
    }
    reference(views[i], "buffer", buffers, "buffer", where);
    const unsigned long long offset = count(views[i], "byteOffset", where);
    if (member(views[i], "byteLength").is_null())
    {
      fail(where + " has no byteLength");
    }
    const unsigned long long bytes = count(views[i], "byteLength", where);
    const unsigned long long buffer = bufferBytes[count(views[i], "buffer", where)];
    if (offset > buffer || bytes > buffer - offset)
    {
      fail(where + " (bytes " + std::to_string(offset) + " + " + std::to_string(bytes) + ") reaches beyond its buffer of " +
        std::to_string(buffer) + " bytes");
    }
    viewBytes.push_back(bytes);
    viewStride.push_back(count(views[i], "byteStride", where));
  }

  // An accessor's last element must end within its view.
  auto span = [&](const std::string& where, unsigned long long view, unsigned long long offset, unsigned long long n,
                unsigned long long element, unsigned long long stride) {
    if (n == 0)
    {
      return;
    }
    const unsigned long long step = stride ? stride : element;
    const unsigned long long limit = viewBytes[view];
    if (offset > limit || element > limit - offset || (n - 1) > (limit - offset - element) / (step ? step : 1))
    {
      fail(where + ": " + std::to_string(n) + " elements of " + std::to_string(element) + " bytes from byte " +
        std::to_string(offset) + " reach beyond its bufferView of " + std::to_string(limit) + " bytes");
    }
  };
  for (size_t i = 0; i < accessors.size(); ++i)
  {
    const json& a = accessors[i];
    const std::string where = at("accessors", i);
    const int size = componentSize(count(a, "componentType", where));
    const json& type = member(a, "type");
    const int components = type.is_string() ? componentCount(type.get<std::string>()) : 0;
    if (size == 0 || components == 0)
    {
      fail(where + " has an unknown componentType or type");
    }
    const unsigned long long n = count(a, "count", where);
    if (n == 0)
    {
      fail(where + " has no count (at least 1)");
    }
    // glTF allows an accessor without a view (all zeros); VTK 9.1 reads
    // through it regardless.
    if (member(a, "bufferView").is_null())
    {
      fail(where + " has no bufferView (zero-filled accessors are not read)");
    }
    reference(a, "bufferView", views, "bufferView", where);
    if (!member(a, "bufferView").is_null())
    {
      const unsigned long long view = count(a, "bufferView", where);
      span(where, view, count(a, "byteOffset", where), n, static_cast<unsigned long long>(size * components),
        viewStride[view]);
    }
    const json& sparse = member(a, "sparse");
    if (!sparse.is_null())
    {
      const unsigned long long m = count(sparse, "count", where + ".sparse");
      const json& indices = member(sparse, "indices");
      const json& values = member(sparse, "values");
      if (member(indices, "bufferView").is_null() || member(values, "bufferView").is_null() || m > n)
      {
        fail(where + ".sparse is incomplete or longer than the accessor");
      }
      reference(indices, "bufferView", views, "bufferView", where + ".sparse.indices");
      reference(values, "bufferView", views, "bufferView", where + ".sparse.values");
      const int indexSize = componentSize(count(indices, "componentType", where + ".sparse.indices"));
      if (indexSize == 0)
      {
        fail(where + ".sparse.indices has an unknown componentType");
      }
      span(where + ".sparse.indices", count(indices, "bufferView", where), count(indices, "byteOffset", where), m,
        static_cast<unsigned long long>(indexSize), 0);
      span(where + ".sparse.values", count(values, "bufferView", where), count(values, "byteOffset", where), m,
        static_cast<unsigned long long>(size * components), 0);
    }
  }

  auto accessorMap = [&](const json& map, const std::string& where) {
    if (map.is_null())
    {
      return;
    }
    if (!map.is_object())
    {
      fail(where + " is not an object");
    }
    for (auto it = map.begin(); it != map.end(); ++it)
    {
      const json holder = { { it.key(), it.value() } };
      reference(holder, it.key().c_str(), accessors, "accessor", where);
    }
  };
  // The accessor @p key of @p object, if present, has the layout VTK reads
  // it with (types: "VEC3"; components: the allowed componentType values).
  auto layout = [&](const json& object, const char* key, const std::string& where, const char* type,
                  std::initializer_list<unsigned long long> components) {
    if (member(object, key).is_null())
    {
      return;
    }
    const json& a = accessors[count(object, key, where)];
    const unsigned long long component = count(a, "componentType", where);
    bool known = false;
    for (unsigned long long c : components)
    {
      known = known || c == component;
    }
    if (member(a, "type") != type || !known)
    {
      fail(where + "." + key + ": accessor " + std::to_string(count(object, key, where)) + " is not of type " + type +
        " with a component type VTK reads there");
    }
  };
  for (size_t m = 0; m < meshes.size(); ++m)
  {
    const json& primitives = member(meshes[m], "primitives");
    for (size_t p = 0; primitives.is_array() && p < primitives.size(); ++p)
    {
      const std::string where = at("meshes", m) + "." + at("primitives", p);
      // vtkGLTFReader builds every primitive from its POSITION accessor.
      if (member(member(primitives[p], "attributes"), "POSITION").is_null())
      {
        fail(where + " has no attributes.POSITION");
      }
      accessorMap(member(primitives[p], "attributes"), where + ".attributes");
      reference(primitives[p], "indices", accessors, "accessor", where);
      layout(primitives[p], "indices", where, "SCALAR", { 5121, 5123, 5125 });
      const json& attributes = member(primitives[p], "attributes");
      layout(attributes, "POSITION", where + ".attributes", "VEC3", { 5126 });
      layout(attributes, "NORMAL", where + ".attributes", "VEC3", { 5126 });
      layout(attributes, "TANGENT", where + ".attributes", "VEC4", { 5126 });
      layout(attributes, "TEXCOORD_0", where + ".attributes", "VEC2", { 5126, 5121, 5123 });
      reference(primitives[p], "material", materials, "material", where);
      const json& targets = member(primitives[p], "targets");
      for (size_t t = 0; targets.is_array() && t < targets.size(); ++t)
      {
        accessorMap(targets[t], where + "." + at("targets", t));
      }
    }
  }
  for (size_t i = 0; i < skins.size(); ++i)
  {
    reference(skins[i], "inverseBindMatrices", accessors, "accessor", at("skins", i));
    reference(skins[i], "skeleton", nodes, "node", at("skins", i));
    const json& joints = member(skins[i], "joints");
    for (size_t j = 0; joints.is_array() && j < joints.size(); ++j)
    {
      const json holder = { { "joint", joints[j] } };
      reference(holder, "joint", nodes, "node", at("skins", i) + "." + at("joints", j));
    }
  }
  for (size_t i = 0; i < images.size(); ++i)
  {
    reference(images[i], "bufferView", views, "bufferView", at("images", i));
    const json& uri = member(images[i], "uri");
    if (!uri.is_null() && !uri.is_string())
    {
      fail(at("images", i) + ".uri is not a string");
    }
    if (uri.is_string() && uri.get<std::string>().rfind("data:", 0) != 0)
    {
      externalFile(folder, uri, at("images", i));
    }
  }
  for (size_t i = 0; i < textures.size(); ++i)
  {
    reference(textures[i], "source", images, "image", at("textures", i));
    reference(textures[i], "sampler", samplers, "sampler", at("textures", i));
  }
  // Texture references of materials: any object with an "index" under a
  // key ending in "Texture".
  std::function<void(const json&, const std::string&)> textureRefs = [&](const json& value, const std::string& where) {
    if (!value.is_object())
    {
      return;
    }
    for (auto it = value.begin(); it != value.end(); ++it)
    {
      const std::string& key = it.key();
      if (key.size() >= 7 && key.compare(key.size() - 7, 7, "Texture") == 0 && it.value().is_object())
      {
        reference(it.value(), "index", textures, "texture", where + "." + key);
      }
      textureRefs(it.value(), where + "." + key);
    }
  };
  for (size_t i = 0; i < materials.size(); ++i)
  {
    textureRefs(materials[i], at("materials", i));
  }
  for (size_t i = 0; i < nodes.size(); ++i)
  {
    const std::string where = at("nodes", i);
    reference(nodes[i], "mesh", meshes, "mesh", where);
    reference(nodes[i], "skin", skins, "skin", where);
    reference(nodes[i], "camera", cameras, "camera", where);
    const json& children = member(nodes[i], "children");
    for (size_t c = 0; children.is_array() && c < children.size(); ++c)
    {
      const json holder = { { "child", children[c] } };
      reference(holder, "child", nodes, "node", where + "." + at("children", c));
    }
  }
  // No node may be its own ancestor (the reader recurses through children).
  std::vector<int> state(nodes.size(), 0); // 0 unvisited, 1 on the path, 2 done
  std::function<void(size_t, int)> visit = [&](size_t n, int depth) {
    if (depth > 1000)
    {
      fail(at("nodes", n) + ": the node hierarchy is deeper than 1000 levels");
    }
    state[n] = 1;
    const json& children = member(nodes[n], "children");
    for (size_t c = 0; children.is_array() && c < children.size(); ++c)
    {
      const size_t child = children[c].get<size_t>();
      if (state[child] == 1)
      {
        fail(at("nodes", n) + ".children: node " + std::to_string(child) + " is its own ancestor");
      }
      if (state[child] == 0)
      {
        visit(child, depth + 1);
      }
    }
    state[n] = 2;
  };
  for (size_t i = 0; i < nodes.size(); ++i)
  {
    if (state[i] == 0)
    {
      visit(i, 0);
    }
  }
  for (size_t i = 0; i < scenes.size(); ++i)
  {
    const json& roots = member(scenes[i], "nodes");
    for (size_t r = 0; roots.is_array() && r < roots.size(); ++r)
    {
      const json holder = { { "node", roots[r] } };
      reference(holder, "node", nodes, "node", at("scenes", i) + "." + at("nodes", r));
    }
  }
  reference(root, "scene", scenes, "scene", "scene");
  const json& animations = list(root, "animations");
  for (size_t i = 0; i < animations.size(); ++i)
  {
    const json& animationSamplers = member(animations[i], "samplers");
    for (size_t s = 0; animationSamplers.is_array() && s < animationSamplers.size(); ++s)
    {
      const std::string where = at("animations", i) + "." + at("samplers", s);
      reference(animationSamplers[s], "input", accessors, "accessor", where);
      reference(animationSamplers[s], "output", accessors, "accessor", where);
    }
    const json& channels = member(animations[i], "channels");
    for (size_t c = 0; channels.is_array() && c < channels.size(); ++c)
    {
      const std::string where = at("animations", i) + "." + at("channels", c);
      reference(channels[c], "sampler", animationSamplers, "sampler", where);
      reference(member(channels[c], "target"), "node", nodes, "node", where + ".target");
    }
  }
}

std::uint32_t little32(const unsigned char* b)
{
  return static_cast<std::uint32_t>(b[0]) | static_cast<std::uint32_t>(b[1]) << 8 |
    static_cast<std::uint32_t>(b[2]) << 16 | static_cast<std::uint32_t>(b[3]) << 24;
}
} // namespace

std::string slGLTFProblem(const std::string& fileName, bool binary)
{
  const std::string bytes = slReadWholeFile(fileName);
  std::string text = bytes;
  long long binChunk = -1;
  if (binary)
  {
    // GLB: "glTF", version 2, total length; a JSON chunk, then maybe a BIN chunk.
    const auto* b = reinterpret_cast<const unsigned char*>(bytes.data());
    if (bytes.size() < 20 || std::memcmp(b, "glTF", 4) != 0)
    {
      return "not a binary glTF file (no \"glTF\" header)";
    }
    if (little32(b + 4) != 2)
    {
      return "binary glTF version " + std::to_string(little32(b + 4)) + " (only 2 is read)";
    }
    if (little32(b + 8) > bytes.size())
    {
      return "truncated binary glTF: its header announces " + std::to_string(little32(b + 8)) + " bytes, the file has " +
        std::to_string(bytes.size());
    }
    const std::uint32_t jsonLength = little32(b + 12);
    if (std::memcmp(b + 16, "JSON", 4) != 0 || jsonLength > bytes.size() - 20)
    {
      return "binary glTF: the first chunk is not a JSON chunk within the file";
    }
    text = bytes.substr(20, jsonLength);
    const size_t next = 20 + static_cast<size_t>(jsonLength);
    if (next + 8 <= bytes.size() && std::memcmp(b + next + 4, "BIN\0", 4) == 0)
    {
      const std::uint32_t binLength = little32(b + next);
      if (binLength > bytes.size() - next - 8)
      {
        return "binary glTF: the BIN chunk of " + std::to_string(binLength) + " bytes reaches beyond the file";
      }
      binChunk = binLength;
    }
  }
  json root;
  try
  {
    root = json::parse(text);
  }
  catch (const json::exception& e)
  {
    const std::string what = e.what();
    const size_t space = what.find("] ");
    return "malformed glTF JSON: " + shadelab::printableText(space == std::string::npos ? what : what.substr(space + 2), 200);
  }
  try
  {
    checkDocument(root, std::filesystem::path(fileName).parent_path(), binChunk);
  }
  catch (const Problem& p)
  {
    return p.text;
  }
  catch (const json::exception& e)
  {
    return std::string("glTF: ") + shadelab::printableText(e.what(), 200);
  }
  return std::string();
}
