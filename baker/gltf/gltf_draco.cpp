// Draco-compressed primitives (see gltf_draco.h).
#include "gltf_draco.h"

#include "gltf_accessors.h" // componentName, componentSize

#include <draco/compression/decode.h>

#include <cstring>
#include <limits>
#include <memory>

namespace lfd::bake::gltf {
namespace {

// The glTF componentType a Draco data type stores as is (0: none). The accessor's type
// must equal the decoded one: the extension maps the decoded data onto the accessors,
// it does not convert it.
int componentTypeOf(draco::DataType type)
{
    switch (type) {
    case draco::DT_INT8: return 5120;
    case draco::DT_UINT8: return 5121;
    case draco::DT_INT16: return 5122;
    case draco::DT_UINT16: return 5123;
    case draco::DT_UINT32: return 5125;
    case draco::DT_FLOAT32: return 5126;
    default: return 0;
    }
}

std::string targetLabel(const DracoTarget& t)
{
    return "accessors[" + std::to_string(t.accessor) + "] (" + t.use + ")";
}

std::unique_ptr<draco::Mesh> decodeMesh(std::span<const uint8_t> stream, std::string& why)
{
    draco::DecoderBuffer buffer;
    buffer.Init(reinterpret_cast<const char*>(stream.data()), stream.size());
    draco::Decoder decoder;
    auto result = decoder.DecodeMeshFromBuffer(&buffer);
    if (!result.ok()) {
        why = "the Draco stream does not decode (" + result.status().error_msg_string() + ")";
        return nullptr;
    }
    return std::move(result).value();
}

// One attribute's values for every point, in point order, as the accessor stores them.
std::string copyAttribute(const draco::Mesh& mesh, const DracoTarget& t, std::vector<uint8_t>& out)
{
    const draco::PointAttribute* att = t.dracoId >= 0 ? mesh.GetAttributeByUniqueId(uint32_t(t.dracoId)) : nullptr;
    if (att == nullptr)
        return "Draco attribute " + std::to_string(t.dracoId) + " (" + t.use + ") is not in the stream";
    const int decodedType = componentTypeOf(att->data_type());
    if (decodedType != t.componentType || att->num_components() != t.components) {
        const std::string decoded =
            decodedType != 0 ? componentName(decodedType) : "Draco data type " + std::to_string(att->data_type());
        return "Draco attribute " + std::to_string(t.dracoId) + " (" + t.use + ") decodes to " +
               std::to_string(att->num_components()) + " x " + decoded + ", but " + targetLabel(t) + " is " +
               std::to_string(t.components) + " x " + componentName(t.componentType);
    }
    const size_t points = mesh.num_points();
    if (t.count != points)
        return "the Draco stream decodes to " + std::to_string(points) + " vertices, but " + targetLabel(t) + " has count " +
               std::to_string(t.count);
    const size_t element = size_t(componentSize(t.componentType)) * size_t(t.components);
    const size_t values = att->size();
    // Defensive bounds on what a corrupt stream could make the mapping point at.
    const bool mapped = att->is_mapping_identity() ? values >= points : att->indices_map_size() >= points;
    if (!mapped || att->byte_stride() < int64_t(element) || att->buffer() == nullptr ||
        (values > 0 && size_t(att->GetBytePos(draco::AttributeValueIndex(uint32_t(values - 1)))) + element >
                           att->buffer()->data_size()))
        return "Draco attribute " + std::to_string(t.dracoId) + " (" + t.use + ") holds fewer values than its vertices";
    out.resize(points * element);
    for (size_t p = 0; p < points; ++p) {
        const draco::AttributeValueIndex v = att->mapped_index(draco::PointIndex(uint32_t(p)));
        if (v.value() >= values)
            return "Draco attribute " + std::to_string(t.dracoId) + " (" + t.use + ") maps vertex " + std::to_string(p) +
                   " to a value it does not hold";
        std::memcpy(out.data() + p * element, att->GetAddress(v), element);
    }
    return {};
}

// The triangles' corner indices in the accessor's componentType.
std::string copyIndices(const draco::Mesh& mesh, const DracoTarget& t, std::vector<uint8_t>& out)
{
    const size_t corners = size_t(mesh.num_faces()) * 3;
    if (t.count != corners)
        return "the Draco stream decodes to " + std::to_string(mesh.num_faces()) + " triangles (" + std::to_string(corners) +
               " indices), but " + targetLabel(t) + " has count " + std::to_string(t.count);
    const size_t bytes = size_t(componentSize(t.componentType));
    const uint32_t largest = bytes == 1 ? 0xFFu : bytes == 2 ? 0xFFFFu : 0xFFFFFFFFu;
    out.resize(corners * bytes);
    for (uint32_t f = 0; f < mesh.num_faces(); ++f)
        for (int c = 0; c < 3; ++c) {
            const uint32_t index = mesh.face(draco::FaceIndex(f))[c].value();
            if (index > largest)
                return "Draco triangle " + std::to_string(f) + " has index " + std::to_string(index) +
                       ", which does not fit " + targetLabel(t) + " (" + componentName(t.componentType) + ")";
            // Little-endian, as glTF stores it (section 3.6.1.1) and as this machine is.
            std::memcpy(out.data() + (size_t(f) * 3 + size_t(c)) * bytes, &index, bytes);
        }
    return {};
}

} // namespace

std::string decodeDracoPrimitive(std::span<const uint8_t> stream, const std::vector<DracoTarget>& targets,
                                 std::vector<DracoDecoded>& out, std::optional<DracoDecoded>& generatedIndices)
{
    std::string why;
    const std::unique_ptr<draco::Mesh> mesh = decodeMesh(stream, why);
    if (!mesh)
        return why;
    if (mesh->num_faces() == 0)
        return "the Draco stream holds no triangles";
    bool indexed = false;
    for (const DracoTarget& t : targets) {
        DracoDecoded decoded{t.accessor, {}};
        why = t.dracoId < 0 ? copyIndices(*mesh, t, decoded.bytes) : copyAttribute(*mesh, t, decoded.bytes);
        if (!why.empty())
            return why;
        indexed = indexed || t.dracoId < 0;
        out.push_back(std::move(decoded));
    }
    if (!indexed) {
        const DracoTarget all{0, "indices", -1, 5125, 1, size_t(mesh->num_faces()) * 3};
        generatedIndices = DracoDecoded{0, {}};
        if (why = copyIndices(*mesh, all, generatedIndices->bytes); !why.empty())
            return why;
    }
    return {};
}

} // namespace lfd::bake::gltf
