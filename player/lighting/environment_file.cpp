// Reading .hdr environments; see environment_file.h.
#include "environment_file.h"

#include "image.h" // ImageError
#include "image_file.h"

#include <cstdlib>
#include <string>

namespace lfd::lighting {

Environment loadEnvironment(const std::filesystem::path& path)
{
    metrics::HdrImage image;
    try {
        image = metrics::readHdrImage(path, kMaxEnvironmentPixels);
    } catch (const metrics::ImageError& e) {
        throw EnvironmentError(e.what());
    }
    const std::string size = std::to_string(image.width) + "x" + std::to_string(image.height);
    // An equirectangular panorama spans 360 x 180 degrees: width = 2 height (1% slack).
    if (std::abs(image.width - 2 * image.height) * 100 > 2 * image.height)
        throw EnvironmentError("'" + path.string() + "': " + size +
                               " is not an equirectangular panorama (width must be twice the height)");
    Environment environment;
    environment.width = uint32_t(image.width);
    environment.height = uint32_t(image.height);
    environment.rgb = std::move(image.rgb);
    try {
        validateEnvironment(environment, "'" + path.string() + "'");
    } catch (const std::invalid_argument& e) {
        throw EnvironmentError(e.what());
    }
    return environment;
}

} // namespace lfd::lighting
