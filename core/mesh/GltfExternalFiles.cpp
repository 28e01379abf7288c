#include "mesh/GltfExternalFiles.h"

#include <algorithm>

#include "common/MemoryBudget.h"
#include "common/ShortText.h"
#include "files/InputFile.h"
#include "mesh/GltfReader.h"

namespace matevo {
namespace {

namespace fs = std::filesystem;

// tinygltf asks whether a file exists before reading it, trying the base directory first; saying
// yes keeps it on that first candidate (and off its second one, the current directory), and the
// read below decides.
bool answerExists(const std::string&, void*) { return true; }
std::string keepPath(const std::string& path, void*) { return path; }
bool refuseWrite(std::string* error, const std::string&, const std::vector<unsigned char>&, void*) {
    *error = "matevo reads glTF files, never writes through them";
    return false;
}

// Why `uri` may not be read, or "" when it lies inside `folder`.
std::string escapeFromFolder(const std::string& uri, const fs::path& folder) {
    if (uri.empty()) return "empty";
    if (uri.find('\0') != std::string::npos) return "contains a NUL character";
    const fs::path relative(uri);
    if (relative.is_absolute()) return "an absolute path; external files must lie beside the glTF";
    for (const fs::path& step : relative)
        if (step == "..") return "steps out of the glTF file's folder with '..'";
    // A symlink inside the folder may still point out of it.
    std::error_code folderError, targetError;
    const fs::path inside = fs::weakly_canonical(folder, folderError);
    const fs::path target = fs::weakly_canonical(folder / relative, targetError);
    if (folderError || targetError)
        return "cannot resolve: " + (folderError ? folderError : targetError).message();
    const auto [folderEnd, targetAt] =
        std::mismatch(inside.begin(), inside.end(), target.begin(), target.end());
    if (folderEnd != inside.end()) return "a symlink that leads out of the glTF file's folder";
    return "";
}

}  // namespace

GltfExternalFiles::GltfExternalFiles(const fs::path& gltfFile)
    : baseDirectory_(gltfFile.has_parent_path() ? gltfFile.parent_path().string() : ".") {}

tinygltf::FsCallbacks GltfExternalFiles::callbacks() {
    return {answerExists, keepPath, readFile, refuseWrite, this};
}

bool GltfExternalFiles::readFile(std::vector<unsigned char>* bytes, std::string* error,
                                 const std::string& joinedPath, void* self) {
    return static_cast<GltfExternalFiles*>(self)->read(*bytes, *error, joinedPath);
}

bool GltfExternalFiles::read(std::vector<unsigned char>& bytes, std::string& error,
                             const std::string& joinedPath) {
    // tinygltf joined the URI to the base directory with one '/' (unless it ended in one).
    const std::string prefix = baseDirectory_.back() == '/' ? baseDirectory_ : baseDirectory_ + "/";
    const std::string uri = joinedPath.compare(0, prefix.size(), prefix) == 0
                                ? joinedPath.substr(prefix.size())
                                : joinedPath;
    std::string problem = escapeFromFolder(uri, baseDirectory_);
    if (problem.empty()) {
        // Read whole and then copied for tinygltf: twice the file's size for a moment.
        const std::uintmax_t limit =
            std::min<std::uintmax_t>(kMaxMeshFileBytes, memoryLimitBytes() / 2);
        auto contents = readInputFile(fs::path(baseDirectory_) / uri, limit);
        if (contents) {
            bytes.assign(contents->begin(), contents->end());
            return true;
        }
        problem = contents.error().message;
    }
    error = "external file \"" + shortText(uri) + "\": " + problem;
    if (firstRefusal_.empty()) firstRefusal_ = error;
    return false;
}

}  // namespace matevo
