#pragma once
// Undo and redo of parameter edits: a bounded list of preset snapshots. A slider drag is one
// step because the caller records only when no widget is active.
#include <cstddef>
#include <vector>

#include "io/Preset.h"

namespace matevo::ui {

class UndoHistory {
public:
    explicit UndoHistory(Preset initial);

    // Starts over from `initial` (after opening a preset).
    void reset(Preset initial);
    // Appends `current` as a new step when it differs from the present one; drops any redo.
    void record(const Preset& current);
    bool canUndo() const { return position_ > 0; }
    bool canRedo() const { return position_ + 1 < steps_.size(); }
    // Both return the preset to show; unchanged when there is nothing to undo or redo.
    const Preset& undo();
    const Preset& redo();
    const Preset& present() const { return steps_[position_]; }

private:
    static constexpr std::size_t kMaxSteps = 200;
    std::vector<Preset> steps_;
    std::size_t position_ = 0;
};

}  // namespace matevo::ui
