// The names of a frame's timed stages, defined once: renderers open them on the GpuTimer,
// the frame pipeline brackets them with "total", and lfd-play's summary, the stats JSON
// and lfd-bench's tables read them back in this order. A stage's stats key is its name
// plus "_ms".
#pragma once

#include <array>
#include <string_view>

namespace lfd::player::stage {

// Scenes with skinned or morphed meshes: the pose pass (scene_poser.h); absent otherwise.
inline constexpr std::string_view kPose = "pose";
// lfdpr: points generated from the scene's triangles (paper section 3.1).
inline constexpr std::string_view kPointGeneration = "point_generation";
// Every renderer: the N views (lfdpr: splatting, paper section 3.2).
inline constexpr std::string_view kViewGeneration = "view_generation";
// lfdpr: per-pixel shading (visibility pipeline) or colour resolve (paper pipeline).
inline constexpr std::string_view kResolve = "resolve";
// Supersampling (--ss 2s|2v): averaging the supersampled views down to the display's.
inline constexpr std::string_view kDownsample = "downsample";
// Interleaving the views into the panel's elemental image array.
inline constexpr std::string_view kEia = "eia";
// The whole frame, around all of the above.
inline constexpr std::string_view kTotal = "total";

// Pipeline order, for reports.
inline constexpr std::array<std::string_view, 7> kAll = {kPose, kPointGeneration, kViewGeneration, kResolve,
                                                         kDownsample, kEia, kTotal};
// The stages every renderer's frame has.
inline constexpr std::array<std::string_view, 3> kRequired = {kViewGeneration, kEia, kTotal};

} // namespace lfd::player::stage
