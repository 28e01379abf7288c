#pragma once
// The test sphere's shading points (core/scene/SphereSamples.h) on the GPU, as
// shaders/SphereRender.comp reads them: one texel per covered pixel (pixel index, first point,
// point count, coverage) and three vec4 per point (normal, direction to the viewer, texture UV
// and environment UV of the mirror direction). They depend on the camera and the image size
// only, so they are traced and uploaded once and shaded for every material of every batch:
// the shader does no ray tracing and no inverse trigonometry.
#include <array>
#include <optional>

#include "common/Result.h"
#include "gpu/Buffer.h"
#include "gpu/Device.h"
#include "scene/SceneSettings.h"

namespace matevo::gpu {

class GpuSphereSamples {
public:
    // What the points depend on; two scenes with equal keys cover the same pixels.
    struct Key {
        std::array<double, 3> cameraPosition;
        double fieldOfViewDegrees;
        int size;
        bool operator==(const Key&) const = default;
    };
    static Key keyOf(const SceneSettings& scene, int size) {
        return {scene.cameraPosition, scene.fieldOfViewDegrees, size};
    }

    // Traces and uploads the points unless those of this camera and size are already there;
    // the caller must not prepare while a submission reads them.
    Status prepare(const Device& device, const SceneSettings& scene, int size);

    // RGBA32UI and RGBA32F texels (uniform texel buffers: llvmpipe gathers them for all SIMD
    // lanes at once).
    VkBufferView pixels() const { return pixels_.view.get(); }
    VkBufferView points() const { return points_.view.get(); }
    uint32_t coveredPixels() const { return coveredPixels_; }
    // The first ones, shaded at one point each; the silhouette's pixels follow.
    uint32_t singlePointPixels() const { return singlePointPixels_; }

private:
    std::optional<Key> key_;
    TexelBuffer pixels_;
    TexelBuffer points_;
    uint32_t coveredPixels_ = 0;
    uint32_t singlePointPixels_ = 0;
};

}  // namespace matevo::gpu
