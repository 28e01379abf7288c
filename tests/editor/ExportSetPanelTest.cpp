// "Export set…" from the kept bin, as a user does it in a headless editor: open the Kept tab,
// click the button, confirm the suggested file in the user's export folder; the export runs on
// its worker (core/export on lavapipe, validated) with progress in the status bar and ends with
// the fitted ΔE00 of each material. The glTF file is read back with tinygltf. Exporting to the
// same file again asks before replacing it. A variant set exported as GLB is checked as
// delivered (its figures in the status bar, the outcome window and a report beside the file),
// and an export past the memory limit is refused before it starts.
#include <chrono>
#include <cmath>
#include <fstream>
#include <regex>
#include <thread>

#include <gtest/gtest.h>
#include <tiny_gltf.h>
#include <nlohmann/json.hpp>

#include "../gpu/GpuTestContext.h"
#include "../ui/EditorUiFixture.h"
#include "ExportWorker.h"
#include "KeptBin.h"

namespace matevo::testing {
namespace {

constexpr const char* kGrid = "Candidates (best first)";

class ExportFromTheKeptBin : public ::testing::Test {
protected:
    ExportFromTheKeptBin()
        : folder(freshDirectory("export")),
          ui(validationMetal(), kShippedMetal,
             PresetFolders{kShippedFolder, folder / "presets", folder / "exports"}) {
        imgui.frame(draw);
    }
    ~ExportFromTheKeptBin() override { fs::remove_all(folder); }

    // Opens the Kept tab and clicks "Export set…" in it.
    void clickExportSet() {
        ImGuiWindow* grid = ImGui::FindWindowByName(kGrid);
        ASSERT_NE(grid, nullptr);
        const ImGuiID tabs = grid->GetID("grid tabs");
        const std::string label =
            "Kept (" + std::to_string(ui.state().preset.kept.size()) + ")###kept";
        const ImGuiID keptTab = ImHashStr(label.c_str(), 0, tabs);
        const auto tab = imgui.locate(*grid, keptTab, draw);
        ASSERT_TRUE(tab.has_value()) << "no Kept tab";
        imgui.click(*tab, draw);
        const auto button = imgui.locate(*grid, ImHashStr("Export set…", 0, keptTab), draw);
        ASSERT_TRUE(button.has_value()) << "no \"Export set…\" in the Kept tab";
        imgui.click(*button, draw);
        imgui.frame(draw);  // a new popup sizes itself in its first, hidden frame
    }
    bool dialogShown() {
        ImGuiWindow* dialog = ImGui::FindWindowByName(ui::ExportDialog::kTitle);
        return dialog && dialog->Active;
    }
    void pressEnter() { imgui.pressKey(257, false, false, draw); }
    void clickInDialog(const char* button) {
        const auto at = imgui.locate(ui::ExportDialog::kTitle, button, draw);
        ASSERT_TRUE(at.has_value()) << button << " not in the dialog";
        imgui.click(*at, draw);
    }

    // Runs `request` on a worker with a quick fit (what is tested is the editor's path, not the
    // fit's quality) until it ends; false when it did not start.
    bool runExport(ui::ExportRequest asked, editor::ExportMemoryCheck checkMemory = {}) {
        gpu::GpuContext* context = test::validatedContext();
        EXPECT_NE(context, nullptr);
        if (!context) return false;
        gpu::RendererRequest renderer(RenderBackend::Gpu, "test");
        renderer.device = &context->device;
        ExportSettings settings;
        settings.fit.imageSize = 32;
        settings.fit.maxEvaluations = 60;
        settings.reportSize = 64;
        editor::ExportWorker worker([] {}, renderer, settings, std::move(checkMemory));
        if (!worker.start(std::move(asked), ui.state())) return false;
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(300);
        while (ui.state().task && std::chrono::steady_clock::now() < deadline) {
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
            worker.update(ui.state());
            imgui.frame(draw);
        }
        EXPECT_FALSE(ui.state().task.has_value()) << "the export did not end in 300 s";
        test::expectNoValidationMessages(*context);
        return true;
    }
    // The text the outcome window shows (ImGui logs a window's text until its End), once the
    // editor shows the window.
    std::string outcomeWindowText() {
        imgui.frame(draw);
        ImGuiWindow* window = ImGui::FindWindowByName(ui::kExportOutcomeTitle);
        EXPECT_TRUE(window && window->Active) << "no outcome window";
        std::string text;
        imgui.frame([&] {
            ImGui::Begin("drawn");
            ImGui::LogToBuffer();
            ui::drawExportOutcomeLines(*ui.state().exportOutcome);
            text = GImGui->LogBuffer.c_str();
            ImGui::End();
        });
        return text;
    }

    fs::path folder;
    HeadlessImGui imgui;
    EditorUi ui;
    std::optional<ui::ExportRequest> request;  // the last one any frame asked for
    std::function<void()> draw = [this] {
        if (auto asked = ui.draw().exportSet) request = std::move(asked);
    };
};

TEST_F(ExportFromTheKeptBin, ExportsTheKeptMaterialsOfTheFamilyToGltfWithTheirFittedDeltaE) {
    gpu::GpuContext* context = test::validatedContext();
    ASSERT_NE(context, nullptr);
    // Two kept materials of this family and one kept in another family, which is left out.
    Preset& preset = ui.state().preset;
    Genome rougher = preset.target, smoother = preset.target;
    rougher[kAlpha2] = std::min(1.0, preset.target[kAlpha2] * 2.0);
    smoother[kAlpha2] = preset.target[kAlpha2] * 0.5;
    ASSERT_EQ(ui::keepMaterials(preset, {rougher, smoother}), 2);
    preset.kept[0].name = "rust, rough";
    KeptMaterial elsewhere = preset.kept[1];
    elsewhere.name = "a dielectric";
    elsewhere.family.base = Base::Dielectric;
    preset.kept.push_back(elsewhere);
    imgui.frame(draw);

    clickExportSet();
    ASSERT_TRUE(dialogShown());
    pressEnter();  // the suggested file
    ASSERT_TRUE(request.has_value()) << ui.state().status.latest().text;
    const fs::path file = folder / "exports" / "validation_metal.gltf";
    EXPECT_EQ(request->file, file) << "not in the user's export folder";
    EXPECT_TRUE(fs::is_directory(folder / "exports")) << "the folder was not created";
    EXPECT_EQ(request->format, ExportFormat::Gltf);
    ASSERT_EQ(request->materials.size(), 2u) << "only the kept materials of this family";

    // A quick fit: what is tested is the editor's path, not the fit's quality.
    gpu::RendererRequest renderer(RenderBackend::Gpu, "test");
    renderer.device = &context->device;
    ExportSettings settings;
    settings.fit.imageSize = 32;
    settings.fit.maxEvaluations = 60;
    settings.reportSize = 64;
    editor::ExportWorker worker([] {}, renderer, settings);
    ASSERT_TRUE(worker.start(std::move(*std::exchange(request, std::nullopt)), ui.state()));
    ASSERT_TRUE(ui.state().task.has_value());
    EXPECT_NE(ui.state().status.latest().text.find("Exporting 2 materials to " + file.string()),
              std::string::npos)
        << ui.state().status.latest().text;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(180);
    while (ui.state().task && std::chrono::steady_clock::now() < deadline) {
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        worker.update(ui.state());
        imgui.frame(draw);  // the status bar draws the progress
    }
    ASSERT_FALSE(ui.state().task.has_value()) << "the export did not end in 180 s";
    const ui::StatusEntry& done = ui.state().status.latest();
    EXPECT_EQ(done.kind, ui::StatusKind::Info) << done.text;
    // "Exported 2 materials to FILE (glTF 2.0, with its .bin): fitted ΔE00 rust, rough: 0.81,
    // validation metal 2: 1.02; mean 0.92 (at 64 px)"
    const std::regex summary(
        "Exported 2 materials to .* fitted ΔE00 rust, rough: ([0-9.]+), "
        "validation metal 2: ([0-9.]+); mean ([0-9.]+) \\(at 64 px\\)");
    std::smatch numbers;
    ASSERT_TRUE(std::regex_search(done.text, numbers, summary)) << done.text;
    for (std::size_t i = 1; i <= 3; ++i) {
        const double deltaE = std::stod(numbers[i].str());
        EXPECT_TRUE(std::isfinite(deltaE) && deltaE >= 0.0 && deltaE < 10.0) << done.text;
    }

    // The outcome window: a line per material, with its fitted ΔE00 and the goal.
    ASSERT_TRUE(ui.state().exportOutcome.has_value());
    const ui::ExportOutcome& outcome = *ui.state().exportOutcome;
    EXPECT_EQ(outcome.summary, done.text);
    ASSERT_EQ(outcome.lines.size(), 2u);
    const std::regex line(
        "rust, rough: fitted ΔE00 ([0-9.]+), (within the goal|past the goal "
        "of 2)");
    ASSERT_TRUE(std::regex_match(outcome.lines[0].text, numbers, line)) << outcome.lines[0].text;
    EXPECT_NE(done.text.find("rust, rough: " + numbers[1].str()), std::string::npos) << done.text;
    EXPECT_EQ(outcome.lines[0].holds, numbers[2] == "within the goal");
    EXPECT_NE(done.text.find("; within the goal of 2: "), std::string::npos) << done.text;

    // Read back: one material per kept one, by name, with the clear coat of the fit.
    tinygltf::TinyGLTF loader;
    tinygltf::Model model;
    std::string error, warning;
    ASSERT_TRUE(loader.LoadASCIIFromFile(&model, &error, &warning, file.string())) << error;
    ASSERT_EQ(model.materials.size(), 2u);
    EXPECT_EQ(model.materials[0].name, "rust, rough");
    EXPECT_EQ(model.materials[1].name, "validation metal 2");
    for (const auto& material : model.materials) {
        EXPECT_TRUE(material.extensions.count("KHR_materials_clearcoat")) << material.name;
        EXPECT_GE(material.pbrMetallicRoughness.roughnessFactor, 0.0);
    }
    EXPECT_EQ(model.meshes.size(), 2u) << "a sphere per material";
    test::expectNoValidationMessages(*context);

    // The same file again: the dialog asks before replacing it.
    clickExportSet();
    pressEnter();
    EXPECT_FALSE(request.has_value()) << "replaced without asking";
    ASSERT_TRUE(dialogShown());
    clickInDialog("Choose another");
    EXPECT_FALSE(request.has_value());
    ASSERT_TRUE(dialogShown()) << "back at the path, to choose another";
    imgui.frame(draw);  // the path field asks for the keyboard, and has it a frame later
    imgui.frame(draw);
    pressEnter();
    clickInDialog("Replace");
    ASSERT_TRUE(request.has_value()) << "Replace did not confirm the export";
    EXPECT_EQ(request->file, file);
    imgui.frame(draw);
    EXPECT_FALSE(dialogShown());
}

// A variant set to GLB: fitted as `matevo variants --deliver gltf` fits it and checked as
// delivered against the Variants window's band and spacing. The status bar, the outcome window
// and the report beside the file give the same figures.
TEST_F(ExportFromTheKeptBin, AVariantSetIsCheckedAsItIsDelivered) {
    Preset& preset = ui.state().preset;
    Genome rougher = preset.target, clearer = preset.target;
    rougher[kAlpha2] = std::min(1.0, preset.target[kAlpha2] * 3.0);
    clearer[kEta2] = preset.target[kEta2] * 0.7;
    preset.variantSet =
        SavedVariantSet{preset.family, preset.target, preset.baseKappa, {rougher, clearer}};
    ui.state().variants.low = 1.0f;
    ui.state().variants.high = 6.0f;
    ui.state().variants.minApart = 1.5f;
    const fs::path file = folder / "exports" / "set.glb";
    fs::create_directories(file.parent_path());
    ui::ExportRequest asked =
        ui::exportRequest(ui.state(), ui::ExportSource::VariantSet, ExportFormat::Glb, file);
    ASSERT_TRUE(asked.delivery.has_value()) << "a variant set as GLB is checked as delivered";
    EXPECT_EQ(asked.delivery->request.band.low, 1.0);
    EXPECT_EQ(asked.delivery->request.band.high, 6.0);
    EXPECT_EQ(asked.delivery->request.minApart, 1.5);
    ASSERT_EQ(asked.materials.size(), 2u);
    ASSERT_TRUE(runExport(std::move(asked)));

    ASSERT_TRUE(ui.state().exportOutcome.has_value());
    const ui::ExportOutcome& outcome = *ui.state().exportOutcome;
    ASSERT_FALSE(outcome.failed) << outcome.summary;
    EXPECT_EQ(ui.state().status.latest().text, outcome.summary);
    // "Exported 2 variants to FILE (glb): fitted ΔE00 within 2 for 1/2; in band 1–6 and at
    // least 1.5 apart as delivered: 2/2"
    const std::regex summary(
        "Exported 2 variants to .*set\\.glb .*: fitted ΔE00 within 2 for ([0-2])/2; in band "
        "1–6 and at least 1\\.5 apart as delivered: ([0-2])/2");
    std::smatch counts;
    ASSERT_TRUE(std::regex_search(outcome.summary, counts, summary)) << outcome.summary;

    // The report beside the export holds the figures the lines give.
    std::ifstream reportFile(folder / "exports" / "set.export.json");
    ASSERT_TRUE(reportFile.good()) << "no report beside the export";
    const auto report = nlohmann::json::parse(reportFile);
    ASSERT_EQ(report.at("variants").size(), 2u);
    EXPECT_EQ(report.at("delivery").at("format"), "gltf");
    EXPECT_EQ(report.at("delivery").at("in_band_and_apart").get<int>(), std::stoi(counts[2]));
    int withinGoal = 0;
    ASSERT_EQ(outcome.lines.size(), 2u);
    const std::regex line(
        "#([01]): fitted ΔE00 ([0-9.]+) \\((within|past) the "
        "goal\\); as delivered ([0-9.]+) from the target, ([0-9.]+) from the nearest.*");
    for (std::size_t i = 0; i < 2; ++i) {
        const auto& entry = report.at("variants")[i];
        const auto& delivered = entry.at("delivered");
        withinGoal += entry.at("within_goal").get<bool>() ? 1 : 0;
        EXPECT_EQ(entry.at("within_goal"), delivered.at("within_goal"));
        std::smatch numbers;
        ASSERT_TRUE(std::regex_match(outcome.lines[i].text, numbers, line))
            << outcome.lines[i].text;
        EXPECT_EQ(std::stoul(numbers[1]), i);
        EXPECT_NEAR(std::stod(numbers[2]), entry.at("mean_de00").get<double>(), 0.006);
        EXPECT_NEAR(std::stod(numbers[2]), delivered.at("de00_to_matevo").get<double>(), 0.006);
        EXPECT_EQ(numbers[3] == "within", delivered.at("within_goal").get<bool>());
        EXPECT_NEAR(std::stod(numbers[4]), delivered.at("de00_to_target").get<double>(), 0.006);
        EXPECT_NEAR(std::stod(numbers[5]), delivered.at("de00_to_nearest_sibling").get<double>(),
                    0.006);
        const double toTarget = delivered.at("de00_to_target").get<double>();
        EXPECT_EQ(delivered.at("in_band_and_apart").get<bool>(),
                  toTarget >= 1.0 && toTarget <= 6.0 &&
                      delivered.at("de00_to_nearest_sibling").get<double>() >= 1.5);
    }
    EXPECT_EQ(withinGoal, std::stoi(counts[1]));

    // The GLB holds the two variants, by the names `matevo export --variants` gives them.
    tinygltf::TinyGLTF loader;
    tinygltf::Model model;
    std::string error, warning;
    ASSERT_TRUE(loader.LoadBinaryFromFile(&model, &error, &warning, file.string())) << error;
    ASSERT_EQ(model.materials.size(), 2u);
    EXPECT_EQ(model.materials[0].name, "validation metal variant_000");

    // The outcome window shows the summary and a line per variant.
    const std::string shown = outcomeWindowText();
    EXPECT_NE(shown.find(outcome.summary), std::string::npos) << shown;
    for (const ui::ExportOutcome::Line& each : outcome.lines)
        EXPECT_NE(shown.find(each.text), std::string::npos) << shown;
}

// Past the memory limit the export is refused before it starts: nothing written, the reason in
// one red line and in the outcome window.
TEST_F(ExportFromTheKeptBin, AnExportPastTheMemoryLimitIsRefused) {
    Preset& preset = ui.state().preset;
    ASSERT_EQ(ui::keepMaterials(preset, {preset.target}), 1);
    const fs::path file = folder / "exports" / "kept.gltf";
    bool checked = false;
    const editor::ExportMemoryCheck overTheLimit = [&](const ui::ExportRequest& refused,
                                                       const ExportSettings& settings) -> Status {
        checked = true;
        EXPECT_EQ(refused.file, file);
        EXPECT_EQ(settings.reportSize, 64) << "the settings the export would run with";
        return badInput(
            "Export set of 1 material needs about 99 MiB of memory, more than the "
            "limit of 1 MiB");
    };
    EXPECT_FALSE(runExport(
        ui::exportRequest(ui.state(), ui::ExportSource::KeptBin, ExportFormat::Gltf, file),
        overTheLimit));
    EXPECT_TRUE(checked);
    EXPECT_FALSE(ui.state().task.has_value());
    EXPECT_FALSE(fs::exists(file));
    const ui::StatusEntry& refused = ui.state().status.latest();
    EXPECT_EQ(refused.kind, ui::StatusKind::Error);
    EXPECT_EQ(refused.text,
              "Export refused: Export set of 1 material needs about 99 MiB of memory, more than "
              "the limit of 1 MiB");
    ASSERT_TRUE(ui.state().exportOutcome.has_value());
    EXPECT_TRUE(ui.state().exportOutcome->failed);
    EXPECT_NE(outcomeWindowText().find(refused.text), std::string::npos);
}

TEST_F(ExportFromTheKeptBin, AnEmptyBinOrAWrongExtensionSaysWhy) {
    ASSERT_TRUE(ui.state().preset.kept.empty());
    // No Kept tab button without kept materials: the panel says how to keep them instead.
    ui::ExportDialog dialog;
    dialog.open(ui.state(), folder);
    EXPECT_FALSE(dialog.isOpen());
    EXPECT_NE(ui.state().status.latest().text.find("keep materials first"), std::string::npos)
        << ui.state().status.latest().text;

    ui::keepMaterials(ui.state().preset, {ui.state().preset.target});
    imgui.frame(draw);
    clickExportSet();
    ImGuiIO& io = ImGui::GetIO();
    io.KeyCtrl = true;  // select the suggested path, then type another
    io.KeysDown[io.KeyMap[ImGuiKey_A]] = true;
    imgui.frame(draw);
    io.KeysDown[io.KeyMap[ImGuiKey_A]] = false;
    io.KeyCtrl = false;
    io.AddInputCharactersUTF8((folder / "set.obj").c_str());
    imgui.frame(draw);
    pressEnter();
    EXPECT_FALSE(request.has_value());
    EXPECT_NE(ui.state().status.latest().text.find("must end in .gltf"), std::string::npos)
        << ui.state().status.latest().text;
    imgui.frame(draw);
    EXPECT_TRUE(dialogShown()) << "the dialog stays for another name";
}

}  // namespace
}  // namespace matevo::testing
