#pragma once
// Undo and redo of document edits: a bounded list of snapshots, each the preset and the file it
// belongs to. A slider drag is one step because the caller records only when no widget is
// active. Saving under a new name re-labels the present step only, so undoing past a "Save as"
// returns to the earlier file too, and a later Ctrl+S cannot write old contents into the new one.
#include <cstddef>
#include <filesystem>
#include <vector>

#include "documents/Preset.h"

namespace matevo::ui {

struct UndoStep {
    Preset preset;
    std::filesystem::path file;  // empty: not saved yet

    bool operator==(const UndoStep&) const = default;
};

class UndoHistory {
public:
    explicit UndoHistory(UndoStep initial);

    // Starts over from `initial` (after opening a preset).
    void reset(UndoStep initial);
    // Appends `current` (in the present file) as a new step when it differs from the present
    // one; drops any redo.
    void record(const Preset& current);
    // The present step was saved, maybe under a new name and with adjusted contents: it becomes
    // `saved` in place. A new file drops the redo steps, which belong to the old one.
    void markSaved(UndoStep saved);
    bool canUndo() const { return position_ > 0; }
    bool canRedo() const { return position_ + 1 < steps_.size(); }
    // Both return the step to show; unchanged when there is nothing to undo or redo.
    const UndoStep& undo();
    const UndoStep& redo();
    const UndoStep& present() const { return steps_[position_]; }

private:
    static constexpr std::size_t kMaxSteps = 200;
    std::vector<UndoStep> steps_;
    std::size_t position_ = 0;
};

}  // namespace matevo::ui
