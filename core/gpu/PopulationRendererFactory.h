#pragma once
// The one place that chooses between the GPU and the CPU renderer. Asked for the GPU, it renders
// on the given device, or on a headless device of its own; when that is not possible it prints
// the one-line fallback notice on stderr and hands back the CPU reference renderer, which draws
// the same pictures (to within the cross-check of tests/gpu), unless the request forbids the
// fallback (the commands' --no-fallback: a farm that wants the GPU or nothing).
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <utility>

#include "common/CancelToken.h"
#include "documents/Preset.h"
#include "gpu/GpuContext.h"
#include "render/PopulationRenderer.h"

namespace matevo::gpu {

struct RendererRequest {
    // `who` prefixes the fallback notice, e.g. "matevo render".
    RendererRequest(RenderBackend chosen = RenderBackend::Gpu, std::string noticePrefix = {})
        : backend(chosen), who(std::move(noticePrefix)) {}

    RenderBackend backend;
    std::string who;
    // The GPU renderer works on this device (e.g. the editor window's), which must outlive it;
    // null: on a headless device of its own, created with `headless`.
    const Device* device = nullptr;
    GpuContextOptions headless;
    // Either renderer stops at its next image (CPU) or submission (GPU) once this is
    // cancelled, its call ending with cancelledError().
    CancelToken cancel;
    // No CPU renderer in place of an unusable GPU: tryCreatePopulationRenderer fails instead.
    bool noFallback = false;
};

// The renderer asked for; an Error only with `noFallback`, saying why the GPU is not usable.
Result<std::unique_ptr<PopulationRenderer>> tryCreatePopulationRenderer(
    const RendererRequest& request, const SceneTextures& textures);
// The same, always falling back (`noFallback` is not looked at).
std::unique_ptr<PopulationRenderer> createPopulationRenderer(const RendererRequest& request,
                                                             const SceneTextures& textures);

// The renderer for `preset`, read from `presetFile`: its textures loaded (loadSceneTextures),
// then the renderer `request` asks for. An Error when a texture cannot be read (bad input,
// naming the file and field) or, with `noFallback`, when the GPU is not usable (environment).
Result<std::unique_ptr<PopulationRenderer>> createPresetRenderer(
    const RendererRequest& request, const Preset& preset, const std::filesystem::path& presetFile);

}  // namespace matevo::gpu
