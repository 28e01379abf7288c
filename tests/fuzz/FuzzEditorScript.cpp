// libFuzzer target: the editor's script parser (`matevo edit --script`).
#include <cstddef>
#include <cstdint>
#include <string>

#include "editor/EditorScript.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    (void)matevo::editor::parseEditorScript(text, "fuzz.script");
    return 0;
}
