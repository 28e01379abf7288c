#include "export/MaterialXWriter.h"

#include <cctype>
#include <cstdio>
#include <set>
#include <sstream>

#include "common/XmlText.h"
#include "files/CompanionFiles.h"
#include "image/ImageFile.h"

namespace matevo {

namespace {

// MaterialX names are identifiers: letters, digits and underscores, not starting with a digit.
std::string identifier(const std::string& text, std::set<std::string>& taken) {
    std::string name;
    for (unsigned char c : text) name += std::isalnum(c) ? char(c) : '_';
    if (name.empty() || std::isdigit(static_cast<unsigned char>(name[0]))) name.insert(0, "m_");
    std::string unique = name;
    for (int suffix = 2; taken.count(unique); ++suffix)
        unique = name + "_" + std::to_string(suffix);
    taken.insert(unique);
    return unique;
}

std::string color(const std::array<double, 3>& value) {
    return xmlNumber(value[0]) + ", " + xmlNumber(value[1]) + ", " + xmlNumber(value[2]);
}

void writeInput(std::ostream& out, const std::string& name, const std::string& type,
                const std::string& value) {
    out << "    <input name=\"" << name << "\" type=\"" << type << "\" value=\"" << value
        << "\" />\n";
}

void writeConnection(std::ostream& out, const std::string& name, const std::string& type,
                     const std::string& node) {
    out << "    <input name=\"" << name << "\" type=\"" << type << "\" nodename=\"" << node
        << "\" />\n";
}

// factor * texture: `image` -> (`extract` green) -> `multiply`; returns the multiply node.
std::string texturedFactor(std::ostream& out, const std::string& prefix, const std::string& file,
                           bool colour, const std::string& factor) {
    const std::string image = prefix + "_image", product = prefix + "_factor";
    out << "  <image name=\"" << image << "\" type=\"" << (colour ? "color3" : "vector3")
        << "\">\n";
    out << "    <input name=\"file\" type=\"filename\" value=\"" << xmlEscaped(file) << "\""
        << (colour ? " colorspace=\"srgb_texture\"" : "") << " />\n";
    out << "  </image>\n";
    std::string source = image;
    if (!colour) {
        source = prefix + "_green";
        out << "  <extract name=\"" << source << "\" type=\"float\">\n";
        writeConnection(out, "in", "vector3", image);
        writeInput(out, "index", "integer", "1");
        out << "  </extract>\n";
    }
    const std::string type = colour ? "color3" : "float";
    out << "  <multiply name=\"" << product << "\" type=\"" << type << "\">\n";
    writeConnection(out, "in1", type, source);
    writeInput(out, "in2", type, factor);
    out << "  </multiply>\n";
    return product;
}

}  // namespace

std::string materialXDocument(const std::vector<NamedGltfMaterial>& materials,
                              const std::string& baseColorFile, const std::string& roughnessFile) {
    std::ostringstream out;
    out << "<?xml version=\"1.0\"?>\n<materialx version=\"1.39\">\n";
    std::set<std::string> taken;
    for (const auto& [name, m] : materials) {
        const std::string id = identifier(name, taken);
        std::string baseColorNode, roughnessNode, clearcoatRoughnessNode;
        if (m.baseColorTextured)
            baseColorNode =
                texturedFactor(out, id + "_base_color", baseColorFile, true, color(m.baseColor));
        if (m.roughnessTextured)
            roughnessNode = texturedFactor(out, id + "_roughness", roughnessFile, false,
                                           xmlNumber(m.roughness));
        if (m.clearcoatRoughnessTextured && clearcoatActs(m))
            clearcoatRoughnessNode = texturedFactor(out, id + "_clearcoat_roughness", roughnessFile,
                                                    false, xmlNumber(m.clearcoatRoughness));
        const std::string shader = id + "_shader";
        out << "  <gltf_pbr name=\"" << shader << "\" type=\"surfaceshader\">\n";
        if (baseColorNode.empty())
            writeInput(out, "base_color", "color3", color(m.baseColor));
        else
            writeConnection(out, "base_color", "color3", baseColorNode);
        writeInput(out, "metallic", "float", xmlNumber(m.metallic));
        if (roughnessNode.empty())
            writeInput(out, "roughness", "float", xmlNumber(m.roughness));
        else
            writeConnection(out, "roughness", "float", roughnessNode);
        // As the glTF writer: only inputs that act on the material (GltfMaterial.h); the others
        // keep gltf_pbr's defaults, which are glTF's.
        if (specularActs(m)) {
            writeInput(out, "specular", "float", xmlNumber(m.specular));
            writeInput(out, "specular_color", "color3", color(m.specularColor));
        }
        if (iorActs(m)) writeInput(out, "ior", "float", xmlNumber(m.ior));
        if (clearcoatActs(m)) {
            writeInput(out, "clearcoat", "float", xmlNumber(m.clearcoat));
            if (clearcoatRoughnessNode.empty())
                writeInput(out, "clearcoat_roughness", "float", xmlNumber(m.clearcoatRoughness));
            else
                writeConnection(out, "clearcoat_roughness", "float", clearcoatRoughnessNode);
        }
        out << "  </gltf_pbr>\n";
        out << "  <surfacematerial name=\"" << id << "\" type=\"material\">\n";
        writeConnection(out, "surfaceshader", "surfaceshader", shader);
        out << "  </surfacematerial>\n";
    }
    out << "</materialx>\n";
    return out.str();
}

Status writeMaterialX(const std::vector<NamedGltfMaterial>& materials,
                      const SceneTextures& textures, const std::filesystem::path& file) {
    bool anyBaseColor = false, anyRoughness = false;
    double roughnessTexelScale = 1.0;
    for (const auto& [name, m] : materials) {
        anyBaseColor = anyBaseColor || m.baseColorTextured;
        if (m.roughnessTextured || m.clearcoatRoughnessTextured) {
            anyRoughness = true;
            roughnessTexelScale = m.roughnessTexelScale;
        }
    }
    // Named after their contents, so that the document and its textures are replaced as one
    // (files/CompanionFiles.h).
    CompanionFile baseColor{"_base_color", ".png", {}};
    CompanionFile roughness{"_roughness", ".png", {}};
    if (anyBaseColor) {
        auto png = encodePng(textures.baseColor, PngValues::Srgb);
        if (!png) return withContext(png.error(), file.string());
        baseColor.contents.assign(png->begin(), png->end());
    }
    if (anyRoughness) {
        auto png = encodePng(gltfRoughnessTexture(textures.roughness, roughnessTexelScale),
                             PngValues::Linear);
        if (!png) return withContext(png.error(), file.string());
        roughness.contents.assign(png->begin(), png->end());
    }
    return writeWithCompanions(file,
                               materialXDocument(materials, companionFileName(file, baseColor),
                                                 companionFileName(file, roughness)),
                               {baseColor, roughness});
}

}  // namespace matevo
