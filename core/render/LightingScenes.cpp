#include "render/LightingScenes.h"

#include <algorithm>
#include <map>

#include "scene/LightingChoice.h"

namespace matevo {

Result<std::vector<std::string>> parseLightingList(const std::string& text) {
    std::vector<std::string> names;
    std::size_t start = 0;
    while (true) {
        const std::size_t comma = text.find(',', start);
        const std::string name =
            text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        if (name.empty())
            return badInput(
                "expected lightings separated by commas (paper, ambient, studio or "
                "an environment file), got '" +
                text + "'");
        if (std::find(names.begin(), names.end(), name) != names.end())
            return badInput("'" + name + "' is listed twice");
        names.push_back(name);
        if (comma == std::string::npos) return names;
        start = comma + 1;
    }
}

Result<std::vector<LitScene>> lightingScenes(const std::vector<std::string>& names,
                                             const SceneSettings& presetScene,
                                             const SceneTextures& presetTextures,
                                             const MakeRenderer& make) {
    std::vector<LitScene> scenes;
    if (names.empty()) {
        auto made = make(presetTextures);
        if (!made) return made.error();
        scenes.push_back({"", presetScene, std::move(made).value()});
        return scenes;
    }
    // By environment: "" for paper and ambient, else the lighting's name.
    std::map<std::string, std::shared_ptr<PopulationRenderer>> renderers;
    for (const std::string& name : names) {
        LitScene lit{name, presetScene, nullptr};
        SceneTextures textures = presetTextures;
        if (auto applied = applyLightingChoice(name, lit.scene, textures); !applied)
            return applied.error();
        std::shared_ptr<PopulationRenderer>& renderer =
            renderers[textures.environment.empty() ? "" : name];
        if (!renderer) {
            auto made = make(textures);
            if (!made) return made.error();
            renderer = std::move(made).value();
        }
        lit.renderer = renderer;
        scenes.push_back(std::move(lit));
    }
    return scenes;
}

}  // namespace matevo
