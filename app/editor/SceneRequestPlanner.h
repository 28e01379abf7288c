#pragma once
// Decides what the Scene window asks its worker (SceneViewWorker) for, frame by frame: nothing
// when the view has not changed since the last request; a preview with fewer pixels while the
// camera moves, so that orbiting and zooming follow the mouse; the whole picture as soon as the
// camera stops (the frame after the last move, or the release of the mouse).
#include <optional>

#include "SceneViewWorker.h"

namespace matevo::editor {

class SceneRequestPlanner {
public:
    // `wanted`: the whole picture of the window as it is now; `cameraHeld`: the mouse button is
    // down on the picture (an orbit under way, even while the mouse rests). The job to request,
    // if any.
    std::optional<SceneViewJob> next(SceneViewJob wanted, bool cameraHeld);

    // A whole picture of `pixels` took `milliseconds` to render: previews are made small enough
    // to take about kPreviewBudgetMs.
    void wholePictureTook(double milliseconds, long long pixels);
    int previewDivisor() const { return previewDivisor_; }

    static constexpr double kPreviewBudgetMs = 60.0;
    static constexpr int kMaxPreviewDivisor = 6;

private:
    std::optional<SceneViewJob> requested_;
    int previewDivisor_ = 2;
};

}  // namespace matevo::editor
