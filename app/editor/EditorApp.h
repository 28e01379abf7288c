#pragma once
// The editor window: GLFW + Vulkan swapchain + Dear ImGui, the GA worker and the image bridge,
// owned by one object and torn down in reverse order. Frame order follows ImGui's GLFW/Vulkan
// example: poll events → apply results → NewFrame → panels → Render → draw → present.
#include <filesystem>
#include <vector>

#include "EditorScript.h"
#include "ExportWorker.h"
#include "documents/Preset.h"
#include "render/PopulationRenderer.h"

namespace matevo::editor {

struct EditorOptions {
    Preset preset;
    std::filesystem::path presetFile;
    std::vector<ScriptAction> script;
    int maxFrames = 0;  // 0: until the window closes
    // Where candidate tiles and Compare metrics render (the CPU when no device is usable).
    RenderBackend backend = RenderBackend::Gpu;
    bool validation = false;
    bool reportTimings = false;
    int width = 1280;
    int height = 800;
    // Refuses an export past the memory limit (--max-memory), by `matevo export`'s estimate.
    ExportMemoryCheck checkExportMemory;
};

// Exit status: 0 normal close, 2 no display (the message names the headless commands),
// 1 Vulkan failure, validation messages (with validation on) or a failed script action.
int runEditor(const EditorOptions& options);

}  // namespace matevo::editor
