#include "experiment/ResultsCsv.h"

#include <array>
#include <charconv>

namespace matevo {

namespace {

std::string exactNumber(double value) {
    std::array<char, 32> buffer{};
    auto [end, ec] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    (void)ec;  // 32 characters hold any double
    return std::string(buffer.data(), end);
}

std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
    std::string quoted = "\"";
    for (char character : text) {
        if (character == '"') quoted += '"';
        quoted += character;
    }
    return quoted + '"';
}

}  // namespace

std::string resultsCsvHeader() {
    std::string header = "preset,metric,population,generations,seed,run,fitness,mean_de00";
    for (std::size_t i = 0; i < kChromosomeCount; ++i)
        header += "," + std::string(chromosomeName(i));
    return header;
}

std::string resultsCsvRow(const RunRecord& record) {
    std::string row = csvField(record.preset) + "," + std::string(toString(record.metric)) + "," +
                      std::to_string(record.size.population) + "," +
                      std::to_string(record.size.generations) + "," +
                      std::to_string(record.seed) + "," + std::to_string(record.run) + "," +
                      exactNumber(record.fitness) + "," + exactNumber(record.meanDeltaE00);
    for (double value : record.genome.values) row += "," + exactNumber(value);
    return row;
}

std::string resultsCsv(std::span<const RunRecord> records) {
    std::string csv = resultsCsvHeader() + "\n";
    for (const auto& record : records) csv += resultsCsvRow(record) + "\n";
    return csv;
}

}  // namespace matevo
