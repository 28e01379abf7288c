#include "SceneRequestPlanner.h"

#include <algorithm>
#include <cmath>

namespace matevo::editor {
namespace {

bool sameCamera(const ui::SceneViewControls& a, const ui::SceneViewControls& b) {
    return a.yawDegrees == b.yawDegrees && a.pitchDegrees == b.pitchDegrees && a.zoom == b.zoom;
}

}  // namespace

std::optional<SceneViewJob> SceneRequestPlanner::next(SceneViewJob wanted, bool cameraHeld) {
    const bool moving =
        cameraHeld || (requested_ && !sameCamera(requested_->controls, wanted.controls));
    wanted.previewDivisor = moving ? previewDivisor_ : 1;
    if (requested_ == wanted) return std::nullopt;
    requested_ = wanted;
    return wanted;
}

void SceneRequestPlanner::wholePictureTook(double milliseconds, long long pixels) {
    if (pixels <= 0 || milliseconds <= 0.0) return;
    // The time per frame scales with the pixels about linearly (the triangles' share is
    // small at a window's size): divide each side by the square root of the excess.
    const double excess = milliseconds / kPreviewBudgetMs;
    previewDivisor_ = std::clamp(int(std::ceil(std::sqrt(excess))), 2, kMaxPreviewDivisor);
}

}  // namespace matevo::editor
