#pragma once
// A small modal that asks for a file path (open or save-as). Plain text entry: Debian's imgui
// has no file browser, and typing a path is what a technical artist does in a terminal anyway.
#include <filesystem>
#include <optional>
#include <string>

namespace matevo::ui {

class PathDialog {
public:
    // Opens the dialog on the next draw() with the given title and a suggested path.
    void open(std::string title, const std::filesystem::path& suggestion);
    // Draws the modal when open; returns the confirmed path once.
    std::optional<std::filesystem::path> draw();
    bool isOpen() const { return wantsOpen_ || visible_; }

private:
    std::string title_;
    std::string path_;
    bool wantsOpen_ = false;
    bool visible_ = false;
};

}  // namespace matevo::ui
