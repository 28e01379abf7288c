#pragma once
// Usage lines list a choice's names as "a|b|c". Help texts write a placeholder instead —
// {distances}, {image-metrics}, {formats}, {backends}, {lightings} — which this fills from the
// choice tables (common/Choice.h), so help never lists a name the parser does not take.
#include <string>
#include <string_view>

namespace matevo::cli {

std::string withChoiceNames(std::string_view help);

}  // namespace matevo::cli
