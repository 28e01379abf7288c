#include "files/XdgFolders.h"

#include <algorithm>
#include <cstdlib>
#include <string_view>

namespace matevo {

namespace {

bool isAbsolute(const char* value) { return value && *value == '/'; }

}  // namespace

std::filesystem::path xdgHome(XdgHome which) {
    struct Rule {
        const char* variable;
        const char* underHome;
    };
    constexpr Rule kRules[] = {{"XDG_CONFIG_HOME", ".config"},
                               {"XDG_DATA_HOME", ".local/share"},
                               {"XDG_CACHE_HOME", ".cache"}};
    const Rule& rule = kRules[int(which)];
    if (const char* value = std::getenv(rule.variable); isAbsolute(value)) return value;
    if (const char* home = std::getenv("HOME"); home && *home)
        return std::filesystem::path(home) / rule.underHome;
    return {};
}

std::vector<std::filesystem::path> xdgDataSearchPath() {
    std::vector<std::filesystem::path> folders;
    if (auto dataHome = xdgHome(XdgHome::Data); !dataHome.empty())
        folders.push_back(std::move(dataHome));
    const char* dirs = std::getenv("XDG_DATA_DIRS");
    const std::string_view list = dirs && *dirs ? dirs : "/usr/local/share:/usr/share";
    for (std::size_t start = 0; start <= list.size();) {
        const std::size_t end = std::min(list.find(':', start), list.size());
        if (end > start && list[start] == '/')
            folders.emplace_back(list.substr(start, end - start));
        start = end + 1;
    }
    return folders;
}

}  // namespace matevo
