#include "files/CompanionFiles.h"

#include <cctype>
#include <cstdio>
#include <system_error>

#include "common/Fnv1a.h"
#include "files/AtomicFile.h"
#include "files/FileLock.h"
#include "files/InputFile.h"

namespace matevo {

namespace {

constexpr std::size_t kHashDigits = 16;

std::string hashText(std::string_view bytes) {
    char text[kHashDigits + 1];
    std::snprintf(text, sizeof text, "%016llx",
                  static_cast<unsigned long long>(
                      fnv1a(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size())));
    return text;
}

// True for STEM + suffix + "." + 16 hex digits + extension: a companion of this kind, whatever
// its contents.
bool isCompanionOfKind(const std::string& name, const std::string& stem,
                       const CompanionFile& kind) {
    const std::string prefix = stem + kind.suffix + ".";
    if (name.size() != prefix.size() + kHashDigits + kind.extension.size()) return false;
    if (name.compare(0, prefix.size(), prefix) != 0) return false;
    if (name.compare(name.size() - kind.extension.size(), kind.extension.size(), kind.extension) !=
        0)
        return false;
    for (std::size_t i = prefix.size(); i < prefix.size() + kHashDigits; ++i)
        if (!std::isxdigit(static_cast<unsigned char>(name[i]))) return false;
    return true;
}

bool holds(const std::filesystem::path& file, std::string_view contents) {
    auto existing = readInputFile(file, contents.size());
    return existing && *existing == contents;
}

}  // namespace

std::string companionFileName(const std::filesystem::path& mainFile,
                              const CompanionFile& companion) {
    // A symlink loop keeps the link's name here; writeWithCompanions then refuses the loop.
    const auto destination = writeDestination(mainFile);
    const auto& named = destination ? *destination : mainFile;
    return named.stem().string() + companion.suffix + "." + hashText(companion.contents) +
           companion.extension;
}

Status writeWithCompanions(const std::filesystem::path& requested, std::string_view mainContents,
                           const std::vector<CompanionFile>& companions) {
    const auto destination = writeDestination(requested);
    if (!destination) return destination.error();
    const std::filesystem::path& mainFile = *destination;
    const auto folder = mainFile.has_parent_path() ? mainFile.parent_path() : ".";
    const auto lock = FileLock::acquire(mainFile);
    if (!lock) return lock.error();
    std::vector<std::string> written;
    for (const auto& companion : companions) {
        if (companion.contents.empty()) continue;
        const std::string name = companionFileName(mainFile, companion);
        written.push_back(name);
        // The name says what it holds; an identical file is kept as it is.
        if (holds(folder / name, companion.contents)) continue;
        if (auto status = writeFileAtomically(folder / name, companion.contents); !status)
            return status;
    }
    if (auto status = writeFileAtomically(requested, mainContents); !status) return status;

    // Best effort: a companion left here is unused, never wrong.
    const std::string stem = mainFile.stem().string();
    std::vector<std::filesystem::path> unused;
    std::error_code error;
    for (std::filesystem::directory_iterator entry(folder, error), end; !error && entry != end;
         entry.increment(error)) {
        const std::string name = entry->path().filename().string();
        bool current = false, companion = false;
        for (const auto& kept : written) current = current || name == kept;
        for (const auto& kind : companions)
            companion = companion || isCompanionOfKind(name, stem, kind);
        if (companion && !current) unused.push_back(entry->path());
    }
    for (const auto& file : unused) std::filesystem::remove(file, error);
    return Ok{};
}

}  // namespace matevo
