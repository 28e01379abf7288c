// The OpenImageIO module: every image format OpenImageIO reads, and OpenEXR writing. Built as a
// shared module that ImageLibrary opens on first use, so that commands which only touch PNG
// never map OpenImageIO and its dependencies.
#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

#include "io/ImageLibraryAbi.h"
#include "io/ImageType.h"

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

// The sample type DecodedImage keeps for a file's own type: 8 and 16 bits as they are, wider
// or signed integers as 16 bits, every floating-point type as float.
template <typename Sample>
Result<DecodedImage> readSamples(OIIO::ImageInput& input, const OIIO::ImageSpec& spec,
                                 OIIO::TypeDesc type) {
    std::vector<Sample> samples(std::size_t(spec.width) * std::size_t(spec.height) *
                                std::size_t(spec.nchannels));
    if (!input.read_image(0, 0, 0, spec.nchannels, type, samples.data()))
        return Error{"cannot decode: " + oneLine(input.geterror())};
    return DecodedImage{spec.width, spec.height, spec.nchannels, std::move(samples)};
}

Result<DecodedImage> decode(std::string_view bytes, const std::filesystem::path& file,
                            const DecodedSizeCheck& checkSize) {
    std::string extension = lowerCaseExtension(file);
    if (extension.empty()) return Error{"no file extension to tell the image type"};
    extension.erase(0, 1);  // OpenImageIO looks formats up by the extension without its dot
    auto input = OIIO::ImageInput::create(extension);
    if (!input)
        return Error{"unsupported image type '." + extension + "' (not one OpenImageIO reads)"};
    OIIO::Filesystem::IOMemReader memory(bytes.data(), bytes.size());
    if (input->supports("ioproxy") && !input->set_ioproxy(&memory))
        return Error{"cannot decode from memory: " + oneLine(input->geterror())};
    // Straight alpha as stored; without this hint OpenImageIO would premultiply on read.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    OIIO::ImageSpec spec;
    if (!input->open(file.string(), spec, config))
        return Error{"not a readable " + displayFormat(input->format_name()) +
                     " image: " + oneLine(input->geterror())};
    if (spec.width <= 0 || spec.height <= 0) return Error{"empty image"};
    if (auto fits = checkSize(spec.width, spec.height, spec.nchannels); !fits)
        return fits.error();

    Result<DecodedImage> decoded = Error{""};
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
    if (!output) return Error{"cannot encode: " + oneLine(OIIO::geterror())};
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
    if (!written) return Error{"cannot encode: " + oneLine(output->geterror())};
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
