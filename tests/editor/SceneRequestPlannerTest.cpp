// What the Scene window asks its worker for: previews while the camera moves, the whole
// picture once it stops, nothing when nothing changed; and the timings it reports.
#include "SceneRequestPlanner.h"

#include <gtest/gtest.h>

#include "SceneTimings.h"

namespace matevo::editor {
namespace {

SceneViewJob view(float yaw, float zoom = 1.0f, int instances = 24) {
    SceneViewJob job;
    job.controls.yawDegrees = yaw;
    job.controls.zoom = zoom;
    job.controls.instances = instances;
    job.controls.width = 1280;
    job.controls.height = 720;
    return job;
}

TEST(SceneRequestPlanner, PreviewsWhileTheCameraMovesAndTheWholePictureWhenItStops) {
    SceneRequestPlanner planner;
    auto first = planner.next(view(0), false);
    ASSERT_TRUE(first.has_value());
    EXPECT_EQ(first->previewDivisor, 1) << "a first picture is whole";
    EXPECT_FALSE(planner.next(view(0), false).has_value()) << "nothing changed";

    // An orbit: the button goes down, the mouse moves, rests, moves, is released.
    auto pressed = planner.next(view(0), true);
    ASSERT_TRUE(pressed.has_value());
    EXPECT_GT(pressed->previewDivisor, 1);
    auto moved = planner.next(view(5), true);
    ASSERT_TRUE(moved.has_value());
    EXPECT_GT(moved->previewDivisor, 1);
    EXPECT_FALSE(planner.next(view(5), true).has_value()) << "resting: that preview stays";
    auto released = planner.next(view(5), false);
    ASSERT_TRUE(released.has_value());
    EXPECT_EQ(released->previewDivisor, 1) << "refined once released";
    EXPECT_EQ(released->controls.yawDegrees, 5.0f);

    // A wheel step: one preview, then the whole picture in the next frame.
    auto zoomed = planner.next(view(5, 0.9f), false);
    ASSERT_TRUE(zoomed.has_value());
    EXPECT_GT(zoomed->previewDivisor, 1);
    auto settled = planner.next(view(5, 0.9f), false);
    ASSERT_TRUE(settled.has_value());
    EXPECT_EQ(settled->previewDivisor, 1);

    // Other controls are not camera moves: the whole picture at once.
    auto more = planner.next(view(5, 0.9f, 40), false);
    ASSERT_TRUE(more.has_value());
    EXPECT_EQ(more->previewDivisor, 1);
}

TEST(SceneRequestPlanner, PreviewsShrinkWithTheTimeAWholePictureTakes) {
    SceneRequestPlanner planner;
    planner.wholePictureTook(40.0, 1280 * 720);
    EXPECT_EQ(planner.previewDivisor(), 2) << "always fewer pixels while moving";
    planner.wholePictureTook(SceneRequestPlanner::kPreviewBudgetMs * 9.0, 1280 * 720);
    EXPECT_EQ(planner.previewDivisor(), 3);
    planner.wholePictureTook(SceneRequestPlanner::kPreviewBudgetMs * 1000.0, 1280 * 720);
    EXPECT_EQ(planner.previewDivisor(), SceneRequestPlanner::kMaxPreviewDivisor);
}

TEST(SceneTimings, FirstPictureReleaseToRefinedAndOrbitRate) {
    using namespace std::chrono_literals;
    SceneTimings timings;
    const auto start = SceneTimings::Clock::now();
    timings.windowOpened(start);
    timings.pictureShown(false, false, start + 800ms, 700.0);
    timings.cameraGrabbed();
    for (int i = 0; i < 5; ++i) timings.pictureShown(true, true, start + 1s + i * 100ms, 40.0);
    timings.cameraReleased(start + 2s);
    timings.pictureShown(true, false, start + 2s + 50ms, 40.0);  // a preview still in flight
    timings.pictureShown(false, false, start + 2s + 400ms, 300.0);
    const std::string report = timings.report();
    EXPECT_NE(report.find("\"first_picture_ms\":800.0"), std::string::npos) << report;
    EXPECT_NE(report.find("\"release_to_refined_ms\":400.0"), std::string::npos) << report;
    EXPECT_NE(report.find("\"orbit_fps\":10.0,\"orbits\":1"), std::string::npos) << report;
    EXPECT_NE(report.find("\"preview_render_ms\":40.0,\"previews\":6"), std::string::npos)
        << report;
    EXPECT_NE(report.find("\"whole_render_ms\":700.0,\"wholes\":2"), std::string::npos) << report;
}

}  // namespace
}  // namespace matevo::editor
