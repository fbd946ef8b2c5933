// The interfaces of the image programs - gstd_reconstruct.comp, gstd_panel_*.comp, view_downsample.comp,
// eia_construct.comp and eia_prefilter.comp - are written once, in shaders/<program>_bindings.glsl, and generated
// into C++ (player/gl/gpu_layout_gen.cpp). Here every generated constant is checked against
// the shader's #define and against what the driver reports for the compiled program: the
// workgroup size, every uniform location, every sampler and image unit.
#include "eia_bindings_gpu.h"
#include "gl_handles.h"
#include "gl_test_support.h"
#include "gstd_bindings_gpu.h"
#include "shader_library.h"
#include "view_downsample_bindings_gpu.h"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <vector>

namespace lfd::test {
namespace {

namespace eb = player::eia_bindings;
namespace gb = player::gstd_bindings;
namespace db = player::downsample_bindings;

// A uniform as C++ uses it: at a location, or (samplers, images) on a unit.
struct UniformUse {
    const char* name;
    std::optional<uint32_t> location;
    std::optional<uint32_t> unit;
};

struct ProgramInterface {
    const char* shader;
    std::vector<std::string> defines;
    const gl::GpuLayoutFile* file;
    uint32_t localSize; // x and y
    std::vector<UniformUse> uniforms;
};

std::vector<ProgramInterface> interfaces()
{
    return {
        {"gstd_reconstruct.comp", {}, &gb::kLayoutFile, gb::kLocalSize,
         {{"u_highRes", {}, gb::kUnitHighRes}, {"u_accum", {}, gb::kImageAccum}, {"u_view", {}, gb::kImageView},
          {"u_size", gb::kLocSize, {}}, {"u_sampleCount", gb::kLocSampleCount, {}},
          {"u_subView", gb::kLocSubView, {}}, {"u_subViewCount", gb::kLocSubViewCount, {}},
          {"u_offsets", gb::kLocOffsets, {}}, {"u_layer", gb::kLocLayer, {}}}},
        {"gstd_panel_phases.comp", {}, &gb::kLayoutFile, gb::kPanelLocalSize,
         {{"u_phase", {}, gb::kPanelImagePhase}, {"u_lens", {}, gb::kPanelImageLens},
          {"u_panelSize", gb::kPanelLocPanelSize, {}}, {"u_perSubpixel", gb::kPanelLocPerSubpixel, {}},
          {"u_perRow", gb::kPanelLocPerRow, {}}, {"u_phaseOffset", gb::kPanelLocPhaseOffset, {}},
          {"u_invertPhase", gb::kPanelLocInvertPhase, {}}, {"u_lensSubpixels", gb::kPanelLocLensSubpixels, {}}}},
        {"gstd_panel_accumulate.comp", {}, &gb::kLayoutFile, gb::kPanelLocalSize,
         {{"u_subViews", {}, gb::kPanelUnitSubViews}, {"u_accum", {}, gb::kPanelImageAccum},
          {"u_phase", {}, gb::kPanelImagePhase}, {"u_lens", {}, gb::kPanelImageLens},
          {"u_panelSize", gb::kPanelLocPanelSize, {}}, {"u_subpixelsBgr", gb::kPanelLocSubpixelsBgr, {}},
          {"u_firstPhase", gb::kPanelLocFirstPhase, {}}, {"u_subViewWidth", gb::kPanelLocSubViewWidth, {}},
          {"u_layerCount", gb::kPanelLocLayerCount, {}}, {"u_spread", gb::kPanelLocSpread, {}},
          {"u_footprint", gb::kPanelLocFootprint, {}}, {"u_taps", gb::kPanelLocTaps, {}}}},
        {"gstd_panel_resolve.comp", {}, &gb::kLayoutFile, gb::kPanelLocalSize,
         {{"u_accum", {}, gb::kPanelImageAccum}, {"u_eia", {}, gb::kPanelImageEia},
          {"u_panelSize", gb::kPanelLocPanelSize, {}}}},
        {"view_downsample.comp", {}, &db::kLayoutFile, db::kLocalSize,
         {{"source", {}, db::kUnitSource}, {"target", {}, db::kImageTarget},
          {"targetSize", db::kLocTargetSize, {}}, {"mode", db::kLocMode, {}}}},
        // View-spatial: the mode that reads every uniform but the views (it reads them
        // prefiltered), the view count (its trilinear read takes the phase as z) and the table.
        {"eia_construct.comp", {"EIA_MODE " + std::to_string(eb::kModeViewSpatial)}, &eb::kLayoutFile, eb::kLocalSize,
         {{"eia", {}, eb::kImageEia},
          {"panelSize", eb::kLocPanelSize, {}}, {"viewSize", eb::kLocViewSize, {}},
          {"perSubpixel", eb::kLocPerSubpixel, {}},
          {"perRow", eb::kLocPerRow, {}}, {"phaseOffset", eb::kLocPhaseOffset, {}},
          {"invertPhase", eb::kLocInvertPhase, {}}, {"subpixelsBgr", eb::kLocSubpixelsBgr, {}},
          {"lensOrder", eb::kLocLensOrder, {}},
          {"prefiltered", {}, eb::kUnitPrefiltered}}},
        // The view mode: the only one that reads the views themselves besides mode none.
        {"eia_construct.comp", {"EIA_MODE " + std::to_string(eb::kModeView)}, &eb::kLayoutFile, eb::kLocalSize,
         {{"views", {}, eb::kUnitViews}, {"eia", {}, eb::kImageEia}, {"viewCount", eb::kLocViewCount, {}},
          {"linearFromByte[0]", eb::kLocLinearFromByte, {}}}},
        // Spatial: the prefiltered views as an array.
        {"eia_construct.comp", {"EIA_MODE " + std::to_string(eb::kModeSpatial)}, &eb::kLayoutFile, eb::kLocalSize,
         {{"prefiltered", {}, eb::kUnitPrefiltered}, {"eia", {}, eb::kImageEia}, {"viewCount", eb::kLocViewCount, {}}}},
        {"eia_prefilter.comp", {}, &eb::kLayoutFile, eb::kPrefilterLocalSize,
         {{"views", {}, eb::kPrefilterUnitViews}, {"prefiltered", {}, eb::kPrefilterImageOut},
          {"size", eb::kPrefilterLocSize, {}}, {"tap", eb::kPrefilterLocTap, {}}}},
        {"eia_prefilter.comp", {"EIA_PREFILTER_LAYERED 1"}, &eb::kLayoutFile, eb::kPrefilterLocalSize,
         {{"views", {}, eb::kPrefilterUnitViews}, {"prefiltered", {}, eb::kPrefilterImageOut},
          {"size", eb::kPrefilterLocSize, {}}, {"tap", eb::kPrefilterLocTap, {}}}},
    };
}

// Every way the compiled program differs from what C++ uses, one line each.
std::vector<std::string> interfaceMismatches(GLuint program, const ProgramInterface& p)
{
    std::vector<std::string> out;
    GLint size[3] = {0, 0, 0};
    glGetProgramiv(program, GL_COMPUTE_WORK_GROUP_SIZE, size);
    if (uint32_t(size[0]) != p.localSize || uint32_t(size[1]) != p.localSize)
        out.push_back("workgroup " + std::to_string(size[0]) + "x" + std::to_string(size[1]) + ", C++ dispatches " +
                      std::to_string(p.localSize) + "x" + std::to_string(p.localSize));
    for (const UniformUse& u : p.uniforms) {
        const GLint location = glGetUniformLocation(program, u.name);
        if (location < 0) {
            out.push_back(std::string(u.name) + ": not an active uniform");
        } else if (u.location && GLint(*u.location) != location) {
            out.push_back(std::string(u.name) + ": location " + std::to_string(location) + ", C++ uses " +
                          std::to_string(*u.location));
        } else if (u.unit) {
            GLint unit = -1;
            glGetUniformiv(program, location, &unit);
            if (GLint(*u.unit) != unit)
                out.push_back(std::string(u.name) + ": unit " + std::to_string(unit) + ", C++ binds " +
                              std::to_string(*u.unit));
        }
    }
    return out;
}

class ProgramInterfaceTest : public GlTest {};

TEST_F(ProgramInterfaceTest, GeneratedConstantsAreTheBindingFilesDefines)
{
    for (const ProgramInterface& p : interfaces()) {
        ASSERT_FALSE(p.file->defines.empty()) << p.file->file;
        for (const gl::GpuDefine& d : p.file->defines)
            EXPECT_EQ(uint64_t(uint32_t(gl::shaderDefineValue(p.file->file, d.name))), d.value) << d.name;
    }
}

TEST_F(ProgramInterfaceTest, EveryProgramHasTheCppLocationsUnitsAndWorkgroupSize)
{
    for (const ProgramInterface& p : interfaces()) {
        SCOPED_TRACE(p.shader);
        const gl::Program program(gl::buildProgram({{GL_COMPUTE_SHADER, p.shader}}, p.defines));
        for (const std::string& mismatch : interfaceMismatches(program, p))
            ADD_FAILURE() << mismatch;
    }
}

// The check itself can fail: a C++ side with a location, a unit or the workgroup size off
// by one is reported.
TEST_F(ProgramInterfaceTest, AWrongLocationUnitOrWorkgroupSizeFailsTheCheck)
{
    ProgramInterface p = interfaces()[0];
    const gl::Program program(gl::buildProgram({{GL_COMPUTE_SHADER, p.shader}}, p.defines));
    p.localSize += 1;
    p.uniforms[0].unit = *p.uniforms[0].unit + 1;
    p.uniforms[3].location = *p.uniforms[3].location + 1;
    EXPECT_EQ(interfaceMismatches(program, p).size(), 3u);
}

} // namespace
} // namespace lfd::test
