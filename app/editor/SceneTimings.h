#pragma once
// The Scene window's part of `--report-timings`: from opening the window to its first picture,
// from releasing the mouse after an orbit to the whole (refined) picture, and the pictures per
// second shown while an orbit is under way. A picture counts when the app takes it to draw, in
// the frame that then shows it. Also the worker's time to render each kind of picture (preview
// or whole), which says whether the renderer or the rest bounds the rate.
#include <chrono>
#include <string>
#include <vector>

namespace matevo::editor {

class SceneTimings {
public:
    using Clock = std::chrono::steady_clock;

    void windowOpened(Clock::time_point when);
    void cameraGrabbed();
    void cameraReleased(Clock::time_point when);
    // `preview`: at a reduced resolution; `cameraHeld`: while the mouse button is down on it;
    // `renderMs`: the worker's time to record and render it.
    void pictureShown(bool preview, bool cameraHeld, Clock::time_point when, double renderMs);
    // A JSON object with medians and sample counts.
    std::string report() const;

private:
    std::vector<double> firstPictureMs_;
    std::vector<double> releaseToRefinedMs_;
    std::vector<double> orbitFps_;  // one per orbit with two pictures or more
    std::vector<double> previewRenderMs_;
    std::vector<double> wholeRenderMs_;
    std::vector<Clock::time_point> orbitPictures_;
    Clock::time_point openedAt_;
    Clock::time_point releasedAt_;
    bool awaitingFirst_ = false;
    bool awaitingRefined_ = false;
};

}  // namespace matevo::editor
