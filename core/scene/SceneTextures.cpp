#include "scene/SceneTextures.h"

#include <algorithm>
#include <cmath>

#include "image/ImageFile.h"
#include "scene/StudioEnvironment.h"

namespace matevo {

namespace {

// `source` names what asked for the texture (a preset or material file) in errors.
Result<Image> loadTexture(const std::string& source, const std::string& field,
                          const std::filesystem::path& file) {
    if (file.empty()) return Image();
    auto image = readImage(file);
    if (!image) return withContext(image.error(), source + ": " + field);
    // Texels scale roughness or colour: an EXR may hold anything, the model needs [0, 1].
    for (std::size_t i = 0; i < image->rgba.size(); ++i) {
        const float value = image->rgba[i];
        if (value < 0.0f || value > 1.0f) {
            const std::size_t pixel = i / 4;
            return badInput(source + ": " + field + ": texel (" +
                            std::to_string(pixel % std::size_t(image->width)) + ", " +
                            std::to_string(pixel / std::size_t(image->width)) + ") value " +
                            std::to_string(value) + " outside [0, 1]");
        }
    }
    return image;
}

Result<SceneTextures> loadTextures(const std::string& source,
                                   const std::filesystem::path& roughnessFile,
                                   const std::filesystem::path& baseColorFile) {
    auto roughness = loadTexture(source, "textures.roughness", roughnessFile);
    if (!roughness) return roughness.error();
    auto baseColor = loadTexture(source, "textures.base_color", baseColorFile);
    if (!baseColor) return baseColor.error();
    // No environment: loadSceneTextures adds it in the environment scene mode.
    return SceneTextures{std::move(roughness).value(), std::move(baseColor).value(), {}};
}

Result<SceneTextures> withEnvironment(SceneTextures textures, const SceneSettings& scene,
                                      const std::filesystem::path& folder,
                                      const std::string& source) {
    if (scene.mode != SceneMode::Environment) return textures;
    auto environment = loadEnvironment(environmentFile(scene, folder));
    if (!environment) return withContext(environment.error(), source + ": scene.environment");
    textures.environment = std::move(environment).value();
    return textures;
}

}  // namespace

Result<SceneTextures> loadSceneTextures(const std::filesystem::path& roughnessFile,
                                        const std::filesystem::path& baseColorFile,
                                        const SceneSettings& scene,
                                        const std::filesystem::path& folder,
                                        const std::string& source) {
    auto textures = loadTextures(source, roughnessFile, baseColorFile);
    if (!textures) return textures;
    return withEnvironment(std::move(*textures), scene, folder, source);
}

std::string environmentFile(const SceneSettings& scene, const std::filesystem::path& folder) {
    const std::filesystem::path name(scene.environment);
    return scene.environment == "studio" || name.is_absolute() ? scene.environment
                                                               : (folder / name).string();
}

std::array<double, 3> sampleTexture(const Image& texture, double u, double v) {
    const double x = u * texture.width - 0.5;
    const double y = std::clamp(v * texture.height - 0.5, 0.0, double(texture.height - 1));
    const double x0 = std::floor(x);
    const double y0 = std::min(std::floor(y), double(std::max(texture.height - 2, 0)));
    const double wx = x - x0, wy = std::min(y - y0, 1.0);
    auto column = [&](double cx) {
        const int wrapped = int(cx) % texture.width;
        return wrapped < 0 ? wrapped + texture.width : wrapped;
    };
    const int columns[2] = {column(x0), column(x0 + 1.0)};
    const int rows[2] = {int(y0), std::min(int(y0) + 1, texture.height - 1)};
    std::array<double, 3> value = {0.0, 0.0, 0.0};
    for (int j = 0; j < 2; ++j) {
        for (int i = 0; i < 2; ++i) {
            const double weight = (i ? wx : 1.0 - wx) * (j ? wy : 1.0 - wy);
            const float* texel = texture.pixel(columns[i], rows[j]);
            for (int c = 0; c < 3; ++c) value[c] += weight * texel[c];
        }
    }
    return value;
}

SurfaceTexels texelsAt(const SceneTextures& textures, double u, double v) {
    SurfaceTexels texels;
    if (textures.roughness.width > 0) texels.roughness = sampleTexture(textures.roughness, u, v)[0];
    if (textures.baseColor.width > 0) texels.baseColor = sampleTexture(textures.baseColor, u, v);
    return texels;
}

}  // namespace matevo
