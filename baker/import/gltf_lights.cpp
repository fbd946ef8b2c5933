// KHR_lights_punctual: tinygltf parses the document's lights into Model::lights; the node
// references are read from each node's extension object (see gltf_lights.h).
#include "gltf_lights.h"

#include "gltf_accessors.h" // fail

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lfd::bake::gltf {
namespace {

// The light index a node's KHR_lights_punctual extension names, or -1.
int nodeLight(const tinygltf::Node& node)
{
    const auto it = node.extensions.find("KHR_lights_punctual");
    if (it == node.extensions.end() || !it->second.IsObject())
        return -1;
    const tinygltf::Value& light = it->second.Get("light");
    return light.IsNumber() ? light.GetNumberAsInt() : -1;
}

LightType lightType(const std::string& type)
{
    return type == "spot" ? LightType::Spot : type == "point" ? LightType::Point : LightType::Directional;
}

Light convertLight(const tinygltf::Light& in, size_t index, uint32_t node, const std::string& file)
{
    const std::string path = "extensions.KHR_lights_punctual.lights[" + std::to_string(index) + "]";
    Light out;
    out.name = in.name.empty() ? "light " + std::to_string(index) : in.name;
    out.type = lightType(in.type);
    out.node = node;
    if (in.color.size() == 3)
        out.color = glm::clamp(glm::vec3(float(in.color[0]), float(in.color[1]), float(in.color[2])), 0.0f, 1.0f);
    out.intensity = float(std::max(in.intensity, 0.0));
    // "range: When undefined, range is assumed to be infinite"; the pack writes that as 0.
    out.range = in.range > 0.0 ? float(in.range) : 0.0f;
    if (out.type == LightType::Spot) {
        constexpr double kQuarterTurn = std::numbers::pi / 2.0;
        out.innerConeAngle = float(std::clamp(in.spot.innerConeAngle, 0.0, kQuarterTurn));
        out.outerConeAngle = float(std::clamp(in.spot.outerConeAngle, 0.0, kQuarterTurn));
        if (!(out.innerConeAngle < out.outerConeAngle)) // the validation refused this already
            fail(file, path + ".spot: innerConeAngle is not less than outerConeAngle");
    }
    for (float v : {out.color.r, out.color.g, out.color.b, out.intensity, out.range})
        if (!std::isfinite(v))
            fail(file, path + " has a value too large for a 32-bit float");
    return out;
}

} // namespace

std::vector<Light> convertLights(const tinygltf::Model& model, const std::vector<int32_t>& newIndex,
                                 const std::string& file, std::vector<std::string>& warnings)
{
    std::vector<Light> lights;
    for (size_t n = 0; n < model.nodes.size(); ++n) {
        const int light = nodeLight(model.nodes[n]);
        if (light < 0)
            continue;
        const std::string path = "nodes[" + std::to_string(n) + "].extensions.KHR_lights_punctual.light";
        if (size_t(light) >= model.lights.size())
            fail(file, path + ": light " + std::to_string(light) + " does not exist");
        if (n >= newIndex.size() || newIndex[n] == kNone) {
            warnings.push_back(path + ": light " + std::to_string(light) +
                               " is on a node outside the imported scene: dropped");
            continue;
        }
        lights.push_back(convertLight(model.lights[size_t(light)], size_t(light), uint32_t(newIndex[n]), file));
    }
    std::stable_sort(lights.begin(), lights.end(), [](const Light& a, const Light& b) { return a.node < b.node; });
    return lights;
}

} // namespace lfd::bake::gltf
