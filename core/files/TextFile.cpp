#include "files/TextFile.h"

#include "files/InputFile.h"

namespace matevo {

Result<std::string> readTextFile(const std::filesystem::path& file) {
    return readInputFile(file, kMaxTextFileBytes);
}

}  // namespace matevo
