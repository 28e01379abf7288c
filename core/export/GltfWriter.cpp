#include "export/GltfWriter.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <sstream>

#include <glm/common.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <tiny_gltf.h>
#include <nlohmann/json.hpp>

#include "files/AtomicFile.h"
#include "files/CompanionFiles.h"
#include "image/ImageFile.h"
#include "mesh/GeneratedMeshes.h"

namespace matevo {

namespace {

constexpr int kArrayBuffer = 34962;  // glTF bufferView targets
constexpr int kElementArrayBuffer = 34963;
constexpr double kSphereSpacing = 2.5;  // centre to centre, unit spheres (Spheres)

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

struct MeshAccessors {
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

MeshAccessors addMesh(tinygltf::Model& model, const Mesh& mesh) {
    const std::size_t count = mesh.vertices.size();
    MeshAccessors accessors;
    accessors.positions = addAccessor(model, addVertexAttribute(model, mesh, &MeshVertex::position),
                                      TINYGLTF_COMPONENT_TYPE_FLOAT, count, TINYGLTF_TYPE_VEC3);
    // glTF requires the bounds of positions.
    glm::vec3 lowest(std::numeric_limits<float>::max()), highest(-lowest);
    for (const auto& vertex : mesh.vertices) {
        lowest = glm::min(lowest, vertex.position);
        highest = glm::max(highest, vertex.position);
    }
    auto& positions = model.accessors[std::size_t(accessors.positions)];
    positions.minValues = {lowest.x, lowest.y, lowest.z};
    positions.maxValues = {highest.x, highest.y, highest.z};
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

tinygltf::Primitive primitiveOf(const MeshAccessors& accessors, int material) {
    tinygltf::Primitive primitive;
    primitive.attributes = {{"POSITION", accessors.positions},
                            {"NORMAL", accessors.normals},
                            {"TEXCOORD_0", accessors.uvs}};
    primitive.indices = accessors.indices;
    primitive.material = material;
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    return primitive;
}

// Adds a mesh of one primitive and a node showing it; returns the node.
int addNode(tinygltf::Model& model, const std::string& name, tinygltf::Primitive primitive) {
    tinygltf::Mesh mesh;
    mesh.name = name;
    mesh.primitives.push_back(std::move(primitive));
    model.meshes.push_back(std::move(mesh));
    tinygltf::Node node;
    node.name = name;
    node.mesh = int(model.meshes.size() - 1);
    model.nodes.push_back(std::move(node));
    return int(model.nodes.size() - 1);
}

void useExtension(tinygltf::Model& model, const std::string& extension) {
    if (std::find(model.extensionsUsed.begin(), model.extensionsUsed.end(), extension) ==
        model.extensionsUsed.end())
        model.extensionsUsed.push_back(extension);
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
                          tinygltf::Model& model) {
    const GltfMaterial& m = named.material;
    tinygltf::Material material;
    material.name = named.name;
    auto& pbr = material.pbrMetallicRoughness;
    pbr.baseColorFactor = {m.baseColor[0], m.baseColor[1], m.baseColor[2], 1.0};
    pbr.metallicFactor = m.metallic;
    pbr.roughnessFactor = m.roughness;
    if (m.baseColorTextured) pbr.baseColorTexture.index = textures.baseColor;
    if (m.roughnessTextured) pbr.metallicRoughnessTexture.index = textures.roughness;

    auto use = [&](const std::string& extension, tinygltf::Value::Object values) {
        material.extensions[extension] = tinygltf::Value(std::move(values));
        useExtension(model, extension);
    };
    // Only values that act on the material (GltfMaterial.h): a client that reads an extension
    // the fit did not use would render something else.
    if (clearcoatActs(m)) {
        tinygltf::Value::Object clearcoat{
            {"clearcoatFactor", number(m.clearcoat)},
            {"clearcoatRoughnessFactor", number(m.clearcoatRoughness)}};
        if (m.clearcoatRoughnessTextured)
            clearcoat["clearcoatRoughnessTexture"] = textureReference(textures.roughness);
        use("KHR_materials_clearcoat", std::move(clearcoat));
    }
    if (iorActs(m)) use("KHR_materials_ior", {{"ior", number(m.ior)}});
    if (specularActs(m))
        use("KHR_materials_specular",
            {{"specularFactor", number(m.specular)},
             {"specularColorFactor", tinygltf::Value(tinygltf::Value::Array{
                                         number(m.specularColor[0]), number(m.specularColor[1]),
                                         number(m.specularColor[2])})}});
    return material;
}

// A sphere per material, side by side on a square grid.
void arrangeSpheres(tinygltf::Model& model, const std::vector<NamedGltfMaterial>& materials,
                    tinygltf::Scene& scene) {
    const MeshAccessors sphere = addMesh(model, makeSphereMesh(64, 32));
    const int columns = std::max(1, int(std::ceil(std::sqrt(double(materials.size())))));
    for (std::size_t i = 0; i < materials.size(); ++i) {
        const int node = addNode(model, materials[i].name, primitiveOf(sphere, int(i)));
        const int column = int(i) % columns, row = int(i) / columns;
        model.nodes[std::size_t(node)].translation = {column * kSphereSpacing,
                                                      -row * kSphereSpacing, 0.0};
        scene.nodes.push_back(node);
    }
}

// KHR_materials_variants: the mesh wears material 0; material i > 0 is variant i - 1, named
// after it.
void arrangeMaterialVariants(tinygltf::Model& model,
                             const std::vector<NamedGltfMaterial>& materials, const Mesh& mesh,
                             tinygltf::Scene& scene) {
    tinygltf::Primitive primitive = primitiveOf(addMesh(model, mesh), 0);
    tinygltf::Value::Array variants, mappings;
    for (std::size_t i = 1; i < materials.size(); ++i) {
        variants.push_back(
            tinygltf::Value(tinygltf::Value::Object{{"name", tinygltf::Value(materials[i].name)}}));
        mappings.push_back(tinygltf::Value(tinygltf::Value::Object{
            {"material", tinygltf::Value(int(i))},
            {"variants", tinygltf::Value(tinygltf::Value::Array{tinygltf::Value(int(i - 1))})}}));
    }
    const std::string extension = "KHR_materials_variants";
    if (!variants.empty()) {
        model.extensions[extension] = tinygltf::Value(
            tinygltf::Value::Object{{"variants", tinygltf::Value(std::move(variants))}});
        primitive.extensions[extension] = tinygltf::Value(
            tinygltf::Value::Object{{"mappings", tinygltf::Value(std::move(mappings))}});
        useExtension(model, extension);
    }
    scene.nodes.push_back(addNode(model, materials.front().name, std::move(primitive)));
}

// A node per instance, with the layout's transform; one glTF mesh per material, all sharing the
// mesh's accessors.
void arrangeInstances(tinygltf::Model& model, const std::vector<NamedGltfMaterial>& materials,
                      const Mesh& mesh, const std::vector<SceneInstance>& instances,
                      tinygltf::Scene& scene) {
    const MeshAccessors accessors = addMesh(model, mesh);
    for (std::size_t i = 0; i < materials.size(); ++i) {
        tinygltf::Mesh gltfMesh;
        gltfMesh.name = materials[i].name;
        gltfMesh.primitives.push_back(primitiveOf(accessors, int(i)));
        model.meshes.push_back(std::move(gltfMesh));
    }
    for (std::size_t i = 0; i < instances.size(); ++i) {
        const std::size_t material = instances[i].material % materials.size();
        tinygltf::Node node;
        node.name = materials[material].name + " #" + std::to_string(i);
        node.mesh = int(material);
        const float* matrix = glm::value_ptr(instances[i].transform);  // column-major, as glTF
        node.matrix.assign(matrix, matrix + 16);
        model.nodes.push_back(std::move(node));
        scene.nodes.push_back(int(model.nodes.size() - 1));
    }
}

Result<tinygltf::Model> buildModel(const std::vector<NamedGltfMaterial>& materials,
                                   const SceneTextures& textures, const GltfAsset& asset) {
    tinygltf::Model model;
    model.asset.version = "2.0";
    model.asset.generator = "matevo";
    model.buffers.resize(1);

    SharedTextures shared;
    const bool anyBaseColor = std::any_of(materials.begin(), materials.end(), [](const auto& m) {
        return m.material.baseColorTextured;
    });
    const auto roughnessUser = std::find_if(materials.begin(), materials.end(), [](const auto& m) {
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
    for (const auto& material : materials)
        model.materials.push_back(toGltf(material, shared, model));

    tinygltf::Scene scene;
    scene.name = "matevo variants";
    switch (asset.arrangement) {
        case GltfArrangement::Spheres:
            arrangeSpheres(model, materials, scene);
            break;
        case GltfArrangement::MaterialVariants:
            arrangeMaterialVariants(model, materials, asset.mesh, scene);
            break;
        case GltfArrangement::Instances:
            arrangeInstances(model, materials, asset.mesh, asset.instances, scene);
            break;
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
                 const std::filesystem::path& file, const GltfAsset& asset) {
    const std::string extension = lowercaseExtension(file);
    if (extension != ".gltf" && extension != ".glb")
        return badInput(file.string() + ": the extension must be .gltf or .glb");
    if (materials.empty()) return badInput(file.string() + ": no materials to write");
    auto model = buildModel(materials, textures, asset);
    if (!model) return withContext(model.error(), file.string());

    tinygltf::TinyGLTF writer;
    std::ostringstream stream;
    const bool binary = extension == ".glb";
    if (!writer.WriteGltfSceneToStream(&*model, stream, true, binary))
        return internalError(file.string() + ": tinygltf could not serialise the asset");
    if (binary) return writeFileAtomically(file, stream.str());

    // tinygltf streams the buffer as a data URI; a .gltf keeps it in a .bin beside the JSON,
    // named after its contents so that the pair is replaced as one (files/CompanionFiles.h).
    const auto& bytes = model->buffers[0].data;
    const CompanionFile bin{"", ".bin",
                            std::string(reinterpret_cast<const char*>(bytes.data()), bytes.size())};
    auto json = nlohmann::ordered_json::parse(stream.str());
    json["buffers"][0]["uri"] = companionFileName(file, bin);
    return writeWithCompanions(file, json.dump(2) + "\n", {bin});
}

}  // namespace matevo
