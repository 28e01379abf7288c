#include "UndoHistory.h"

#include <utility>

namespace matevo::ui {

UndoHistory::UndoHistory(Preset initial) { reset(std::move(initial)); }

void UndoHistory::reset(Preset initial) {
    steps_.assign(1, std::move(initial));
    position_ = 0;
}

void UndoHistory::record(const Preset& current) {
    if (current == present()) return;
    steps_.resize(position_ + 1);
    steps_.push_back(current);
    if (steps_.size() > kMaxSteps) steps_.erase(steps_.begin());
    position_ = steps_.size() - 1;
}

const Preset& UndoHistory::undo() {
    if (canUndo()) --position_;
    return present();
}

const Preset& UndoHistory::redo() {
    if (canRedo()) ++position_;
    return present();
}

}  // namespace matevo::ui
