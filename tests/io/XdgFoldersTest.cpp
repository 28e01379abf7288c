// The user's XDG folders by one rule (files/XdgFolders.h): a variable counts only when it holds an
// absolute path, otherwise its default under $HOME applies.
#include "files/XdgFolders.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "support/ScopedEnvironment.h"

namespace matevo {
namespace {

using testing::ScopedEnvironment;

std::vector<std::string> dataSearchPath() {
    std::vector<std::string> folders;
    for (const auto& folder : xdgDataSearchPath()) folders.push_back(folder.string());
    return folders;
}

TEST(XdgFolders, AnAbsoluteVariableWinsOverTheDefaultUnderHome) {
    ScopedEnvironment home("HOME", "/home/someone");
    ScopedEnvironment config("XDG_CONFIG_HOME", "/elsewhere/config");
    ScopedEnvironment data("XDG_DATA_HOME", std::nullopt);
    ScopedEnvironment cache("XDG_CACHE_HOME", "");
    EXPECT_EQ(xdgHome(XdgHome::Config).string(), "/elsewhere/config");
    EXPECT_EQ(xdgHome(XdgHome::Data).string(), "/home/someone/.local/share");
    EXPECT_EQ(xdgHome(XdgHome::Cache).string(), "/home/someone/.cache");
}

TEST(XdgFolders, ARelativeVariableIsIgnoredForEveryFolder) {
    ScopedEnvironment home("HOME", "/home/someone");
    ScopedEnvironment config("XDG_CONFIG_HOME", "config");
    ScopedEnvironment data("XDG_DATA_HOME", "./data");
    ScopedEnvironment cache("XDG_CACHE_HOME", "cache");
    EXPECT_EQ(xdgHome(XdgHome::Config).string(), "/home/someone/.config");
    EXPECT_EQ(xdgHome(XdgHome::Data).string(), "/home/someone/.local/share");
    EXPECT_EQ(xdgHome(XdgHome::Cache).string(), "/home/someone/.cache");
}

TEST(XdgFolders, WithoutHomeOrVariableThereIsNoFolder) {
    ScopedEnvironment home("HOME", std::nullopt);
    ScopedEnvironment cache("XDG_CACHE_HOME", std::nullopt);
    EXPECT_TRUE(xdgHome(XdgHome::Cache).empty());
}

TEST(XdgFolders, DataIsLookedUpInTheDataHomeThenInEachAbsoluteDataDir) {
    ScopedEnvironment home("HOME", "/home/someone");
    ScopedEnvironment data("XDG_DATA_HOME", std::nullopt);
    ScopedEnvironment dirs("XDG_DATA_DIRS", "/opt/share::relative:/usr/share");
    EXPECT_EQ(dataSearchPath(),
              (std::vector<std::string>{"/home/someone/.local/share", "/opt/share", "/usr/share"}));
    ScopedEnvironment unset("XDG_DATA_DIRS", std::nullopt);
    EXPECT_EQ(dataSearchPath(), (std::vector<std::string>{"/home/someone/.local/share",
                                                          "/usr/local/share", "/usr/share"}));
}

}  // namespace
}  // namespace matevo
