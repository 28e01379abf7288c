#pragma once
// The modal that stands between unsaved changes and whatever would discard them (opening another
// preset, quitting, closing the window, dropping a file on it): Save, Discard or Cancel.
#include <string>

namespace matevo::ui {

enum class PromptAnswer { None, Save, Discard, Cancel };

class UnsavedChangesPrompt {
public:
    // Shows the prompt from the next draw(): "<document> has unsaved changes. Save them before
    // <action>?"
    void open(std::string document, std::string action);
    // The answer, once, in the frame it is given; None while undecided or closed.
    PromptAnswer draw();
    bool isOpen() const { return wantsOpen_ || visible_; }

    static constexpr const char* kTitle = "Unsaved changes";

private:
    std::string question_;
    bool wantsOpen_ = false;
    bool visible_ = false;
};

}  // namespace matevo::ui
