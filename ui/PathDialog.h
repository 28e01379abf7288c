#pragma once
// A small modal that asks for a file path (open or save-as): a text entry, and below it the
// folder it points into to browse (FolderBrowser.h). A dialog that writes can ask before
// replacing an existing file.
#include <filesystem>
#include <optional>
#include <string>

namespace matevo::ui {

class PathDialog {
public:
    enum class Existing { Accept, AskBeforeReplacing };

    // Opens the dialog on the next draw() with the given title and a suggested path. With
    // AskBeforeReplacing, a path naming an existing file is returned only once the user chose
    // "Replace" (`except`, e.g. the document's own file, is replaced without asking).
    void open(std::string title, const std::filesystem::path& suggestion,
              Existing existing = Existing::Accept, std::filesystem::path except = {});
    // Draws the modal when open; returns the confirmed path once.
    std::optional<std::filesystem::path> draw();
    bool isOpen() const { return wantsOpen_ || visible_; }

private:
    bool mustAsk() const;

    std::string title_;
    std::string path_;
    Existing existing_ = Existing::Accept;
    std::filesystem::path except_;
    bool askingToReplace_ = false;  // the typed path exists: Replace or choose another
    bool focusPath_ = false;        // give the path field the keyboard in the next frame
    bool wantsOpen_ = false;
    bool visible_ = false;
};

}  // namespace matevo::ui
