#include "io/TextFile.h"

#include <fstream>
#include <sstream>

namespace matevo {

Result<std::string> readTextFile(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return Error{file.string() + ": cannot open for reading"};
    std::stringstream text;
    text << in.rdbuf();
    if (in.bad()) return Error{file.string() + ": read failed"};
    return text.str();
}

}  // namespace matevo
