#include "shadelab/DefaultScene.h"

namespace shadelab
{

Scene defaultScene()
{
  Scene scene;
  scene.description = "ShadeLab built-in default: camera-space key and fill lights";

  SceneLight key;
  key.name = "key";
  key.space = LightSpace::Camera;
  key.direction = glm::vec3(0.5f, -0.6f, -1.0f);
  scene.lights.push_back(key);

  SceneLight fill;
  fill.name = "fill";
  fill.space = LightSpace::Camera;
  fill.direction = glm::vec3(-0.8f, 0.2f, -0.6f);
  fill.diffuse = glm::vec3(0.35f, 0.38f, 0.45f);
  fill.specular = glm::vec3(0.0f);
  scene.lights.push_back(fill);

  SceneLight ambient;
  ambient.name = "ambient";
  ambient.type = LightType::Ambient;
  ambient.ambient = glm::vec3(1.0f);
  ambient.diffuse = ambient.specular = glm::vec3(0.0f);
  scene.lights.push_back(ambient);
  return scene;
}

} // namespace shadelab
