// Renderer registry: name -> constructor. Each method or variant adds a line here.
#include "renderer_registry.h"

#include "raster_draw.h"

#include <algorithm>
#include <functional>
#include <stdexcept>

namespace lfd::player {

namespace {

struct Entry {
    const char* name;
    bool variant;
    std::function<std::unique_ptr<Renderer>(const RendererOptions&)> create;
    // An experiment: selectable by name only (lfd-play --renderer, lfd-bench --renderers),
    // in neither the methods (the window's R cycle) nor the ablation variants (--lfdpr-variants).
    bool experiment = false;
};

// An lfdpr variant: the caller's lfdpr options with one change.
template <typename Configure>
Entry lfdprVariant(const char* name, Configure configure, bool experiment = false)
{
    return {name, true,
            [configure](const RendererOptions& options) -> std::unique_ptr<Renderer> {
                LfdprOptions lfdpr = options.lfdpr;
                configure(lfdpr);
                return createLfdprRenderer(lfdpr);
            },
            experiment};
}

const std::vector<Entry>& registry()
{
    static const std::vector<Entry> entries = {
        {"mvr", false, [](const RendererOptions&) { return createMvrRenderer(); }},
        {"mvr-layered", false, [](const RendererOptions&) { return createMvrLayeredRenderer(); }},
        {"lfdpr", false,
         [](const RendererOptions& o) -> std::unique_ptr<Renderer> { return createLfdprRenderer(o.lfdpr); }},
        {"gstd", false, [](const RendererOptions& o) { return createGstdRenderer(o.gstd); }},
        // The paper's pipeline side by side with the default visibility pipeline, and each
        // of the paper's three innovations switched off (ablation; multiview mipmapping
        // exists in the paper's pipeline only).
        lfdprVariant("lfdpr-paper", [](LfdprOptions& o) { o.pipeline = LfdprOptions::Pipeline::Paper; }),
        lfdprVariant("lfdpr-no-lfd-sampling", [](LfdprOptions& o) { o.lfdBiasedSampling = false; }),
        lfdprVariant("lfdpr-no-texture-splatting", [](LfdprOptions& o) { o.textureSplatting = false; }),
        // Beyond the paper: the visibility pipeline without pixel-centre culling.
        lfdprVariant("lfdpr-no-pixel-culling", [](LfdprOptions& o) { o.pixelCentreCulling = false; }),
        // Beyond the paper: the visibility pipeline sampling the margin cells as well.
        lfdprVariant("lfdpr-no-margin-trim", [](LfdprOptions& o) { o.trimSamplingMargin = false; }),
        // Beyond the paper: the visibility pipeline at the paper's point density.
        lfdprVariant("lfdpr-no-cell-scaling", [](LfdprOptions& o) { o.cellScale = 1; }),
        lfdprVariant("lfdpr-no-mv-mipmapping",
                     [](LfdprOptions& o) {
                         o.pipeline = LfdprOptions::Pipeline::Paper;
                         o.multiviewMipmapping = false;
                     }),
        // An experiment beyond the paper: the panel image splatted directly, without views
        // (docs/player/direct-splat.md); equal to lfdpr's EIA at --aa none.
        lfdprVariant(
            "lfdpr-direct", [](LfdprOptions& o) { o.direct = LfdprOptions::Direct::Nearest; }, true),
        // ... its exact-ray hybrid: the same visibility, each subpixel shaded along its own ray.
        lfdprVariant(
            "lfdpr-direct-exact", [](LfdprOptions& o) { o.direct = LfdprOptions::Direct::ExactRay; }, true),
    };
    return entries;
}

std::vector<std::string> names(bool methods, bool variants)
{
    std::vector<std::string> out;
    for (const Entry& e : registry())
        if (e.experiment ? (methods && variants) : (e.variant ? variants : methods))
            out.emplace_back(e.name);
    return out;
}

} // namespace

std::vector<std::string> rendererNames() { return names(true, false); }
std::vector<std::string> lfdprVariantNames() { return names(false, true); }
std::vector<std::string> allRendererNames() { return names(true, true); }

bool isKnownRenderer(const std::string& name)
{
    const auto& r = registry();
    return std::any_of(r.begin(), r.end(), [&](const Entry& e) { return name == e.name; });
}

std::unique_ptr<Renderer> createRenderer(const std::string& name, const RendererOptions& options)
{
    for (const Entry& e : registry())
        if (name == e.name)
            return e.create(options);
    std::string known;
    for (const Entry& e : registry())
        known += (known.empty() ? "" : ", ") + std::string(e.name);
    throw std::invalid_argument("unknown renderer \"" + name + "\" (known: " + known + ")");
}

} // namespace lfd::player
