#include "mesh/MeshFile.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "io/InputFile.h"
#include "mesh/GeneratedMeshes.h"
#include "mesh/GltfReader.h"
#include "mesh/ObjReader.h"

namespace matevo {

Result<Mesh> loadMesh(const std::string& nameOrFile) {
    if (const auto builtIn = parseBuiltInMesh(nameOrFile)) return makeBuiltInMesh(*builtIn);
    const std::filesystem::path file(nameOrFile);
    std::string extension = file.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    Result<Mesh> mesh = Error{};
    if (extension == ".obj") {
        auto text = readInputFile(file, kMaxMeshFileBytes);
        if (!text) return text.error();
        mesh = parseObj(*text, nameOrFile);
    } else if (extension == ".gltf" || extension == ".glb") {
        mesh = readGltf(file);
    } else {
        return Error{nameOrFile +
                     ": not a mesh: expected sphere, shaderball, knot or a .obj, .gltf or .glb file"};
    }
    if (!mesh) return mesh.error();
    if (auto valid = validateMesh(*mesh, nameOrFile); !valid) return valid.error();
    fitToUnitSphere(*mesh);
    return mesh;
}

}  // namespace matevo
