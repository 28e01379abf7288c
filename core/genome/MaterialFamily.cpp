#include "genome/MaterialFamily.h"

namespace matevo {

std::string_view toString(Coat coat) { return coat == Coat::Roughcoat ? "roughcoat" : "clearcoat"; }

std::string_view toString(Base base) {
    return base == Base::Conductor ? "conductor" : "dielectric";
}

std::string_view toString(TexturedLayer layer) {
    switch (layer) {
        case TexturedLayer::Top:
            return "top";
        case TexturedLayer::Bottom:
            return "bottom";
        case TexturedLayer::None:
            break;
    }
    return "none";
}

std::optional<Coat> parseCoat(std::string_view text) {
    if (text == "roughcoat") return Coat::Roughcoat;
    if (text == "clearcoat") return Coat::Clearcoat;
    return std::nullopt;
}

std::optional<Base> parseBase(std::string_view text) {
    if (text == "conductor") return Base::Conductor;
    if (text == "dielectric") return Base::Dielectric;
    return std::nullopt;
}

std::optional<TexturedLayer> parseTexturedLayer(std::string_view text) {
    if (text == "none") return TexturedLayer::None;
    if (text == "top") return TexturedLayer::Top;
    if (text == "bottom") return TexturedLayer::Bottom;
    return std::nullopt;
}

std::string describe(const MaterialFamily& family) {
    std::string label =
        std::string(toString(family.coat)) + "/" + std::string(toString(family.base));
    if (family.hasMedium) label += "+medium";
    if (family.texturedLayer != TexturedLayer::None)
        label += "+textured-" + std::string(toString(family.texturedLayer));
    return label;
}

}  // namespace matevo
