// Descriptions of the GPU layouts defined in shaders/*_bindings.glsl, as the generated
// C++ mirrors lay them out. lfd_gpu_layout_gen (gpu_layout_gen.cpp) writes one header per
// bindings file at build time: the #define constants, one C++ struct per GLSL struct and
// per fixed-member block, and these tables of their members (offsetof / sizeof of the
// generated structs). The layout test compiles a probe shader from the tables and checks
// every member, stride, block size and binding against what the driver reports, so the
// GLSL text is the only place a layout is written.
#pragma once

#include <cstdint>
#include <span>

namespace lfd::gl {

// One member of a struct or block: GLSL name and type, C++ offset and size.
struct GpuMember {
    const char* name;     // GLSL member name
    const char* glslType; // GLSL type of the member (of one element for arrays): "vec4", "uint", "mat4", ...
    uint32_t offset;      // offsetof in the C++ mirror
    uint32_t size;        // sizeof of the C++ member (the whole array for arrays)
    uint32_t arraySize;   // element count; 0 when the member is not an array
    uint32_t arrayStride; // C++ size of one element of an array member; 0 otherwise
};

// A GLSL struct, or the members of a block, and the C++ struct that mirrors it.
struct GpuStruct {
    const char* glslName; // struct name, or block name for a block's members
    const char* cppName;  // generated C++ struct
    uint32_t size;        // sizeof of the C++ struct (= the std430 / std140 size)
    std::span<const GpuMember> members;
};

enum class GpuInterface { Uniform, Storage };

// An interface block declared in a bindings file: either fixed members (`layout`) or one
// unsized array (`arrayMember` of `arrayStruct` elements).
struct GpuBlock {
    const char* name; // GLSL block name
    GpuInterface interface;
    const char* packing; // "std140" or "std430"
    uint32_t binding;
    const GpuStruct* layout;      // fixed-member block: its members; null for an array block
    const char* arrayMember;      // array block: the array's name; null otherwise
    const GpuStruct* arrayStruct; // array block: the element struct
    const char* instance;         // GLSL instance name (u_lfd, counters), null if none
};

// An integer #define of a bindings file and its value.
struct GpuDefine {
    const char* name;
    uint64_t value;
};

// Everything one bindings file defines.
struct GpuLayoutFile {
    const char* file; // shaders/ file name, e.g. "lfdpr_bindings.glsl"
    std::span<const GpuStruct> structs;
    std::span<const GpuBlock> blocks;
    std::span<const GpuDefine> defines;
};

} // namespace lfd::gl
