// lfdpr: Light Field Display Point Rendering (Gavane & Watson 2024). Two pipelines stand
// behind the one LfdprRenderer interface, chosen by LfdprOptions::pipeline; both report
// the stages "point_generation", "view_generation" and "resolve", and every class, file,
// shader and GPU struct names the pipeline it belongs to (LfdprPaper* / lfdpr_paper_*,
// LfdprVisibility* / lfdpr_visibility_*); the other Lfdpr* names are shared (options,
// frame block, math) or name a visibility-only mechanism (the camera line, shading chunks).
//
// Visibility (the default, beyond the paper; renderer_lfdpr_visibility.cpp):
//   1. point generation in a compute pass (LfdprVisibilityPointGeneration,
//      lfdpr_visibility_points.comp): each triangle sampled at the paper's LFD-biased
//      densities into 8-byte points (LfdprVisibilityPointGpu: triangle record + cell);
//   2. visibility splatting (lfdpr_visibility_splat.comp): every point's depth and
//      triangle record into every view, with camera-line coherence;
//   3. shading once per visible view pixel, as mvr shades a fragment
//      (lfdpr_visibility_shade*.comp, textureGrad at the exact footprint).
//
// Paper (the published method, paper section 3; renderer_lfdpr_paper.cpp):
//   1. point generation through VS -> GS -> FS (LfdprPaperPointGeneration,
//      lfdpr_paper_points.vert/geom/frag): the GS samples each visible triangle at
//      LFD-biased horizontal / vertical densities (section 3.1, T_align and S_ortho),
//      reduced where the texture is coarser than the views (eq. lfd_texelSplatDensity),
//      and sets up multiview mipmapping (eqs. minVPUVSize..maxLOD); every fragment appends
//      a 48-byte LfdprPaperPointGpu carrying tv_min / tv_max;
//   2. view generation (LfdprPaperViewGeneration, lfdpr_paper_splat.comp): every point
//      splatted into every view as a world-space square clipped by its own triangle
//      (section 3.2), shaded per view with the texture value interpolated between its
//      min- and max-LOD fetches, depth-resolved by atomicMin on a 64-bit
//      (depth << 32 | rgba8) word or by the two-pass 32-bit fallback;
//   3. resolve (lfdpr_paper_resolve.comp): the winning colours into the ViewTargets.
// The shared formulas live in shaders/lfdpr_math.glsl (player/render/lfdpr/lfdpr_math.h on
// the CPU); the GPU layouts of both in shaders/lfdpr_bindings.glsl.
#pragma once

#include "renderer.h"

#include <cstdint>
#include <memory>

namespace lfd::player {

struct LfdprOptions {
    // Visibility (default, beyond the paper): compute point generation, 8-byte points,
    // visibility splatting of depth and triangle record with camera-line coherence, then one
    // mvr-identical shading per visible view pixel with textureGrad at the exact footprint.
    // Paper: the paper's pipeline as published - geometry-shader point generation, 48-byte
    // points carrying tv_min / tv_max, shading per splat and view (multiview mipmapping).
    enum class Pipeline { Visibility, Paper } pipeline = Pipeline::Visibility;
    // false: isotropic sampling at the finer of the two densities (as iVIR).
    bool lfdBiasedSampling = true;
    // false: never reduce density by texture (eq. lfd_texelSplatDensity off).
    bool textureSplatting = true;
    // false: texture values fetched at LOD 0 (as iVIR / EPR). Paper pipeline only (the
    // visibility pipeline filters every texture per pixel and view).
    bool multiviewMipmapping = true;
    // Beyond the paper, visibility pipeline only: a triangle that holds no view pixel centre
    // in any view emits no points (none of them could win a pixel: the splat writes only
    // centres inside the point's triangle), so the views are unchanged and dense scenes of
    // sub-pixel triangles generate and splat fewer points. false: every triangle is sampled
    // as in the paper (the point set then equals the paper pipeline's).
    bool pixelCentreCulling = true;
    // Beyond the paper, visibility pipeline only: the sampling box's one-cell margin on its
    // low sides (for the paper's conservative rasteriser) is not sampled. Those cells lie
    // wholly outside the triangle and only touch it, yet the closed overlap test gives each
    // that holds a vertex a point: a sub-pixel triangle gets three or four points where one
    // cell holds it. The splat clips every cell to its triangle's box and reaches
    // LFDPR_SPLAT_SLACK pixels past it, so the views are unchanged (tested). false: the margin
    // is sampled as in the paper.
    bool trimSamplingMargin = true;
    // Beyond the paper, visibility pipeline only: each point's cell spans cellScale x
    // cellScale of the paper's sampling spacings (so cellScale^2 fewer points on triangles
    // that span several cells). Each pixel is shaded from its winning point's triangle at
    // the pixel's own centre and the splat writes only centres inside that triangle, so
    // the cell size decides which point of a triangle wins a pixel, never what the pixel
    // shows: the views are the same for every scale. Alpha-masked materials keep the
    // paper's spacing (their cells carry the mask). 1: the paper's density.
    uint32_t cellScale = 2;
    // Visibility pipeline: how its work is cut into invocations (shaders/lfdpr_work_shape.glsl,
    // docs/player/lfdpr.md "Work shaped for a GPU"). Gpu: many short invocations (a splat per point
    // and slice of views, splats of a few pixels, shading per slice of views); Cpu: long
    // invocations that amortise per-point setup over every view, which a CPU rasteriser runs
    // fastest. Auto: Cpu on Mesa's software rasterisers (llvmpipe, softpipe) and OpenSWR, Gpu
    // elsewhere. The views are the same either way.
    enum class WorkShape { Auto, Gpu, Cpu } workShape = WorkShape::Auto;
    // Visibility pipeline, --aniso above 1: how the shading filters a texture anisotropically at
    // the pixel's exact footprint (docs/player/reconstruction.md "Anisotropic filtering").
    // Hardware: one textureGrad through the textures' own anisotropic sampler state, the texture
    // unit's filter - the one mvr's texture() uses, given the analytic gradients instead of the
    // quad's differences. Taps: n = min(ceil(major / minor), N) trilinear textureGrad taps along
    // the footprint's major axis, averaged. Auto: Taps on Mesa's software rasterisers and OpenSWR
    // (llvmpipe's anisotropic filter takes its ellipse from the lanes of a 2x2 quad, which in a
    // compute shader are unrelated pixels), Hardware elsewhere. At --aniso 1 both are the same
    // single trilinear textureGrad.
    enum class AnisoFilter { Auto, Hardware, Taps } anisoFilter = AnisoFilter::Auto;
    // Auto: 64-bit atomics where GL_NV_shader_atomic_int64 exists, else two-pass 32-bit.
    // Int64 where unsupported throws gl::GlError at construction.
    enum class Atomics { Auto, Int64, TwoPass32 } atomics = Atomics::Auto;
    // Points the buffer holds initially. 0 (the default): the visibility pipeline sizes it
    // when a scene is first rendered, from a count-only run of point generation for that
    // first frame's views (the one wait of a scene, at load; 1.5 x the count),
    // so the first frame does not overflow; the paper pipeline starts at 2^20.
    // Either way it grows (needed * 1.25) after an overflow, once the
    // overflowing frame's counts are back from the GPU (read without waiting, frames later).
    // Frames rendered until then keep what fits and are counted (overflow_frames);
    // Renderer::settle() reports an overflowed last frame, which lfd-play and lfd-bench
    // render again before reading its outputs, so no output ever lacks points below the cap.
    uint32_t initialPointCapacity = 0;
    // Upper bound of that growth (also capped by GL_MAX_SHADER_STORAGE_BLOCK_SIZE): past
    // it every frame stores what fits, is flagged as overflowed and renders partially,
    // rather than asking the driver for an unbounded allocation. 2^26 points = 3 GiB.
    uint32_t maxPointCapacity = 1u << 26;
    // Test hook, visibility pipeline, 32-bit path: when n > 0, every n-th point also stores
    // its index where it lost the depth test, as a lost race would, so tests can exercise
    // the index repair deterministically. Never set outside tests.
    uint32_t testIndexRaces = 0;
    // Test hook, visibility pipeline, 32-bit path on the GPU work shape: when n > 0, the tie
    // queue holds n points, so tests can overflow it into the repair. Never set outside tests.
    uint32_t testTieCapacity = 0;
    // Visibility pipeline: the splat and the shading count their work on the GPU (views
    // culled before setup, samples, atomics, words lowered, shadings; docs/player/8k-panels.md
    // "Work counters"), read back with the point count (no added GL call or wait). Off by
    // default: the counts cost a few adds per sample and a reduction per workgroup.
    bool countWork = false;
    // Visibility pipeline, an experiment (renderer lfdpr-direct; docs/player/direct-splat.md):
    // Nearest renders the panel image without views - the same points and splat, each
    // sample fanned out to the panel subpixels that show its view pixel, shaded per
    // subpixel - equal byte for byte to the views and the EIA's nearest mode (--aa none),
    // which it replaces (the reconstruction flag does not apply). Needs 64-bit atomics; no
    // views are written. ExactRay (renderer lfdpr-direct-exact): the same visibility, each
    // subpixel's winner shaded along its own ray (the camera of its continuous phase, through
    // its lens centre) instead of the nearest view's pixel centre. Off: the views, then the
    // EIA pass.
    enum class Direct { Off, Nearest, ExactRay } direct = Direct::Off;
};

// Introspection for tests and the benchmark: values of the most recent frame whose counts
// have come back from the GPU (after settle(): the last frame rendered).
struct LfdprFrameInfo {
    uint64_t points = 0;           // points generated (may exceed capacity on overflow)
    uint64_t pointsStored = 0;     // min(points, capacity): points splatted this frame
    uint64_t triangles = 0;        // triangle records written (triangles that emitted)
    uint64_t trianglesOversized = 0; // triangles larger than one sampling tile
    uint32_t pointCapacity = 0;    // capacity used this frame
    uint32_t triangleCapacity = 0;
    bool overflowed = false;       // points (or triangle records) were dropped this frame
    uint64_t overflowFrames = 0;   // frames overflowed so far
    bool int64Atomics = false;     // atomics path in use
    bool hardwareAniso = false;    // visibility pipeline: AnisoFilter in use is Hardware
    uint32_t bytesPerPoint = 0;
    uint64_t pointBufferBytes = 0;
    uint64_t triangleBufferBytes = 0; // per-triangle records (and the large-triangle list)
    uint64_t trianglesLarge = 0;      // visibility pipeline: sampled by a workgroup
    uint64_t bufferGrowths = 0;       // visibility pipeline: the point buffer grown after an overflow
    uint64_t repairs = 0;             // visibility pipeline, 32-bit: pixels whose index was repaired
    uint64_t tiePoints = 0;           // visibility pipeline, 32-bit views path: points queued at a depth tie
    uint64_t viewBufferBytes = 0;
    uint64_t sizedPoints = 0;         // visibility pipeline: the load-time count-only run's points
    // Visibility pipeline with LfdprOptions::countWork (else 0): the GPU's work counters
    // (LfdprVisibilityCountersGpu work*: docs/player/8k-panels.md "Work counters").
    uint64_t workCulled = 0, workCulledCentres = 0, workSamples = 0, workAtomics = 0, workLowered = 0, workShadings = 0;
};

class LfdprRenderer : public Renderer {
public:
    virtual const LfdprOptions& options() const = 0;
    virtual const LfdprFrameInfo& lastFrame() const = 0;
    // Points of the last frame per drawn triangle (draws in order, then triangles), read
    // back from the GPU: lets tests check that both pipelines sample alike. Slow.
    virtual std::vector<uint32_t> pointsPerTriangle() const = 0;
};

// Needs a current GL 4.5 context. Builds options.pipeline's implementation.
std::unique_ptr<LfdprRenderer> createLfdprRenderer(const LfdprOptions& options = {});
// The two implementations (renderer_lfdpr_paper.cpp, renderer_lfdpr_visibility.cpp).
std::unique_ptr<LfdprRenderer> createLfdprPaperRenderer(const LfdprOptions& options);
std::unique_ptr<LfdprRenderer> createLfdprVisibilityRenderer(const LfdprOptions& options);
// Parses "visibility" | "paper" (the --lfdpr-pipeline flag); throws std::invalid_argument.
LfdprOptions::Pipeline parseLfdprPipeline(const std::string& text);
// Whether the driver has the 64-bit atomics the Int64 path needs; throws gl::GlError
// for Int64 where it has not.
bool lfdprUseInt64(LfdprOptions::Atomics atomics);

// Whether the visibility pipeline runs the GPU work shape (WorkShape::Auto decided from
// GL_RENDERER). Needs a current context.
bool lfdprGpuWorkShape(LfdprOptions::WorkShape shape);
// Whether the visibility pipeline's shading filters through the texture unit
// (AnisoFilter::Auto decided from GL_RENDERER as WorkShape::Auto is). Needs a current context.
bool lfdprHardwareAniso(LfdprOptions::AnisoFilter filter);
// Parses "auto" | "hardware" | "taps" (the --lfdpr-aniso flag); throws std::invalid_argument.
LfdprOptions::AnisoFilter parseLfdprAnisoFilter(const std::string& text);
// Parses "auto" | "gpu" | "cpu" (the --lfdpr-work flag); throws std::invalid_argument.
LfdprOptions::WorkShape parseLfdprWorkShape(const std::string& text);

// Parses "auto" | "64" | "32" (the --atomics flag); throws std::invalid_argument.
LfdprOptions::Atomics parseLfdprAtomics(const std::string& text);

} // namespace lfd::player
