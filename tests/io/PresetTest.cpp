#include "documents/Preset.h"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "documents/GenomeJson.h"

namespace matevo {
namespace {

namespace fs = std::filesystem;

const std::string kValidPreset = R"({
  "name": "test",
  "family": {"coat": "clearcoat", "base": "conductor", "medium": false},
  "target": {"eta1": 1.2, "eta2": 0.8, "alpha1": 0.03, "alpha2": 0.1},
  "base_kappa": [3.1, 2.9, 2.8],
  "ga": {"population": 50, "generations": 5, "metric": "manhattan", "seed": 7}
})";

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    auto at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return text.replace(at, from.size(), to);
}

std::string errorOf(const std::string& json) {
    auto result = parsePreset(json, "p.json");
    EXPECT_FALSE(result.ok()) << json;
    return result.ok() ? "" : result.error().message;
}

fs::path freshDirectory(const std::string& name) {
    auto dir = fs::temp_directory_path() / ("matevo_test_" + name + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

TEST(Preset, ParsesAValidPreset) {
    auto result = parsePreset(kValidPreset, "p.json");
    ASSERT_TRUE(result.ok()) << result.error().message;
    const Preset& preset = result->preset;
    EXPECT_EQ(preset.name, "test");
    EXPECT_EQ(preset.family.coat, Coat::Clearcoat);
    EXPECT_EQ(preset.family.base, Base::Conductor);
    EXPECT_DOUBLE_EQ(preset.target.eta2(), 0.8);
    EXPECT_EQ(preset.ga.metric, DistanceMetric::Manhattan);
    EXPECT_EQ(preset.ga.seed, 7u);
    EXPECT_TRUE(result->warnings.empty());
}

TEST(Preset, RoundTripsThroughText) {
    Preset preset = parsePreset(kValidPreset, "p.json")->preset;
    preset.family.hasMedium = true;
    preset.target[kDepth] = 1.5;
    preset.target[kSigmaSG] = 0.25;
    preset.target[kG] = 0.8;
    preset.ga.weights[kDepth] = 0.01;
    preset.ga.normalizeByRange = true;
    preset.ga.elitism = 2;
    preset.ga.seed = 18446744073709551615ull;  // the whole 64-bit range survives
    preset.scene.imageSize = 128;
    preset.scene.mode = SceneMode::Ambient;
    preset.scene.environmentRadiance = {0.1, 0.2, 0.3};
    auto reparsed = parsePreset(serializePreset(preset), "again.json");
    ASSERT_TRUE(reparsed.ok()) << reparsed.error().message;
    EXPECT_EQ(reparsed->preset, preset);
    EXPECT_TRUE(reparsed->warnings.empty());
}

// The editor's variant set is part of the document: its members (a hue-variety member with its
// own kappa too) and the target it was made for come back as they were saved.
TEST(Preset, TheVariantSetRoundTripsWithTheTargetItWasMadeFor) {
    Preset preset = parsePreset(kValidPreset, "p.json")->preset;
    SavedVariantSet set{preset.family, preset.target, preset.baseKappa, {}};
    Genome grey = preset.target;
    grey[kAlpha1] = 0.06;
    Genome hued = preset.target;
    hued[kEta2] = 0.6;
    hued[kKappaR] = 2.5;
    hued[kKappaG] = 1.5;
    hued[kKappaB] = 3.0;
    set.variants = {grey, hued};
    preset.variantSet = set;
    EXPECT_FALSE(variantSetMadeForAnotherTarget(preset));
    const std::string text = serializePreset(preset);
    EXPECT_NE(text.find("\"variant_set\""), std::string::npos) << text;
    auto reparsed = parsePreset(text, "again.json");
    ASSERT_TRUE(reparsed.ok()) << reparsed.error().message;
    EXPECT_TRUE(reparsed->warnings.empty());
    ASSERT_TRUE(reparsed->preset.variantSet.has_value());
    EXPECT_EQ(reparsed->preset.variantSet->variants, set.variants);
    EXPECT_EQ(reparsed->preset, preset);
    // The target moved on: the set says it was made for another.
    preset.target[kAlpha1] = 0.2;
    EXPECT_TRUE(variantSetMadeForAnotherTarget(preset));
    // A member outside the set's family is bad input naming the field.
    auto json = nlohmann::ordered_json::parse(text);
    json["variant_set"]["variants"][0]["genome"]["eta1"] = -1;
    const std::string problem = errorOf(json.dump());
    EXPECT_NE(problem.find("variant_set.variants[0].genome"), std::string::npos) << problem;
}

TEST(Preset, EnvironmentModeNamesItsEnvironment) {
    auto parsed = parsePreset(
        replaced(
            kValidPreset, R"("base_kappa")",
            R"("scene": {"mode": "environment", "environment": "hdr/hall.exr"}, "base_kappa")"),
        "p.json");
    ASSERT_TRUE(parsed.ok()) << parsed.error().message;
    EXPECT_EQ(parsed->preset.scene.mode, SceneMode::Environment);
    EXPECT_EQ(parsed->preset.scene.environment, "hdr/hall.exr");
    auto reparsed = parsePreset(serializePreset(parsed->preset), "again.json");
    ASSERT_TRUE(reparsed.ok());
    EXPECT_EQ(reparsed->preset, parsed->preset);
    EXPECT_NE(errorOf(replaced(kValidPreset, R"("base_kappa")",
                               R"("scene": {"mode": "sunset"}, "base_kappa")"))
                  .find("paper, ambient or environment"),
              std::string::npos);
}

TEST(Preset, SavesAtomicallyAndLoadsBack) {
    auto dir = freshDirectory("save");
    Preset preset = parsePreset(kValidPreset, "p.json")->preset;
    auto file = dir / "saved.json";
    ASSERT_TRUE(savePreset(preset, file).ok());
    preset.name = "second version";
    ASSERT_TRUE(savePreset(preset, file).ok());  // replaces the first
    auto loaded = loadPreset(file);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    EXPECT_EQ(loaded->preset, preset);
    // No temporary file is left behind.
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}), 1);
    fs::remove_all(dir);
}

TEST(Preset, SavingIntoAMissingFolderFailsAndSaysWhere) {
    Preset preset;
    auto status = savePreset(preset, "/nonexistent-folder/x.json");
    ASSERT_FALSE(status.ok());
    EXPECT_NE(status.error().message.find("/nonexistent-folder/x.json"), std::string::npos);
}

TEST(Preset, MalformedDocumentsNameTheFileAndTheProblem) {
    EXPECT_NE(errorOf("").find("p.json: not valid JSON"), std::string::npos);
    EXPECT_NE(errorOf(kValidPreset.substr(0, kValidPreset.size() / 2)).find("not valid JSON"),
              std::string::npos);
    EXPECT_NE(errorOf("[1, 2]").find("must be a JSON object"), std::string::npos);
    EXPECT_NE(errorOf(replaced(kValidPreset, R"("name": "test",)", "")).find("name: missing"),
              std::string::npos);
}

// One edit of the valid preset and a fragment its error message must contain.
struct RejectedEdit {
    const char* from;
    const char* to;
    const char* expected;
};

void expectRejected(const std::vector<RejectedEdit>& edits) {
    for (const auto& edit : edits) {
        const std::string message = errorOf(replaced(kValidPreset, edit.from, edit.to));
        EXPECT_NE(message.find(edit.expected), std::string::npos)
            << edit.to << " gave: " << message;
        EXPECT_EQ(message.rfind("p.json: ", 0), 0u) << message;  // names the file first
    }
}

TEST(Preset, WrongTypesNameTheField) {
    expectRejected({
        {R"("population": 50)", R"("population": "50")", "ga.population: must be an integer"},
        {R"("eta1": 1.2)", R"("eta1": [1.2])", "target.eta1: must be a number"},
        {R"("medium": false)", R"("medium": 0)", "family.medium: must be true or false"},
        {"[3.1, 2.9, 2.8]", "[3.1, 2.9]", "base_kappa: must be an array of 3 numbers"},
    });
}

TEST(Preset, AbsurdValuesAreRejectedNotAttempted) {
    expectRejected({
        {R"("population": 50)", R"("population": 0)",
         "ga.population: must be in [2, 100000], got 0"},
        {R"("population": 50)", R"("population": 2000000000)", "ga.population"},
        {R"("generations": 5)", R"("generations": -1)", "ga.generations"},
        {R"("population": 50)", R"("population": 50.5)", "must be an integer, got 50.5"},
        {R"("eta1": 1.2)", R"("eta1": 1e999)", "1e999"},
        {R"("eta1": 1.2)", R"("eta1": NaN)", "not valid JSON"},
        {R"("seed": 7)", R"("seed": -7)", "ga.seed: must be a non-negative integer"},
        {"[3.1, 2.9, 2.8]", "[0, 0, 0]", "base_kappa: a conductor base needs"},
    });
}

TEST(Preset, UnknownFamilyIsRejected) {
    expectRejected({
        {R"("clearcoat")", R"("glittercoat")", "family.coat: unknown value 'glittercoat'"},
        {R"("conductor")", R"("plasma")", "family.base: unknown value 'plasma'"},
    });
}

TEST(Preset, TargetOutsideItsFamilyIsRejected) {
    expectRejected({
        {R"("alpha1": 0.03)", R"("alpha1": 0.5)", "target: "},  // a clearcoat needs alpha1 < 0.1
        {R"("eta2": 0.8)", R"("eta2": 1.9)", "target: "},  // a conductor's eta2 lies below eta1
    });
}

TEST(Preset, UnknownFieldsWarnButLoad) {
    auto result = parsePreset(
        replaced(kValidPreset, R"("name": "test",)", R"("name": "test", "colour": 3,)"), "p.json");
    ASSERT_TRUE(result.ok());
    ASSERT_EQ(result->warnings.size(), 1u);
    EXPECT_EQ(result->warnings[0], "p.json: colour: unknown field, ignored");
}

TEST(Preset, SceneModeIsReadAndDefaultsToThePapersScene) {
    const std::string withScene = replaced(kValidPreset, R"("ga")", R"("scene": {}, "ga")");
    auto plain = parsePreset(withScene, "p.json");
    ASSERT_TRUE(plain.ok()) << plain.error().message;
    EXPECT_EQ(plain->preset.scene.mode, SceneMode::Paper);

    auto ambient = parsePreset(
        replaced(withScene, R"("scene": {})",
                 R"("scene": {"mode": "ambient", "environment_radiance": [0.5, 0.5, 0.5]})"),
        "p.json");
    ASSERT_TRUE(ambient.ok()) << ambient.error().message;
    EXPECT_EQ(ambient->preset.scene.mode, SceneMode::Ambient);
    EXPECT_EQ(ambientRadiance(ambient->preset.scene), (std::array{0.5, 0.5, 0.5}));
    EXPECT_TRUE(ambient->warnings.empty());

    const std::string message =
        errorOf(replaced(withScene, R"("scene": {})", R"("scene": {"mode": "studio"})"));
    EXPECT_NE(
        message.find(
            "p.json: scene.mode: unknown value 'studio' (expected paper, ambient or environment)"),
        std::string::npos)
        << message;
}

// A preset saved before the modes existed names an environment but no mode: it loads in the
// paper's scene and says that its environment is not used.
TEST(Preset, EnvironmentWithoutAModeWarnsThatThePaperSceneIgnoresIt) {
    auto old =
        parsePreset(replaced(kValidPreset, R"("ga")",
                             R"("scene": {"environment_radiance": [0.25, 0.25, 0.25]}, "ga")"),
                    "p.json");
    ASSERT_TRUE(old.ok()) << old.error().message;
    EXPECT_EQ(old->preset.scene.mode, SceneMode::Paper);
    EXPECT_EQ(ambientRadiance(old->preset.scene), (std::array{0.0, 0.0, 0.0}));
    ASSERT_EQ(old->warnings.size(), 1u);
    EXPECT_NE(old->warnings[0].find("p.json: scene.environment_radiance: ignored"),
              std::string::npos)
        << old->warnings[0];
}

TEST(Preset, MissingTextureFileIsAnError) {
    auto dir = freshDirectory("texture");
    auto file = dir / "textured.json";
    std::ofstream(file) << replaced(kValidPreset, R"("ga")",
                                    R"("textures": {"base_color": "missing.png"}, "ga")");
    auto loaded = loadPreset(file);
    ASSERT_FALSE(loaded.ok());
    EXPECT_NE(loaded.error().message.find("textures.base_color: no such file"), std::string::npos);
    fs::remove_all(dir);
}

TEST(Preset, UnreadableFileNamesTheFile) {
    auto loaded = loadPreset("/nonexistent/preset.json");
    ASSERT_FALSE(loaded.ok());
    EXPECT_EQ(loaded.error().message, "/nonexistent/preset.json: cannot read: no such file");
}

std::vector<std::string> keysOf(const nlohmann::ordered_json& object) {
    std::vector<std::string> keys;
    for (const auto& field : object.items()) keys.push_back(field.key());
    return keys;
}

using Keys = std::vector<std::string>;

// A saved preset names its format and writes, in reading order, only what differs from the
// defaults: a shipped preset saved again keeps its target, family and GA size and drops the
// metric, seed and scene it spelled out although they are the defaults.
TEST(SavedPreset, IsMinimalOrderedAndVersioned) {
    auto loaded =
        loadPreset(fs::path(MATEVO_SOURCE_DIR) / "presets" / "validation_painted_metal.json");
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    const auto saved = nlohmann::ordered_json::parse(serializePreset(loaded->preset));
    EXPECT_EQ(keysOf(saved), (Keys{"format_version", "name", "description", "family", "target",
                                   "base_kappa", "textures", "ga"}));
    EXPECT_EQ(saved["format_version"], kPresetFormatVersion);
    EXPECT_EQ(keysOf(saved["family"]), (Keys{"coat", "base", "medium", "textured_layer"}));
    EXPECT_EQ(keysOf(saved["target"]), (Keys{"eta1", "eta2", "alpha1", "alpha2"}));
    EXPECT_EQ(keysOf(saved["ga"]), (Keys{"population", "generations"}));

    Preset changed = loaded->preset;
    changed.ga.seed = 7;
    changed.scene.imageSize = 128;
    changed.ga.metric = DistanceMetric::Manhattan;
    const auto savedChanged = nlohmann::ordered_json::parse(serializePreset(changed));
    EXPECT_EQ(keysOf(savedChanged["ga"]), (Keys{"population", "generations", "metric", "seed"}));
    EXPECT_EQ(savedChanged["scene"], (nlohmann::ordered_json{{"image_size", 128}}));
    auto reread = parsePreset(savedChanged.dump(), "again.json");
    ASSERT_TRUE(reread.ok()) << reread.error().message;
    EXPECT_EQ(reread->preset, changed);
}

// tests/data/saved_preset.json is what matevo writes for a preset with kept materials and a
// changed scene: it reads back to the same preset and is written again byte for byte (the
// preset_schema test validates the same file against docs/preset.schema.json).
TEST(SavedPreset, TheCommittedExampleIsWhatMatevoWrites) {
    const fs::path example = fs::path(MATEVO_TEST_DATA_DIR) / "saved_preset.json";
    auto loaded = loadPreset(example);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    EXPECT_TRUE(loaded->warnings.empty());
    std::ifstream in(example);
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    EXPECT_EQ(serializePreset(loaded->preset), text);
    EXPECT_EQ(loaded->preset.kept.size(), 2u);
    EXPECT_EQ(loaded->preset.scene.mode, SceneMode::Ambient);
}

// A preset written before format versions (every field spelled out, no "format_version") reads
// as it always did; a newer format than this matevo knows is refused, naming the field.
TEST(SavedPreset, OldFullPresetsReadAndNewerFormatsAreRefused) {
    const std::string full = R"({
  "name": "full", "description": "",
  "family": {"coat": "clearcoat", "base": "conductor", "medium": false, "textured_layer": "none"},
  "target": {"eta1": 1.2, "eta2": 0.8, "alpha1": 0.03, "alpha2": 0.1, "depth": 0.0,
             "sigma_s": [0, 0, 0], "sigma_a": [0, 0, 0], "g": 0.0},
  "textures": {"roughness": "", "base_color": ""},
  "ga": {"population": 50, "generations": 5, "metric": "euclidean",
         "weights": [1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1], "normalize_by_range": false,
         "elitism": 0, "seed": 1},
  "scene": {"mode": "paper", "image_size": 256, "camera_position": [0, 0, 4],
            "field_of_view_degrees": 32, "light_direction": [-0.5, 0.6, 0.62],
            "light_radiance": [1.5, 1.5, 1.5], "environment_radiance": [0.25, 0.25, 0.25],
            "environment": "studio"},
  "base_kappa": [3.1, 2.9, 2.8]
})";
    auto old = parsePreset(full, "full.json");
    ASSERT_TRUE(old.ok()) << old.error().message;
    EXPECT_TRUE(old->warnings.empty());
    auto minimal = parsePreset(kValidPreset, "p.json");
    ASSERT_TRUE(minimal.ok());
    Preset expected = minimal->preset;
    expected.name = "full";
    expected.ga.metric = DistanceMetric::Euclidean;
    expected.ga.seed = 1;
    EXPECT_EQ(old->preset, expected);

    EXPECT_EQ(errorOf(replaced(kValidPreset, R"("name")", R"("format_version": 3, "name")")),
              "p.json: format_version: version 3 is newer than this matevo reads (2)");
}

// From format 2 on, a scene field without scene.mode is simply stored (the mode is the
// default's); only a format-1 preset gets the warning of the test above.
TEST(SavedPreset, AFormat2SceneWithoutAModeKeepsItsFields) {
    auto parsed = parsePreset(
        replaced(
            kValidPreset, R"("name")",
            R"("format_version": 2, "scene": {"environment_radiance": [0.5, 0.5, 0.5]}, "name")"),
        "p.json");
    ASSERT_TRUE(parsed.ok()) << parsed.error().message;
    EXPECT_TRUE(parsed->warnings.empty());
    EXPECT_EQ(parsed->preset.scene.environmentRadiance, (std::array{0.5, 0.5, 0.5}));
    auto reparsed = parsePreset(serializePreset(parsed->preset), "again.json");
    ASSERT_TRUE(reparsed.ok());
    EXPECT_TRUE(reparsed->warnings.empty());
    EXPECT_EQ(reparsed->preset, parsed->preset);
}

TEST(ShippedPresets, ValidationMetalLoadsWithoutWarnings) {
    auto loaded = loadPreset(fs::path(MATEVO_SOURCE_DIR) / "presets" / "validation_metal.json");
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    EXPECT_TRUE(loaded->warnings.empty());
    EXPECT_DOUBLE_EQ(loaded->preset.target.alpha1(), 0.03);
}

TEST(ShippedPresets, EveryPresetLoadsWithoutWarnings) {
    int count = 0;
    for (const auto& entry : fs::directory_iterator(fs::path(MATEVO_SOURCE_DIR) / "presets")) {
        if (entry.path().extension() != ".json") continue;
        ++count;
        auto loaded = loadPreset(entry.path());
        ASSERT_TRUE(loaded.ok()) << loaded.error().message;
        EXPECT_TRUE(loaded->warnings.empty()) << entry.path();
    }
    EXPECT_GE(count, 3);
}

}  // namespace
}  // namespace matevo
