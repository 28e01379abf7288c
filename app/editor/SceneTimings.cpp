#include "SceneTimings.h"

#include <algorithm>
#include <cstdio>

namespace matevo::editor {
namespace {

double milliseconds(SceneTimings::Clock::duration span) {
    return std::chrono::duration<double, std::milli>(span).count();
}

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    const auto middle = values.begin() + std::ptrdiff_t(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
}

}  // namespace

void SceneTimings::windowOpened(Clock::time_point when) {
    openedAt_ = when;
    awaitingFirst_ = true;
}

void SceneTimings::cameraGrabbed() {
    orbitPictures_.clear();
    awaitingRefined_ = false;
}

void SceneTimings::cameraReleased(Clock::time_point when) {
    if (orbitPictures_.size() >= 2)
        orbitFps_.push_back(double(orbitPictures_.size() - 1) * 1000.0 /
                            milliseconds(orbitPictures_.back() - orbitPictures_.front()));
    orbitPictures_.clear();
    releasedAt_ = when;
    awaitingRefined_ = true;
}

void SceneTimings::pictureShown(bool preview, bool cameraHeld, Clock::time_point when,
                                double renderMs) {
    (preview ? previewRenderMs_ : wholeRenderMs_).push_back(renderMs);
    if (awaitingFirst_) firstPictureMs_.push_back(milliseconds(when - openedAt_));
    awaitingFirst_ = false;
    if (cameraHeld) orbitPictures_.push_back(when);
    if (!preview && !cameraHeld && awaitingRefined_) {
        releaseToRefinedMs_.push_back(milliseconds(when - releasedAt_));
        awaitingRefined_ = false;
    }
}

std::string SceneTimings::report() const {
    char text[480];
    std::snprintf(text, sizeof text,
                  "{\"first_picture_ms\":%.1f,\"openings\":%zu,"
                  "\"release_to_refined_ms\":%.1f,\"releases\":%zu,"
                  "\"orbit_fps\":%.1f,\"orbits\":%zu,"
                  "\"preview_render_ms\":%.1f,\"previews\":%zu,"
                  "\"whole_render_ms\":%.1f,\"wholes\":%zu}",
                  median(firstPictureMs_), firstPictureMs_.size(), median(releaseToRefinedMs_),
                  releaseToRefinedMs_.size(), median(orbitFps_), orbitFps_.size(),
                  median(previewRenderMs_), previewRenderMs_.size(), median(wholeRenderMs_),
                  wholeRenderMs_.size());
    return text;
}

}  // namespace matevo::editor
