#include "OutputNeeds.h"

#include "CommandLine.h"
#include "image/ImageFile.h"

namespace matevo::cli {

Font requireChartFont() {
    auto font = Font::dejaVuSans();
    if (!font) throw UsageError(font.error().message);
    return std::move(font).value();
}

void requireImageEncoder(const std::filesystem::path& file, const std::string& option) {
    if (Status ready = checkImageEncoder(file); !ready)
        throw UsageError(option + ": " + ready.error().message);
}

}  // namespace matevo::cli
