#include "gpu_environment.h"

#include "gl_context.h"
#include "scene_bindings.h"

#include <epoxy/gl.h>

#include <string>

namespace lfd::player {

GpuEnvironment::GpuEnvironment(const EnvironmentMaps& maps) : sh_(maps.irradianceSh)
{
    const GLsizei levels = GLsizei(maps.levels.size());
    if (levels == 0 || maps.faceSize == 0 || (maps.faceSize >> (levels - 1)) == 0)
        throw gl::GlError("environment: " + std::to_string(levels) + " levels do not fit a " +
                          std::to_string(maps.faceSize) + "-texel cube face");
    if (maps.brdfSize == 0 || maps.brdfTable.size() != size_t(maps.brdfSize) * maps.brdfSize)
        throw gl::GlError("environment: the BRDF table has " + std::to_string(maps.brdfTable.size()) +
                          " texels, not " + std::to_string(maps.brdfSize) + "^2");

    // Step 1: the specular cube, RGB16F (half floats keep HDR radiance to 0.05%), one
    // roughness per level; seamless filtering across faces (GL 4.5 core, every driver).
    cube_ = gl::createTexture(GL_TEXTURE_CUBE_MAP);
    glTextureStorage2D(cube_, levels, GL_RGB16F, GLsizei(maps.faceSize), GLsizei(maps.faceSize));
    for (GLsizei l = 0; l < levels; ++l) {
        const uint32_t size = maps.faceSize >> l;
        const std::vector<glm::vec3>& level = maps.levels[size_t(l)];
        if (level.size() != size_t(6) * size * size)
            throw gl::GlError("environment: cube level " + std::to_string(l) + " has " + std::to_string(level.size()) +
                              " texels, not 6 x " + std::to_string(size) + "^2");
        // Cube faces are layers 0..5 of a cube map's image (GL 4.5, 8.22: glTextureSubImage3D).
        glTextureSubImage3D(cube_, l, 0, 0, 0, GLsizei(size), GLsizei(size), 6, GL_RGB, GL_FLOAT, level.data());
        gpuBytes_ += size_t(6) * size * size * 6;
    }
    glTextureParameteri(cube_, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(cube_, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(cube_, GL_TEXTURE_MAX_LEVEL, levels - 1);
    glEnable(GL_TEXTURE_CUBE_MAP_SEAMLESS);
    maxLevel_ = float(levels - 1);

    // Step 2: the BRDF table, read with bilinear filtering at (n.v, roughness).
    brdf_ = gl::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(brdf_, 1, GL_RGB16F, GLsizei(maps.brdfSize), GLsizei(maps.brdfSize));
    glTextureSubImage2D(brdf_, 0, 0, 0, GLsizei(maps.brdfSize), GLsizei(maps.brdfSize), GL_RGB, GL_FLOAT,
                        maps.brdfTable.data());
    glTextureParameteri(brdf_, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(brdf_, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(brdf_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(brdf_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    gpuBytes_ += size_t(maps.brdfSize) * maps.brdfSize * 6;
}

void GpuEnvironment::bind() const
{
    glBindTextureUnit(bindings::kUnitEnvironment, cube_);
    glBindTextureUnit(bindings::kUnitBrdfTable, brdf_);
}

} // namespace lfd::player
