#include "gstd_cache.h"

#include "atomic_file.h"
#include "view_targets.h"

#include "lfd/subpixel_phase.h"

#include <epoxy/gl.h>
#include <xxhash.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <vector>

namespace lfd::player {

namespace {

namespace fs = std::filesystem;

constexpr char kMagic[8] = {'L', 'F', 'D', 'G', 'S', 'T', 'D', '2'};

void appendU32(std::vector<uint8_t>& out, uint32_t v)
{
    const uint8_t* p = reinterpret_cast<const uint8_t*>(&v); // little-endian hosts only (x86-64, arm64)
    out.insert(out.end(), p, p + 4);
}

uint32_t readU32(const std::vector<uint8_t>& in, size_t at)
{
    uint32_t v = 0;
    std::memcpy(&v, in.data() + at, 4);
    return v;
}

std::vector<uint8_t> readWholeFile(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        return {};
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    if (size <= 0)
        return {};
    in.seekg(0);
    std::vector<uint8_t> bytes(static_cast<size_t>(size));
    in.read(reinterpret_cast<char*>(bytes.data()), size);
    return in ? bytes : std::vector<uint8_t>{};
}

} // namespace

uint64_t hashFileContents(const fs::path& path)
{
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw std::runtime_error(path.string() + ": cannot open for hashing");
    std::unique_ptr<XXH3_state_t, decltype(&XXH3_freeState)> state(XXH3_createState(), &XXH3_freeState);
    if (!state || XXH3_64bits_reset(state.get()) != XXH_OK)
        throw std::runtime_error("xxhash: cannot create a hash state");
    std::vector<char> buffer(1 << 20);
    while (in) {
        in.read(buffer.data(), std::streamsize(buffer.size()));
        if (in.gcount() > 0)
            XXH3_64bits_update(state.get(), buffer.data(), size_t(in.gcount()));
    }
    if (in.bad())
        throw std::runtime_error(path.string() + ": read error while hashing");
    return XXH3_64bits_digest(state.get());
}

std::string gstdCacheKey(uint64_t packHash, double time, double turntablePeriod,
                         const DisplayProfile& profile, const GstdOptions& options,
                         const std::string& glDriver)
{
    // %a: exact (hexadecimal) doubles, so equal keys mean bit-equal inputs.
    char text[512];
    std::snprintf(text, sizeof(text),
                  "pack=%016llx time=%a period=%a views=%u size=%ux%u cone=%a distance=%a screen=%ax%a",
                  static_cast<unsigned long long>(packHash), time, turntablePeriod, profile.viewCount,
                  profile.viewWidth, profile.viewHeight, profile.viewConeDeg, profile.viewingDistanceMm,
                  profile.screenWidthMm, profile.screenHeightMm);
    std::string key = std::string(text) + " " + gstdSettingsKey(options);
    if (options.model == GstdModel::Panel) {
        // The panel model's EIA also depends on the panel and its lenses.
        const SubpixelMapping& m = profile.mapping;
        // phase=: the subpixel phase's definition (fixed point, lfd/subpixel_phase.h), so a
        // panel image cached by the double-precision phase of earlier builds is not reused.
        std::snprintf(text, sizeof(text), " panel=%ux%u mapping=%a,%a,%a,%d order=%u phase=fixed%d", profile.panelWidth,
                      profile.panelHeight, m.perSubpixel, m.perRow, m.offset, m.invert ? 1 : 0,
                      unsigned(profile.subpixelOrder), kSubpixelPhaseBits);
        key += text;
    }
    return key + " gl=" + glDriver;
}

fs::path defaultGstdCacheDir()
{
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
        return fs::path(xdg) / "lfdpr" / "gstd";
    if (const char* home = std::getenv("HOME"); home && *home)
        return fs::path(home) / ".cache" / "lfdpr" / "gstd";
    return {};
}

fs::path GstdCache::entryPath(const std::string& key) const
{
    char name[40];
    std::snprintf(name, sizeof(name), "%016llx.gstdviews",
                  static_cast<unsigned long long>(XXH3_64bits(key.data(), key.size())));
    return dir_ / name;
}

bool GstdCache::load(const std::string& key, ViewTargets& targets, const GstdCachePanel* panel) const
{
    const std::vector<uint8_t> bytes = readWholeFile(entryPath(key));
    const size_t header = sizeof(kMagic) + 4 + key.size() + 12;
    const size_t payload = size_t(targets.viewCount()) * targets.width() * targets.height() * 4;
    const uint32_t panelWidth = panel ? panel->width : 0, panelHeight = panel ? panel->height : 0;
    const size_t panelBytes = size_t(panelWidth) * panelHeight * 4;
    // Step 1: exact size, magic, key, dimensions, then the checksum over all of it.
    if (bytes.size() != header + payload + 8 + panelBytes + 8 ||
        std::memcmp(bytes.data(), kMagic, sizeof(kMagic)) != 0)
        return false;
    if (readU32(bytes, 8) != key.size() || std::memcmp(bytes.data() + 12, key.data(), key.size()) != 0)
        return false;
    const size_t dims = 12 + key.size();
    if (readU32(bytes, dims) != targets.viewCount() || readU32(bytes, dims + 4) != targets.width() ||
        readU32(bytes, dims + 8) != targets.height())
        return false;
    if (readU32(bytes, header + payload) != panelWidth || readU32(bytes, header + payload + 4) != panelHeight)
        return false;
    const size_t body = header + payload + 8 + panelBytes;
    uint64_t stored = 0;
    std::memcpy(&stored, bytes.data() + body, 8);
    if (XXH3_64bits(bytes.data(), body) != stored)
        return false;

    // Step 2: the views (and the panel image), as gstd left them.
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTextureSubImage3D(targets.colorArray(), 0, 0, 0, 0, GLsizei(targets.width()), GLsizei(targets.height()),
                        GLsizei(targets.viewCount()), GL_RGBA, GL_UNSIGNED_BYTE, bytes.data() + header);
    if (panel)
        glTextureSubImage2D(panel->texture, 0, 0, 0, GLsizei(panelWidth), GLsizei(panelHeight), GL_RGBA,
                            GL_UNSIGNED_BYTE, bytes.data() + header + payload + 8);
    glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    return true;
}

void GstdCache::store(const std::string& key, const ViewTargets& targets, const GstdCachePanel* panel) const
{
    const fs::path target = entryPath(key);
    std::vector<uint8_t> bytes(kMagic, kMagic + sizeof(kMagic));
    appendU32(bytes, uint32_t(key.size()));
    bytes.insert(bytes.end(), key.begin(), key.end());
    appendU32(bytes, targets.viewCount());
    appendU32(bytes, targets.width());
    appendU32(bytes, targets.height());
    const size_t header = bytes.size();
    const size_t payload = size_t(targets.viewCount()) * targets.width() * targets.height() * 4;
    bytes.resize(header + payload);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTextureImage(targets.colorArray(), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(payload), bytes.data() + header);
    appendU32(bytes, panel ? panel->width : 0);
    appendU32(bytes, panel ? panel->height : 0);
    if (panel) {
        const size_t at = bytes.size(), panelBytes = size_t(panel->width) * panel->height * 4;
        bytes.resize(at + panelBytes);
        glGetTextureImage(panel->texture, 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(panelBytes), bytes.data() + at);
    }
    const uint64_t checksum = XXH3_64bits(bytes.data(), bytes.size());
    const uint8_t* c = reinterpret_cast<const uint8_t*>(&checksum);
    bytes.insert(bytes.end(), c, c + 8);

    std::error_code ec;
    fs::create_directories(dir_, ec);
    if (ec)
        throw std::runtime_error(dir_.string() + ": cannot create the gstd cache directory: " + ec.message());
    writeFileAtomically(target, bytes); // readers never see a partial entry
}

} // namespace lfd::player
