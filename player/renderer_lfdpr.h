// lfdpr: Light Field Display Point Rendering (Gavane & Watson 2024, section 3).
//
// Per frame (DESIGN.md section 2, "LFDPR per frame"):
//   1. "point_generation": VS -> GS -> FS into a framebuffer without attachments. The GS
//      samples each visible triangle at LFD-biased horizontal / vertical densities (paper
//      section 3.1, T_align and S_ortho), reduced where the texture is coarser than the
//      views (eq. lfd_texelSplatDensity), and sets up multiview mipmapping (eqs.
//      minVPUVSize..maxLOD); every fragment appends one point to the point buffer.
//   2. "view_generation": a compute pass splats every point into every view as a
//      world-space square clipped by its own triangle (section 3.2), shaded per view with
//      the texture value interpolated between the point's min- and max-LOD fetches (eqs.
//      interpolationParameter, interplateTexValue), depth-resolved by atomicMin on a
//      64-bit (depth << 32 | rgba8) word, or by the two-pass 32-bit fallback.
//   3. "resolve": a compute pass writes the winning colours (or the background) into the
//      ViewTargets colour array, so the EIA builder, quilt and view outputs are shared.
// The shared formulas live in shaders/lfdpr_math.glsl (player/lfdpr_math.h on the CPU).
#pragma once

#include "renderer.h"

#include <cstdint>
#include <memory>

namespace lfd::player {

struct LfdprOptions {
    // false: isotropic sampling at the finer of the two densities (as iVIR).
    bool lfdBiasedSampling = true;
    // false: never reduce density by texture (eq. lfd_texelSplatDensity off).
    bool textureSplatting = true;
    // false: texture values fetched at LOD 0 (as iVIR / EPR).
    bool multiviewMipmapping = true;
    // Auto: 64-bit atomics where GL_NV_shader_atomic_int64 exists, else two-pass 32-bit.
    // Int64 where unsupported throws gl::GlError at construction.
    enum class Atomics { Auto, Int64, TwoPass32 } atomics = Atomics::Auto;
    // Points the buffer holds initially; it grows (needed * 1.25) after an overflow.
    uint32_t initialPointCapacity = 1u << 20;
    // Upper bound of that growth (also capped by GL_MAX_SHADER_STORAGE_BLOCK_SIZE): past
    // it every frame stores what fits, is flagged as overflowed and renders partially,
    // rather than asking the driver for an unbounded allocation. 2^26 points = 3 GiB.
    uint32_t maxPointCapacity = 1u << 26;
};

// Introspection for tests and the benchmark (values of the most recent render()).
struct LfdprFrameInfo {
    uint64_t points = 0;           // points generated (may exceed capacity on overflow)
    uint64_t pointsStored = 0;     // min(points, capacity): points splatted this frame
    uint64_t triangles = 0;        // triangle records written (triangles that emitted)
    uint64_t trianglesOversized = 0; // triangles sampled coarser to fit the viewport
    uint32_t pointCapacity = 0;    // capacity used this frame
    uint32_t triangleCapacity = 0;
    bool overflowed = false;       // points (or triangle records) were dropped this frame
    uint64_t overflowFrames = 0;   // frames overflowed so far
    bool int64Atomics = false;     // atomics path in use
    uint32_t bytesPerPoint = 0;
    uint64_t pointBufferBytes = 0;
    uint64_t viewBufferBytes = 0;
};

class LfdprRenderer : public Renderer {
public:
    virtual const LfdprOptions& options() const = 0;
    virtual const LfdprFrameInfo& lastFrame() const = 0;
};

// Needs a current GL 4.5 context.
std::unique_ptr<LfdprRenderer> createLfdprRenderer(const LfdprOptions& options = {});

// Parses "auto" | "64" | "32" (the --atomics flag); throws std::invalid_argument.
LfdprOptions::Atomics parseLfdprAtomics(const std::string& text);

} // namespace lfd::player
