#include "gpu_environment.h"

#include "gl_context.h"
#include "scene_bindings.h"

#include <epoxy/gl.h>

#include <chrono>
#include <string>

namespace lfd::player {

namespace {

// One cube map texture from `levels` (float RGB, GL's face order and rows), RGB16F: half
// floats keep HDR radiance to 0.05%, the filtering is GL_LINEAR(_MIPMAP_LINEAR), seamless.
gl::Texture createCube(const std::vector<lighting::CubeLevel>& levels, size_t& gpuBytes)
{
    gl::Texture cube = gl::createTexture(GL_TEXTURE_CUBE_MAP);
    const GLsizei count = GLsizei(levels.size());
    glTextureStorage2D(cube, count, GL_RGB16F, GLsizei(levels[0].size), GLsizei(levels[0].size));
    for (GLsizei l = 0; l < count; ++l) {
        const lighting::CubeLevel& level = levels[size_t(l)];
        // Cube faces are layers 0..5 of the texture's image (GL 4.5, 8.22).
        glTextureSubImage3D(cube, l, 0, 0, 0, GLsizei(level.size), GLsizei(level.size), GLsizei(lighting::kCubeFaces),
                            GL_RGB, GL_FLOAT, level.rgb.data());
        gpuBytes += size_t(lighting::kCubeFaces) * level.size * level.size * 6;
    }
    glTextureParameteri(cube, GL_TEXTURE_MIN_FILTER, count > 1 ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
    glTextureParameteri(cube, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(cube, GL_TEXTURE_MAX_LEVEL, count - 1);
    return cube;
}

// A size x size table of 3 or 4 float channels (row 0 first), half floats, GL_LINEAR and
// GL_CLAMP_TO_EDGE: the texel centres hold the table's exact ends (lighting/brdf_table.h).
gl::Texture createTable(uint32_t size, int channels, const float* texels, size_t& gpuBytes)
{
    gl::Texture t = gl::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(t, 1, channels == 4 ? GL_RGBA16F : GL_RGB16F, GLsizei(size), GLsizei(size));
    glTextureSubImage2D(t, 0, 0, 0, GLsizei(size), GLsizei(size), channels == 4 ? GL_RGBA : GL_RGB, GL_FLOAT, texels);
    glTextureParameteri(t, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(t, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(t, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(t, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    gpuBytes += size_t(size) * size * size_t(channels) * 2;
    return t;
}

} // namespace

GpuEnvironment::GpuEnvironment(std::shared_ptr<const lighting::Environment> source, std::string key,
                               const lighting::PrefilterSettings& settings, const lighting::BrdfTable& table)
    : source_(std::move(source)), key_(std::move(key)), settings_(settings)
{
    if (table.size != uint32_t(bindings::kBrdfTableSize))
        throw gl::GlError("environment: the BRDF table is " + std::to_string(table.size) + "^2, the shaders read " +
                          std::to_string(bindings::kBrdfTableSize) + "^2");
    // Step 1: the prefilter (CPU, every core).
    const auto start = std::chrono::steady_clock::now();
    const lighting::PrefilteredEnvironment prefiltered = lighting::prefilterEnvironment(*source_, settings_);
    prefilterSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    // Step 2: the cubes; seamless filtering across faces (GL 4.5 core, every driver), as
    // lighting::sampleCubeBilinear mirrors it.
    specular_ = createCube(prefiltered.specular.levels, gpuBytes_);
    irradiance_ = createCube({prefiltered.irradianceCube}, gpuBytes_);
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    maxLevel_ = float(prefiltered.specular.levels.size() - 1);

    // Step 3: the tables, read with bilinear filtering at lighting::brdfTableCoordinate.
    brdf_ = createTable(table.size, 3, table.abc.data(), gpuBytes_);
    const lighting::LobeTapTable& taps = lighting::lobeTapTable();
    if (taps.size != table.size)
        throw gl::GlError("environment: the lobe tap table is " + std::to_string(taps.size) + "^2, the BRDF table " +
                          std::to_string(table.size) + "^2 (the shaders read both at one coordinate)");
    lobeTaps_ = createTable(taps.size, 4, taps.taps.data(), gpuBytes_);
}

void GpuEnvironment::bind() const
{
    glBindTextureUnit(bindings::kUnitEnvironment, specular_);
    glBindTextureUnit(bindings::kUnitIrradiance, irradiance_);
    glBindTextureUnit(bindings::kUnitBrdfTable, brdf_);
    glBindTextureUnit(bindings::kUnitLobeTaps, lobeTaps_);
}

const lighting::BrdfTable& shaderBrdfTable()
{
    static const lighting::BrdfTable table = lighting::splitSumBrdfTable(uint32_t(bindings::kBrdfTableSize), 2048);
    return table;
}

std::shared_ptr<const GpuEnvironment> uploadEnvironment(const lighting::EnvironmentChoice& choice)
{
    if (!choice.environment)
        return nullptr;
    return std::make_shared<const GpuEnvironment>(choice.environment, choice.key, lighting::PrefilterSettings::player(),
                                                  shaderBrdfTable());
}

std::shared_ptr<const GpuEnvironment> withSettings(const GpuEnvironment& environment,
                                                   const lighting::PrefilterSettings& settings)
{
    return std::make_shared<const GpuEnvironment>(environment.source(), environment.key(), settings,
                                                  shaderBrdfTable());
}

} // namespace lfd::player
