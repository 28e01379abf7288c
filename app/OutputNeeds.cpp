#include "OutputNeeds.h"

#include "CommandLine.h"
#include "image/ImageFile.h"

namespace matevo::cli {

Font requireChartFont() {
    auto font = Font::dejaVuSans();
    if (!font) throw CommandFailure(font.error());
    return std::move(font).value();
}

void requireImageEncoder(const std::filesystem::path& file, const std::string& option) {
    if (Status ready = checkImageEncoder(file); !ready)
        throw CommandFailure(withContext(ready.error(), option));
}

}  // namespace matevo::cli
