#include "export/GltfMaterial.h"

namespace matevo {

bool clearcoatActs(const GltfMaterial& material) { return material.clearcoat > 0.0; }

bool iorActs(const GltfMaterial& material) {
    return material.metallic < 1.0 && material.ior != GltfMaterial::kDefaultIor;
}

bool specularActs(const GltfMaterial& material) {
    return material.metallic < 1.0 &&
           (material.specular != 1.0 ||
            material.specularColor != std::array<double, 3>{1.0, 1.0, 1.0});
}

}  // namespace matevo
