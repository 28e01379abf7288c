#include "EditorApp.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>
#include <imgui.h>

#include "CompareMetricsController.h"
#include "DrawDataSnapshot.h"
#include "EditorStyle.h"
#include "EditorTimings.h"
#include "EditorUi.h"
#include "EvolutionController.h"
#include "ExportController.h"
#include "ImageBridge.h"
#include "SceneController.h"
#include "ScriptPlayer.h"
#include "VariantsController.h"
#include "ViewSettings.h"
#include "VulkanContext.h"
#include "WindowInput.h"
#include "WindowRenderer.h"
#include "documents/PresetCatalog.h"
#include "files/ResourcePaths.h"
#include "image/ImageFile.h"
#include "material/FgdTableCache.h"

namespace matevo::editor {
namespace {

// How error maps are coloured: drawn by the image bridge, so not in ImGui's draw data.
struct HeatmapDisplay {
    ImageMetric metric;
    float minDeltaE;
    float maxDeltaE;
};
static_assert(sizeof(HeatmapDisplay) == sizeof(ImageMetric) + 2 * sizeof(float),
              "no padding: a snapshot compares its bytes");

// Every command that works without a window, for the messages that say the editor cannot open.
constexpr const char* kHeadlessCommands =
    "matevo evolve, render, compare, experiment, variants, scene, export, merge, bench, presets";

// Signal handlers can only set a flag; the frame loop reads it.
std::atomic<bool> terminationRequested{false};

void onTerminationSignal(int) { terminationRequested.store(true); }

// A script's resize, no larger than the screen: past it no one sees the rest, and the
// swapchain's images with the renders that fill them grow without bound (16384x16384 on
// lavapipe under Xvfb: 8 GiB and no frame in two minutes). Clamped with one line.
void resizeForScript(GLFWwindow* window, int width, int height) {
    GLFWmonitor* monitor = glfwGetPrimaryMonitor();
    const GLFWvidmode* screen = monitor ? glfwGetVideoMode(monitor) : nullptr;
    if (screen && (width > screen->width || height > screen->height)) {
        std::fprintf(stderr, "matevo edit: warning: resize %d %d: clamped to the screen, %dx%d\n",
                     width, height, std::min(width, screen->width),
                     std::min(height, screen->height));
        width = std::min(width, screen->width);
        height = std::min(height, screen->height);
    }
    glfwSetWindowSize(window, width, height);
}

// No window, or no Vulkan device to present it with: a property of the machine, exit 2.
struct WindowUnavailable : std::runtime_error {
    using std::runtime_error::runtime_error;
};

class GlfwSession {
public:
    GlfwSession() {
        glfwSetErrorCallback([](int, const char*) {});  // failures are reported by return value
        ok_ = glfwInit() == GLFW_TRUE;
    }
    ~GlfwSession() {
        if (ok_) glfwTerminate();
    }
    GlfwSession(const GlfwSession&) = delete;
    GlfwSession& operator=(const GlfwSession&) = delete;
    bool ok() const { return ok_; }

private:
    bool ok_ = false;
};

// $XDG_CONFIG_HOME/matevo/imgui.ini, else ~/.config/matevo/imgui.ini; empty if neither exists.
std::string imguiIniPath() {
    const std::filesystem::path folder = userConfigDirectory();
    if (folder.empty()) return {};
    std::error_code error;
    std::filesystem::create_directories(folder, error);
    return error ? std::string() : (folder / "imgui.ini").string();
}

// Shipped presets are read-only; the user's own go to their data folder.
ui::PresetFolders presetFolders() {
    ui::PresetFolders folders;
    if (auto shipped = findResourceDirectory("presets")) folders.shipped = *shipped;
    folders.user = userPresetDirectory();
    // Beside the presets: $XDG_DATA_HOME/matevo/exports.
    if (!folders.user.empty()) folders.exports = folders.user.parent_path() / "exports";
    return folders;
}

class EditorApp {
public:
    explicit EditorApp(const EditorOptions& options);
    ~EditorApp();
    EditorApp(const EditorApp&) = delete;
    EditorApp& operator=(const EditorApp&) = delete;

    int run();

private:
    struct WindowDeleter {
        void operator()(GLFWwindow* window) const { glfwDestroyWindow(window); }
    };
    // ImGui's context and its GLFW and Vulkan backends, shut down in reverse.
    class ImGuiSession {
    public:
        ImGuiSession(GLFWwindow* window, VulkanContext& vulkan, const WindowRenderer& renderer,
                     const std::string& iniPath);
        ~ImGuiSession();
        ImGuiSession(const ImGuiSession&) = delete;
        ImGuiSession& operator=(const ImGuiSession&) = delete;
    };

    enum class FrameOutcome {
        Drawn,
        Unchanged,  // the same picture as the one on screen: not drawn again
        Skipped,    // nothing drawn (the swapchain is being rebuilt, or a failure)
    };
    FrameOutcome frame(std::optional<std::filesystem::path>& screenshotPath);
    // What the script's actions ask of the features this frame, as if from the panels.
    ui::FrameRequests playScript(std::optional<std::filesystem::path>& screenshotPath);
    // Whether the GA run and the variant search a script may wait for are done and shown.
    ScriptPlayer::Settled scriptSettled();
    // Registers a feature: called at the same points of every frame as the others.
    template <typename Controller>
    Controller& add(std::unique_ptr<Controller> controller);
    void saveScreenshot(const Rgba8Image& frame, const std::filesystem::path& path);
    std::filesystem::path nextSnapshotPath() const;
    bool shouldQuit() const;
    // A job is queued or running (an ended one's last result may still wait to be shown).
    bool jobsRunning() const;

    EditorOptions options_;
    std::string iniPath_;
    std::unique_ptr<GLFWwindow, WindowDeleter> window_;
    std::unique_ptr<WindowInput> input_;
    std::unique_ptr<VulkanContext> vulkan_;
    std::unique_ptr<WindowRenderer> renderer_;
    std::unique_ptr<ImGuiSession> imgui_;
    std::unique_ptr<ImageBridge> bridge_;
    ui::EditorUi ui_;
    ScriptPlayer script_;
    EditorTimings timings_;
    SceneTimings sceneTimings_;
    std::string title_;
    std::string failure_;
    bool quitRequested_ = false;
    bool redrawRequested_ = false;   // by a script: the whole window, on the next frame
    ui::DrawDataSnapshot onScreen_;  // what the last frame drawn shows
    ui::DrawDataSnapshot next_;      // this frame's, compared with it
    // Frames drawn after input or a finished job, so that hover states and popups settle
    // before waiting.
    static constexpr int kSettleFrames = 3;
    // While a job runs, its progress is drawn at most this often: on lavapipe every frame takes
    // both cores from the job for 10-30 ms.
    static constexpr std::chrono::milliseconds kProgressInterval{100};
    std::atomic<bool> workerPosted_{false};  // a worker has a result or progress to show
    // Each feature's background work and display, in the order they are shown each frame;
    // stopped before the window they draw into.
    std::vector<std::unique_ptr<FeatureController>> features_;
    EvolutionController* evolution_ = nullptr;
    VariantsController* variants_ = nullptr;
    ExportController* export_ = nullptr;
    SceneController* scene_ = nullptr;
};

EditorApp::ImGuiSession::ImGuiSession(GLFWwindow* window, VulkanContext& vulkan,
                                      const WindowRenderer& renderer, const std::string& iniPath) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = iniPath.empty() ? nullptr : iniPath.c_str();
    ui::applyEditorStyle();
    ui::loadEditorFont();
    ImGui_ImplGlfw_InitForVulkan(window, false);  // WindowInput owns the callbacks
    ImGui_ImplVulkan_InitInfo info{};
    info.Instance = vulkan.instance().handle();
    info.PhysicalDevice = vulkan.device().physicalDevice();
    info.Device = vulkan.device().handle();
    info.QueueFamily = vulkan.device().queueFamily();
    info.Queue = vulkan.device().queue();
    info.DescriptorPool = vulkan.descriptorPool();
    info.MinImageCount = renderer.minImageCount();
    info.ImageCount = renderer.imageCount();
    info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
    ImGui_ImplVulkan_Init(&info, renderer.renderPass());
    gpu::CommandRunner& runner = vulkan.setupRunner();
    auto commands = runner.begin();
    if (!commands) throw std::runtime_error(commands.error().message);
    ImGui_ImplVulkan_CreateFontsTexture(*commands);
    if (Status uploaded = runner.submitAndWait(); !uploaded)
        throw std::runtime_error(uploaded.error().message);
    ImGui_ImplVulkan_DestroyFontUploadObjects();
}

EditorApp::ImGuiSession::~ImGuiSession() {
    ImGui_ImplVulkan_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

EditorApp::EditorApp(const EditorOptions& options)
    : options_(options),
      iniPath_(imguiIniPath()),
      ui_(options.preset, options.presetFile, presetFolders(),
          ui::ShortcutKeys{GLFW_KEY_O, GLFW_KEY_S, GLFW_KEY_Q, GLFW_KEY_F12, GLFW_KEY_K}),
      script_(options.script) {
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    window_.reset(glfwCreateWindow(options.width, options.height, "matevo", nullptr, nullptr));
    if (!window_) throw WindowUnavailable("cannot open a window on this display");
    input_ = std::make_unique<WindowInput>(window_.get());
    auto vulkan = VulkanContext::create(window_.get(), options.validation);
    if (!vulkan) throw WindowUnavailable(vulkan.error().message);
    vulkan_ = std::move(*vulkan);
    int width = 0, height = 0;
    glfwGetFramebufferSize(window_.get(), &width, &height);
    auto renderer =
        WindowRenderer::create(*vulkan_, VkExtent2D{std::uint32_t(width), std::uint32_t(height)});
    if (!renderer) throw std::runtime_error(renderer.error().message);
    renderer_ = std::move(renderer).value();
    imgui_ = std::make_unique<ImGuiSession>(window_.get(), *vulkan_, *renderer_, iniPath_);
    ui::rememberViewSettings(ui_.state());
    auto bridge = ImageBridge::create(*vulkan_, renderer_->renderPass());
    if (!bridge) throw std::runtime_error(bridge.error().message);
    bridge_ = std::move(bridge).value();
    const FeatureContext context{*bridge_, vulkan_->device(), options.backend, [this] {
                                     workerPosted_.store(true);
                                     glfwPostEmptyEvent();
                                 }};
    // The features, one line each.
    evolution_ = &add(std::make_unique<EvolutionController>(context, timings_));
    add(std::make_unique<CompareMetricsController>(context));
    variants_ = &add(std::make_unique<VariantsController>(context));
    export_ = &add(std::make_unique<ExportController>(context, options.checkExportMemory));
    scene_ = &add(std::make_unique<SceneController>(context, sceneTimings_));
    std::signal(SIGTERM, onTerminationSignal);
    std::signal(SIGINT, onTerminationSignal);
}

EditorApp::~EditorApp() {
    // imgui.ini holds the view settings, read from ui_: write it now, while ui_ is alive, and
    // not again when the ImGui context goes after it.
    ImGuiIO& io = ImGui::GetIO();
    if (io.IniFilename) ImGui::SaveIniSettingsToDisk(io.IniFilename);
    io.IniFilename = nullptr;
    // Every job is asked to stop first, so they end together; then each is joined.
    for (auto& feature : features_) feature->cancel();
    while (!features_.empty()) features_.pop_back();
    (void)renderer_->waitIdle();  // frames in flight use the images released below
}

template <typename Controller>
Controller& EditorApp::add(std::unique_ptr<Controller> controller) {
    Controller& added = *controller;
    features_.push_back(std::move(controller));
    return added;
}

bool EditorApp::jobsRunning() const {
    return std::any_of(features_.begin(), features_.end(),
                       [](const auto& feature) { return feature->running(); });
}

bool EditorApp::shouldQuit() const {
    return quitRequested_ || terminationRequested.load() || glfwWindowShouldClose(window_.get()) ||
           !failure_.empty();
}

int EditorApp::run() {
    int frames = 0;
    std::optional<std::filesystem::path> screenshotPath;
    int framesToSettle = 0;
    bool resultWaiting = false;  // a worker posted something no frame has shown yet
    auto lastDrawn = std::chrono::steady_clock::time_point{};
    while (!shouldQuit()) {
        // Draw only when something changed: input (and a few frames after it, for ImGui's
        // hover and popups to settle), a worker's result (it posts an empty event), a due script
        // step or snapshot, or the progress of a running job. An idle editor draws nothing: on
        // a two-core machine every frame is time taken from the GA. The timeout keeps SIGTERM
        // and the progress line responsive.
        // A script waiting for work needs frames once the work has settled, even when the
        // work was never started (a setting changed to the value it had): nothing else would
        // wake the loop then.
        const bool scriptDue =
            !script_.finished() &&
            (script_.waitingForEvolution() ? script_.awaitedWorkSettled(scriptSettled())
                                           : script_.resumed());
        const bool due = screenshotPath || scriptDue || input_->hasPending() || framesToSettle > 0;
        const bool busy = jobsRunning();
        const auto sinceDrawn = std::chrono::steady_clock::now() - lastDrawn;
        // Until the next progress frame is due, or the script resumes (a scene-orbit's next move).
        const double wait = std::min(
            busy ? std::chrono::duration<double>(kProgressInterval - sinceDrawn).count() : 0.25,
            script_.finished() || script_.waitingForEvolution() ? 0.25 : script_.secondsToResume());
        if (due)
            glfwPollEvents();
        else
            glfwWaitEventsTimeout(std::max(0.001, wait));
        if (shouldQuit()) break;
        if (input_->takeCloseRequest()) ui_.requestQuit();
        if (auto dropped = input_->takeDroppedFiles(); !dropped.empty())
            ui_.dropFile(dropped.front());
        if (workerPosted_.exchange(false)) resultWaiting = true;
        if (input_->takeChanged()) framesToSettle = kSettleFrames;
        // While jobs run, their results and progress are drawn every kProgressInterval (the
        // first result of a new GA job at once); the last result is drawn as soon as its job
        // ends, and settles like input.
        const bool running = jobsRunning();
        if (resultWaiting && !running) framesToSettle = std::max(framesToSettle, kSettleFrames);
        const bool firstResult = resultWaiting && evolution_->newJobUnshown();
        const bool progressDue =
            running &&
            (firstResult || std::chrono::steady_clock::now() - lastDrawn >= kProgressInterval);
        if (!due && !progressDue && framesToSettle == 0) continue;  // draw nothing now
        framesToSettle = std::max(0, framesToSettle - 1);
        if (script_.idling()) timings_.frameWhileScriptIdle();
        int width = 0, height = 0;
        glfwGetFramebufferSize(window_.get(), &width, &height);
        if (width == 0 || height == 0) {  // minimised: nothing to draw into until restored
            glfwWaitEventsTimeout(0.1);
            continue;
        }

        const bool evolving = evolution_->busy();
        const EditorTimings::Mark started = EditorTimings::now();
        const FrameOutcome outcome = frame(screenshotPath);
        // A change starts its job once the frame showing it is on screen: on lavapipe the
        // frame would otherwise wait behind the job's first renders on the one queue.
        evolution_->submitChanges(ui_.state(), ImGui::IsAnyItemActive(), started);
        if (outcome == FrameOutcome::Skipped) continue;
        resultWaiting = false;  // the frame applied every result posted so far
        lastDrawn = std::chrono::steady_clock::now();
        const EditorTimings::Mark finished = EditorTimings::now();
        if (outcome == FrameOutcome::Drawn)
            timings_.addFrame(EditorTimings::between(started, finished), evolving);
        else
            timings_.frameUnchanged();
        timings_.resultsShown(evolution_->shownJob(), evolution_->shownFinished(), finished);
        if (options_.maxFrames > 0 && ++frames >= options_.maxFrames) break;
    }
    if (options_.reportTimings) {
        std::printf("editor timings: %s\n", timings_.report().c_str());
        std::printf("scene timings: %s\n", sceneTimings_.report().c_str());
    }
    if (!failure_.empty()) {
        std::fprintf(stderr, "matevo edit: %s\n", failure_.c_str());
        return 1;
    }
    const int validationMessages = vulkan_->validationMessages();
    if (validationMessages > 0) {
        std::fprintf(stderr, "matevo edit: %d Vulkan validation message(s)\n", validationMessages);
        return 1;
    }
    return 0;
}

EditorApp::FrameOutcome EditorApp::frame(std::optional<std::filesystem::path>& screenshotPath) {
    // A screenshot shows the frame after the one that asked, so the request has settled; the
    // script waits for it.
    const std::optional<std::filesystem::path> captureNow = std::exchange(screenshotPath, {});
    ui::FrameRequests scripted;
    if (!captureNow) scripted = playScript(screenshotPath);

    for (auto& feature : features_)
        if (Status shown = feature->showResults(ui_.state()); !shown)
            failure_ = shown.error().message;
    ui_.state().evolution.tableBuildProgress = tableBuildProgress();
    ImGui_ImplVulkan_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    input_->applyFrame();  // after the backend's pointer polling, which it overrides
    ImGui::NewFrame();
    const ui::FrameRequests requests = ui_.draw();
    ImGui::Render();
    if (requests.quit) quitRequested_ = true;
    if (requests.snapshot) screenshotPath = nextSnapshotPath();
    for (const ui::FrameRequests* asked : {&std::as_const(requests), &std::as_const(scripted)})
        for (auto& feature : features_) feature->handleRequests(*asked, ui_.state());
    if (std::string title = ui::windowTitle(ui_.state()); title != title_) {
        glfwSetWindowTitle(window_.get(), title.c_str());
        title_ = std::move(title);
    }

    int width = 0, height = 0;
    glfwGetFramebufferSize(window_.get(), &width, &height);
    ImDrawData* drawData = ImGui::GetDrawData();
    const HeatmapDisplay heatmap{ui_.state().evolution.heatmapMetric, ui_.state().heatmap.minDeltaE,
                                 ui_.state().heatmap.maxDeltaE};
    bridge_->setHeatmap(heatmap.metric, heatmap.minDeltaE, heatmap.maxDeltaE);
    // Hover, progress and worker wakes often end in the picture already on screen.
    next_.capture(*drawData, std::as_bytes(std::span(&heatmap, 1)));
    // The window lost its contents (uncovered), or a script asks for a whole redraw.
    const bool redraw = input_->takeRefreshRequest() || std::exchange(redrawRequested_, false);
    if (redraw) renderer_->forgetPictures();
    if (!captureNow && !redraw && next_ == onScreen_) return FrameOutcome::Unchanged;
    FrameRecording recording;
    if (std::vector<ui::PixelArea> changed = next_.changedSince(onScreen_);
        changed != std::vector<ui::PixelArea>{next_.whole()})
        recording.changed = std::move(changed);
    recording.inPass = [this, drawData](VkCommandBuffer commands, std::size_t frameSlot,
                                        std::span<const ui::PixelArea> areas) {
        ui::clipDrawData(*drawData, areas);
        bridge_->prepare(*drawData, commands, frameSlot);
        ImGui_ImplVulkan_RenderDrawData(drawData, commands);
    };
    Rgba8Image captured;
    auto drawFrame = renderer_->drawFrame(VkExtent2D{std::uint32_t(width), std::uint32_t(height)},
                                          recording, captureNow ? &captured : nullptr);
    if (!drawFrame) failure_ = drawFrame.error().message;
    const bool drawn = drawFrame && *drawFrame;
    if (drawn && captureNow) saveScreenshot(captured, *captureNow);
    if (!drawn && captureNow) screenshotPath = captureNow;  // try again next frame
    if (!drawn) {
        onScreen_.clear();  // whatever is on screen now, the next frame draws
        return FrameOutcome::Skipped;
    }
    std::swap(onScreen_, next_);
    return FrameOutcome::Drawn;
}

ScriptPlayer::Settled EditorApp::scriptSettled() {
    return {evolution_->settled(), variants_->settled(ui_.state()), export_->settled(),
            !scene_->running()};
}

ui::FrameRequests EditorApp::playScript(std::optional<std::filesystem::path>& screenshotPath) {
    const ScriptEffects effects = script_.step(ui_, scriptSettled());
    if (!effects.error.empty()) failure_ = effects.error;
    if (effects.quit) quitRequested_ = true;
    if (effects.resize)
        resizeForScript(window_.get(), effects.resize->first, effects.resize->second);
    if (effects.redraw) redrawRequested_ = true;
    screenshotPath = effects.screenshot;
    ui::FrameRequests scripted;
    scripted.variants = effects.variants;
    scripted.exportSet = effects.exportSet;
    return scripted;
}

std::filesystem::path EditorApp::nextSnapshotPath() const {
    for (int i = 1;; ++i) {
        char name[64];
        std::snprintf(name, sizeof name, "matevo-snapshot-%03d.png", i);
        if (!std::filesystem::exists(name)) return name;
    }
}

void EditorApp::saveScreenshot(const Rgba8Image& frame, const std::filesystem::path& path) {
    const Status written = writeImage(toLinearImage(frame), path);
    if (written)
        ui_.state().status.post("Snapshot " + path.string());
    else
        ui_.state().status.post("Snapshot failed: " + written.error().message,
                                ui::StatusKind::Error);
    if (!written && !options_.script.empty()) failure_ = written.error().message;
}

}  // namespace

int runEditor(const EditorOptions& options) {
    GlfwSession glfw;
    if (!glfw.ok()) {
        std::fprintf(stderr,
                     "matevo edit: no display to open a window on (is DISPLAY set?); the "
                     "headless commands work without one: %s\n",
                     kHeadlessCommands);
        return 2;
    }
    try {
        EditorApp app(options);
        return app.run();
    } catch (const WindowUnavailable& error) {
        // The window itself needs a Vulkan device that can present; the headless commands
        // do not, and fall back to the CPU renderer.
        const std::string reason = error.what();
        // Where the Vulkan loader looks, unless the reason already says it.
        const char* drivers =
            reason.find("icd.d") == std::string::npos
                ? " (Vulkan drivers are looked for through VK_DRIVER_FILES or VK_ICD_FILENAMES, "
                  "else in vulkan/icd.d under each of $XDG_DATA_DIRS)"
                : "";
        std::fprintf(stderr,
                     "matevo edit: cannot show the editor: %s%s; the headless commands render on "
                     "the CPU without Vulkan: %s\n",
                     reason.c_str(), drivers, kHeadlessCommands);
        return 2;
    }
}

}  // namespace matevo::editor
