// Renderer registry: name -> constructor. Each method adds a line here.
#include "raster_draw.h"
#include "renderer_gstd.h"
#include "renderer_lfdpr.h"

#include <functional>
#include <stdexcept>

namespace lfd::player {

namespace {

struct Entry {
    const char* name;
    std::function<std::unique_ptr<Renderer>()> create;
};

const std::vector<Entry>& registry()
{
    static const std::vector<Entry> entries = {
        {"mvr", createMvrRenderer},
        {"mvr-layered", createMvrLayeredRenderer},
        {"lfdpr", [] { return std::unique_ptr<Renderer>(createLfdprRenderer()); }},
        {"gstd", [] { return createGstdRenderer(); }},
    };
    return entries;
}

} // namespace

std::vector<std::string> rendererNames()
{
    std::vector<std::string> names;
    for (const Entry& e : registry())
        names.emplace_back(e.name);
    return names;
}

std::unique_ptr<Renderer> createRenderer(const std::string& name)
{
    for (const Entry& e : registry())
        if (name == e.name)
            return e.create();
    std::string known;
    for (const Entry& e : registry())
        known += (known.empty() ? "" : ", ") + std::string(e.name);
    throw std::invalid_argument("unknown renderer \"" + name + "\" (known: " + known + ")");
}

} // namespace lfd::player
