// libFuzzer entry point for the pack reader (built with -DLFD_BUILD_FUZZERS=ON, run by
// scripts/fuzz.sh; see formats/README.md "Tests and fuzzing").
// Any input must either decode or throw lfd::PackError: crashes, sanitizer reports,
// other exceptions and huge allocations are bugs.
#include "lfd/pack.h"
#include "lfd/pack_layout.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace {

void readAndReencode(const uint8_t* data, size_t size)
{
    try {
        const lfd::Scene scene = lfd::readPackFromMemory(data, size, "fuzz.lfdpack");
        // A pack that validates must re-encode to a pack that validates.
        const std::vector<uint8_t> again = lfd::writePackToMemory(scene);
        lfd::readPackFromMemory(again.data(), again.size(), "fuzz-again.lfdpack");
    } catch (const lfd::PackError&) {
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    // As given: exercises the header, table and checksum checks.
    readAndReencode(data, size);
    // Resealed: checksums fixed up, so mutations reach the decoder and the scene rules.
    std::vector<uint8_t> sealed(data, data + size);
    lfd::pack::resealPack(sealed);
    readAndReencode(sealed.data(), sealed.size());
    return 0;
}
