#include "UndoHistory.h"

#include <utility>

namespace matevo::ui {

UndoHistory::UndoHistory(UndoStep initial) { reset(std::move(initial)); }

void UndoHistory::reset(UndoStep initial) {
    steps_.assign(1, std::move(initial));
    position_ = 0;
}

void UndoHistory::record(const Preset& current) {
    if (current == present().preset) return;
    UndoStep step{current, present().file};
    steps_.resize(position_ + 1);
    steps_.push_back(std::move(step));
    if (steps_.size() > kMaxSteps) steps_.erase(steps_.begin());
    position_ = steps_.size() - 1;
}

void UndoHistory::markSaved(UndoStep saved) {
    if (saved.file != present().file) steps_.resize(position_ + 1);
    steps_[position_] = std::move(saved);
}

const UndoStep& UndoHistory::undo() {
    if (canUndo()) --position_;
    return present();
}

const UndoStep& UndoHistory::redo() {
    if (canRedo()) ++position_;
    return present();
}

}  // namespace matevo::ui
