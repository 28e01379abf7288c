#include "experiment/ResultsCsv.h"

#include <array>
#include <charconv>
#include <string_view>

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
    for (std::size_t i = 0; i < kPaperChromosomeCount; ++i) {
        header += ',';
        header += chromosomeName(i);
    }
    return header;
}

std::string resultsCsvRow(const RunRecord& record) {
    std::string row = csvField(record.preset);
    auto addField = [&row](std::string_view field) {
        row += ',';
        row += field;
    };
    addField(toString(record.metric));
    addField(std::to_string(record.size.population));
    addField(std::to_string(record.size.generations));
    addField(std::to_string(record.seed));
    addField(std::to_string(record.run));
    addField(exactNumber(record.fitness));
    addField(exactNumber(record.meanDeltaE00));
    for (std::size_t i = 0; i < kPaperChromosomeCount; ++i) addField(exactNumber(record.genome[i]));
    return row;
}

std::string resultsCsv(std::span<const RunRecord> records) {
    std::string csv = resultsCsvHeader() + "\n";
    for (const auto& record : records) {
        csv += resultsCsvRow(record);
        csv += '\n';
    }
    return csv;
}

}  // namespace matevo
