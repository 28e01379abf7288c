#include "io/VariantFolder.h"

#include <algorithm>

#include "io/GenomeJson.h"
#include "io/JsonReader.h"
#include "io/TextFile.h"

namespace matevo {

Result<std::vector<VariantFile>> loadVariantFolder(const std::filesystem::path& folder) {
    std::error_code error;
    if (!std::filesystem::is_directory(folder, error))
        return Error{folder.string() + ": not a folder of variants"};
    // `matevo variants --out DIR` puts the genomes one level down.
    const std::filesystem::path variants =
        std::filesystem::is_directory(folder / "variants", error) ? folder / "variants" : folder;
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(variants, error))
        if (entry.is_regular_file() && entry.path().extension() == ".json")
            files.push_back(entry.path());
    if (error) return Error{variants.string() + ": cannot list: " + error.message()};
    std::sort(files.begin(), files.end());
    if (files.empty()) return Error{variants.string() + ": no genome .json files"};
    std::vector<VariantFile> loaded;
    for (const auto& file : files) {
        auto text = readTextFile(file);
        if (!text) return text.error();
        // A material file (what `matevo variants` writes) holds the genome under "genome".
        std::vector<std::string> ignored;
        auto genome = readJsonDocument<Genome>(*text, file.string(), ignored,
                                               [&](const nlohmann::json& json) {
                                                   const auto& object = json.is_object() &&
                                                                                json.contains("genome")
                                                                            ? json["genome"]
                                                                            : json;
                                                   JsonReader reader(object, "", ignored);
                                                   return readGenome(reader);
                                               });
        if (!genome) return genome.error();
        loaded.push_back({file, *genome});
    }
    return loaded;
}

}  // namespace matevo
