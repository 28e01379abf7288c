#pragma once
// Scripted editor sessions for tests and demos (`matevo edit --script FILE`): one action per
// line, '#' starts a comment.
//
//   wait N                  draw N frames
//   wait-evolution          draw until the GA run is finished and shown (gives up after 120 s)
//   idle MS                 do nothing for MS milliseconds: frames are drawn only if something
//                           asks for one (an idle editor draws none)
//   population N | generations N | seed N
//   metric NAME             a genotype distance by name (kDistanceMetrics)
//   heatmap on|off|toggle  the overlay; or heatmap METRIC (kImageMetrics' names): on, showing
//                           that metric
//   select I                inspect candidate I (0 = best)
//   scene open|close        the Scene window
//   lighting L              the lighting every view uses (the preset's scene): paper, ambient,
//                           studio or an .hdr/.exr FILE
//   variants-hold L1,L2     the lightings the variant set must hold under besides the chosen
//                           one ("hold under several lightings"); "none" clears them
//   scene-show variants|kept|population   what the Scene window's instances wear
//   scene-mesh FILE|sphere|shaderball|knot the Scene window's mesh (.obj, .gltf, .glb file)
//   wait-scene              draw until the Scene window shows the whole picture of its current
//                           settings (gives up after 120 s; a mesh that fails to load fails)
//   scene-orbit N           drag the Scene window's camera as a mouse would: N moves (each
//                           turns it 4 degrees), one every 20 ms, the button held, then released
//   undo | redo
//   resize W H              resize the window (pixels; clamped to the screen)
//   check-layout            fail (exit 1) if a panel cuts off a control at its right edge
//   screenshot PATH         PNG of the window, as F12
//   redraw                  draw the whole window again, as after it was uncovered (frames
//                           otherwise redraw only the windows that changed)
//   save PATH               save the preset
//   variants-hue on|off     the Variants window's "Hue variety" (evolve the metal's kappa too)
//   variants-from-kept on|off  "Start from the kept bin" (off by default)
//   variants-deliver on|off  "Hold as delivered (glTF)" (off by default; not with variants-hold)
//   variants N              open the Variants window and find N variants (its band and spacing)
//   wait-variants           draw until the variant search is finished and shown (120 s at most)
//   discard-variant I       drop variant I from the set
//   variants-inspect I      show variant I beside the target in the Inspect panel, as a click on
//                           its tile does (wait-variants then waits for its renders)
//   refill-variants         keep the set and find the missing variants
//   save-variants PATH      save the set into the folder PATH, as `matevo variants --out`
//   variants-keep all|I     put the whole set (or variant I) into the kept bin
//   export-set PATH         export the set shown in the Variants window (glTF, GLB or MaterialX
//                           from the extension of PATH) and wait for the export to end
//   save-document PATH      save the document (the preset with its kept bin and variant set)
//   open PATH               open a document (asks first if there are unsaved changes)
//   quit
#include <optional>
#include <string>
#include <vector>

#include "common/Result.h"

namespace matevo::editor {

struct ScriptAction {
    enum class Kind {
        Wait,
        WaitEvolution,
        Idle,
        Population,
        Generations,
        Seed,
        Metric,
        Heatmap,
        Select,
        Scene,
        Lighting,
        VariantsHold,
        WaitScene,
        SceneShow,
        SceneMesh,
        SceneOrbit,
        Undo,
        Redo,
        Resize,
        CheckLayout,
        Screenshot,
        Redraw,
        Save,
        VariantsHue,
        VariantsFromKept,
        VariantsDeliver,
        Variants,
        WaitVariants,
        DiscardVariant,
        InspectVariant,
        RefillVariants,
        SaveVariants,
        KeepVariants,
        ExportSet,
        Open,
        Quit
    };
    Kind kind = Kind::Wait;
    long long first = 0;   // the first number argument
    long long second = 0;  // resize height
    std::string text;      // path, metric name or heatmap mode
    int line = 0;
};

// The variant index of a script word ("3"), if it is one in [0, 47].
std::optional<std::size_t> variantIndexOf(const std::string& word);

// Errors name the source and line: "demo.txt:3: population: expected an integer, got 'x'".
Result<std::vector<ScriptAction>> parseEditorScript(const std::string& text,
                                                    const std::string& sourceName);

}  // namespace matevo::editor
