#pragma once
// What a command needs to write its output besides the folder (claimed up front too:
// CommandLine.h's claimOutputFolder), looked for before the work starts: a run of minutes must
// not fail only when it writes. Whatever is missing is a UsageError (exit 2) naming it and
// where it was looked for.
#include <filesystem>
#include <string>

#include "image/Font.h"

namespace matevo::cli {

// DejaVu Sans, the font of experiment's charts and variants' contact sheets.
Font requireChartFont();

// The encoder of `file`'s image type (image/ImageFile.h): an .exr needs matevo's OpenImageIO
// module. `option` names what asked for the type ("--out", "--format").
void requireImageEncoder(const std::filesystem::path& file, const std::string& option);

}  // namespace matevo::cli
