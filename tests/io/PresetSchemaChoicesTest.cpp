// The preset schema (docs/preset.schema.json, a checked-in file that editors and users validate
// against) lists the same names as the choice tables the reader parses with: a name added to a
// table and not to the schema, or the other way round, fails here.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "common/Choice.h"
#include "evolve/GaSettings.h"
#include "scene/SceneSettings.h"

namespace matevo {
namespace {

std::vector<std::string> schemaEnum(const nlohmann::json& schema, const std::string& object,
                                    const std::string& field) {
    return schema.at("properties").at(object).at("properties").at(field).at("enum");
}

TEST(PresetSchemaChoices, EnumListsAreTheChoiceTables) {
    std::ifstream file(std::filesystem::path(MATEVO_SOURCE_DIR) / "docs/preset.schema.json");
    ASSERT_TRUE(file) << "docs/preset.schema.json";
    const nlohmann::json schema = nlohmann::json::parse(file);
    EXPECT_EQ(schemaEnum(schema, "ga", "metric"), choiceNames(kDistanceMetrics));
    EXPECT_EQ(schemaEnum(schema, "scene", "mode"), choiceNames(kSceneModes));
}

}  // namespace
}  // namespace matevo
