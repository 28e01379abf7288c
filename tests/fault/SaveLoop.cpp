// The victim of the kill -9 fault test: saves a preset over and over through the real save path
// (savePreset, the one atomic writer), each save a different size, until it is killed. Each
// version's description is one repeated letter, so a reader can tell a whole file from a torn
// one. Usage: matevo_save_loop PRESET_IN FILE_OUT
#include <cstdio>
#include <string>

#include "documents/Preset.h"

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: %s PRESET_IN FILE_OUT\n", argv[0]);
        return 2;
    }
    auto loaded = matevo::loadPreset(argv[1]);
    if (!loaded) {
        std::fprintf(stderr, "%s\n", loaded.error().message.c_str());
        return 2;
    }
    matevo::Preset preset = loaded->preset;
    for (unsigned version = 0;; ++version) {
        preset.description.assign(1 + (version * 7919u) % 400000u, char('a' + version % 26));
        if (auto saved = matevo::savePreset(preset, argv[2]); !saved) {
            std::fprintf(stderr, "%s\n", saved.error().message.c_str());
            return 1;
        }
    }
}
