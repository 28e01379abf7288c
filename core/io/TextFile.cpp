#include "io/TextFile.h"

#include "io/InputFile.h"

namespace matevo {

Result<std::string> readTextFile(const std::filesystem::path& file) {
    return readInputFile(file, kMaxTextFileBytes);
}

}  // namespace matevo
