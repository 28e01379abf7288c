#include "mesh/MeshFile.h"

#include <filesystem>

#include "files/InputFile.h"
#include "image/ImageType.h"
#include "mesh/GeneratedMeshes.h"
#include "mesh/GltfReader.h"
#include "mesh/ObjReader.h"

namespace matevo {
namespace {

bool isMeshFileName(const std::filesystem::path& file) {
    const std::string extension = lowerCaseExtension(file);
    return extension == ".obj" || extension == ".gltf" || extension == ".glb";
}

}  // namespace

Result<Mesh> loadMesh(const std::string& nameOrFile) {
    if (const auto builtIn = parseBuiltInMesh(nameOrFile)) return makeBuiltInMesh(*builtIn);
    const std::filesystem::path file(nameOrFile);
    if (!isMeshFileName(file))
        return badInput(
            nameOrFile +
            ": not a mesh: expected sphere, shaderball, knot or a .obj, .gltf or .glb file");
    auto bytes = readInputFile(file, kMaxMeshFileBytes);
    if (!bytes) return bytes.error();
    return parseMeshFile(*bytes, file);
}

Result<Mesh> parseMeshFile(const std::string& bytes, const std::filesystem::path& file) {
    Result<Mesh> mesh = lowerCaseExtension(file) == ".obj" ? parseObj(bytes, file.string())
                                                           : parseGltf(bytes, file);
    if (!mesh) return mesh.error();
    if (auto valid = validateMesh(*mesh, file.string()); !valid) return valid.error();
    fitToUnitSphere(*mesh);
    return mesh;
}

}  // namespace matevo
