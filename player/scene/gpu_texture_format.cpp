#include "gpu_texture_format.h"

#include "gl_context.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <string>

namespace lfd::player {

namespace {

void requireExtension(const char* extension, TextureFormat format)
{
    if (!epoxy_has_gl_extension(extension))
        throw gl::GlError(std::string("the OpenGL driver lacks ") + extension + ", needed for " +
                          textureFormatName(format) + " textures (rebake with --texture-compression none)");
}

// S3TC (BC1/BC3) is an extension every desktop driver has; sRGB blocks need another.
GLenum s3tcFormat(TextureFormat format, bool srgb, GLenum linear, GLenum srgbFormat)
{
    requireExtension("GL_EXT_texture_compression_s3tc", format);
    if (srgb)
        requireExtension("GL_EXT_texture_sRGB", format);
    return srgb ? srgbFormat : linear;
}

} // namespace

GlTextureFormat glTextureFormat(TextureFormat format, bool srgb)
{
    GlTextureFormat f;
    f.compressed = format != TextureFormat::Rgba8;
    const GLint rgba[4] = {GL_RED, GL_GREEN, GL_BLUE, GL_ALPHA};
    std::copy(rgba, rgba + 4, f.swizzle);
    switch (format) {
    case TextureFormat::Rgba8:
        f.internalFormat = srgb ? GL_SRGB8_ALPHA8 : GL_RGBA8;
        break;
    case TextureFormat::Bc1:
        // The RGB variant: alpha reads 1, and no block decodes as transparent.
        f.internalFormat = s3tcFormat(format, srgb, GL_COMPRESSED_RGB_S3TC_DXT1_EXT, GL_COMPRESSED_SRGB_S3TC_DXT1_EXT);
        break;
    case TextureFormat::Bc3:
        f.internalFormat =
            s3tcFormat(format, srgb, GL_COMPRESSED_RGBA_S3TC_DXT5_EXT, GL_COMPRESSED_SRGB_ALPHA_S3TC_DXT5_EXT);
        break;
    case TextureFormat::Bc4: {
        // RGTC is core since GL 3.0. One channel: the materials read it as R (occlusion),
        // G (roughness) or B (metallic), so it is replicated to all three.
        f.internalFormat = GL_COMPRESSED_RED_RGTC1;
        const GLint red[4] = {GL_RED, GL_RED, GL_RED, GL_ONE};
        std::copy(red, red + 4, f.swizzle);
        break;
    }
    case TextureFormat::Bc5: {
        f.internalFormat = GL_COMPRESSED_RG_RGTC2;
        const GLint rg[4] = {GL_RED, GL_GREEN, GL_ZERO, GL_ONE}; // z is rebuilt in the shader
        std::copy(rg, rg + 4, f.swizzle);
        break;
    }
    }
    return f;
}

uint32_t rowsPerUnit(TextureFormat format) { return format == TextureFormat::Rgba8 ? 1u : 4u; }

uint64_t unitRowBytes(TextureFormat format, uint32_t width)
{
    return textureLevelBytes(format, width, rowsPerUnit(format));
}

void uploadLevelRows(unsigned texture, int level, TextureFormat format, const GlTextureFormat& gl, uint32_t width,
                     uint32_t height, uint32_t firstUnit, uint32_t units, const uint8_t* data)
{
    const uint32_t per = rowsPerUnit(format);
    const uint32_t y = firstUnit * per;
    const uint32_t rows = std::min(height - y, units * per); // the last block row may be partial
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    if (!gl.compressed) {
        glTextureSubImage2D(texture, level, 0, GLint(y), GLsizei(width), GLsizei(rows), GL_RGBA, GL_UNSIGNED_BYTE,
                            data);
        return;
    }
    glCompressedTextureSubImage2D(texture, level, 0, GLint(y), GLsizei(width), GLsizei(rows), gl.internalFormat,
                                  GLsizei(uint64_t(units) * unitRowBytes(format, width)), data);
}

} // namespace lfd::player
