#pragma once
// The files a glTF names by URI (external buffers and images), read for tinygltf only from inside
// the glTF file's own folder and only through readInputFile: an absolute path, a `..` step or a
// symlink that leads out of the folder is refused, and so are FIFOs, devices and folders, and
// files larger than the mesh limit or half the memory limit, before any byte is read. Without
// this, tinygltf's default file access would read any path (`../../etc/passwd` as vertex data)
// and hang on a FIFO.
#include <filesystem>
#include <string>

#include <tiny_gltf.h>

namespace matevo {

class GltfExternalFiles {
public:
    explicit GltfExternalFiles(const std::filesystem::path& gltfFile);

    // The folder tinygltf joins URIs to; pass it as the loaders' base directory.
    const std::string& baseDirectory() const { return baseDirectory_; }
    // Callbacks for TinyGLTF::SetFsCallbacks; they refer to this object, which must outlive them.
    tinygltf::FsCallbacks callbacks();
    // Why the first refused file was refused ("" when none was), also part of tinygltf's error
    // when it was a buffer.
    const std::string& firstRefusal() const { return firstRefusal_; }

private:
    static bool readFile(std::vector<unsigned char>* bytes, std::string* error,
                         const std::string& joinedPath, void* self);
    bool read(std::vector<unsigned char>& bytes, std::string& error, const std::string& joinedPath);

    std::string baseDirectory_;
    std::string firstRefusal_;
};

}  // namespace matevo
