// Environments from Radiance .hdr files (`--environment FILE.hdr`), decoded by stb_image
// through the player's one image codec (image_file.h in lfd_image_metrics).
#pragma once

#include "environment.h"

#include <filesystem>
#include <stdexcept>

namespace lfd::lighting {

// The largest environment read: 8192 x 4096 (Poly Haven's "8K"), 400 MB as float RGB;
// the player's cube faces are 256 texels (512 for gstd), so more would only cost memory.
constexpr uint64_t kMaxEnvironmentPixels = uint64_t(8192) * 4096;

// One line naming the file and the problem.
class EnvironmentError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Reads an equirectangular Radiance .hdr (width twice the height, within 1%; row 0 = the
// zenith, see environment.h). Throws EnvironmentError for a missing file, a directory,
// another format, an image over kMaxEnvironmentPixels (before decoding), a truncated or
// corrupt file, a panorama that is not 2:1, or radiance that is not finite.
Environment loadEnvironment(const std::filesystem::path& path);

} // namespace lfd::lighting
