#include "mesh/GltfReader.h"

#include <cctype>
#include <cstring>
#include <functional>
#include <string>

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <tiny_gltf.h>

#include "io/InputFile.h"

namespace matevo {
namespace {

struct GltfError {
    std::string message;
};

// Images are not needed (matevo supplies the material): accept them without decoding.
bool skipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int,
               const unsigned char*, int, void*) {
    return true;
}

std::size_t componentBytes(int componentType) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return 2;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return 4;
        default: return 0;
    }
}

// Reads accessor `index` as `components` numbers per element, after checking that every byte it
// names lies inside its buffer. Integer components are read as the glTF spec says for their use:
// normalised (`normalized`) or plain.
std::vector<float> readAccessor(const tinygltf::Model& model, int index, int components,
                                const std::string& what) {
    if (index < 0 || index >= int(model.accessors.size()))
        throw GltfError{what + ": accessor " + std::to_string(index) + " does not exist"};
    const tinygltf::Accessor& accessor = model.accessors[std::size_t(index)];
    if (accessor.sparse.isSparse) throw GltfError{what + ": sparse accessors are not supported"};
    if (tinygltf::GetNumComponentsInType(std::uint32_t(accessor.type)) != components)
        throw GltfError{what + ": expected " + std::to_string(components) +
                        " components per element"};
    const std::size_t elementBytes = componentBytes(accessor.componentType);
    if (elementBytes == 0) throw GltfError{what + ": unsupported component type"};
    if (accessor.bufferView < 0 || accessor.bufferView >= int(model.bufferViews.size()))
        throw GltfError{what + ": accessor has no buffer view"};
    const tinygltf::BufferView& view = model.bufferViews[std::size_t(accessor.bufferView)];
    if (view.buffer < 0 || view.buffer >= int(model.buffers.size()))
        throw GltfError{what + ": buffer view names no buffer"};
    const std::vector<unsigned char>& buffer = model.buffers[std::size_t(view.buffer)].data;
    const std::size_t stride =
        view.byteStride > 0 ? view.byteStride : elementBytes * std::size_t(components);
    const std::size_t begin = view.byteOffset + accessor.byteOffset;
    const std::size_t count = accessor.count;
    const std::size_t lastByte =
        count == 0 ? begin : begin + stride * (count - 1) + elementBytes * std::size_t(components);
    if (lastByte > view.byteOffset + view.byteLength || lastByte > buffer.size())
        throw GltfError{what + ": accessor reads past the end of its buffer"};

    std::vector<float> values(count * std::size_t(components));
    for (std::size_t element = 0; element < count; ++element) {
        const unsigned char* source = buffer.data() + begin + element * stride;
        for (int c = 0; c < components; ++c) {
            const unsigned char* at = source + std::size_t(c) * elementBytes;
            float value = 0.0f;
            switch (accessor.componentType) {
                case TINYGLTF_COMPONENT_TYPE_FLOAT: std::memcpy(&value, at, 4); break;
                case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
                    value = accessor.normalized ? float(*at) / 255.0f : float(*at);
                    break;
                case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
                    std::uint16_t raw;
                    std::memcpy(&raw, at, 2);
                    value = accessor.normalized ? float(raw) / 65535.0f : float(raw);
                    break;
                }
                case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
                    std::uint32_t raw;
                    std::memcpy(&raw, at, 4);
                    value = float(raw);
                    break;
                }
                default: throw GltfError{what + ": unsupported component type"};
            }
            values[element * std::size_t(components) + std::size_t(c)] = value;
        }
    }
    return values;
}

std::vector<std::uint32_t> readIndices(const tinygltf::Model& model, int index,
                                       const std::string& what) {
    const tinygltf::Accessor& accessor = model.accessors.at(std::size_t(index));
    if (accessor.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        accessor.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        accessor.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
        throw GltfError{what + ": indices must be unsigned integers"};
    // Exact as floats: glTF caps vertex counts far below 2^24 in practice; checked below.
    const std::vector<float> values = readAccessor(model, index, 1, what);
    std::vector<std::uint32_t> indices;
    indices.reserve(values.size());
    for (float value : values) {
        if (value >= 16777216.0f) throw GltfError{what + ": index too large"};
        indices.push_back(std::uint32_t(value));
    }
    return indices;
}

// Triangle list corners from a primitive's mode; other modes (points, lines) draw no surface.
std::vector<std::uint32_t> triangleCorners(int mode, const std::vector<std::uint32_t>& order) {
    std::vector<std::uint32_t> corners;
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        corners.assign(order.begin(), order.end() - std::ptrdiff_t(order.size() % 3));
    } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        for (std::size_t i = 2; i < order.size(); ++i) {
            // Every other triangle of a strip is flipped to keep the winding.
            if (i % 2 == 0) corners.insert(corners.end(), {order[i - 2], order[i - 1], order[i]});
            else corners.insert(corners.end(), {order[i - 1], order[i - 2], order[i]});
        }
    } else if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
        for (std::size_t i = 2; i < order.size(); ++i)
            corners.insert(corners.end(), {order[0], order[i - 1], order[i]});
    }
    return corners;
}

glm::mat4 localTransform(const tinygltf::Node& node) {
    if (node.matrix.size() == 16) {
        glm::dmat4 matrix;
        std::memcpy(glm::value_ptr(matrix), node.matrix.data(), sizeof(double) * 16);
        return glm::mat4(matrix);
    }
    glm::dmat4 transform(1.0);
    if (node.translation.size() == 3)
        transform = glm::translate(transform, glm::dvec3(node.translation[0], node.translation[1],
                                                         node.translation[2]));
    if (node.rotation.size() == 4)
        transform *= glm::mat4_cast(glm::dquat(node.rotation[3], node.rotation[0],
                                               node.rotation[1], node.rotation[2]));
    if (node.scale.size() == 3)
        transform = glm::scale(transform, glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
    return glm::mat4(transform);
}

struct MeshBuilder {
    const tinygltf::Model& model;
    Mesh mesh;
    bool missingNormals = false;

    void addPrimitive(const tinygltf::Primitive& primitive, const glm::mat4& transform,
                      const std::string& what) {
        const auto position = primitive.attributes.find("POSITION");
        if (position == primitive.attributes.end()) throw GltfError{what + ": no POSITION"};
        const std::vector<float> positions =
            readAccessor(model, position->second, 3, what + " POSITION");
        const std::size_t vertexCount = positions.size() / 3;
        std::vector<float> normals, uvs;
        if (auto found = primitive.attributes.find("NORMAL"); found != primitive.attributes.end())
            normals = readAccessor(model, found->second, 3, what + " NORMAL");
        if (auto found = primitive.attributes.find("TEXCOORD_0");
            found != primitive.attributes.end())
            uvs = readAccessor(model, found->second, 2, what + " TEXCOORD_0");
        if ((!normals.empty() && normals.size() != positions.size()) ||
            (!uvs.empty() && uvs.size() / 2 != vertexCount))
            throw GltfError{what + ": attributes have different vertex counts"};
        missingNormals = missingNormals || normals.empty();

        std::vector<std::uint32_t> order;
        if (primitive.indices >= 0) {
            order = readIndices(model, primitive.indices, what + " indices");
        } else {
            for (std::size_t i = 0; i < vertexCount; ++i) order.push_back(std::uint32_t(i));
        }
        for (std::uint32_t index : order)
            if (index >= vertexCount)
                throw GltfError{what + ": index " + std::to_string(index) + " out of range (" +
                                std::to_string(vertexCount) + " vertices)"};

        const glm::mat3 normalTransform = glm::inverseTranspose(glm::mat3(transform));
        const auto first = std::uint32_t(mesh.vertices.size());
        for (std::size_t v = 0; v < vertexCount; ++v) {
            MeshVertex vertex;
            vertex.position = glm::vec3(
                transform * glm::vec4(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2],
                                      1.0f));
            if (!normals.empty()) {
                const glm::vec3 normal =
                    normalTransform * glm::vec3(normals[3 * v], normals[3 * v + 1],
                                                normals[3 * v + 2]);
                const float length = glm::length(normal);
                vertex.normal = length > 0.0f ? normal / length : glm::vec3(0.0f, 1.0f, 0.0f);
            }
            if (!uvs.empty()) vertex.uv = {uvs[2 * v], uvs[2 * v + 1]};
            mesh.vertices.push_back(vertex);
        }
        // A mirroring transform turns the winding inside out.
        const bool mirrored = glm::determinant(glm::mat3(transform)) < 0.0f;
        const std::vector<std::uint32_t> corners = triangleCorners(primitive.mode, order);
        for (std::size_t i = 0; i + 2 < corners.size(); i += 3) {
            const std::uint32_t a = first + corners[i], b = first + corners[i + 1],
                                c = first + corners[i + 2];
            if (mirrored) mesh.indices.insert(mesh.indices.end(), {a, c, b});
            else mesh.indices.insert(mesh.indices.end(), {a, b, c});
        }
    }

    void addMesh(int meshIndex, const glm::mat4& transform) {
        if (meshIndex < 0 || meshIndex >= int(model.meshes.size()))
            throw GltfError{"a node names mesh " + std::to_string(meshIndex) +
                            ", which does not exist"};
        const tinygltf::Mesh& source = model.meshes[std::size_t(meshIndex)];
        for (std::size_t p = 0; p < source.primitives.size(); ++p)
            addPrimitive(source.primitives[p], transform,
                         "mesh " + std::to_string(meshIndex) + " primitive " + std::to_string(p));
    }

    void addNode(int nodeIndex, const glm::mat4& parent, int depth) {
        // Cycles are invalid glTF; the depth bound turns one into an error, not a stack overflow.
        if (nodeIndex < 0 || nodeIndex >= int(model.nodes.size()) || depth > 256)
            throw GltfError{"the node hierarchy names a missing node or has a cycle"};
        const tinygltf::Node& node = model.nodes[std::size_t(nodeIndex)];
        const glm::mat4 transform = parent * localTransform(node);
        if (node.mesh >= 0) addMesh(node.mesh, transform);
        for (int child : node.children) addNode(child, transform, depth + 1);
    }
};

}  // namespace

Result<Mesh> readGltf(const std::filesystem::path& file) {
    const std::string name = file.string();
    auto bytes = readInputFile(file, kMaxMeshFileBytes);
    if (!bytes) return bytes.error();
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(skipImage, nullptr);
    tinygltf::Model model;
    std::string errors, warnings;
    // External buffers are found beside the file.
    const std::string folder = file.parent_path().string();
    std::string extension = file.extension().string();
    for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
    const bool loaded =
        extension == ".glb"
            ? loader.LoadBinaryFromMemory(&model, &errors, &warnings,
                                          reinterpret_cast<const unsigned char*>(bytes->data()),
                                          unsigned(bytes->size()), folder)
            : loader.LoadASCIIFromString(&model, &errors, &warnings, bytes->data(),
                                         unsigned(bytes->size()), folder);
    if (!loaded) {
        // tinygltf's messages span lines; the first says what went wrong.
        std::string first = errors.substr(0, errors.find('\n'));
        if (first.empty()) first = "not a valid glTF 2.0 file";
        return Error{name + ": " + first};
    }
    MeshBuilder builder{model, {}};
    try {
        if (!model.scenes.empty()) {
            const int sceneIndex = model.defaultScene >= 0 ? model.defaultScene : 0;
            if (sceneIndex >= int(model.scenes.size()))
                throw GltfError{"the default scene does not exist"};
            for (int node : model.scenes[std::size_t(sceneIndex)].nodes)
                builder.addNode(node, glm::mat4(1.0f), 0);
        } else {
            for (std::size_t m = 0; m < model.meshes.size(); ++m)
                builder.addMesh(int(m), glm::mat4(1.0f));
        }
    } catch (const GltfError& failure) {
        return Error{name + ": " + failure.message};
    }
    if (builder.mesh.indices.empty()) return Error{name + ": no triangles to draw"};
    if (builder.missingNormals) computeVertexNormals(builder.mesh);
    return std::move(builder.mesh);
}

}  // namespace matevo
