#include <cstdio>

#include "CommandLine.h"
#include "PresetOption.h"
#include "commands/Commands.h"
#include "documents/PresetCatalog.h"

namespace matevo::cli {

int runPresets(CommandLine& args) {
    if (args.wantsHelp()) {
        std::printf(
            "usage: matevo presets\n\n"
            "Lists the presets that --preset NAME (and matevo edit NAME) accept: the user's own,\n"
            "NAME.json in %s, then the shipped ones. A user's preset\n"
            "hides a shipped one of the same name. Each preset: name, family,\n"
            "description and file.\n",
            userPresetDirectory().empty() ? "$XDG_DATA_HOME/matevo/presets"
                                          : userPresetDirectory().c_str());
        return 0;
    }
    args.finish();
    auto presets = listPresets();
    if (!presets) throw CommandFailure(presets.error());
    for (const PresetEntry& entry : *presets) {
        // A preset that does not load is listed with its error rather than hidden.
        auto loaded = loadPreset(entry.file);
        const std::string family = loaded ? describe(loaded->preset.family) : "(unreadable)";
        const std::string description =
            loaded ? loaded->preset.description : loaded.error().message;
        std::printf("%-28s %s%s\n    %s\n    %s\n", entry.name.c_str(), family.c_str(),
                    entry.shipped ? "" : "  (yours)", description.c_str(), entry.file.c_str());
    }
    return 0;
}

}  // namespace matevo::cli
