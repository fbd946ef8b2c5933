// shaders/subpixel_phase.glsl on the GL driver against lfd/subpixel_phase.h on the CPU: a
// compute shader writes, for every subpixel of a set of panel rows, the fixed-point phase,
// its view index and its float conversion; all three must equal the CPU's bit for bit. On
// a small panel every row, on the 8K panels (7680 x 4320, the largest products k * perSubpixel)
// the first and last rows and every 97th.
#include "display_test_profiles.h"
#include "gl_handles.h"
#include "gl_test_support.h"
#include "sample_profiles.h"
#include "shader_library.h"

#include "lfd/display_profile.h"
#include "lfd/subpixel_phase.h"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace lfd::test {
namespace {

const char* const kProbe = R"(#version 450 core
#extension GL_ARB_gpu_shader_int64 : require
layout(local_size_x = 64) in;
#include "subpixel_phase.glsl"
layout(std430, binding = 0) readonly buffer Rows { uint rows[]; };
layout(std430, binding = 1) writeonly buffer Results { uvec4 results[]; };
layout(location = 0) uniform uvec2 perSubpixel;
layout(location = 1) uniform uvec2 perRow;
layout(location = 2) uniform uvec2 phaseOffset;
layout(location = 3) uniform bool invertPhase;
layout(location = 4) uniform uint viewCount;
layout(location = 5) uniform uint subpixelsPerRow;
layout(location = 6) uniform uint count;
void main()
{
    const uint i = gl_GlobalInvocationID.x;
    if (i >= count)
        return;
    const uint k = i % subpixelsPerRow, l = rows[i / subpixelsPerRow];
    const uint64_t raw = fixedRawSubpixelPhase(k, l, fixedPhaseUniform(perSubpixel), fixedPhaseUniform(perRow),
                                               fixedPhaseUniform(phaseOffset));
    const uint64_t phase = fixedSubpixelPhase(raw, invertPhase);
    results[i] = uvec4(unpackUint2x32(phase), fixedPhaseView(phase, viewCount), floatBitsToUint(fixedPhaseToFloat(phase)));
}
)";

gl::Program buildProbe()
{
    const gl::ShaderLookup lookup = [](std::string_view name) -> std::optional<std::string> {
        if (name == "subpixel_phase_probe.comp")
            return std::string(kProbe);
        return std::string(gl::shaderSource(name));
    };
    const gl::Shader shader(
        gl::compileShader(GL_COMPUTE_SHADER, gl::preprocessShader("subpixel_phase_probe.comp", lookup)));
    gl::Program program(glCreateProgram());
    glAttachShader(program, shader);
    glLinkProgram(program);
    GLint linked = GL_FALSE;
    glGetProgramiv(program, GL_LINK_STATUS, &linked);
    EXPECT_EQ(linked, GL_TRUE);
    return program;
}

struct Mismatches {
    size_t checked = 0, phase = 0, view = 0, toFloat = 0;
};

// Runs the probe on `rows` of `profile` and compares every subpixel with the CPU.
Mismatches compareRows(GLuint program, const DisplayProfile& profile, const std::vector<uint32_t>& rows)
{
    const FixedSubpixelMapping m = fixedSubpixelMapping(profile.mapping);
    const uint32_t perRow = 3 * profile.panelWidth, count = perRow * uint32_t(rows.size());
    const gl::Buffer rowBuffer = gl::createBuffer(rows.size() * sizeof(uint32_t), 0, rows.data());
    const gl::Buffer results = gl::createBuffer(size_t(count) * 16, GL_MAP_READ_BIT, nullptr);
    glUseProgram(program);
    const auto fixedUniform = [](GLint location, uint64_t value) {
        glUniform2ui(location, GLuint(value), GLuint(value >> 32));
    };
    fixedUniform(0, m.perSubpixel);
    fixedUniform(1, m.perRow);
    fixedUniform(2, m.offset);
    glUniform1i(3, m.invert ? 1 : 0);
    glUniform1ui(4, profile.viewCount);
    glUniform1ui(5, perRow);
    glUniform1ui(6, count);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, rowBuffer);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, results);
    glDispatchCompute((count + 63) / 64, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<uint32_t> words(size_t(count) * 4);
    glGetNamedBufferSubData(results, 0, GLsizeiptr(words.size() * 4), words.data());
    glUseProgram(0);
    Mismatches out;
    for (uint32_t i = 0; i < count; ++i) {
        const uint32_t k = i % perRow, l = rows[i / perRow];
        const uint64_t phase = fixedSubpixelPhase(m, k, l);
        const uint32_t* w = &words[size_t(i) * 4];
        const float asFloat = fixedPhaseToFloat(phase);
        uint32_t floatBits = 0;
        std::memcpy(&floatBits, &asFloat, 4);
        out.phase += (uint64_t(w[1]) << 32 | w[0]) != phase;
        out.view += w[2] != fixedPhaseView(phase, profile.viewCount);
        out.toFloat += w[3] != floatBits;
        ++out.checked;
    }
    return out;
}

class SubpixelPhaseGpu : public GlTest {};

TEST_F(SubpixelPhaseGpu, SmallPanelEveryRowEqualsTheCpu)
{
    const gl::Program program = buildProbe();
    for (const DisplayProfile& profile : {player::displaytest::smallProfile("RGB"), player::displaytest::smallProfile("RGB", true)}) {
        std::vector<uint32_t> rows(profile.panelHeight);
        for (uint32_t l = 0; l < profile.panelHeight; ++l)
            rows[l] = l;
        const Mismatches m = compareRows(program, profile, rows);
        EXPECT_EQ(m.checked, size_t(3) * profile.panelWidth * profile.panelHeight);
        EXPECT_EQ(m.phase, 0u);
        EXPECT_EQ(m.view, 0u);
        EXPECT_EQ(m.toFloat, 0u);
    }
}

TEST_F(SubpixelPhaseGpu, EightKPanelsSampledRowsEqualTheCpu)
{
    const gl::Program program = buildProbe();
    const std::filesystem::path dir = lfd::test::kSampleProfiles;
    const DisplayProfile lg65 = loadDisplayProfile(dir / "looking_glass_65_8k.json");
    for (const DisplayProfile& profile : {lg65, withViews(lg65, 72, 960, 480),
                                          loadDisplayProfile(dir / "looking_glass_32_8k.json"),
                                          loadDisplayProfile(dir / "generic_example.json")}) {
        SCOPED_TRACE(profile.name);
        std::vector<uint32_t> rows;
        for (uint32_t l = 0; l < profile.panelHeight; l += 97)
            rows.push_back(l);
        rows.push_back(profile.panelHeight - 1);
        const Mismatches m = compareRows(program, profile, rows);
        EXPECT_EQ(m.checked, size_t(3) * profile.panelWidth * rows.size());
        EXPECT_EQ(m.phase, 0u);
        EXPECT_EQ(m.view, 0u);
        EXPECT_EQ(m.toFloat, 0u);
    }
}

} // namespace
} // namespace lfd::test
