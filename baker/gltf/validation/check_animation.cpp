// Animations (glTF 2.0 sections 3.11, 5.2-5.5): the JSON of an animation, its samplers and
// channels; the targets (once each, a node without a matrix, morph targets for weights) and
// the samplers' data (key times, value counts and formats).
#include "validation/checks.h"
#include "validation/model_context.h"

#include <cmath>
#include <map>
#include <set>

namespace lfd::bake::gltf {
namespace {

void samplerSchema(ValidationContext& ctx, const json& s, const std::string& p)
{
    ctx.indexMember(s, "input", p, "accessors", kRead, true);
    ctx.indexMember(s, "output", p, "accessors", kRead, true);
    ctx.enumString(s, "interpolation", p, {"LINEAR", "STEP", "CUBICSPLINE"}, kRead, false, "");
    ctx.common(s, p);
}

void channelSchema(ValidationContext& ctx, const json& c, const std::string& p, const std::string& animation,
                   size_t samplerCount)
{
    if (const json* s = member(c, "sampler"))
        ctx.indexInto(*s, at(p, "sampler"), at(animation, "samplers"), samplerCount, kRead);
    else
        ctx.report(IssueCode::MISSING_REQUIRED_PROPERTY, at(p, "sampler"), "required property missing");
    if (const json* target = ctx.object(c, "target", p, kRead, true)) {
        const std::string tp = at(p, "target");
        ctx.indexMember(*target, "node", tp, "nodes", kRead);
        // A path the baker does not animate (KHR_animation_pointer's "pointer"): the channel
        // is ignored.
        ctx.enumString(*target, "path", tp, {"translation", "rotation", "scale", "weights"}, kIgnored, true,
                       ": channel ignored");
        ctx.common(*target, tp);
    }
    ctx.common(c, p);
}

// Key times: FLOAT SCALAR with min and max, non-negative, strictly increasing. False when
// the input is not key times at all (nothing more to check).
bool keyTimes(ModelContext& mc, const tinygltf::AnimationSampler& s, const std::string& ip)
{
    const tinygltf::Accessor& input = mc.model.accessors[size_t(s.input)];
    if (input.type != TINYGLTF_TYPE_SCALAR || input.componentType != kFloat || input.normalized) {
        mc.report(IssueCode::ACCESSOR_WRONG_FORMAT, ip, formatOf(s.input, input, false) + ", not SCALAR/FLOAT (key times)");
        return false;
    }
    if (input.minValues.size() != 1 || input.maxValues.size() != 1)
        mc.report(IssueCode::ACCESSOR_BOUNDS_MISSING, accessorPath(s.input),
                  "is animation input (" + ip + ") without min and max (both required)");
    if (const std::optional<FloatArray>& times = mc.floats(s.input, TINYGLTF_TYPE_SCALAR)) {
        for (size_t k = 0; k < times->count; ++k) {
            const float t = times->values[k];
            if (!std::isfinite(t) || t < 0.0f) {
                mc.report(IssueCode::ANIMATION_KEY_TIME_INVALID, accessorPath(s.input),
                          "key time " + std::to_string(k) + " is " + json(t).dump() +
                              " (key times are finite and >= 0; " + ip + ")");
                break;
            }
            if (k > 0 && !(t > times->values[k - 1])) {
                mc.report(IssueCode::ANIMATION_KEY_TIMES_NOT_INCREASING, accessorPath(s.input),
                          "key time " + std::to_string(k) + " (" + json(t).dump() + ") does not increase strictly (" +
                              ip + ")");
                break;
            }
        }
    }
    return true;
}

// Values: as many as keys (three per key for cubic splines, at least two keys), of the
// formats section 3.11 lists for the target path.
void values(ModelContext& mc, const tinygltf::AnimationSampler& s, const std::string& path,
            const std::string& targetPath, size_t morphs)
{
    const tinygltf::Accessor& input = mc.model.accessors[size_t(s.input)];
    const tinygltf::Accessor& output = mc.model.accessors[size_t(s.output)];
    const std::string ip = at(path, "input"), op = at(path, "output");
    const bool cubic = s.interpolation == "CUBICSPLINE";
    const size_t perKey = (targetPath == "weights" ? std::max<size_t>(morphs, 1) : 1) * (cubic ? 3 : 1);
    if (cubic && input.count < 2)
        mc.report(IssueCode::ANIMATION_CUBICSPLINE_TOO_FEW_KEYS, ip,
                  "CUBICSPLINE needs at least 2 keys, " + accessorPath(s.input) + " has " + std::to_string(input.count));
    if (output.count != input.count * perKey)
        mc.report(IssueCode::ANIMATION_SAMPLER_OUTPUT_COUNT_MISMATCH, op,
                  accessorPath(s.output) + " has " + std::to_string(output.count) + " elements, " +
                      std::to_string(input.count * perKey) + " expected (" + std::to_string(input.count) + " keys" +
                      (cubic ? ", 3 values per key" : "") + ")");
    const std::vector<std::pair<int, bool>> floatOnly = {{kFloat, false}};
    const std::vector<std::pair<int, bool>> quantized = {
        {kFloat, false}, {kByte, true}, {kUByte, true}, {kShort, true}, {kUShort, true}};
    std::optional<Format> format;
    if (targetPath == "translation" || targetPath == "scale")
        format = Format{TINYGLTF_TYPE_VEC3, floatOnly};
    else if (targetPath == "rotation")
        format = Format{TINYGLTF_TYPE_VEC4, quantized};
    else if (targetPath == "weights")
        format = Format{TINYGLTF_TYPE_SCALAR, quantized};
    if (format && !matches(output, *format))
        mc.report(IssueCode::ACCESSOR_WRONG_FORMAT, op,
                  formatOf(s.output, output) + ", not " + describe(*format) + " (" + targetPath + ")");
}

// One sampler as one channel uses it (a sampler serving two target paths is checked for each).
void sampler(ModelContext& mc, std::set<std::string>& checked, const tinygltf::AnimationSampler& s,
             const std::string& path, const std::string& targetPath, size_t morphs)
{
    if (!checked.insert(path + "/" + targetPath).second || !mc.validAccessor(s.input) || !mc.validAccessor(s.output))
        return;
    const std::string ip = at(path, "input");
    // Animation data is tightly packed: its buffer views have no byteStride.
    for (const auto& [a, where] : {std::pair{s.input, ip}, std::pair{s.output, at(path, "output")}})
        if (mc.viewStride(a) != 0)
            mc.report(IssueCode::ANIMATION_SAMPLER_ACCESSOR_WITH_BYTESTRIDE, where,
                      accessorPath(a) + " lies in " + viewPath(mc.model.accessors[size_t(a)].bufferView) +
                          ", which has a byteStride (animation data must be tightly packed)");
    if (keyTimes(mc, s, ip))
        values(mc, s, path, targetPath, morphs);
}

void channel(ModelContext& mc, std::set<std::string>& checked, std::map<std::pair<int, std::string>, size_t>& targets,
             const tinygltf::Animation& anim, size_t c, const std::string& path)
{
    const tinygltf::AnimationChannel& ch = anim.channels[c];
    const std::string cp = at(at(path, "channels"), c);
    if (ch.target_node < 0 || size_t(ch.target_node) >= mc.model.nodes.size())
        return;
    // "Within one animation, each target MUST NOT be used more than once."
    const auto [it, fresh] = targets.emplace(std::make_pair(ch.target_node, ch.target_path), c);
    if (!fresh)
        mc.report(IssueCode::ANIMATION_DUPLICATE_TARGETS, at(cp, "target"),
                  "targets node " + std::to_string(ch.target_node) + " " + ch.target_path + ", as channels[" +
                      std::to_string(it->second) + "] does");
    const tinygltf::Node& node = mc.model.nodes[size_t(ch.target_node)];
    const bool trs = ch.target_path == "translation" || ch.target_path == "rotation" || ch.target_path == "scale";
    // "When a node is targeted for animation ... it MUST NOT have a matrix".
    if (trs && node.matrix.size() == 16)
        mc.report(IssueCode::ANIMATION_CHANNEL_TARGET_NODE_MATRIX, at(at(cp, "target"), "node"),
                  "nodes[" + std::to_string(ch.target_node) + "] has a matrix, so its " + ch.target_path +
                      " cannot be animated");
    if (ch.target_path == "weights" && mc.morphTargets(node.mesh) == 0)
        mc.report(IssueCode::ANIMATION_CHANNEL_TARGET_NODE_WEIGHTS_NO_MORPHS, at(at(cp, "target"), "path"),
                  "weights animated, but nodes[" + std::to_string(ch.target_node) + "] has no morph targets");
    if (ch.sampler >= 0 && size_t(ch.sampler) < anim.samplers.size())
        sampler(mc, checked, anim.samplers[size_t(ch.sampler)], at(at(path, "samplers"), size_t(ch.sampler)),
                ch.target_path, mc.morphTargets(node.mesh));
}

} // namespace

void checkAnimationSchema(ValidationContext& ctx, const json& a, const std::string& path)
{
    size_t samplerCount = 0;
    if (const json* samplers = ctx.array(a, "samplers", path, kRead, true)) {
        samplerCount = samplers->size();
        ctx.forEachObject(*samplers, at(path, "samplers"), kRead, nullptr,
                          [&](const json& s, const std::string& p) { samplerSchema(ctx, s, p); });
    }
    if (const json* channels = ctx.array(a, "channels", path, kRead, true))
        ctx.forEachObject(*channels, at(path, "channels"), kRead, "empty array: the animation animates nothing",
                          [&](const json& c, const std::string& p) { channelSchema(ctx, c, p, path, samplerCount); });
    ctx.common(a, path);
}

void checkAnimationSemantics(ModelContext& mc)
{
    std::set<std::string> checked; // "samplers path/target path" already checked
    for (size_t a = 0; a < mc.model.animations.size(); ++a) {
        std::map<std::pair<int, std::string>, size_t> targets;
        for (size_t c = 0; c < mc.model.animations[a].channels.size(); ++c)
            channel(mc, checked, targets, mc.model.animations[a], c, at("animations", a));
    }
}

} // namespace lfd::bake::gltf
