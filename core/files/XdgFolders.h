#pragma once
// The user's folders after the XDG Base Directory specification, with one rule for all of
// matevo: a variable counts only when it holds an absolute path (the specification says to
// ignore a relative one), otherwise its default under $HOME applies.
#include <filesystem>
#include <vector>

namespace matevo {

enum class XdgHome { Config, Data, Cache };

// $XDG_CONFIG_HOME (default ~/.config), $XDG_DATA_HOME (default ~/.local/share) or
// $XDG_CACHE_HOME (default ~/.cache). Empty when neither the variable nor HOME is set.
std::filesystem::path xdgHome(XdgHome which);

// Where data files are looked up, in order: xdgHome(XdgHome::Data), then each absolute folder
// of $XDG_DATA_DIRS (default /usr/local/share:/usr/share).
std::vector<std::filesystem::path> xdgDataSearchPath();

}  // namespace matevo
