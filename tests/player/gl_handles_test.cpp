// Owning GL handles (player/gl/gl_handles.h) and the one GL row flip (row_order.h).
#include "gl_handles.h"
#include "gl_test_support.h"
#include "row_order.h"

#include <epoxy/gl.h>
#include <gtest/gtest.h>

#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

namespace lfd::test {
namespace {

// Move-only; a name converts out of a named handle only, never out of a temporary (whose
// object would be deleted at the end of the statement).
static_assert(!std::is_copy_constructible_v<gl::Buffer> && !std::is_copy_assignable_v<gl::Buffer>);
static_assert(std::is_nothrow_move_constructible_v<gl::Buffer> && std::is_nothrow_move_assignable_v<gl::Buffer>);
static_assert(std::is_convertible_v<const gl::Buffer&, unsigned>);
static_assert(!std::is_convertible_v<gl::Buffer&&, unsigned>);
static_assert(!std::is_convertible_v<gl::Program, unsigned>);

class GlHandlesTest : public GlTest {};

TEST_F(GlHandlesTest, DeletesOnDestructionResetAndMoveAssignment)
{
    GLuint name = 0;
    {
        const gl::Buffer buffer = gl::createBuffer(64);
        name = buffer;
        EXPECT_TRUE(glIsBuffer(name));
    }
    EXPECT_FALSE(glIsBuffer(name)) << "deleted when the handle went out of scope";

    gl::Texture a = gl::createTexture(GL_TEXTURE_2D), b = gl::createTexture(GL_TEXTURE_2D);
    const GLuint first = a, second = b;
    a = std::move(b); // the texture a held is deleted, b's moves over
    EXPECT_FALSE(glIsTexture(first));
    EXPECT_TRUE(glIsTexture(second));
    EXPECT_EQ(a.get(), second);
    EXPECT_FALSE(b) << "a moved-from handle is empty";
    a.reset();
    EXPECT_FALSE(glIsTexture(second));

    gl::Framebuffer f = gl::createFramebuffer();
    const GLuint kept = f.release();
    EXPECT_FALSE(f);
    EXPECT_TRUE(glIsFramebuffer(kept)) << "released, not deleted";
    const gl::Framebuffer reclaimed(kept); // owned again, deleted at the end of the test

    for (const GLuint n : {gl::createVertexArray().get(), gl::createSampler().get(), gl::createQuery(GL_TIMESTAMP).get()})
        EXPECT_NE(n, 0u);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
}

// createBuffer keeps at least 16 bytes (an empty buffer stays bindable) and copies data
// shorter than that out first instead of reading past it.
TEST_F(GlHandlesTest, BuffersKeepSixteenBytesAndTheirData)
{
    const uint32_t words[2] = {7u, 9u};
    const gl::Buffer small = gl::createBuffer(sizeof(words), 0, words);
    GLint64 size = 0;
    glGetNamedBufferParameteri64v(small, GL_BUFFER_SIZE, &size);
    EXPECT_EQ(size, 16);
    uint32_t back[4] = {1, 1, 1, 1};
    glGetNamedBufferSubData(small, 0, sizeof(back), back);
    EXPECT_EQ(back[0], 7u);
    EXPECT_EQ(back[1], 9u);
    EXPECT_EQ(back[2], 0u);
    const gl::Buffer empty = gl::createBuffer(0);
    glGetNamedBufferParameteri64v(empty, GL_BUFFER_SIZE, &size);
    EXPECT_EQ(size, 16);
}

TEST(RowOrder, FlipsRowsBothWays)
{
    const std::vector<uint8_t> image = {1, 2, 3, 4, 5, 6}; // 3 rows of 2 bytes
    const std::vector<uint8_t> flipped = gl::flipRows(image, 2);
    EXPECT_EQ(flipped, (std::vector<uint8_t>{5, 6, 3, 4, 1, 2}));
    EXPECT_EQ(gl::flipRows(flipped, 2), image);
    EXPECT_TRUE(gl::flipRows(std::vector<uint8_t>{}, 4).empty());
    EXPECT_THROW(gl::flipRows(image, 4), std::invalid_argument) << "not whole rows";
    EXPECT_THROW(gl::flipRows(image, 0), std::invalid_argument);
}

} // namespace
} // namespace lfd::test
