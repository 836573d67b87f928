// Internal to the glTF loader: validation, accessor reading, conversion to rtlab's Scene.
// Order of use: parse (gltf_loader.cpp) -> validateModel -> convertMaterials -> convertMeshes ->
// convertNodes. Nothing reads buffer data before validateModel has checked its bounds.
#pragma once
#include "scene/scene.h"

#include <tiny_gltf.h>

#include <string>
#include <vector>

namespace rtlab::gltf {

// Throws Error(Input): "scene 'FILE': WHAT".
[[noreturn]] void fail(const std::string& file, const std::string& what);
void warn(const std::string& file, const std::string& what);

// Structure and bounds: every index in range, every accessor inside its buffer view and every
// buffer view inside its buffer, attribute types as glTF requires, a tree-shaped node hierarchy,
// finite transforms, valid lights and cameras.
void validateModel(const tinygltf::Model& model, const std::string& file);

// Accessor reading; only after validateModel, for accessors whose type validateModel checked.
// Normalized integer components are mapped to [0,1] / [-1,1].
std::vector<glm::vec2> readVec2(const tinygltf::Model& model, int accessor);
std::vector<glm::vec3> readVec3(const tinygltf::Model& model, int accessor);
std::vector<glm::vec4> readVec4(const tinygltf::Model& model, int accessor);
std::vector<std::uint32_t> readIndices(const tinygltf::Model& model, int accessor);
// Component size in bytes (0 if not a glTF accessor component type) and components per element
// (0 if unknown).
int componentSize(int componentType);
int componentCount(int type);

// Fills scene.materials (same indices as the file) and scene.textures (one per image and color
// space actually used; an image used both as sRGB and linear data is stored twice).
void convertMaterials(const tinygltf::Model& model, Scene& scene, const std::string& file);

// Fills scene.meshes, one per triangle primitive; returns, per glTF mesh, its scene mesh indices.
std::vector<std::vector<int>> convertMeshes(const tinygltf::Model& model, Scene& scene,
                                            const std::string& file);

// Walks the default scene (scene 0 if none; all root nodes if the file has no scenes) depth first:
// instances, the first perspective camera, KHR_lights_punctual lights in node order, then
// rtlab_area_light rectangles from node extras in node order.
void convertNodes(const tinygltf::Model& model, const std::vector<std::vector<int>>& meshMap,
                  Scene& scene, const std::string& file);

} // namespace rtlab::gltf
