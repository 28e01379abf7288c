// libFuzzer target: our image reader (PNG through libpng, OpenEXR and Radiance HDR through
// OpenImageIO; decoded from memory, with the size and finiteness checks). The first byte chooses
// the type. A header may claim any size: the memory limit, set low here, is what keeps decoding
// bounded, as it does for users.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "common/MemoryBudget.h"
#include "image/ImageFile.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    // 1 MiB holds a 180x180 image with its decoded samples: enough for every decoder path, and
    // inputs whose headers claim more are refused at once instead of filled (which made most of
    // the fuzzer's time page faults and memset).
    matevo::setMemoryLimitBytes(1u << 20);
    // Load the OpenImageIO module now: its first use maps ~250 libraries and runs their static
    // initialisers (GDCM's DICOM dictionary alone takes seconds under ASan), which would
    // otherwise count against the first input's -timeout. The bytes need not decode.
    (void)matevo::decodeImageFile("#?RADIANCE\n", "warm-up.hdr");
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    const std::string_view bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
    static constexpr const char* kNames[] = {"fuzz.png", "fuzz.exr", "fuzz.hdr"};
    auto image = matevo::decodeImageFile(bytes, kNames[data[0] % 3]);
    if (image)
        for (float value : image->image.rgba)
            if (!std::isfinite(value)) __builtin_trap();
    return 0;
}
