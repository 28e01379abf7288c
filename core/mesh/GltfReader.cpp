#include "mesh/GltfReader.h"

#include <cstring>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include <tiny_gltf.h>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include "common/MemoryBudget.h"
#include "common/ShortText.h"
#include "files/InputFile.h"
#include "files/JsonReader.h"
#include "image/ImageType.h"
#include "mesh/GltfExternalFiles.h"

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
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
            return 1;
        case TINYGLTF_COMPONENT_TYPE_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
            return 2;
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            return 4;
        default:
            return 0;
    }
}

// a + b and a * b for byte offsets and sizes from the file: a value near 2^64 must not wrap
// around and pass a bounds check.
std::size_t checkedAdd(std::size_t a, std::size_t b, const std::string& what) {
    std::size_t sum = 0;
    if (__builtin_add_overflow(a, b, &sum)) throw GltfError{what + ": byte offsets overflow"};
    return sum;
}

std::size_t checkedMultiply(std::size_t a, std::size_t b, const std::string& what) {
    std::size_t product = 0;
    if (__builtin_mul_overflow(a, b, &product)) throw GltfError{what + ": byte sizes overflow"};
    return product;
}

const tinygltf::Accessor& findAccessor(const tinygltf::Model& model, int index,
                                       const std::string& what) {
    if (index < 0 || index >= int(model.accessors.size()))
        throw GltfError{what + ": accessor " + std::to_string(index) + " does not exist"};
    return model.accessors[std::size_t(index)];
}

// The first byte of an accessor's elements, after checking that every byte they span lies inside
// its buffer view and the view inside its buffer.
const unsigned char* locateElements(const tinygltf::Model& model,
                                    const tinygltf::Accessor& accessor, std::size_t elementSize,
                                    std::size_t stride, const std::string& what) {
    if (accessor.bufferView < 0 || accessor.bufferView >= int(model.bufferViews.size()))
        throw GltfError{what + ": accessor has no buffer view"};
    const tinygltf::BufferView& view = model.bufferViews[std::size_t(accessor.bufferView)];
    if (view.buffer < 0 || view.buffer >= int(model.buffers.size()))
        throw GltfError{what + ": buffer view names no buffer"};
    const std::vector<unsigned char>& buffer = model.buffers[std::size_t(view.buffer)].data;
    const std::size_t viewEnd = checkedAdd(view.byteOffset, view.byteLength, what + " bufferView");
    if (viewEnd > buffer.size())
        throw GltfError{what + ": bufferView reads past the end of its buffer"};
    if (stride < elementSize)
        throw GltfError{what + ": bufferView byteStride " + std::to_string(stride) +
                        " is smaller than an element (" + std::to_string(elementSize) + " bytes)"};
    const std::size_t begin = checkedAdd(view.byteOffset, accessor.byteOffset, what + " accessor");
    if (accessor.count > 0) {
        const std::size_t span =
            checkedAdd(checkedMultiply(stride, accessor.count - 1, what + " accessor"), elementSize,
                       what + " accessor");
        if (checkedAdd(begin, span, what + " accessor") > viewEnd)
            throw GltfError{what + ": accessor reads past the end of its buffer"};
    }
    return buffer.data() + (accessor.count > 0 ? begin : 0);
}

// Reads accessor `index` as `components` numbers per element, after checking that every byte it
// names lies inside its buffer. Integer components are read as the glTF spec says for their use:
// normalised (`normalized`) or plain.
std::vector<float> readAccessor(const tinygltf::Model& model, int index, int components,
                                const std::string& what) {
    const tinygltf::Accessor& accessor = findAccessor(model, index, what);
    if (accessor.sparse.isSparse) throw GltfError{what + ": sparse accessors are not supported"};
    if (tinygltf::GetNumComponentsInType(std::uint32_t(accessor.type)) != components)
        throw GltfError{what + ": expected " + std::to_string(components) +
                        " components per element"};
    const std::size_t elementBytes = componentBytes(accessor.componentType);
    if (elementBytes == 0) throw GltfError{what + ": unsupported component type"};
    const std::size_t elementSize = elementBytes * std::size_t(components);
    const int viewIndex = accessor.bufferView;
    const std::size_t viewStride = viewIndex >= 0 && viewIndex < int(model.bufferViews.size())
                                       ? model.bufferViews[std::size_t(viewIndex)].byteStride
                                       : 0;
    const std::size_t stride = viewStride > 0 ? viewStride : elementSize;
    const unsigned char* first = locateElements(model, accessor, elementSize, stride, what);
    const std::size_t count = accessor.count;

    std::vector<float> values(count * std::size_t(components));
    for (std::size_t element = 0; element < count; ++element) {
        const unsigned char* source = first + element * stride;
        for (int c = 0; c < components; ++c) {
            const unsigned char* at = source + std::size_t(c) * elementBytes;
            float value = 0.0f;
            switch (accessor.componentType) {
                case TINYGLTF_COMPONENT_TYPE_FLOAT:
                    std::memcpy(&value, at, 4);
                    break;
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
                default:
                    throw GltfError{what + ": unsupported component type"};
            }
            values[element * std::size_t(components) + std::size_t(c)] = value;
        }
    }
    return values;
}

std::vector<std::uint32_t> readIndices(const tinygltf::Model& model, int index,
                                       const std::string& what) {
    const tinygltf::Accessor& accessor = findAccessor(model, index, what);
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
            if (i % 2 == 0)
                corners.insert(corners.end(), {order[i - 2], order[i - 1], order[i]});
            else
                corners.insert(corners.end(), {order[i - 1], order[i - 2], order[i]});
        }
    } else if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
        for (std::size_t i = 2; i < order.size(); ++i)
            corners.insert(corners.end(), {order[0], order[i - 1], order[i]});
    }
    return corners;
}

// A node's own transform, or nothing when it has none (most nodes that only group others).
std::optional<glm::mat4> localTransform(const tinygltf::Node& node) {
    if (node.matrix.size() == 16) {
        glm::dmat4 matrix;
        std::memcpy(glm::value_ptr(matrix), node.matrix.data(), sizeof(double) * 16);
        return glm::mat4(matrix);
    }
    if (node.translation.size() != 3 && node.rotation.size() != 4 && node.scale.size() != 3)
        return std::nullopt;
    glm::dmat4 transform(1.0);
    if (node.translation.size() == 3)
        transform = glm::translate(
            transform, glm::dvec3(node.translation[0], node.translation[1], node.translation[2]));
    if (node.rotation.size() == 4)
        transform *= glm::mat4_cast(
            glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]));
    if (node.scale.size() == 3)
        transform = glm::scale(transform, glm::dvec3(node.scale[0], node.scale[1], node.scale[2]));
    return glm::mat4(transform);
}

// Each node's transform, worked out once however many paths place the node.
std::vector<std::optional<glm::mat4>> localTransforms(const tinygltf::Model& model) {
    std::vector<std::optional<glm::mat4>> transforms;
    transforms.reserve(model.nodes.size());
    for (const tinygltf::Node& node : model.nodes) transforms.push_back(localTransform(node));
    return transforms;
}

// Nodes that share children place those children once per path through the hierarchy: a file of
// a few hundred nodes can name 2^200 placements. Placing stops with an error after this many, and
// the placed geometry must fit the memory limit (common/MemoryBudget.h).
constexpr std::size_t kMaxNodePlacements = 100000;
// Deeper hierarchies are refused before they exhaust the stack.
constexpr int kMaxNodeDepth = 256;

// One primitive decoded: per-vertex arrays (normals and uvs empty when absent) and the triangle
// corners, before any node's transform.
struct DecodedPrimitive {
    std::vector<float> positions, normals, uvs;
    std::vector<std::uint32_t> corners;
};

DecodedPrimitive decodePrimitive(const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                                 const std::string& what) {
    DecodedPrimitive decoded;
    const auto position = primitive.attributes.find("POSITION");
    if (position == primitive.attributes.end()) throw GltfError{what + ": no POSITION"};
    decoded.positions = readAccessor(model, position->second, 3, what + " POSITION");
    const std::size_t vertexCount = decoded.positions.size() / 3;
    if (auto found = primitive.attributes.find("NORMAL"); found != primitive.attributes.end())
        decoded.normals = readAccessor(model, found->second, 3, what + " NORMAL");
    if (auto found = primitive.attributes.find("TEXCOORD_0"); found != primitive.attributes.end())
        decoded.uvs = readAccessor(model, found->second, 2, what + " TEXCOORD_0");
    if ((!decoded.normals.empty() && decoded.normals.size() != decoded.positions.size()) ||
        (!decoded.uvs.empty() && decoded.uvs.size() / 2 != vertexCount))
        throw GltfError{what + ": attributes have different vertex counts"};

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
    decoded.corners = triangleCorners(primitive.mode, order);
    return decoded;
}

struct MeshBuilder {
    const tinygltf::Model& model;
    Mesh mesh;
    bool missingNormals = false;
    std::size_t placements = 0;
    std::vector<bool> onPath = std::vector<bool>(model.nodes.size(), false);
    const std::vector<std::optional<glm::mat4>> nodeTransforms = localTransforms(model);
    // Each mesh is decoded once, however many nodes place it; its size is bounded by the
    // buffers' sizes.
    std::map<int, std::vector<DecodedPrimitive>> decodedMeshes{};

    // Refuses geometry that would take the mesh past the memory limit or 32-bit indices. The
    // counts are those of decoded arrays, far from overflowing.
    void reserveFor(std::size_t vertexCount, std::size_t cornerCount, int meshIndex) {
        const std::size_t vertices = mesh.vertices.size() + vertexCount;
        const std::size_t corners = mesh.indices.size() + cornerCount;
        const std::string what = "mesh " + std::to_string(meshIndex);
        if (vertices > std::numeric_limits<std::uint32_t>::max())
            throw GltfError{what + ": more than 2^32 vertices placed in all"};
        const std::uint64_t bytes =
            std::uint64_t(vertices) * sizeof(MeshVertex) + std::uint64_t(corners) * 4;
        if (auto fits = checkMemoryEstimate(bytes, what + ": the placed triangles"); !fits)
            throw GltfError{fits.error().message};
    }

    void place(const DecodedPrimitive& primitive, const glm::mat4& transform, int meshIndex) {
        const std::size_t vertexCount = primitive.positions.size() / 3;
        reserveFor(vertexCount, primitive.corners.size(), meshIndex);
        missingNormals = missingNormals || primitive.normals.empty();
        const std::vector<float>& positions = primitive.positions;
        const std::vector<float>& normals = primitive.normals;
        const std::vector<float>& uvs = primitive.uvs;
        const glm::mat3 normalTransform = glm::inverseTranspose(glm::mat3(transform));
        const auto first = std::uint32_t(mesh.vertices.size());
        mesh.vertices.resize(first + vertexCount);
        for (std::size_t v = 0; v < vertexCount; ++v) {
            MeshVertex& vertex = mesh.vertices[first + v];
            vertex.position =
                glm::vec3(transform * glm::vec4(positions[3 * v], positions[3 * v + 1],
                                                positions[3 * v + 2], 1.0f));
            if (!normals.empty()) {
                const glm::vec3 normal =
                    normalTransform *
                    glm::vec3(normals[3 * v], normals[3 * v + 1], normals[3 * v + 2]);
                const float length = glm::length(normal);
                vertex.normal = length > 0.0f ? normal / length : glm::vec3(0.0f, 1.0f, 0.0f);
            }
            if (!uvs.empty()) vertex.uv = {uvs[2 * v], uvs[2 * v + 1]};
        }
        // A mirroring transform turns the winding inside out.
        const bool mirrored = glm::determinant(glm::mat3(transform)) < 0.0f;
        const std::vector<std::uint32_t>& corners = primitive.corners;
        const std::size_t firstCorner = mesh.indices.size();
        mesh.indices.resize(firstCorner + corners.size() / 3 * 3);
        std::uint32_t* placed = mesh.indices.data() + firstCorner;
        for (std::size_t i = 0; i + 2 < corners.size(); i += 3, placed += 3) {
            placed[0] = first + corners[i];
            placed[1] = first + corners[mirrored ? i + 2 : i + 1];
            placed[2] = first + corners[mirrored ? i + 1 : i + 2];
        }
    }

    const std::vector<DecodedPrimitive>& decodedMesh(int meshIndex) {
        if (auto found = decodedMeshes.find(meshIndex); found != decodedMeshes.end())
            return found->second;
        if (meshIndex < 0 || meshIndex >= int(model.meshes.size()))
            throw GltfError{"a node names mesh " + std::to_string(meshIndex) +
                            ", which does not exist"};
        const tinygltf::Mesh& source = model.meshes[std::size_t(meshIndex)];
        std::vector<DecodedPrimitive> primitives;
        for (std::size_t p = 0; p < source.primitives.size(); ++p)
            primitives.push_back(decodePrimitive(
                model, source.primitives[p],
                "mesh " + std::to_string(meshIndex) + " primitive " + std::to_string(p)));
        return decodedMeshes.emplace(meshIndex, std::move(primitives)).first->second;
    }

    void addMesh(int meshIndex, const glm::mat4& transform) {
        for (const DecodedPrimitive& primitive : decodedMesh(meshIndex))
            place(primitive, transform, meshIndex);
    }

    void addNode(int nodeIndex, const glm::mat4& parent, int depth) {
        if (nodeIndex < 0 || nodeIndex >= int(model.nodes.size()))
            throw GltfError{"the node hierarchy names node " + std::to_string(nodeIndex) +
                            ", which does not exist"};
        const auto index = std::size_t(nodeIndex);
        if (onPath[index])
            throw GltfError{"node " + std::to_string(nodeIndex) +
                            " is its own ancestor: the node hierarchy has a cycle"};
        if (depth > kMaxNodeDepth)
            throw GltfError{"nodes are nested deeper than " + std::to_string(kMaxNodeDepth) +
                            " levels"};
        if (++placements > kMaxNodePlacements)
            throw GltfError{"the nodes place more than " + std::to_string(kMaxNodePlacements) +
                            " instances (nodes that share children multiply)"};
        const tinygltf::Node& node = model.nodes[index];
        const std::optional<glm::mat4>& local = nodeTransforms[index];
        const glm::mat4 transform = local ? parent * *local : parent;
        if (node.mesh >= 0) addMesh(node.mesh, transform);
        onPath[index] = true;
        for (int child : node.children) addNode(child, transform, depth + 1);
        onPath[index] = false;
    }
};

// The JSON text of a .gltf, or of a .glb's first chunk (after a 12-byte header and the chunk's
// length and type); a malformed header leaves tinygltf to refuse the file.
std::string_view jsonTextOf(const std::string& bytes, bool binary) {
    if (!binary) return bytes;
    if (bytes.size() < 20) return {};
    std::uint32_t length = 0;
    for (int i = 3; i >= 0; --i)  // little-endian, whatever the machine's order
        length = (length << 8) | static_cast<unsigned char>(bytes[12 + std::size_t(i)]);
    return std::string_view(bytes).substr(20, length);
}

}  // namespace

Result<Mesh> readGltf(const std::filesystem::path& file) {
    auto bytes = readInputFile(file, kMaxMeshFileBytes);
    if (!bytes) return bytes.error();
    return parseGltf(*bytes, file);
}

Result<Mesh> parseGltf(const std::string& bytes, const std::filesystem::path& file) {
    const std::string name = displayPath(file);
    const bool binary = lowerCaseExtension(file) == ".glb";
    // tinygltf recurses once per level of the JSON, extras included.
    if (auto nesting = checkJsonNesting(jsonTextOf(bytes, binary), name); !nesting)
        return nesting.error();

    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(skipImage, nullptr);
    GltfExternalFiles externalFiles(file);
    loader.SetFsCallbacks(externalFiles.callbacks());
    tinygltf::Model model;
    std::string errors, warnings;
    const std::string& folder = externalFiles.baseDirectory();
    bool loaded = false;
    try {
        loaded = binary ? loader.LoadBinaryFromMemory(
                              &model, &errors, &warnings,
                              reinterpret_cast<const unsigned char*>(bytes.data()),
                              unsigned(bytes.size()), folder)
                        : loader.LoadASCIIFromString(&model, &errors, &warnings, bytes.data(),
                                                     unsigned(bytes.size()), folder);
    } catch (const std::logic_error&) {
        // tinygltf checks some indices with vector::at, e.g. a GLB buffer of byteLength 0
        // (the GLB fuzzer found it). Not std::exception: running out of memory is not bad input.
        return badInput(name + ": not a valid glTF 2.0 file (an index or length out of range)");
    }
    if (!loaded) {
        // tinygltf's messages span lines; the first says what went wrong. A refused external
        // file says it better, if it is what failed (a refused image is only a warning).
        std::string first = externalFiles.firstRefusal();
        if (first.empty() || errors.find(first) == std::string::npos)
            first = shortText(errors.substr(0, errors.find('\n')));
        if (first.empty()) first = "not a valid glTF 2.0 file";
        return badInput(name + ": " + first);
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
        return badInput(name + ": " + failure.message);
    }
    if (builder.mesh.indices.empty()) return badInput(name + ": no triangles to draw");
    if (builder.missingNormals) computeVertexNormals(builder.mesh);
    return std::move(builder.mesh);
}

}  // namespace matevo
