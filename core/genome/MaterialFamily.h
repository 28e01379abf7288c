#pragma once
// A material family (Bernardi et al. 2020, §4.2.1 and Table 2): which coat, which base, whether
// a participating medium lies between them, and which layer (if any) has textured roughness.
#include <optional>
#include <string>
#include <string_view>

namespace matevo {

enum class Coat { Roughcoat, Clearcoat };
enum class Base { Conductor, Dielectric };
enum class TexturedLayer { None, Top, Bottom };

struct MaterialFamily {
    Coat coat = Coat::Clearcoat;
    Base base = Base::Conductor;
    bool hasMedium = false;
    TexturedLayer texturedLayer = TexturedLayer::None;

    bool operator==(const MaterialFamily&) const = default;
};

std::string_view toString(Coat coat);
std::string_view toString(Base base);
std::string_view toString(TexturedLayer layer);
std::optional<Coat> parseCoat(std::string_view text);
std::optional<Base> parseBase(std::string_view text);
std::optional<TexturedLayer> parseTexturedLayer(std::string_view text);

// Short human-readable label, e.g. "clearcoat/conductor+medium".
std::string describe(const MaterialFamily& family);

}  // namespace matevo
