#pragma once
// The experiment's results as CSV, one row per run:
//   preset,metric,population,generations,seed,run,fitness,mean_de00,eta1,...,g
// Numbers are written in their shortest exact form (they read back to the same double), so a
// row's genome can be rendered again bit for bit. A preset name with a comma or a quote is
// quoted as RFC 4180 says.
#include <span>
#include <string>

#include "experiment/RunRecord.h"

namespace matevo {

std::string resultsCsvHeader();
std::string resultsCsvRow(const RunRecord& record);
std::string resultsCsv(std::span<const RunRecord> records);  // header and rows, '\n' endings

}  // namespace matevo
