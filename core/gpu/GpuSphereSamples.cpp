#include "gpu/GpuSphereSamples.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <vector>

#include <glm/geometric.hpp>

#include "scene/LatLong.h"
#include "scene/SphereMapping.h"
#include "scene/SphereSamples.h"

namespace matevo::gpu {
namespace {

// shaders/SphereRender.comp's texels: one RGBA32UI per pixel, three RGBA32F per point.
struct GpuPixel {
    uint32_t pixel;  // y * size + x
    uint32_t firstPoint;
    uint32_t pointCount;
    uint32_t coverageBits;  // the float coverage alpha
};

struct GpuPoint {
    float normal[4];
    float toViewer[4];
    float uvs[4];  // texture UV, environment UV
};

Result<TexelBuffer> uploadRecords(const Device& device, const void* records, std::size_t bytes,
                                  VkFormat format) {
    auto buffer = createTexelBuffer(device, std::max<std::size_t>(bytes, 16), format);
    if (!buffer) return buffer.error();
    std::memcpy(buffer->buffer.bytes().data(), records, bytes);
    return buffer;
}

}  // namespace

Status GpuSphereSamples::prepare(const Device& device, const SceneSettings& scene, int size) {
    const Key key = keyOf(scene, size);
    if (key_ == key) return Ok{};
    const SphereSamples samples = traceSphereSamples(scene, size);
    std::vector<GpuPixel> pixels;
    pixels.reserve(samples.pixels.size());
    for (const SpherePixel& pixel : samples.pixels)
        pixels.push_back({uint32_t(pixel.y * size + pixel.x), uint32_t(pixel.firstSample),
                          uint32_t(pixel.sampleCount),
                          std::bit_cast<uint32_t>(float(pixel.hits) / kSubsamplesPerPixel)});
    std::vector<GpuPoint> points;
    points.reserve(samples.samples.size());
    for (const SphereSurfacePoint& point : samples.samples) {
        const auto textureUv = sphereUv(point.normal);
        const glm::dvec3 mirror =
            2.0 * glm::dot(point.normal, point.toViewer) * point.normal - point.toViewer;
        const glm::dvec2 environmentUv = latLongUv(mirror);
        const glm::dvec3& n = point.normal;
        const glm::dvec3& v = point.toViewer;
        points.push_back({{float(n.x), float(n.y), float(n.z), 0.0f},
                          {float(v.x), float(v.y), float(v.z), 0.0f},
                          {float(textureUv[0]), float(textureUv[1]), float(environmentUv.x),
                           float(environmentUv.y)}});
    }
    auto pixelBuffer = uploadRecords(device, pixels.data(), pixels.size() * sizeof(GpuPixel),
                                     VK_FORMAT_R32G32B32A32_UINT);
    if (!pixelBuffer) return pixelBuffer.error();
    auto pointBuffer = uploadRecords(device, points.data(), points.size() * sizeof(GpuPoint),
                                     VK_FORMAT_R32G32B32A32_SFLOAT);
    if (!pointBuffer) return pointBuffer.error();
    pixels_ = std::move(pixelBuffer).value();
    points_ = std::move(pointBuffer).value();
    coveredPixels_ = uint32_t(pixels.size());
    singlePointPixels_ =
        uint32_t(std::count_if(samples.pixels.begin(), samples.pixels.end(),
                               [](const SpherePixel& pixel) { return pixel.sampleCount == 1; }));
    key_ = key;
    return Ok{};
}

}  // namespace matevo::gpu
