#include "export/GltfWriter.h"

#include <algorithm>
#include <cmath>
#include <cctype>
#include <sstream>

#include <nlohmann/json.hpp>
#include <tiny_gltf.h>

#include "mesh/GeneratedMeshes.h"
#include "io/AtomicFile.h"
#include "io/CompanionFiles.h"
#include "io/ImageFile.h"

namespace matevo {

namespace {

constexpr int kArrayBuffer = 34962;         // glTF bufferView targets
constexpr int kElementArrayBuffer = 34963;
constexpr double kSphereSpacing = 2.5;      // centre to centre, unit spheres

// Appends bytes to the one buffer as a new buffer view (4-byte aligned); returns its index.
int addBufferView(tinygltf::Model& model, const void* data, std::size_t size, int target) {
    auto& bytes = model.buffers[0].data;
    bytes.resize((bytes.size() + 3) / 4 * 4, 0);
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = bytes.size();
    view.byteLength = size;
    view.target = target;
    const auto* begin = static_cast<const unsigned char*>(data);
    bytes.insert(bytes.end(), begin, begin + size);
    model.bufferViews.push_back(view);
    return int(model.bufferViews.size() - 1);
}

int addAccessor(tinygltf::Model& model, int bufferView, int componentType, std::size_t count,
                int type) {
    tinygltf::Accessor accessor;
    accessor.bufferView = bufferView;
    accessor.componentType = componentType;
    accessor.count = count;
    accessor.type = type;
    model.accessors.push_back(accessor);
    return int(model.accessors.size() - 1);
}

struct SphereAccessors {
    int positions, normals, uvs, indices;
};

// Appends one attribute of every vertex as a tightly packed array; returns its buffer view.
template <typename Attribute>
int addVertexAttribute(tinygltf::Model& model, const Mesh& mesh, Attribute MeshVertex::*member) {
    std::vector<Attribute> values;
    values.reserve(mesh.vertices.size());
    for (const auto& vertex : mesh.vertices) values.push_back(vertex.*member);
    return addBufferView(model, values.data(), values.size() * sizeof(Attribute), kArrayBuffer);
}

SphereAccessors addSphere(tinygltf::Model& model) {
    const Mesh mesh = makeSphereMesh(64, 32);
    const std::size_t count = mesh.vertices.size();
    SphereAccessors accessors;
    accessors.positions =
        addAccessor(model, addVertexAttribute(model, mesh, &MeshVertex::position),
                    TINYGLTF_COMPONENT_TYPE_FLOAT, count, TINYGLTF_TYPE_VEC3);
    model.accessors[std::size_t(accessors.positions)].minValues = {-1.0, -1.0, -1.0};
    model.accessors[std::size_t(accessors.positions)].maxValues = {1.0, 1.0, 1.0};
    accessors.normals = addAccessor(model, addVertexAttribute(model, mesh, &MeshVertex::normal),
                                    TINYGLTF_COMPONENT_TYPE_FLOAT, count, TINYGLTF_TYPE_VEC3);
    accessors.uvs = addAccessor(model, addVertexAttribute(model, mesh, &MeshVertex::uv),
                                TINYGLTF_COMPONENT_TYPE_FLOAT, count, TINYGLTF_TYPE_VEC2);
    const int indexView =
        addBufferView(model, mesh.indices.data(), mesh.indices.size() * sizeof(mesh.indices[0]),
                      kElementArrayBuffer);
    accessors.indices = addAccessor(model, indexView, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT,
                                    mesh.indices.size(), TINYGLTF_TYPE_SCALAR);
    return accessors;
}

// Adds a PNG in the buffer, its image, a sampler (once) and a texture; returns the texture.
Result<int> addTexture(tinygltf::Model& model, const Image& image, PngValues values,
                       const std::string& name) {
    auto png = encodePng(image, values);
    if (!png) return png.error();
    tinygltf::Image gltfImage;
    gltfImage.name = name;
    gltfImage.mimeType = "image/png";
    gltfImage.bufferView = addBufferView(model, png->data(), png->size(), 0);
    model.images.push_back(gltfImage);
    if (model.samplers.empty()) {
        tinygltf::Sampler sampler;  // repeat in u (the seam), clamp in v (the poles)
        sampler.magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
        sampler.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
        sampler.wrapS = TINYGLTF_TEXTURE_WRAP_REPEAT;
        sampler.wrapT = TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;
        model.samplers.push_back(sampler);
    }
    tinygltf::Texture texture;
    texture.name = name;
    texture.sampler = 0;
    texture.source = int(model.images.size() - 1);
    model.textures.push_back(texture);
    return int(model.textures.size() - 1);
}

tinygltf::Value number(double value) { return tinygltf::Value(value); }

tinygltf::Value textureReference(int texture) {
    return tinygltf::Value(tinygltf::Value::Object{{"index", tinygltf::Value(texture)}});
}

struct SharedTextures {
    int baseColor = -1;
    int roughness = -1;
};

tinygltf::Material toGltf(const NamedGltfMaterial& named, const SharedTextures& textures,
                          std::vector<std::string>& extensionsUsed) {
    const GltfMaterial& m = named.material;
    tinygltf::Material material;
    material.name = named.name;
    auto& pbr = material.pbrMetallicRoughness;
    pbr.baseColorFactor = {m.baseColor[0], m.baseColor[1], m.baseColor[2], 1.0};
    pbr.metallicFactor = m.metallic;
    pbr.roughnessFactor = m.roughness;
    if (m.baseColorTextured) pbr.baseColorTexture.index = textures.baseColor;
    if (m.roughnessTextured)
        pbr.metallicRoughnessTexture.index = textures.roughness;

    auto use = [&](const std::string& extension, tinygltf::Value::Object values) {
        material.extensions[extension] = tinygltf::Value(std::move(values));
        if (std::find(extensionsUsed.begin(), extensionsUsed.end(), extension) ==
            extensionsUsed.end())
            extensionsUsed.push_back(extension);
    };
    tinygltf::Value::Object clearcoat{{"clearcoatFactor", number(m.clearcoat)},
                                      {"clearcoatRoughnessFactor", number(m.clearcoatRoughness)}};
    if (m.clearcoatRoughnessTextured)
        clearcoat["clearcoatRoughnessTexture"] = textureReference(textures.roughness);
    use("KHR_materials_clearcoat", std::move(clearcoat));
    use("KHR_materials_ior", {{"ior", number(m.ior)}});
    if (m.specular != 1.0 || m.specularColor != std::array<double, 3>{1.0, 1.0, 1.0})
        use("KHR_materials_specular",
            {{"specularFactor", number(m.specular)},
             {"specularColorFactor",
              tinygltf::Value(tinygltf::Value::Array{number(m.specularColor[0]),
                                                     number(m.specularColor[1]),
                                                     number(m.specularColor[2])})}});
    return material;
}

Result<tinygltf::Model> buildModel(const std::vector<NamedGltfMaterial>& materials,
                                   const SceneTextures& textures) {
    tinygltf::Model model;
    model.asset.version = "2.0";
    model.asset.generator = "matevo";
    model.buffers.resize(1);
    const SphereAccessors sphere = addSphere(model);

    SharedTextures shared;
    const bool anyBaseColor = std::any_of(materials.begin(), materials.end(), [](const auto& m) {
        return m.material.baseColorTextured;
    });
    const auto roughnessUser =
        std::find_if(materials.begin(), materials.end(), [](const auto& m) {
            return m.material.roughnessTextured || m.material.clearcoatRoughnessTextured;
        });
    if (anyBaseColor) {
        auto texture = addTexture(model, textures.baseColor, PngValues::Srgb, "base_color");
        if (!texture) return texture.error();
        shared.baseColor = *texture;
    }
    if (roughnessUser != materials.end()) {
        auto texture = addTexture(
            model,
            gltfRoughnessTexture(textures.roughness, roughnessUser->material.roughnessTexelScale),
            PngValues::Linear, "roughness");
        if (!texture) return texture.error();
        shared.roughness = *texture;
    }

    const int columns = std::max(1, int(std::ceil(std::sqrt(double(materials.size())))));
    tinygltf::Scene scene;
    scene.name = "matevo variants";
    for (std::size_t i = 0; i < materials.size(); ++i) {
        model.materials.push_back(toGltf(materials[i], shared, model.extensionsUsed));
        tinygltf::Primitive primitive;
        primitive.attributes = {{"POSITION", sphere.positions},
                                {"NORMAL", sphere.normals},
                                {"TEXCOORD_0", sphere.uvs}};
        primitive.indices = sphere.indices;
        primitive.material = int(i);
        primitive.mode = TINYGLTF_MODE_TRIANGLES;
        tinygltf::Mesh mesh;
        mesh.name = materials[i].name;
        mesh.primitives.push_back(primitive);
        model.meshes.push_back(mesh);
        tinygltf::Node node;
        node.name = materials[i].name;
        node.mesh = int(i);
        const int column = int(i) % columns, row = int(i) / columns;
        node.translation = {column * kSphereSpacing, -row * kSphereSpacing, 0.0};
        model.nodes.push_back(node);
        scene.nodes.push_back(int(i));
    }
    model.scenes.push_back(scene);
    model.defaultScene = 0;
    return model;
}

std::string lowercaseExtension(const std::filesystem::path& file) {
    std::string extension = file.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return extension;
}

}  // namespace

Image gltfRoughnessTexture(const Image& roughness, double texelScale) {
    Image derived(roughness.width, roughness.height);
    for (std::size_t i = 0; i < roughness.pixelCount(); ++i) {
        const double texel = std::clamp(double(roughness.rgba[4 * i]) * texelScale, 0.0, 1.0);
        float* pixel = &derived.rgba[4 * i];
        pixel[0] = 1.0f;  // occlusion: none
        pixel[1] = float(std::sqrt(texel));
        pixel[2] = 1.0f;  // metallic multiplier: the factor alone
        pixel[3] = 1.0f;
    }
    return derived;
}

Status writeGltf(const std::vector<NamedGltfMaterial>& materials, const SceneTextures& textures,
                 const std::filesystem::path& file) {
    const std::string extension = lowercaseExtension(file);
    if (extension != ".gltf" && extension != ".glb")
        return Error{file.string() + ": the extension must be .gltf or .glb"};
    auto model = buildModel(materials, textures);
    if (!model) return Error{file.string() + ": " + model.error().message};

    tinygltf::TinyGLTF writer;
    std::ostringstream stream;
    const bool binary = extension == ".glb";
    if (!writer.WriteGltfSceneToStream(&*model, stream, true, binary))
        return Error{file.string() + ": tinygltf could not serialise the asset"};
    if (binary) return writeFileAtomically(file, stream.str());

    // tinygltf streams the buffer as a data URI; a .gltf keeps it in a .bin beside the JSON,
    // named after its contents so that the pair is replaced as one (io/CompanionFiles.h).
    const auto& bytes = model->buffers[0].data;
    const CompanionFile bin{"", ".bin",
                            std::string(reinterpret_cast<const char*>(bytes.data()), bytes.size())};
    auto json = nlohmann::ordered_json::parse(stream.str());
    json["buffers"][0]["uri"] = companionFileName(file, bin);
    return writeWithCompanions(file, json.dump(2) + "\n", {bin});
}

}  // namespace matevo
