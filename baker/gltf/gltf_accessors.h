// glTF data helpers for the import stage (internal to the baker): typed, bounds-checked
// reads of accessors and buffer views, primitive topology conversion and generated
// vertex attributes. tinygltf parses the JSON and loads the buffers but does not check
// that accessors stay inside them; every read here does, so a hostile file yields a
// BakeError instead of an out-of-bounds read.
#pragma once

#include "bake_log.h"

#include <glm/glm.hpp>
#include <tiny_gltf.h>

#include <cstdint>
#include <initializer_list>
#include <span>
#include <string>
#include <vector>

namespace lfd::bake::gltf {

// Throws BakeError("<file>: <message>") with the message cut to its first line.
[[noreturn]] void fail(const std::string& file, const std::string& message);

// First line of a (possibly multi-line) message, trailing whitespace removed.
std::string firstLine(const std::string& text);

// Bytes of one component (1, 2 or 4; 0 for a componentType glTF 2.0 accessors do not use).
int componentSize(int componentType);
// glTF's names of accessor types and component types, for messages.
std::string typeName(int type);
std::string componentName(int componentType);

// Accessor contents as floats, `components` values per element. Normalized integer
// components follow the glTF 2.0 decoding rules (e.g. ubyte c -> c / 255); other
// integer components are converted as is (KHR_mesh_quantization). Sparse accessors
// are applied. `what` names the use for messages, e.g. "mesh 'Cube' primitive 0 POSITION".
struct FloatArray {
    std::vector<float> values; // count * components
    size_t count = 0;
    int components = 0;
};
FloatArray readFloatAccessor(const tinygltf::Model& model, int accessorIndex,
                             std::initializer_list<int> allowedTypes, const std::string& file,
                             const std::string& what);

// Index accessor (SCALAR of unsigned byte/short/int) widened to uint32.
std::vector<uint32_t> readIndexAccessor(const tinygltf::Model& model, int accessorIndex,
                                        const std::string& file, const std::string& what);

// Element count of an accessor (validated index), for checks before reading.
size_t accessorCount(const tinygltf::Model& model, int accessorIndex, const std::string& file,
                     const std::string& what);

// Bytes of a buffer view (e.g. an embedded image), checked against its buffer.
std::span<const uint8_t> bufferViewBytes(const tinygltf::Model& model, int bufferViewIndex,
                                         const std::string& file, const std::string& what);

// Triangle list for a TRIANGLES / TRIANGLE_STRIP / TRIANGLE_FAN index sequence (glTF 2.0
// "Topology Types"), winding as the spec defines each triangle. A list keeps every
// complete triangle (a trailing partial one is dropped); strips and fans drop their
// degenerate (repeated-index) stitching triangles. Other modes give an empty list.
std::vector<uint32_t> triangulate(const std::vector<uint32_t>& indices, int mode);

// Unit normal of a triangle; +z for a degenerate one.
glm::vec3 faceNormal(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2);

// Area-weighted vertex normals of a triangle list (+z where a vertex has no area).
std::vector<glm::vec3> smoothNormals(const std::vector<glm::vec3>& positions,
                                     const std::vector<uint32_t>& triangles);

// Some unit vector perpendicular to the unit vector n.
glm::vec3 anyPerpendicular(const glm::vec3& n);

// Per-vertex glTF tangents (xyz unit, orthogonal to the normal; w = +-1 handedness)
// computed from the uv parameterisation of the triangles (local indices).
std::vector<glm::vec4> generateTangents(const std::vector<glm::vec3>& positions,
                                        const std::vector<glm::vec3>& normals,
                                        const std::vector<glm::vec2>& uvs,
                                        const std::vector<uint32_t>& triangles);

} // namespace lfd::bake::gltf
