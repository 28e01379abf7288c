// Export of the three validation presets to glTF and MaterialX: the files re-read by tinygltf
// (the library that wrote them) field by field, the MaterialX document well-formed (libxml2)
// with MaterialX 1.39's input names, and the reported ΔE00 recomputed here from our glTF BRDF
// render against our Belcour render.
#include "export/ExportSet.h"

#include <libxml/parser.h>
#include <libxml/tree.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <tiny_gltf.h>
#include <nlohmann/json.hpp>

#include "documents/Preset.h"
#include "documents/PresetTextures.h"
#include "export/GltfRenderer.h"
#include "export/GltfWriter.h"
#include "export/MaterialXWriter.h"
#include "render/CpuPopulationRenderer.h"
#include "scene/SphereRenderer.h"
#include "support/RunCommand.h"
#include "support/ScratchFolder.h"

namespace matevo {
namespace {

namespace fs = std::filesystem;

const fs::path kPresets = fs::path(MATEVO_SOURCE_DIR) / "presets";

MaterialFile presetTarget(const std::string& name, SceneMode mode = SceneMode::Paper) {
    const fs::path file = kPresets / (name + ".json");
    auto loaded = loadPreset(file);
    EXPECT_TRUE(loaded.ok()) << loaded.error().message;
    MaterialFile material = materialFromPreset(loaded->preset, file, loaded->preset.target, name);
    material.scene.mode = mode;
    return material;
}

// The fits are the slow part: each preset is fitted once for every test here, and written in
// each format from that one fit.
const ExportReport& exportedPreset(const std::string& name, ExportFormat format,
                                   const fs::path& file, SceneMode mode = SceneMode::Paper) {
    static std::map<std::string, FittedSet> fits;
    static std::map<std::string, ExportReport> reports;
    const std::string key = name + std::string(toString(mode));
    auto fit = fits.find(key);
    if (fit == fits.end()) {
        CpuPopulationRenderer belcour({});
        auto fitted = fitForExport({presetTarget(name, mode)}, belcour);
        EXPECT_TRUE(fitted.ok()) << fitted.error().message;
        fit = fits.emplace(key, std::move(*fitted)).first;
    }
    auto report = writeExport(fit->second, format, file);
    EXPECT_TRUE(report.ok()) << report.error().message;
    return reports.insert_or_assign(name + file.string(), std::move(*report)).first->second;
}

const char* const kValidationPresets[] = {"validation_metal", "validation_painted_metal",
                                          "validation_metal_depth"};

double numberOf(const tinygltf::Value& object, const std::string& key) {
    return object.Get(key).GetNumberAsDouble();
}

TEST(ExportSet, ACancelledExportEndsCancelledAndWritesNothing) {
    testing::ScratchFolder folder("export-cancelled");
    CpuPopulationRenderer belcour({});
    const CancelToken cancel;
    cancel.cancel();
    const fs::path file = folder / "set.gltf";
    auto report = exportMaterials({presetTarget("validation_metal")}, belcour, ExportFormat::Gltf,
                                  file, {}, {}, {}, cancel);
    ASSERT_FALSE(report.ok());
    EXPECT_EQ(report.error().kind, ErrorKind::Cancelled);
    EXPECT_FALSE(fs::exists(file));
}

TEST(ExportSet, GltfFilesReadBackFieldByField) {
    testing::ScratchFolder folder("export");
    for (const char* name : kValidationPresets) {
        for (ExportFormat format : {ExportFormat::Gltf, ExportFormat::Glb}) {
            const fs::path file = folder / (std::string(name) + std::string(fileExtension(format)));
            const ExportReport& report = exportedPreset(name, format, file);
            ASSERT_EQ(report.variants.size(), 1u);
            const GltfMaterial& fitted = report.variants[0].fit.material;

            tinygltf::TinyGLTF loader;
            tinygltf::Model model;
            std::string error, warning;
            const bool loaded =
                format == ExportFormat::Glb
                    ? loader.LoadBinaryFromFile(&model, &error, &warning, file.string())
                    : loader.LoadASCIIFromFile(&model, &error, &warning, file.string());
            ASSERT_TRUE(loaded) << error;
            EXPECT_TRUE(warning.empty()) << warning;
            if (format == ExportFormat::Gltf) {
                // NAME.HASH.bin (files/CompanionFiles.h), beside the JSON.
                const std::string& uri = model.buffers[0].uri;
                EXPECT_EQ(uri.rfind(std::string(name) + ".", 0), 0u) << uri;
                EXPECT_EQ(uri.size(), std::strlen(name) + 1 + 16 + 4) << uri;
                EXPECT_EQ(fs::file_size(folder / uri), model.buffers[0].data.size());
            }
            ASSERT_EQ(model.materials.size(), 1u);
            const auto& material = model.materials[0];
            EXPECT_EQ(material.name, name);
            const auto& pbr = material.pbrMetallicRoughness;
            for (int c = 0; c < 3; ++c)
                EXPECT_DOUBLE_EQ(pbr.baseColorFactor[std::size_t(c)], fitted.baseColor[c]);
            EXPECT_DOUBLE_EQ(pbr.metallicFactor, fitted.metallic);
            EXPECT_DOUBLE_EQ(pbr.roughnessFactor, fitted.roughness);
            const auto& clearcoat = material.extensions.at("KHR_materials_clearcoat");
            EXPECT_DOUBLE_EQ(numberOf(clearcoat, "clearcoatFactor"), fitted.clearcoat);
            EXPECT_DOUBLE_EQ(numberOf(clearcoat, "clearcoatRoughnessFactor"),
                             fitted.clearcoatRoughness);
            EXPECT_EQ(material.extensions.count("KHR_materials_ior"), iorActs(fitted) ? 1u : 0u);
            if (iorActs(fitted)) {
                EXPECT_DOUBLE_EQ(numberOf(material.extensions.at("KHR_materials_ior"), "ior"),
                                 fitted.ior);
            }
            if (specularActs(fitted)) {
                EXPECT_DOUBLE_EQ(
                    numberOf(material.extensions.at("KHR_materials_specular"), "specularFactor"),
                    fitted.specular);
            }
            // Textures follow the preset: painted metal's roughness drives the coat's and the
            // base's, metal depth's base colour texture the base colour.
            const bool painted = std::string(name) == "validation_painted_metal";
            EXPECT_EQ(clearcoat.Has("clearcoatRoughnessTexture"), painted);
            EXPECT_EQ(pbr.metallicRoughnessTexture.index >= 0, painted);
            EXPECT_EQ(pbr.baseColorTexture.index >= 0,
                      std::string(name) == "validation_metal_depth");
            for (const auto& image : model.images) EXPECT_GT(image.width, 0) << image.name;
            // One sphere: positions on the unit sphere, as many UVs as positions.
            ASSERT_EQ(model.meshes.size(), 1u);
            const auto& primitive = model.meshes[0].primitives[0];
            EXPECT_EQ(primitive.material, 0);
            const auto& positions =
                model.accessors[std::size_t(primitive.attributes.at("POSITION"))];
            EXPECT_EQ(model.accessors[std::size_t(primitive.attributes.at("TEXCOORD_0"))].count,
                      positions.count);
            EXPECT_EQ(model.nodes.size(), 1u);
            EXPECT_NE(std::find(model.extensionsUsed.begin(), model.extensionsUsed.end(),
                                "KHR_materials_clearcoat"),
                      model.extensionsUsed.end());
        }
    }
}

// The report's ΔE00 is what our glTF render of the written parameters gives against our Belcour
// render; returns it.
double recomputedDeltaE(const std::string& name, SceneMode mode, const fs::path& folder) {
    const ExportReport& report = exportedPreset(
        name, ExportFormat::Glb, folder / (name + std::string(toString(mode)) + ".glb"), mode);
    const MaterialFile material = presetTarget(name, mode);
    auto textures = loadSceneTextures(material, name);
    EXPECT_TRUE(textures.ok());
    const int size = report.settings.reportSize;
    const Image gltf =
        renderGltfSphere(report.variants[0].fit.material, *textures, material.scene, size);
    const Image belcour = renderSphereCpu(material.material, *textures, material.scene, size);
    auto difference = compareImages(gltf, belcour);
    EXPECT_TRUE(difference.ok());
    EXPECT_NEAR(difference->stats.mean, report.variants[0].deltaE.stats.mean, 1e-9) << name;
    std::printf("%s (%s scene): mean dE00 %.3f (p95 %.3f) at %d px, %d renders\n", name.c_str(),
                std::string(toString(mode)).c_str(), difference->stats.mean, difference->stats.p95,
                size, report.variants[0].fit.evaluations);
    return difference->stats.mean;
}

TEST(ExportSet, ReportedDeltaEIsRecomputedFromTheGltfRender) {
    testing::ScratchFolder folder("export");
    double sum = 0.0;
    for (const char* name : kValidationPresets) {
        const double deltaE = recomputedDeltaE(name, SceneMode::Paper, folder.path());
        // The goal: glTF reaches the Belcour look within ΔE00 2 (docs/export.md has the figures).
        EXPECT_LT(deltaE, 2.0) << name;
        sum += deltaE;
    }
    std::printf("mean over the validation presets: %.3f\n", sum / 3.0);
}

// With the ambient light the environment goes through the glTF BRDF's directional albedo.
TEST(ExportSet, TheAmbientSceneIsFittedThroughTheAlbedo) {
    testing::ScratchFolder folder("export");
    EXPECT_LT(recomputedDeltaE("validation_metal", SceneMode::Ambient, folder.path()), 2.0);
}

// The official Khronos validator (npm gltf-validator, installed by scripts/install-deps.sh).
TEST(ExportSet, KhronosValidatorFindsNoErrors) {
    testing::ScratchFolder folder("export");
    std::string files;
    for (const char* name : kValidationPresets) {
        for (ExportFormat format : {ExportFormat::Gltf, ExportFormat::Glb}) {
            const fs::path file = folder / (std::string(name) + std::string(fileExtension(format)));
            exportedPreset(name, format, file);
            files += " '" + file.string() + "'";
        }
    }
    const fs::path script = fs::path(MATEVO_SOURCE_DIR) / "tests/export/gltf-validator/validate.js";
    const auto result =
        testing::runCommand(std::string(MATEVO_NODE) + " '" + script.string() + "'" + files);
    EXPECT_EQ(result.exitCode, 0) << result.out << result.err;
    std::size_t reports = 0;
    std::istringstream lines(result.out);
    for (std::string line; std::getline(lines, line);) {
        const auto report = nlohmann::json::parse(line);
        EXPECT_EQ(report["errors"], 0) << line;
        ++reports;
    }
    EXPECT_EQ(reports, 6u) << result.err;
}

tinygltf::Model loadGlb(const fs::path& file) {
    tinygltf::TinyGLTF loader;
    tinygltf::Model model;
    std::string error, warning;
    EXPECT_TRUE(loader.LoadBinaryFromFile(&model, &error, &warning, file.string())) << error;
    return model;
}

bool uses(const tinygltf::Model& model, const std::string& extension) {
    return std::find(model.extensionsUsed.begin(), model.extensionsUsed.end(), extension) !=
           model.extensionsUsed.end();
}

// The writer leaves out what does not act on the material, whatever the material holds: no ior
// or specular on a full metal (a client that reads the ior into the coat, as the Khronos Sample
// Viewer does, would otherwise render a different coat), no coat of weight 0, and nothing at
// glTF's defaults; what acts is written as it is.
TEST(ExportSet, WritesOnlyExtensionValuesThatAct) {
    testing::ScratchFolder folder("export");
    GltfMaterial metal;
    metal.metallic = 1.0;
    metal.ior = 2.62;
    metal.specular = 0.4;
    metal.clearcoat = 1.0;
    GltfMaterial paint = metal;
    paint.metallic = 0.3;
    paint.ior = 1.7;
    paint.specular = 0.8;
    GltfMaterial bare;
    bare.metallic = 0.5;
    bare.clearcoat = 0.0;
    const fs::path file = folder / "acting.glb";
    ASSERT_TRUE(
        writeGltf({{"metal", metal}, {"paint", paint}, {"bare", bare}}, SceneTextures{}, file)
            .ok());
    const tinygltf::Model model = loadGlb(file);
    ASSERT_EQ(model.materials.size(), 3u);
    const auto& metalExtensions = model.materials[0].extensions;
    EXPECT_EQ(metalExtensions.count("KHR_materials_clearcoat"), 1u);
    EXPECT_EQ(metalExtensions.count("KHR_materials_ior"), 0u);
    EXPECT_EQ(metalExtensions.count("KHR_materials_specular"), 0u);
    const auto& paintExtensions = model.materials[1].extensions;
    EXPECT_DOUBLE_EQ(numberOf(paintExtensions.at("KHR_materials_ior"), "ior"), 1.7);
    EXPECT_DOUBLE_EQ(numberOf(paintExtensions.at("KHR_materials_specular"), "specularFactor"), 0.8);
    EXPECT_TRUE(model.materials[2].extensions.empty());
    for (const char* extension :
         {"KHR_materials_clearcoat", "KHR_materials_ior", "KHR_materials_specular"})
        EXPECT_TRUE(uses(model, extension)) << extension;
    EXPECT_EQ(model.extensionsUsed.size(), 3u);
}

// What the fit gives the writer: a metal fit holds glTF's defaults for the values that do not act
// on it (so a client that reads them anyway sees glTF's defaults); the ior stays
// within the indices Table 2 gives the reference model's base, which for the validation presets'
// metal bases means none is written. The exported files carry ior and specular exactly where
// they act.
TEST(ExportSet, FitsWriteIorOnlyWhereItActsAndWithinTheReferenceRange) {
    testing::ScratchFolder folder("export");
    EXPECT_DOUBLE_EQ(maximumFittedIor({Coat::Roughcoat, Base::Dielectric}), 2.5);
    EXPECT_DOUBLE_EQ(maximumFittedIor({Coat::Clearcoat, Base::Conductor}),
                     GltfMaterial::kDefaultIor);
    for (const char* name : kValidationPresets) {
        const fs::path file = folder / (std::string(name) + ".glb");
        const ExportReport& report = exportedPreset(name, ExportFormat::Glb, file);
        const GltfMaterial& fitted = report.variants[0].fit.material;
        const MaterialFamily family = presetTarget(name).material.family;
        EXPECT_GE(fitted.ior, 1.0) << name;
        EXPECT_LE(fitted.ior, maximumFittedIor(family)) << name;
        EXPECT_FALSE(iorActs(fitted)) << name << ": a metal base has no dielectric ior";
        if (fitted.metallic == 1.0) {
            EXPECT_EQ(fitted.ior, GltfMaterial::kDefaultIor) << name;
            EXPECT_EQ(fitted.specular, 1.0) << name;
        }
        const tinygltf::Model model = loadGlb(file);
        ASSERT_EQ(model.materials.size(), 1u);
        const auto& extensions = model.materials[0].extensions;
        const bool dielectricLeft = model.materials[0].pbrMetallicRoughness.metallicFactor < 1.0;
        if (!dielectricLeft) {
            EXPECT_EQ(extensions.count("KHR_materials_ior"), 0u) << name;
            EXPECT_EQ(extensions.count("KHR_materials_specular"), 0u) << name;
        }
        if (extensions.count("KHR_materials_ior")) {
            const double ior = numberOf(extensions.at("KHR_materials_ior"), "ior");
            EXPECT_NE(ior, GltfMaterial::kDefaultIor) << name;
            EXPECT_LE(ior, maximumFittedIor(family)) << name;
        }
        // The report gives the values the file has, and says whether the goal is met.
        const auto json = exportReportJson(report);
        const auto& variant = json["variants"][0];
        EXPECT_EQ(variant["gltf"].contains("ior"), extensions.count("KHR_materials_ior") == 1);
        EXPECT_EQ(variant["within_goal"].get<bool>(),
                  variant["mean_de00"].get<double>() <= json["goal_mean_de00"].get<double>());
        std::printf("%s: metallic %.3f, ior %s, mean dE00 %.3f\n", name, fitted.metallic,
                    iorActs(fitted) ? std::to_string(fitted.ior).c_str() : "(none)",
                    report.variants[0].deltaE.stats.mean);
    }
}

// The PNG chunks that say how the samples are encoded: sRGB, and gAMA's value (100000 = 1.0).
struct PngEncodingChunks {
    bool srgb = false;
    long gamma = -1;
};

PngEncodingChunks pngEncodingChunks(const unsigned char* png, std::size_t size) {
    PngEncodingChunks chunks;
    const auto bigEndian = [&](std::size_t at) {
        return long(png[at]) << 24 | long(png[at + 1]) << 16 | long(png[at + 2]) << 8 |
               long(png[at + 3]);
    };
    for (std::size_t at = 8; at + 8 <= size;) {
        const long length = bigEndian(at);
        const std::string type(reinterpret_cast<const char*>(png + at + 4), 4);
        if (type == "sRGB") chunks.srgb = true;
        if (type == "gAMA") chunks.gamma = bigEndian(at + 8);
        at += 12 + std::size_t(length);
    }
    return chunks;
}

PngEncodingChunks imageChunks(const tinygltf::Model& model, const std::string& name) {
    for (const auto& image : model.images) {
        if (image.name != name) continue;
        const auto& view = model.bufferViews[std::size_t(image.bufferView)];
        return pngEncodingChunks(model.buffers[0].data.data() + view.byteOffset, view.byteLength);
    }
    ADD_FAILURE() << "no image " << name;
    return {};
}

// The roughness texture holds data, not colour: tagged linear (gAMA 1.0, no sRGB chunk), so
// that an importer or a viewer that honours the tag does not decode it as sRGB; the base colour
// texture stays tagged sRGB. Both in the glTF buffer and beside a MaterialX document.
TEST(ExportSet, TheRoughnessTextureIsTaggedLinear) {
    testing::ScratchFolder folder("export");
    const fs::path painted = folder / "painted.glb", depth = folder / "depth.glb";
    exportedPreset("validation_painted_metal", ExportFormat::Glb, painted);
    exportedPreset("validation_metal_depth", ExportFormat::Glb, depth);
    const PngEncodingChunks roughness = imageChunks(loadGlb(painted), "roughness");
    EXPECT_FALSE(roughness.srgb);
    EXPECT_EQ(roughness.gamma, 100000);
    const PngEncodingChunks baseColor = imageChunks(loadGlb(depth), "base_color");
    EXPECT_TRUE(baseColor.srgb);
    EXPECT_EQ(baseColor.gamma, -1);

    exportedPreset("validation_painted_metal", ExportFormat::MaterialX, folder / "painted.mtlx");
    int roughnessFiles = 0;
    for (const auto& entry : fs::directory_iterator(folder.path())) {
        const std::string fileName = entry.path().filename().string();
        if (fileName.find("_roughness") == std::string::npos) continue;
        ++roughnessFiles;
        std::ifstream in(entry.path(), std::ios::binary);
        const std::string bytes{std::istreambuf_iterator<char>(in),
                                std::istreambuf_iterator<char>()};
        const PngEncodingChunks chunks =
            pngEncodingChunks(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size());
        EXPECT_FALSE(chunks.srgb) << fileName;
        EXPECT_EQ(chunks.gamma, 100000) << fileName;
    }
    EXPECT_EQ(roughnessFiles, 1);
}

// MaterialX 1.39's gltf_pbr inputs and the nodes we use, named as its standard library does.
const std::set<std::string> kGltfPbrInputs = {"base_color", "metallic",           "roughness",
                                              "specular",   "specular_color",     "ior",
                                              "clearcoat",  "clearcoat_roughness"};

// An `image` node's file input names a file beside the document.
void expectTextureFileExists(xmlNodePtr image, const fs::path& folder) {
    bool named = false;
    for (xmlNodePtr input = image->children; input; input = input->next) {
        if (input->type != XML_ELEMENT_NODE) continue;
        xmlChar* inputName = xmlGetProp(input, BAD_CAST "name");
        xmlChar* value = xmlGetProp(input, BAD_CAST "value");
        if (inputName && value && std::string(reinterpret_cast<const char*>(inputName)) == "file") {
            named = true;
            EXPECT_TRUE(fs::is_regular_file(folder / reinterpret_cast<const char*>(value)))
                << reinterpret_cast<const char*>(value);
        }
        xmlFree(inputName);
        xmlFree(value);
    }
    EXPECT_TRUE(named);
}

TEST(ExportSet, MaterialXIsWellFormedWithMaterialXInputNames) {
    testing::ScratchFolder folder("export");
    for (const char* name : kValidationPresets) {
        const fs::path file = folder / (std::string(name) + ".mtlx");
        const ExportReport& report = exportedPreset(name, ExportFormat::MaterialX, file);
        ASSERT_EQ(report.variants.size(), 1u);
        xmlDocPtr document = xmlReadFile(file.c_str(), nullptr, XML_PARSE_NONET);
        ASSERT_NE(document, nullptr) << file;
        xmlNodePtr root = xmlDocGetRootElement(document);
        EXPECT_STREQ(reinterpret_cast<const char*>(root->name), "materialx");
        xmlChar* version = xmlGetProp(root, BAD_CAST "version");
        EXPECT_STREQ(reinterpret_cast<const char*>(version), "1.39");
        xmlFree(version);
        std::map<std::string, std::string> shaderInputs;
        std::set<std::string> nodeNames;
        int materials = 0, images = 0;
        for (xmlNodePtr node = root->children; node; node = node->next) {
            if (node->type != XML_ELEMENT_NODE) continue;
            const std::string element = reinterpret_cast<const char*>(node->name);
            xmlChar* nodeName = xmlGetProp(node, BAD_CAST "name");
            EXPECT_TRUE(nodeNames.insert(reinterpret_cast<const char*>(nodeName)).second);
            xmlFree(nodeName);
            if (element == "surfacematerial") ++materials;
            if (element == "image") ++images;
            if (element == "image") expectTextureFileExists(node, folder.path());
            if (element != "gltf_pbr") continue;
            for (xmlNodePtr input = node->children; input; input = input->next) {
                if (input->type != XML_ELEMENT_NODE) continue;
                xmlChar* inputName = xmlGetProp(input, BAD_CAST "name");
                xmlChar* value = xmlGetProp(input, BAD_CAST "value");
                xmlChar* connected = xmlGetProp(input, BAD_CAST "nodename");
                const std::string key = reinterpret_cast<const char*>(inputName);
                EXPECT_TRUE(kGltfPbrInputs.count(key)) << key;
                shaderInputs[key] = value ? reinterpret_cast<const char*>(value) : "(connected)";
                EXPECT_TRUE(value || connected) << key;
                if (connected) {
                    EXPECT_TRUE(nodeNames.count(reinterpret_cast<const char*>(connected)));
                }
                xmlFree(inputName);
                xmlFree(value);
                xmlFree(connected);
            }
        }
        EXPECT_EQ(materials, 1);
        // Painted metal textures its roughnesses, metal depth its base colour.
        EXPECT_EQ(images > 0, std::string(name) != "validation_metal") << name;
        // Only the inputs that act on the fitted material, as in the glTF (GltfMaterial.h); the
        // others keep gltf_pbr's defaults, which are glTF's.
        const GltfMaterial& fitted = report.variants[0].fit.material;
        std::set<std::string> acting = {"base_color", "metallic", "roughness"};
        if (specularActs(fitted)) acting.insert({"specular", "specular_color"});
        if (iorActs(fitted)) acting.insert("ior");
        if (clearcoatActs(fitted)) acting.insert({"clearcoat", "clearcoat_roughness"});
        std::set<std::string> written;
        for (const auto& [input, value] : shaderInputs) written.insert(input);
        EXPECT_EQ(written, acting) << name;
        EXPECT_NEAR(std::stod(shaderInputs.at("metallic")),
                    report.variants[0].fit.material.metallic, 1e-5);
        xmlFreeDoc(document);
    }
}

// A document's inputs follow what acts (GltfMaterial.h), whatever values the material holds: a
// full metal without a coat carries neither ior, specular nor clear coat, a paint all three.
TEST(ExportSet, MaterialXWritesOnlyTheInputsThatAct) {
    GltfMaterial metal;
    metal.metallic = 1.0;
    metal.ior = 2.6;
    metal.specular = 0.4;
    metal.clearcoat = 0.0;
    metal.clearcoatRoughness = 0.3;
    GltfMaterial paint;
    paint.metallic = 0.2;
    paint.ior = 1.7;
    paint.specular = 0.8;
    paint.clearcoat = 0.5;
    const std::string document = materialXDocument({{"metal", metal}, {"paint", paint}}, "", "");
    const auto count = [&](const std::string& input) {
        std::size_t found = 0;
        for (auto at = document.find("name=\"" + input + "\""); at != std::string::npos;
             at = document.find("name=\"" + input + "\"", at + 1))
            ++found;
        return found;
    };
    EXPECT_EQ(count("metallic"), 2u);
    for (const char* input :
         {"ior", "specular", "specular_color", "clearcoat", "clearcoat_roughness"})
        EXPECT_EQ(count(input), 1u) << input << "\n" << document;
}

}  // namespace
}  // namespace matevo
