// The object checks of glTF validation (internal to the baker), one file per glTF object
// with both phases of it (gltf_validation.h): check_<object>.cpp. The drivers in
// gltf_validation.cpp call them in a fixed order, which is the order of the issues.
#pragma once

#include "validation/context.h"

#include <string>

namespace lfd::bake::gltf {

class ModelContext;

// ---- Schema phase: the JSON of one object (or of the document's lists) ---------------
void checkAssetSchema(ValidationContext& ctx);           // check_asset.cpp
void checkExtensionListsSchema(ValidationContext& ctx);  // check_asset.cpp
void checkSceneSchema(ValidationContext& ctx, const json& scene, const std::string& path);
void checkPunctualLightsSchema(ValidationContext& ctx);  // check_light.cpp
void checkNodeSchema(ValidationContext& ctx, const json& node, const std::string& path);
void checkMeshSchema(ValidationContext& ctx, const json& mesh, const std::string& path);
void checkAccessorSchema(ValidationContext& ctx, const json& accessor, const std::string& path);
void checkBufferViewSchema(ValidationContext& ctx, const json& view, const std::string& path); // check_buffer.cpp
void checkBufferSchema(ValidationContext& ctx, const json& buffer, const std::string& path);
void checkMaterialSchema(ValidationContext& ctx, const json& material, const std::string& path);
void checkTextureSchema(ValidationContext& ctx, const json& texture, const std::string& path); // check_texture.cpp
void checkSamplerSchema(ValidationContext& ctx, const json& sampler, const std::string& path); // check_texture.cpp
void checkImageSchema(ValidationContext& ctx, const json& image, const std::string& path);     // check_texture.cpp
void checkAnimationSchema(ValidationContext& ctx, const json& animation, const std::string& path);
void checkCameraSchema(ValidationContext& ctx, const json& camera, const std::string& path);
void checkSkinSchema(ValidationContext& ctx, const json& skin, const std::string& path);

// ---- Semantic phase: rules beyond the schema, on tinygltf's model ---------------------
void checkImageViewSemantics(ModelContext& mc);  // check_texture.cpp
void checkBufferViewSemantics(ModelContext& mc); // check_buffer.cpp
void checkAccessorSemantics(ModelContext& mc);
void checkNodeHierarchy(ModelContext& mc);       // check_node.cpp
void checkSceneSemantics(ModelContext& mc);
void checkNodeSemantics(ModelContext& mc);
void checkMeshSemantics(ModelContext& mc);
void checkAnimationSemantics(ModelContext& mc);
void checkSkinSemantics(ModelContext& mc);

} // namespace lfd::bake::gltf
