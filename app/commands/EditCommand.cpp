#include <cstdio>

#include "ChoiceHelp.h"
#include "PresetOption.h"
#include "RenderBackend.h"
#include "WorkEstimate.h"
#include "commands/Commands.h"
#include "common/MemoryBudget.h"
#include "editor/EditorApp.h"
#include "files/TextFile.h"

namespace matevo::cli {
namespace {

constexpr const char* kHelp =
    "usage: matevo [edit] [PRESET] [--script FILE] [--frames N] [--size WxH]\n"
    "                     [--backend {backends}] [--validate] [--report-timings]\n\n"
    "Opens the editor on PRESET, a file or a name from matevo presets (default:\n"
    "validation_metal): the target sphere, a live grid of GA candidates with a CIEDE2000\n"
    "heatmap, the GA controls and per-generation fitness. Needs a display; without one it says\n"
    "so and exits 2 (use evolve, render, compare or experiment instead).\n\n"
    "keys: Ctrl+O open, Ctrl+S save, Ctrl+Shift+S save as, Ctrl+Z undo, Ctrl+Y or\n"
    "      Ctrl+Shift+Z redo, F12 PNG snapshot of the window (matevo-snapshot-NNN.png),\n"
    "      Ctrl+Q quit; dropping a preset on the window opens it. Anything that would\n"
    "      discard unsaved changes asks first.\n\n"
    "Shipped presets are read-only: Save as starts in $XDG_DATA_HOME/matevo/presets\n"
    "(default ~/.local/share/matevo/presets) and creates missing folders.\n\n"
    "options:\n"
    "  --script FILE      play scripted actions, one per line: wait N, wait-evolution,\n"
    "                     idle MS, population N, generations N, seed N, metric NAME,\n"
    "                     heatmap on|off|toggle|{image-metrics}, select I, scene open|close,\n"
    "                     wait-scene, undo, redo, resize W H, check-layout,\n"
    "                     screenshot PATH, redraw, save PATH, variants-hue on|off,\n"
    "                     variants N, wait-variants, discard-variant I, refill-variants,\n"
    "                     variants-inspect I, save-variants PATH, export-set PATH, quit\n"
    "  --frames N         quit after N frames\n"
    "  --size WxH         initial window size (default 1280x800)\n"
    "  --backend {backends}  where candidate tiles and Compare metrics render (default gpu;\n"
    "                     the CPU reference renderer when no Vulkan device is usable)\n"
    "  --validate         enable VK_LAYER_KHRONOS_validation; any message makes the exit\n"
    "                     status 1\n"
    "  --report-timings   print median frame times (idle, while evolving) and the time from\n"
    "                     a change to the updated grid, as one JSON line on exit\n\n"
    "imgui.ini is kept in $XDG_CONFIG_HOME/matevo (default ~/.config/matevo).\n";

std::string readScript(const std::string& file) {
    auto text = readTextFile(file);
    if (!text) throw CommandFailure(withContext(text.error(), "--script"));
    return std::move(text).value();
}

}  // namespace

int runEdit(CommandLine& args) {
    if (args.wantsHelp()) {
        std::fputs(withChoiceNames(kHelp).c_str(), stdout);
        return 0;
    }
    editor::EditorOptions options;
    if (auto file = args.option("--script")) {
        auto script = editor::parseEditorScript(readScript(*file), *file);
        if (!script) throw CommandFailure(withContext(script.error(), "--script"));
        options.script = std::move(*script);
    }
    if (auto frames = args.integerOption("--frames", 1, 100000000))
        options.maxFrames = int(*frames);
    if (auto size = args.option("--size")) {
        const ImageSize window = parseImageSize(*size, "--size", {320, 240}, 16384);
        options.width = window.width;
        options.height = window.height;
    }
    if (auto backend = args.option("--backend"))
        options.backend = parseRenderBackend(*backend, "--backend");
    options.validation = args.flag("--validate");
    // Export set is refused past --max-memory as `matevo export` is, by the same estimate.
    options.checkExportMemory = [](const ui::ExportRequest& request,
                                   const ExportSettings& settings) -> Status {
        const WorkEstimate estimate = exportSetEstimate(request.materials, settings, {});
        return checkMemoryEstimate(estimate.bytes, "Export set of " + estimate.what);
    };
    options.reportTimings = args.flag("--report-timings");
    const auto positionals = args.positionals();
    if (positionals.size() > 1) throw UsageError("expected at most one PRESET");
    args.finish();

    PresetChoice choice = positionals.empty() ? loadDefaultPreset()
                                              : loadPresetFile(resolvePreset(positionals.front()));
    options.preset = std::move(choice.preset);
    options.presetFile = std::move(choice.file);
    return editor::runEditor(options);
}

}  // namespace matevo::cli
