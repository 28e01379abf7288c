// `matevo export` end to end through the real executable: what evolve and variant sets write goes
// in; a glTF/MaterialX file and a report come out; mistakes exit 2 with one line.
#include <libxml/parser.h>
#include <libxml/tree.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <tiny_gltf.h>
#include <nlohmann/json.hpp>

#include "documents/MaterialFile.h"
#include "support/RunCommand.h"
#include "support/ScratchFolder.h"

namespace matevo {
namespace {

namespace fs = std::filesystem;

const std::string kPaintedMetal =
    (fs::path(MATEVO_SOURCE_DIR) / "presets/validation_painted_metal.json").string();

std::string shellQuoted(const fs::path& path) {
    std::string text = "'";  // appended piecewise: GCC 12 warns falsely (-Wrestrict) otherwise
    text += path.string();
    text += "'";
    return text;
}

TEST(ExportCommand, EvolveJsonExportsToGlbWithAReport) {
    testing::ScratchFolder folder("export_cli");
    const auto evolved = testing::runMatevo(
        "evolve --population 8 --generations 2 --json --preset " + shellQuoted(kPaintedMetal));
    ASSERT_EQ(evolved.exitCode, 0) << evolved.err;
    std::ofstream(folder / "ev.json") << evolved.out;

    const auto out = folder / "best.glb";
    const auto exported = testing::runMatevo(
        "export --genome " + shellQuoted(folder / "ev.json") + " --out " + shellQuoted(out) +
        " --json --fit-size 24 --fit-renders 120 --report-size 32"
        " --images " +
        shellQuoted(folder / "look"));
    ASSERT_EQ(exported.exitCode, 0) << exported.err;
    const auto report = nlohmann::json::parse(exported.out);
    EXPECT_EQ(report["format"], "glb");
    ASSERT_EQ(report["variants"].size(), 1u);
    const auto& variant = report["variants"][0];
    EXPECT_GE(variant["mean_de00"].get<double>(), 0.0);
    EXPECT_TRUE(variant["gltf"].contains("clearcoat_roughness"));
    EXPECT_EQ(variant["gltf"]["clearcoat_roughness_texture"], true);
    EXPECT_EQ(variant["gltf"]["roughness_texture"], true);
    EXPECT_TRUE(fs::exists(out));
    const std::string stem = "validation_painted_metal_best";
    for (const char* suffix : {"_matevo.png", "_gltf.png", "_heatmap.png"})
        EXPECT_TRUE(fs::exists(folder / "look" / (stem + suffix))) << suffix;
}

std::string contentsOf(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The file stem `export --images` gives a material's name.
std::string imageStem(const std::string& name) {
    std::string stem;
    for (unsigned char c : name) stem += std::isalnum(c) || c == '-' || c == '_' ? char(c) : '_';
    return stem;
}

// The materials of a MaterialX document: surfacematerial names, and per gltf_pbr the value of
// its metallic input; every image node's file must exist beside the document.
struct MaterialXContents {
    std::vector<std::string> materials;
    std::vector<double> metallic;
};

MaterialXContents readMaterialX(const fs::path& file) {
    MaterialXContents contents;
    xmlDocPtr document = xmlReadFile(file.c_str(), nullptr, XML_PARSE_NONET);
    EXPECT_NE(document, nullptr) << file;
    if (!document) return contents;
    const auto property = [](xmlNodePtr node, const char* name) {
        xmlChar* value = xmlGetProp(node, BAD_CAST name);
        std::string text = value ? reinterpret_cast<const char*>(value) : "";
        xmlFree(value);
        return text;
    };
    for (xmlNodePtr node = xmlDocGetRootElement(document)->children; node; node = node->next) {
        if (node->type != XML_ELEMENT_NODE) continue;
        const std::string element = reinterpret_cast<const char*>(node->name);
        if (element == "surfacematerial") contents.materials.push_back(property(node, "name"));
        for (xmlNodePtr input = node->children; input; input = input->next) {
            if (input->type != XML_ELEMENT_NODE) continue;
            if (element == "gltf_pbr" && property(input, "name") == "metallic")
                contents.metallic.push_back(std::stod(property(input, "value")));
            if (element == "image" && property(input, "name") == "file") {
                EXPECT_TRUE(fs::is_regular_file(file.parent_path() / property(input, "value")))
                    << property(input, "value");
            }
        }
    }
    xmlFreeDoc(document);
    return contents;
}

// The round trip as a user makes it: `variants --out DIR` writes a set, `export --variants DIR`
// takes it to glTF and to MaterialX. The material files must carry the whole material (family,
// kappa, textures, scene): export's own render of each variant equals, byte for byte, the render
// `variants` wrote; the written assets hold one material per variant, in the set's order, with
// the reported fitted values.
TEST(ExportCommand, AVariantsSetExportsToGltfAndMaterialX) {
    testing::ScratchFolder folder("export_cli");
    const auto set = folder / "set";
    const auto made = testing::runMatevo(
        "variants --preset " + shellQuoted(kPaintedMetal) +
        " --count 3 --band 2,10 --min-apart 1 --seed 5 --size 48 --fitness-size 16"
        " --backend cpu --out " +
        shellQuoted(set));
    ASSERT_EQ(made.exitCode, 0) << made.err;
    std::ifstream reportFile(set / "report.json");
    const auto variantsReport = nlohmann::json::parse(reportFile);
    const auto& variants = variantsReport["variants"];
    ASSERT_EQ(variants.size(), 3u);
    std::vector<std::string> names;
    for (const auto& variant : variants) {
        auto material = loadMaterial(set / variant["file"].get<std::string>(), MaterialFile{});
        ASSERT_TRUE(material.ok()) << material.error().message;
        names.push_back(material->file.name);
    }

    for (const std::string format : {"gltf", "mtlx"}) {
        SCOPED_TRACE(format);
        const auto out = folder / ("set." + format);
        const auto look = folder / ("look_" + format);
        const auto exported = testing::runMatevo(
            "export --variants " + shellQuoted(set) + " --out " + shellQuoted(out) +
            " --backend cpu --fit-size 16 --fit-renders 60 --report-size 48 --json --images " +
            shellQuoted(look));
        ASSERT_EQ(exported.exitCode, 0) << exported.err;
        const auto report = nlohmann::json::parse(exported.out);
        EXPECT_EQ(report["format"], format);
        ASSERT_EQ(report["variants"].size(), variants.size());
        for (std::size_t i = 0; i < variants.size(); ++i) {
            const auto& fitted = report["variants"][i];
            EXPECT_EQ(fitted["name"], names[i]);
            EXPECT_EQ(contentsOf(look / (imageStem(names[i]) + "_matevo.png")),
                      contentsOf(set / variants[i]["image"].get<std::string>()))
                << names[i] << ": export did not render the material variants wrote";
            EXPECT_LE(fitted["mean_de00"].get<double>(), 10.0) << names[i];
        }

        if (format == "gltf") {
            tinygltf::TinyGLTF loader;
            tinygltf::Model model;
            std::string error, warning;
            ASSERT_TRUE(loader.LoadASCIIFromFile(&model, &error, &warning, out.string())) << error;
            ASSERT_EQ(model.materials.size(), variants.size());
            ASSERT_EQ(model.nodes.size(), variants.size());  // a sphere each, side by side
            EXPECT_NE(model.nodes[0].translation, model.nodes[1].translation);
            for (std::size_t i = 0; i < variants.size(); ++i) {
                const auto& fitted = report["variants"][i]["gltf"];
                const auto& material = model.materials[i];
                EXPECT_EQ(material.name, names[i]);
                EXPECT_DOUBLE_EQ(material.pbrMetallicRoughness.metallicFactor,
                                 fitted["metallic"].get<double>());
                EXPECT_DOUBLE_EQ(material.pbrMetallicRoughness.roughnessFactor,
                                 fitted["roughness"].get<double>());
                // Painted metal textures its roughness: the texture travels in the buffer.
                EXPECT_GE(material.pbrMetallicRoughness.metallicRoughnessTexture.index, 0);
            }
        } else {
            const MaterialXContents document = readMaterialX(out);
            ASSERT_EQ(document.materials.size(), variants.size());
            ASSERT_EQ(document.metallic.size(), variants.size());
            for (std::size_t i = 0; i < variants.size(); ++i)
                EXPECT_NEAR(document.metallic[i],
                            report["variants"][i]["gltf"]["metallic"].get<double>(), 1e-5);
        }
    }
}

// A set is read the one way every command reads it (documents/VariantFolder.h): every material
// .json in DIR/variants, in name order, whatever its name (a material the user added is exported,
// as `scene --variants` draws it); other files are passed over; a .json that is not a material is
// refused with one line naming it, and nothing is written.
TEST(ExportCommand, ASetIsEveryMaterialFileInItsFolder) {
    testing::ScratchFolder folder("export_cli");
    const auto set = folder / "set";
    const auto made = testing::runMatevo(
        "variants --count 2 --band 2,10 --min-apart 1 --size 16 --fitness-size 8"
        " --max-evaluations 200 --backend cpu --out " +
        shellQuoted(set));
    ASSERT_EQ(made.exitCode, 0) << made.err;
    // A material the user put in the set: a copy of the first variant under a name of its own.
    auto added = nlohmann::json::parse(contentsOf(set / "variants" / "variant_000.json"));
    added["name"] = "added";
    std::ofstream(set / "variants" / "added.json") << added.dump();
    std::ofstream(set / "variants" / "notes.txt") << "picked on Tuesday\n";
    const auto out = folder / "set.glb";
    const std::string exportSet = "export --variants " + shellQuoted(set) + " --out " +
                                  shellQuoted(out) +
                                  " --backend cpu --fit-size 16 --fit-renders 20 --report-size 16"
                                  " --json";
    const auto exported = testing::runMatevo(exportSet);
    ASSERT_EQ(exported.exitCode, 0) << exported.err;
    const auto report = nlohmann::json::parse(exported.out);
    ASSERT_EQ(report["variants"].size(), 3u) << exported.out;
    EXPECT_EQ(report["variants"][0]["name"], "added");  // name order

    fs::remove(out);
    std::ofstream(set / "variants" / "variant_001.json") << R"({"eta1": 1.3, "eta2": )";
    const auto broken = testing::runMatevo(exportSet);
    EXPECT_EQ(broken.exitCode, 2) << broken.err;
    EXPECT_EQ(std::count(broken.err.begin(), broken.err.end(), '\n'), 1) << broken.err;
    EXPECT_NE(broken.err.find((set / "variants" / "variant_001.json").string()), std::string::npos)
        << broken.err;
    EXPECT_FALSE(fs::exists(out));
}

// Whether `text` holds `option` as a whole word ("--fit-size" does not name "--fit").
bool names(const std::string& text, const std::string& option) {
    for (std::size_t at = text.find(option); at != std::string::npos;
         at = text.find(option, at + 1)) {
        const std::size_t end = at + option.size();
        const unsigned char next = end < text.size() ? text[end] : ' ';
        if (!std::isalnum(next) && next != '-') return true;
    }
    return false;
}

// Every option the help describes is on its usage line.
TEST(ExportCommand, TheUsageLineNamesEveryOption) {
    const auto help = testing::runMatevo("help export");
    ASSERT_EQ(help.exitCode, 0);
    const std::size_t usageEnd = help.out.find("\n\n");
    ASSERT_NE(usageEnd, std::string::npos);
    const std::string usage = help.out.substr(0, usageEnd);
    // The command's own text: the options every command shares follow its last blank line.
    const std::size_t ownEnd = help.out.rfind("\n\n");
    std::istringstream body(help.out.substr(usageEnd, ownEnd - usageEnd));
    int described = 0;
    for (std::string line; std::getline(body, line);) {
        if (line.rfind("  --", 0) != 0) continue;
        const std::string option = line.substr(2, line.find(' ', 2) - 2);
        EXPECT_TRUE(names(usage, option)) << option << " is not on the usage line:\n" << usage;
        ++described;
    }
    EXPECT_GE(described, 13);
}

// Like the other commands' --out, export makes the folder it writes into.
TEST(ExportCommand, OutCreatesItsFolder) {
    testing::ScratchFolder folder("export_cli");
    const auto out = folder / "new" / "deeper" / "target.glb";
    const auto exported =
        testing::runMatevo("export --out " + shellQuoted(out) +
                           " --backend cpu --fit-size 16 --fit-renders 20 --report-size 16");
    ASSERT_EQ(exported.exitCode, 0) << exported.err;
    EXPECT_TRUE(fs::is_regular_file(out));
}

TEST(ExportCommand, MistakesExitTwoWithOneLine) {
    testing::ScratchFolder folder("export_cli");
    const auto genome = folder / "g.json";
    std::ofstream(genome) << R"({"eta1": 1.2, "eta2": 0.8, "alpha1": 0.03, "alpha2": 0.1})";
    const auto out = folder / "x.glb";
    fs::create_directories(folder / "empty");
    for (const std::string& arguments :
         {"export --genome " + shellQuoted(genome) + " --variants " + shellQuoted(folder.path()) +
              " --out " + shellQuoted(out),
          "export --genome " + shellQuoted(genome) + " --out " + shellQuoted(folder / "x.obj"),
          "export --genome " + shellQuoted(genome) + " --format fbx --out " + shellQuoted(out),
          "export --genome " + shellQuoted(genome) + " --format gltf --out " + shellQuoted(out),
          "export --genome " + shellQuoted(genome) + " --out " + shellQuoted(genome / "x.glb"),
          "export --genome " + shellQuoted(genome) + " --out " + shellQuoted(out) + " --mesh knot",
          "export --genome " + shellQuoted(genome) + " --out " + shellQuoted(out) +
              " --arrange variants --instances 3",
          "export --genome " + shellQuoted(genome) + " --out " + shellQuoted(out) +
              " --arrange carousel",
          "export --genome " + shellQuoted(genome) + " --out " + shellQuoted(folder / "x.mtlx") +
              " --arrange crowd",
          "export --variants " + shellQuoted(folder / "empty") + " --out " + shellQuoted(out),
          "export --variants " + shellQuoted(folder / "missing") + " --out " + shellQuoted(out)}) {
        const auto result = testing::runMatevo(arguments);
        EXPECT_EQ(result.exitCode, 2) << arguments;
        EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
        EXPECT_FALSE(fs::exists(out)) << arguments;
    }
}

}  // namespace
}  // namespace matevo
