#include "EditorState.h"

namespace matevo::ui {

std::string windowTitle(const EditorState& state) {
    std::string title = "matevo — ";
    title += state.presetPath.empty() ? state.preset.name + " (unsaved preset)"
                                      : state.presetPath.filename().string();
    if (state.hasUnsavedChanges()) title += " *";
    return title;
}

const CandidateView* EditorState::inspectedCandidate() const {
    const auto& candidates = evolution.candidates;
    if (candidates.empty()) return nullptr;
    if (selected)
        for (const auto* views : {&candidates, &evolution.kept})
            for (const CandidateView& candidate : *views)
                if (candidate.genome == *selected) return &candidate;
    return selected ? nullptr : &candidates.front();
}

}  // namespace matevo::ui
