// The OpenImageIO module: every image format OpenImageIO reads, and OpenEXR writing. Built as a
// shared module that ImageLibrary opens on first use, so that commands which only touch PNG
// never map OpenImageIO and its dependencies.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "image/ImageLibraryAbi.h"
#include "image/ImageType.h"

namespace matevo {
namespace {

// OpenImageIO messages may span lines; our errors are one line.
std::string oneLine(std::string text) {
    std::replace(text.begin(), text.end(), '\n', ' ');
    while (!text.empty() && text.back() == ' ') text.pop_back();
    return text.empty() ? std::string("unknown OpenImageIO error") : text;
}

// "OpenEXR", "JPEG", "TIFF": OpenImageIO's format name as people write it.
std::string displayFormat(std::string name) {
    if (name == "openexr") return "OpenEXR";
    std::transform(name.begin(), name.end(), name.begin(),
                   [](unsigned char c) { return char(std::toupper(c)); });
    return name;
}

// The file's bytes as OpenImageIO reads them. OpenImageIO 2.4's IOMemReader accepts a seek to
// any offset and then copies from before the buffer for a negative one: an OpenEXR file whose
// line offsets point before its start (found by the image fuzz target) read past our memory.
class BoundedMemoryReader final : public OIIO::Filesystem::IOMemReader {
public:
    using IOMemReader::IOMemReader;
    bool seek(int64_t offset) override {
        return offset >= 0 && std::uint64_t(offset) <= size() && IOMemReader::seek(offset);
    }
    size_t pread(void* buffer, size_t count, int64_t offset) override {
        return offset < 0 ? 0 : IOMemReader::pread(buffer, count, offset);
    }
};

// The sample type DecodedImage keeps for a file's own type: 8 and 16 bits as they are, wider
// or signed integers as 16 bits, every floating-point type as float. The samples are read as
// stored (TypeDesc::UNKNOWN) and, if that is not Sample, converted here channel by channel (an
// OpenEXR file's channels may differ in type) from a copy of the image's size, freed before the
// RGBA image is made. Asked for any type, even the file's own, OpenImageIO 2.4 reads a scanline
// image through a 64 MiB buffer whatever the image's size: most of the time it took to read a
// small OpenEXR file.
template <typename Sample>
Result<DecodedImage> readSamples(OIIO::ImageInput& input, const OIIO::ImageSpec& spec,
                                 OIIO::TypeDesc type) {
    const int channels = spec.nchannels;
    const std::size_t pixelCount = std::size_t(spec.width) * std::size_t(spec.height);
    std::vector<Sample> samples(pixelCount * std::size_t(channels));
    const auto readAsStored = [&](void* destination) {
        return input.read_image(0, 0, 0, channels, OIIO::TypeDesc::UNKNOWN, destination);
    };
    const auto cannotDecode = [&input] {
        return badInput("cannot decode: " + oneLine(input.geterror()));
    };
    if (spec.channelformats.empty() && spec.format == type) {
        if (!readAsStored(samples.data())) return cannotDecode();
        return DecodedImage{spec.width, spec.height, channels, std::move(samples)};
    }
    const auto storedPixelBytes = OIIO::stride_t(spec.pixel_bytes(true));
    std::vector<std::byte> stored(pixelCount * std::size_t(storedPixelBytes));
    if (!readAsStored(stored.data())) return cannotDecode();
    const auto samplePixelBytes = OIIO::stride_t(sizeof(Sample)) * channels;
    std::size_t offset = 0;
    for (int c = 0; c < channels; ++c) {
        const OIIO::TypeDesc storedType = spec.channelformat(c);
        if (!OIIO::convert_image(1, spec.width, spec.height, 1, stored.data() + offset, storedType,
                                 storedPixelBytes, storedPixelBytes * spec.width, OIIO::AutoStride,
                                 samples.data() + c, type, samplePixelBytes,
                                 samplePixelBytes * spec.width, OIIO::AutoStride))
            return badInput("cannot decode: no conversion from " + std::string(storedType.c_str()));
        offset += storedType.size();
    }
    return DecodedImage{spec.width, spec.height, channels, std::move(samples)};
}

Result<DecodedImage> decode(std::string_view bytes, const std::filesystem::path& file,
                            const DecodedSizeCheck& checkSize) {
    std::string extension = lowerCaseExtension(file);
    if (extension.empty()) return badInput("no file extension to tell the image type");
    extension.erase(0, 1);  // OpenImageIO looks formats up by the extension without its dot
    auto input = OIIO::ImageInput::create(extension);
    if (!input)
        return badInput("unsupported image type '." + extension + "' (not one OpenImageIO reads)");
    BoundedMemoryReader memory(bytes.data(), bytes.size());
    if (input->supports("ioproxy") && !input->set_ioproxy(&memory))
        return badInput("cannot decode from memory: " + oneLine(input->geterror()));
    // Straight alpha as stored; without this hint OpenImageIO would premultiply on read.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    OIIO::ImageSpec spec;
    if (!input->open(file.string(), spec, config))
        return badInput("not a readable " + displayFormat(input->format_name()) +
                        " image: " + oneLine(input->geterror()));
    if (spec.width <= 0 || spec.height <= 0) return badInput("empty image");
    // A volume (a TIFF or DDS with depth) holds several images; we read one.
    if (spec.depth != 1) return badInput("volume images are not supported");
    if (auto fits = checkSize(spec.width, spec.height, spec.nchannels); !fits) return fits.error();

    Result<DecodedImage> decoded = internalError("no sample type chosen");
    switch (spec.format.basetype) {
        case OIIO::TypeDesc::UINT8:
            decoded = readSamples<std::uint8_t>(*input, spec, OIIO::TypeDesc::UINT8);
            break;
        case OIIO::TypeDesc::HALF:
        case OIIO::TypeDesc::FLOAT:
        case OIIO::TypeDesc::DOUBLE:
            decoded = readSamples<float>(*input, spec, OIIO::TypeDesc::FLOAT);
            break;
        default:
            decoded = readSamples<std::uint16_t>(*input, spec, OIIO::TypeDesc::UINT16);
            break;
    }
    input->close();
    return decoded;
}

Result<std::string> encodeExr(const float* rgba, int width, int height) {
    auto output = OIIO::ImageOutput::create("openexr");
    if (!output) return badInput("cannot encode: " + oneLine(OIIO::geterror()));
    OIIO::ImageSpec spec(width, height, 4, OIIO::TypeDesc::FLOAT);
    spec.alpha_channel = 3;
    std::vector<unsigned char> encoded;
    OIIO::Filesystem::IOVecOutput memory(encoded);
    output->set_ioproxy(&memory);
    bool written = output->open("image.exr", spec);
    if (written) {
        written = output->write_image(OIIO::TypeDesc::FLOAT, rgba);
        written = output->close() && written;
    }
    if (!written) return badInput("cannot encode: " + oneLine(output->geterror()));
    return std::string(reinterpret_cast<const char*>(encoded.data()), encoded.size());
}

}  // namespace
}  // namespace matevo

extern "C" __attribute__((visibility("default"))) const matevo::ImageLibraryFunctions*
matevoImageLibrary() {
    static const matevo::ImageLibraryFunctions functions{matevo::kImageLibraryAbiVersion,
                                                         matevo::decode, matevo::encodeExr};
    return &functions;
}
