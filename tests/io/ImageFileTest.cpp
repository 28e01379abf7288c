#include "image/ImageFile.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "color/Srgb.h"
#include "common/MemoryBudget.h"
#include "support/ScratchFolder.h"
#include "support/TestImages.h"

namespace matevo {
namespace {

class ImageFileTest : public ::testing::Test {
protected:
    std::size_t filesInFolder() const {
        std::size_t count = 0;
        for ([[maybe_unused]] const auto& entry :
             std::filesystem::directory_iterator(scratch_.path()))
            ++count;
        return count;
    }

    testing::ScratchFolder scratch_{"matevo_imagefile"};
    const std::filesystem::path& folder_ = scratch_.path();
};

std::string fileBytes(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// An input the fuzzer found, kept in its corpus: byte 0 chose the image type, the rest is the file.
std::string fuzzFinding(const std::string& name) {
    return fileBytes(std::string(MATEVO_SOURCE_DIR) + "/tests/fuzz/corpus/image/" + name);
}

Image randomImage(int width, int height, std::uint32_t seed) {
    return testdata::randomImage(width, height, seed, true);
}

TEST_F(ImageFileTest, ExrRoundTripIsExact) {
    Image original = randomImage(17, 9, 1);
    original.rgba[0] = 3.5f;  // EXR keeps values beyond 1 (linear light)
    const auto file = folder_ / "a.exr";
    ASSERT_TRUE(writeImage(original, file).ok());
    auto read = readImageFile(file);
    ASSERT_TRUE(read.ok()) << read.error().message;
    EXPECT_TRUE(read->hasAlpha);
    EXPECT_EQ(read->image.width, 17);
    EXPECT_EQ(read->image.height, 9);
    EXPECT_EQ(read->image.rgba, original.rgba);
}

TEST_F(ImageFileTest, PngStoresSrgbEncodedEightBitsAndDecodesToLinear) {
    Image original = randomImage(31, 7, 2);
    const auto file = folder_ / "a.png";
    ASSERT_TRUE(writeImage(original, file).ok());
    auto read = readImageFile(file);
    ASSERT_TRUE(read.ok()) << read.error().message;
    EXPECT_TRUE(read->hasAlpha);
    ASSERT_EQ(read->image.rgba.size(), original.rgba.size());
    for (std::size_t i = 0; i < original.rgba.size(); ++i) {
        const bool alpha = i % 4 == 3;
        const double expected = alpha ? original.rgba[i] : linearToSrgb(original.rgba[i]);
        const double got = alpha ? read->image.rgba[i] : linearToSrgb(read->image.rgba[i]);
        // Quantised to 8 bits in the encoded domain, independently of alpha (straight alpha).
        ASSERT_NEAR(got, expected, 0.5 / 255.0 + 1e-6) << "value " << i;
    }
    // The raw bytes are the sRGB encoding of straight colour, not linear or premultiplied.
    OIIO::ImageSpec keepStraightAlpha;
    keepStraightAlpha.attribute("oiio:UnassociatedAlpha", 1);
    auto input = OIIO::ImageInput::open(file.string(), &keepStraightAlpha);
    ASSERT_TRUE(input);
    std::vector<unsigned char> bytes(original.rgba.size());
    ASSERT_TRUE(input->read_image(0, 0, 0, 4, OIIO::TypeDesc::UINT8, bytes.data()));
    EXPECT_EQ(bytes[0], std::lround(linearToSrgb(original.rgba[0]) * 255.0));
}

TEST_F(ImageFileTest, PngWithoutAlphaReadsAsFullyCovered) {
    const auto file = folder_ / "rgb.png";
    const unsigned char bytes[] = {255, 128, 0, 10, 20, 30};
    auto output = OIIO::ImageOutput::create(file.string());
    ASSERT_TRUE(output);
    ASSERT_TRUE(output->open(file.string(), OIIO::ImageSpec(2, 1, 3, OIIO::TypeDesc::UINT8)));
    ASSERT_TRUE(output->write_image(OIIO::TypeDesc::UINT8, bytes));
    ASSERT_TRUE(output->close());

    auto read = readImageFile(file);
    ASSERT_TRUE(read.ok()) << read.error().message;
    EXPECT_FALSE(read->hasAlpha);
    EXPECT_FLOAT_EQ(read->image.pixel(0, 0)[3], 1.0f);
    EXPECT_FLOAT_EQ(read->image.pixel(1, 0)[3], 1.0f);
    EXPECT_FLOAT_EQ(read->image.pixel(0, 0)[0], 1.0f);
    EXPECT_NEAR(read->image.pixel(0, 0)[1], srgbToLinear(128.0 / 255.0), 1e-6);
    EXPECT_NEAR(read->image.pixel(1, 0)[2], srgbToLinear(30.0 / 255.0), 1e-6);
}

void expectOneLineErrorNaming(const Error& error, const std::filesystem::path& file) {
    EXPECT_NE(error.message.find(file.string()), std::string::npos) << error.message;
    EXPECT_EQ(error.message.find('\n'), std::string::npos) << error.message;
}

// Writes a real file with OpenImageIO, an encoder independent of ours.
template <typename Sample>
void writeWithOpenImageIO(const std::filesystem::path& file, int width, int height, int channels,
                          OIIO::TypeDesc type, const std::vector<Sample>& samples) {
    auto output = OIIO::ImageOutput::create(file.string());
    ASSERT_TRUE(output) << file;
    OIIO::ImageSpec spec(width, height, channels, type);
    spec.attribute("oiio:UnassociatedAlpha", 1);
    ASSERT_TRUE(output->open(file.string(), spec)) << output->geterror();
    ASSERT_TRUE(output->write_image(type, samples.data())) << output->geterror();
    ASSERT_TRUE(output->close());
}

TEST_F(ImageFileTest, ReadsEveryFormatOpenImageIOReadsInAnyExtensionCase) {
    // 8-bit TIFF: sRGB-encoded like PNG, exactly.
    const std::vector<std::uint8_t> rgba8 = {255, 128, 0, 255, 10, 20, 30, 128};
    writeWithOpenImageIO(folder_ / "a.TIF", 2, 1, 4, OIIO::TypeDesc::UINT8, rgba8);
    auto tiff = readImageFile(folder_ / "a.TIF");
    ASSERT_TRUE(tiff.ok()) << tiff.error().message;
    EXPECT_TRUE(tiff->hasAlpha);
    EXPECT_NEAR(tiff->image.pixel(0, 0)[1], srgbToLinear(128.0 / 255.0), 1e-6);
    EXPECT_NEAR(tiff->image.pixel(1, 0)[2], srgbToLinear(30.0 / 255.0), 1e-6);
    EXPECT_NEAR(tiff->image.pixel(1, 0)[3], 128.0 / 255.0, 1e-6);  // alpha is not encoded

    // Float TIFF: linear, kept as it is.
    const std::vector<float> linear = {0.25f, 2.5f, 0.0f, 0.125f, 0.5f, 1.0f};
    writeWithOpenImageIO(folder_ / "b.tiff", 2, 1, 3, OIIO::TypeDesc::FLOAT, linear);
    auto floats = readImageFile(folder_ / "b.tiff");
    ASSERT_TRUE(floats.ok()) << floats.error().message;
    EXPECT_FALSE(floats->hasAlpha);
    EXPECT_EQ(floats->image.pixel(0, 0)[1], 2.5f);
    EXPECT_EQ(floats->image.pixel(1, 0)[0], 0.125f);

    // JPEG (lossy): a flat grey patch comes back within a few code values.
    writeWithOpenImageIO(folder_ / "c.JPG", 8, 8, 3, OIIO::TypeDesc::UINT8,
                         std::vector<std::uint8_t>(8 * 8 * 3, 100));
    auto jpeg = readImageFile(folder_ / "c.JPG");
    ASSERT_TRUE(jpeg.ok()) << jpeg.error().message;
    EXPECT_NEAR(linearToSrgb(jpeg->image.pixel(3, 3)[0]) * 255.0, 100.0, 3.0);

    // 16-bit grey + alpha PNG under an upper-case extension: libpng's path, all 16 bits.
    const std::vector<std::uint16_t> greyAlpha16 = {65535, 65535, 30000, 0};
    writeWithOpenImageIO(folder_ / "d.PNG", 2, 1, 2, OIIO::TypeDesc::UINT16, greyAlpha16);
    auto png16 = readImageFile(folder_ / "d.PNG");
    ASSERT_TRUE(png16.ok()) << png16.error().message;
    EXPECT_TRUE(png16->hasAlpha);
    EXPECT_FLOAT_EQ(png16->image.pixel(0, 0)[0], 1.0f);
    EXPECT_NEAR(png16->image.pixel(1, 0)[2], srgbToLinear(30000.0 / 65535.0), 1e-6);
    EXPECT_EQ(png16->image.pixel(1, 0)[3], 0.0f);
}

// libpng allocates a chunk at the length its header claims; a claim beyond the file's end is
// refused before that (a 340-byte PNG claiming a 1.9 GB chunk once made it allocate 1.9 GB).
TEST_F(ImageFileTest, PngChunkClaimingMoreThanTheFileIsRefusedBeforeDecoding) {
    const auto valid = folder_ / "valid.png";
    ASSERT_TRUE(writeImage(randomImage(3, 2, 7), valid).ok());
    std::ifstream in(valid, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_TRUE(decodeImageFile(bytes, valid).ok());

    // After the signature (8 bytes) and IHDR (25): a text chunk claiming 0x72650000 bytes.
    const std::string claim = std::string("\x72\x65\x00\x00", 4) + "tEXtComment\0only this";
    const std::string forged = bytes.substr(0, 33) + claim + bytes.substr(33);
    auto read = decodeImageFile(forged, folder_ / "forged.png");
    ASSERT_FALSE(read.ok());
    expectOneLineErrorNaming(read.error(), folder_ / "forged.png");
    EXPECT_NE(read.error().message.find("more than the file holds"), std::string::npos)
        << read.error().message;
}

// OpenEXR channels may each have their own type; they are read as stored and converted by us,
// every one to the exact float it holds.
TEST_F(ImageFileTest, OpenExrChannelsOfMixedTypesReadExactly) {
    const auto file = folder_ / "mixed.exr";
    auto output = OIIO::ImageOutput::create(file.string());
    ASSERT_TRUE(output);
    OIIO::ImageSpec spec(2, 1, 4, OIIO::TypeDesc::HALF);
    spec.channelformats = {OIIO::TypeDesc::HALF, OIIO::TypeDesc::FLOAT, OIIO::TypeDesc::HALF,
                           OIIO::TypeDesc::FLOAT};
    spec.alpha_channel = 3;
    spec.attribute("oiio:UnassociatedAlpha", 1);
    ASSERT_TRUE(output->open(file.string(), spec)) << output->geterror();
    // Values a half holds exactly, and floats it would round (1/3, 0.1).
    const std::vector<float> written = {0.5f,   1.0f / 3.0f, 1024.0f, 0.25f,
                                        0.125f, 0.1f,        3.5f,    1.0f};
    ASSERT_TRUE(output->write_image(OIIO::TypeDesc::FLOAT, written.data())) << output->geterror();
    ASSERT_TRUE(output->close());
    {
        auto check = OIIO::ImageInput::open(file.string());
        ASSERT_TRUE(check);
        ASSERT_FALSE(check->spec().channelformats.empty()) << "OpenEXR kept one type";
    }

    auto read = readImageFile(file);
    ASSERT_TRUE(read.ok()) << read.error().message;
    EXPECT_TRUE(read->hasAlpha);
    for (int x = 0; x < 2; ++x)
        for (int c = 0; c < 4; ++c) EXPECT_EQ(read->image.pixel(x, 0)[c], written[x * 4 + c]);
}

// A volume (several images stacked in depth, here a DDS volume texture of 4x4x8 RGBA pixels)
// is refused: OpenImageIO would write every slice into the memory of one image (a heap
// overflow, which once crashed `matevo compare` on this 640-byte file).
TEST_F(ImageFileTest, VolumeImagesAreRefused) {
    const std::uint32_t width = 4, height = 4, depth = 8;
    std::vector<std::uint32_t> header = {
        0x20534444,  // "DDS "
        124,
        0x1 | 0x2 | 0x4 | 0x1000 | 0x800000,  // size; caps, height, width, format, depth
        height,
        width,
        width * 4,
        depth,
        0};
    header.resize(header.size() + 11, 0);  // reserved
    // Pixel format: 32-bit RGB with alpha, by channel masks.
    for (std::uint32_t word : {32u, 0x41u, 0u, 32u, 0xff0000u, 0xff00u, 0xffu, 0xff000000u})
        header.push_back(word);
    for (std::uint32_t word : {0x1008u, 0x200000u, 0u, 0u, 0u})  // texture, complex; volume
        header.push_back(word);
    std::string bytes(reinterpret_cast<const char*>(header.data()), header.size() * 4);
    bytes.append(std::size_t(width * height * depth) * 4, char(100));
    const auto file = folder_ / "volume.dds";
    std::ofstream(file, std::ios::binary) << bytes;

    auto read = readImageFile(file);
    ASSERT_FALSE(read.ok());
    expectOneLineErrorNaming(read.error(), file);
    EXPECT_NE(read.error().message.find("volume"), std::string::npos) << read.error().message;
}

TEST_F(ImageFileTest, UnsupportedExtensionsAreRejected) {
    const auto jpeg = folder_ / "a.jpg";  // read, but never written
    auto written = writeImage(randomImage(2, 2, 3), jpeg);
    ASSERT_FALSE(written.ok());
    expectOneLineErrorNaming(written.error(), jpeg);

    for (const char* name : {"notes.txt", "no_extension"}) {
        const auto file = folder_ / name;
        std::ofstream(file) << "not an image\n";
        auto read = readImage(file);
        ASSERT_FALSE(read.ok());
        expectOneLineErrorNaming(read.error(), file);
    }
}

TEST_F(ImageFileTest, MissingAndNonImageFilesGiveOneLineErrors) {
    const auto missing = folder_ / "missing.png";
    auto read = readImage(missing);
    ASSERT_FALSE(read.ok());
    expectOneLineErrorNaming(read.error(), missing);

    const auto text = folder_ / "text.png";
    std::ofstream(text) << "this is not an image\n";
    read = readImage(text);
    ASSERT_FALSE(read.ok());
    expectOneLineErrorNaming(read.error(), text);

    const auto exrNamedPng = folder_ / "really_exr.png";
    ASSERT_TRUE(writeImage(randomImage(2, 2, 4), folder_ / "b.exr").ok());
    std::filesystem::copy_file(folder_ / "b.exr", exrNamedPng);
    read = readImage(exrNamedPng);
    ASSERT_FALSE(read.ok());
    expectOneLineErrorNaming(read.error(), exrNamedPng);
}

// OpenEXR allocates each header attribute at the size the file claims; a claim beyond the file's
// end is refused before OpenEXR sees it (a 472-byte file once made it allocate 1.8 GB).
TEST_F(ImageFileTest, ExrHeaderClaimingMoreThanTheFileIsRefusedBeforeDecoding) {
    const auto valid = folder_ / "valid.exr";
    ASSERT_TRUE(writeImage(randomImage(3, 2, 6), valid).ok());
    std::string bytes = fileBytes(valid);
    ASSERT_TRUE(decodeImageFile(bytes, valid).ok());

    // The first attribute: its name and type, NUL-terminated, then its size (little-endian).
    std::size_t at = bytes.find('\0', 8) + 1;
    const std::string firstName = bytes.substr(8, at - 9);
    at = bytes.find('\0', at) + 1;
    const std::uint32_t claimed = 0x6e5b0000;  // about 1.8 GB
    for (int i = 0; i < 4; ++i) bytes[at + std::size_t(i)] = char((claimed >> (8 * i)) & 0xff);
    const auto forged = folder_ / "forged.exr";
    auto read = decodeImageFile(bytes, forged);
    ASSERT_FALSE(read.ok());
    expectOneLineErrorNaming(read.error(), forged);
    EXPECT_NE(read.error().message.find("'" + firstName + "' claims 1851457536 bytes"),
              std::string::npos)
        << read.error().message;
}

// OpenEXR reads a channel list up to its empty name, whatever size the file declares, and reads
// the next attribute from there: the check walks it the same way. This file (found by the
// fuzzer) declares 73 bytes for 37 bytes of channels, and what OpenEXR then reads as the next
// attribute claims far more than the file holds.
TEST_F(ImageFileTest, ExrHeaderIsWalkedAsOpenExrReadsIt) {
    const std::string input = fuzzFinding("exr-chlist-declared-size.bin");
    ASSERT_GT(input.size(), 1u);
    const auto file = folder_ / "found.exr";
    auto read = decodeImageFile(std::string_view(input).substr(1), file);  // byte 0: the type
    ASSERT_FALSE(read.ok());
    expectOneLineErrorNaming(read.error(), file);
    EXPECT_NE(read.error().message.find("claims"), std::string::npos) << read.error().message;
}

// OpenEXR allocates one block's buffers when it opens a file, sized by the data window's width
// and the compression's rows per block, whatever the height. This 542-byte file (found by the
// fuzzer) claims a ZIP-compressed data window about a million pixels wide: OpenEXR allocated
// 124 MiB twice for it. Under a limit below that it is refused before OpenEXR sees it.
TEST_F(ImageFileTest, ExrBlocksPastTheMemoryLimitAreRefusedBeforeOpenExrAllocatesThem) {
    const std::string input = fuzzFinding("exr-wide-zip-blocks.bin");
    ASSERT_GT(input.size(), 1u);
    const auto file = folder_ / "wide.exr";
    const auto small = folder_ / "small.exr";
    ASSERT_TRUE(writeImage(randomImage(64, 64, 7), small).ok());

    setMemoryLimitBytes(8u << 20);
    auto read = decodeImageFile(std::string_view(input).substr(1), file);  // byte 0: the type
    auto smallRead = readImage(small);
    setMemoryLimitBytes(0);  // the default again
    ASSERT_FALSE(read.ok());
    expectOneLineErrorNaming(read.error(), file);
    EXPECT_NE(read.error().message.find("its blocks of "), std::string::npos)
        << read.error().message;
    EXPECT_NE(read.error().message.find("x16 pixels needs about"), std::string::npos)
        << read.error().message;  // ZIP: 16 rows a block
    EXPECT_TRUE(smallRead.ok());
}

TEST_F(ImageFileTest, WritesAreAtomicAndLeaveNoTemporaryFiles) {
    const auto file = folder_ / "a.png";
    ASSERT_TRUE(writeImage(randomImage(4, 4, 5), file).ok());
    const Image replacement = randomImage(8, 2, 6);
    ASSERT_TRUE(writeImage(replacement, file).ok());
    EXPECT_EQ(filesInFolder(), 1u);
    auto read = readImage(file);
    ASSERT_TRUE(read.ok());
    EXPECT_EQ(read->width, 8);

    const auto unwritable = folder_ / "no_such_folder" / "a.exr";
    auto failed = writeImage(replacement, unwritable);
    ASSERT_FALSE(failed.ok());
    expectOneLineErrorNaming(failed.error(), unwritable);
    EXPECT_EQ(filesInFolder(), 1u);
}

}  // namespace
}  // namespace matevo
