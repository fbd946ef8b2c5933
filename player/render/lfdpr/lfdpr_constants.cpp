#include "lfdpr_constants.h"

#include "shader_library.h"

namespace lfd::player {

namespace {

long define(const char* name) { return gl::shaderDefineValue("lfdpr_bindings.glsl", name); }

LfdprConstants parse()
{
    LfdprConstants c{};
    c.ssboPoints = unsigned(define("LFDPR_SSBO_POINTS"));
    c.ssboCounters = unsigned(define("LFDPR_SSBO_COUNTERS"));
    c.ssboViewDepth = unsigned(define("LFDPR_SSBO_VIEW_DEPTH"));
    c.ssboViewColor = unsigned(define("LFDPR_SSBO_VIEW_COLOR"));
    c.uboFrame = unsigned(define("LFDPR_UBO_FRAME"));
    c.imageViews = unsigned(define("LFDPR_IMAGE_VIEWS"));
    c.locPass = int(define("LFDPR_LOC_PASS"));
    c.groupSize = uint32_t(define("LFDPR_GROUP_SIZE"));
    c.ssboRecords = unsigned(define("LFDPR_SSBO_RECORDS"));
    c.ssboIndices = unsigned(define("LFDPR_SSBO_INDICES"));
    c.ssboPositions = unsigned(define("LFDPR_SSBO_POSITIONS"));
    c.ssboNormals = unsigned(define("LFDPR_SSBO_NORMALS"));
    c.ssboTangents = unsigned(define("LFDPR_SSBO_TANGENTS"));
    c.ssboUvs = unsigned(define("LFDPR_SSBO_UVS"));
    c.ssboDraws = unsigned(define("LFDPR_SSBO_DRAWS"));
    c.ssboLarge = unsigned(define("LFDPR_SSBO_LARGE"));
    c.ssboLargeDispatch = unsigned(define("LFDPR_SSBO_LARGE_DISPATCH"));
    c.ssboVisCounters = unsigned(define("LFDPR_SSBO_VIS_COUNTERS"));
    c.ssboMaterialIds = unsigned(define("LFDPR_SSBO_MATERIAL_IDS"));
    c.ssboShadeWork = unsigned(define("LFDPR_SSBO_SHADE_WORK"));
    c.ssboMaterialGroups = unsigned(define("LFDPR_SSBO_MATERIAL_GROUPS"));
    c.uboCameraLine = unsigned(define("LFDPR_UBO_CAMERA_LINE"));
    c.locDraw = int(define("LFDPR_LOC_DRAW"));
    c.locTriangles = int(define("LFDPR_LOC_TRIANGLES"));
    c.locShadeMaterial = int(define("LFDPR_LOC_SHADE_MATERIAL"));
    c.locLargeBase = int(define("LFDPR_LOC_LARGE_BASE"));
    c.locShadeGroup = int(define("LFDPR_LOC_SHADE_GROUP"));
    c.locShadeGroups = int(define("LFDPR_LOC_SHADE_GROUPS"));
    c.shadeTile = uint32_t(define("LFDPR_SHADE_TILE"));
    c.maxShadeGroups = uint32_t(define("LFDPR_MAX_SHADE_GROUPS"));
    c.shadeDispatchWidth = uint32_t(define("LFDPR_SHADE_DISPATCH_WIDTH"));
    c.recordBytes = uint32_t(define("LFDPR_RECORD_BYTES"));
    c.compactPointBytes = uint32_t(define("LFDPR_COMPACT_POINT_BYTES"));
    c.visCounterBytes = uint32_t(define("LFDPR_VIS_COUNTER_BYTES"));
    c.optionLfdSampling = uint32_t(define("LFDPR_OPTION_LFD_SAMPLING"));
    c.optionTextureSplatting = uint32_t(define("LFDPR_OPTION_TEXTURE_SPLATTING"));
    c.optionMvMipmapping = uint32_t(define("LFDPR_OPTION_MV_MIPMAPPING"));
    return c;
}

} // namespace

const LfdprConstants& LfdprConstants::get()
{
    static const LfdprConstants constants = parse();
    return constants;
}

} // namespace lfd::player
