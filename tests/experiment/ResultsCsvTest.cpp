#include "experiment/ResultsCsv.h"

#include <charconv>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace matevo {
namespace {

std::vector<std::string> splitFields(const std::string& line) {
    std::vector<std::string> fields;
    std::stringstream stream(line);
    std::string field;
    while (std::getline(stream, field, ',')) fields.push_back(field);
    return fields;
}

double parseDouble(const std::string& text) {
    double value = 0;
    auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    EXPECT_EQ(ec, std::errc()) << text;
    EXPECT_EQ(end, text.data() + text.size()) << text;
    return value;
}

RunRecord sampleRecord() {
    RunRecord record;
    record.preset = "validation metal";
    record.metric = ExperimentMetric::Manhattan;
    record.size = {100, 10};
    record.seed = 0x9e3779b97f4a7c15ULL;
    record.run = 7;
    record.fitness = 0.1 + 0.2;  // not exactly 0.3: the CSV must keep every bit
    record.meanDeltaE00 = 2.0 / 3.0;
    for (std::size_t i = 0; i < kPaperChromosomeCount; ++i) record.genome[i] = 1.0 / double(i + 3);
    return record;
}

TEST(ResultsCsv, HeaderNamesTheRunColumnsThenTheTwelveChromosomes) {
    const auto fields = splitFields(resultsCsvHeader());
    ASSERT_EQ(fields.size(), 8 + kPaperChromosomeCount);
    const std::vector<std::string> leading = {"preset", "metric", "population", "generations",
                                              "seed",   "run",    "fitness",    "mean_de00"};
    for (std::size_t i = 0; i < leading.size(); ++i) EXPECT_EQ(fields[i], leading[i]);
    for (std::size_t i = 0; i < kPaperChromosomeCount; ++i)
        EXPECT_EQ(fields[8 + i], chromosomeName(i));
}

TEST(ResultsCsv, RowHasOneParseableFieldPerColumnAndKeepsEveryBit) {
    const RunRecord record = sampleRecord();
    const auto fields = splitFields(resultsCsvRow(record));
    ASSERT_EQ(fields.size(), splitFields(resultsCsvHeader()).size());
    EXPECT_EQ(fields[0], record.preset);
    EXPECT_EQ(fields[1], "manhattan");
    EXPECT_EQ(parseDouble(fields[2]), 100);
    EXPECT_EQ(parseDouble(fields[3]), 10);
    EXPECT_EQ(std::stoull(fields[4]), record.seed);
    EXPECT_EQ(parseDouble(fields[5]), 7);
    EXPECT_EQ(parseDouble(fields[6]), record.fitness);
    EXPECT_EQ(parseDouble(fields[7]), record.meanDeltaE00);
    for (std::size_t i = 0; i < kPaperChromosomeCount; ++i)
        EXPECT_EQ(parseDouble(fields[8 + i]), record.genome[i]) << chromosomeName(i);
}

TEST(ResultsCsv, QuotesAPresetNameWithACommaOrQuote) {
    RunRecord record = sampleRecord();
    record.preset = "metal, \"shiny\"";
    const std::string row = resultsCsvRow(record);
    EXPECT_EQ(row.rfind("\"metal, \"\"shiny\"\"\",manhattan,", 0), 0u) << row;
}

TEST(ResultsCsv, DocumentHasTheHeaderThenOneLinePerRecord) {
    const std::vector<RunRecord> records(3, sampleRecord());
    const std::string csv = resultsCsv(records);
    std::stringstream stream(csv);
    std::string line;
    std::vector<std::string> lines;
    while (std::getline(stream, line)) lines.push_back(line);
    ASSERT_EQ(lines.size(), 4u);
    EXPECT_EQ(lines[0], resultsCsvHeader());
    for (std::size_t i = 1; i < lines.size(); ++i) EXPECT_EQ(lines[i], resultsCsvRow(records[0]));
    EXPECT_EQ(csv.back(), '\n');
}

}  // namespace
}  // namespace matevo
