// FGD/TIR integrals against docs/bsdf.md §8, the tables against direct integration, and the
// on-disk cache (version, settings and checksum checks).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include <gtest/gtest.h>

#include "files/AtomicFile.h"
#include "material/FgdIntegrals.h"
#include "material/FgdTableCache.h"
#include "material/Fresnel.h"

namespace matevo {
namespace {

TEST(FgdIntegrals, SingleScatteringReferenceValues) {
    EXPECT_NEAR(integrateFgdSingleScattering(1.0, 0.1, 1.5, 0.0), 0.03972, 1.5e-4);
    EXPECT_NEAR(integrateFgdSingleScattering(0.5, 0.1, 1.5, 0.0), 0.08592, 1e-4);
    EXPECT_NEAR(integrateFgdSingleScattering(0.2, 0.1, 1.5, 0.0), 0.23561, 1e-4);
    EXPECT_NEAR(integrateFgdSingleScattering(1.0, 0.5, 1.5, 0.0), 0.02817, 1e-4);
    EXPECT_NEAR(integrateFgdSingleScattering(0.5, 0.5, 1.5, 0.0), 0.04285, 1e-4);
    EXPECT_NEAR(integrateFgdSingleScattering(0.5, 0.3, 0.6667, 0.0), 0.65078, 1e-4);
    EXPECT_NEAR(integrateFgdSingleScattering(1.0, 0.2, 0.5333, 0.0), 0.13564, 1e-4);
    EXPECT_NEAR(integrateFgdSingleScattering(1.0, 0.2, 1.0, 1.0), 0.19076, 1.5e-4);
    EXPECT_NEAR(integrateFgdSingleScattering(0.5, 0.5, 1.0, 1.0), 0.1716, 1e-4);
    EXPECT_NEAR(integrateFgdSingleScattering(1.0, 0.3, 0.143, 3.983), 0.8479, 1e-4);
}

TEST(FgdIntegrals, AlbedoWithoutFresnel) {
    EXPECT_NEAR(integrateMaskingAlbedo(1.0, 0.1), 0.99, 1e-4);
    EXPECT_NEAR(integrateMaskingAlbedo(1.0, 0.5), 0.6878, 1e-4);
    EXPECT_NEAR(integrateMaskingAlbedo(0.5, 0.5), 0.686, 1e-4);
    EXPECT_NEAR(integrateMaskingAlbedo(1.0, 1.0), 0.307, 5e-4);  // given to 3 digits
}

TEST(FgdIntegrals, KullaContyCompensation) {
    EXPECT_NEAR(averageFresnel(1.0, 1.0), 0.2823, 1e-4);
    EXPECT_NEAR(averageMaskingAlbedo(0.5), 0.6894, 2e-4);
    EXPECT_NEAR(averageFresnel(1.5, 0.0), 0.0918, 1e-4);
    EXPECT_NEAR(integrateFgd(1.0, 0.5, 1.0, 1.0), 0.1588, 2e-4);
    EXPECT_NEAR(integrateFgd(1.0, 0.3, 0.143, 3.983), 0.9614, 2e-4);
    EXPECT_NEAR(integrateFgd(1.0, 1.0, 0.143, 3.983), 0.9058, 2e-4);
    // Dielectrics keep the single-scattering value (T = 1 - R absorbs the rest).
    EXPECT_EQ(integrateFgd(0.7, 0.4, 1.5, 0.0), integrateFgdSingleScattering(0.7, 0.4, 1.5, 0.0));
}

TEST(FgdIntegrals, EscapeFractionReferenceValues) {
    const double inside = 1.0 / 1.5;
    EXPECT_NEAR(integrateEscapeFraction(1.0, 0.01, inside), 0.960, 1e-3);
    EXPECT_NEAR(integrateEscapeFraction(0.8, 0.01, inside), 0.867, 1e-3);
    EXPECT_NEAR(integrateEscapeFraction(0.75, 0.01, inside), 0.398, 1e-3);
    EXPECT_NEAR(integrateEscapeFraction(1.0, 0.3, inside), 0.651, 1.5e-3);
    EXPECT_NEAR(integrateEscapeFraction(0.5, 0.3, inside), 0.283, 1.5e-3);
    EXPECT_NEAR(integrateEscapeFraction(1.0, 0.6, inside), 0.434, 1e-3);
    EXPECT_NEAR(integrateEscapeFraction(0.6, 0.2, 1.0), 1.0, 1e-12);  // nothing to reflect
}

TEST(FgdTables, SmoothRowIsFresnel) {
    const FgdTables& tables = defaultFgdTables();
    // eta = 1.5 lies between eta nodes (geometric blend): within 0.3 % of Fresnel.
    EXPECT_NEAR(tables.reflectance(1.0, 0.0, 1.5, 0.0), 0.04, 0.04 * 3e-3);
    EXPECT_NEAR(tables.reflectance(0.5, 0.0, 1.5, 0.0), 0.08919, 0.08919 * 3e-3);
    const double etaNode = tables.grid().eta.nodeValue(30);
    EXPECT_NEAR(tables.reflectance(0.5, 0.0, etaNode, 0.0), fresnelDielectric(0.5, etaNode), 1e-6);
    EXPECT_NEAR(tables.reflectance(1.0, 0.0, 1.0, 1.0), 0.2, 1e-4);
    EXPECT_NEAR(tables.reflectance(0.5, 0.5, 1.5, 0.0), 0.04285, 2e-4);
    EXPECT_NEAR(tables.reflectance(1.0, 0.5, 1.0, 1.0), 0.1588, 2e-4);
}

TEST(FgdTables, EveryEntryIsFinite) {
    // The index-matched grazing node (mu = 0, alpha = 0, eta = 1) was once 0/0.
    const FgdTables& tables = defaultFgdTables();
    for (const auto* data : {&tables.fgdData(), &tables.tirData()})
        EXPECT_TRUE(
            std::all_of(data->begin(), data->end(), [](float v) { return std::isfinite(v); }));
}

// The grid was chosen by this error (docs/belcour-decisions.md): random points over the domain
// the presets and Table 2 use, against direct integration.
TEST(FgdTables, InterpolationErrorAgainstDirectIntegration) {
    const FgdTables& tables = defaultFgdTables();
    unsigned state = 12345u;
    auto next = [&state] {
        state = state * 1664525u + 1013904223u;
        return (state >> 8) / 16777216.0;
    };
    double fgdErrorSum = 0.0, tirErrorSum = 0.0, fgdErrorMax = 0.0;
    const int count = 120;
    for (int i = 0; i < count; ++i) {
        const bool conductor = next() < 0.5;
        const double mu = 0.05 + 0.95 * next();
        const double alpha = 0.02 + 0.98 * next();
        const double eta = conductor ? 0.2 + 1.8 * next() : 1.05 + 1.95 * next();
        const double kappa = conductor ? 0.5 + 3.5 * next() : 0.0;
        const double fgdError = std::abs(tables.reflectance(mu, alpha, eta, kappa) -
                                         integrateFgd(mu, alpha, eta, kappa, 48));
        fgdErrorSum += fgdError;
        fgdErrorMax = std::max(fgdErrorMax, fgdError);
        const double inside = 1.0 / eta;
        tirErrorSum += std::abs(tables.escapeFraction(mu, alpha, inside) -
                                integrateEscapeFraction(mu, alpha, inside, 48));
    }
    EXPECT_LT(fgdErrorSum / count, 3e-3);
    EXPECT_LT(fgdErrorMax, 3e-2);
    EXPECT_LT(tirErrorSum / count, 1e-2);
}

class FgdTableCacheTest : public ::testing::Test {
protected:
    void SetUp() override {
        directory_ = std::filesystem::path(MATEVO_BINARY_DIR) / "test_tmp" /
                     ::testing::UnitTest::GetInstance()->current_test_info()->name();
        std::filesystem::remove_all(directory_);
        settings_.grid.mu.count = settings_.grid.alpha.count = 5;
        settings_.grid.eta.count = settings_.grid.kappa.count = 4;
        settings_.samplesPerAxis = 16;
    }
    void TearDown() override { std::filesystem::remove_all(directory_); }

    std::filesystem::path directory_;
    TableGenerationSettings settings_;
};

TEST_F(FgdTableCacheTest, WritesReadsBackAndRejectsStaleOrCorruptFiles) {
    const FgdTables built = loadOrBuildFgdTables(directory_, settings_);
    const std::filesystem::path file =
        directory_ / ("fgd_tir_v" + std::to_string(kTableFormatVersion) + ".bin");
    ASSERT_TRUE(std::filesystem::exists(file));

    auto reread = readFgdTables(file, settings_);
    ASSERT_TRUE(reread.ok()) << reread.error().message;
    EXPECT_EQ(reread->fgdData(), built.fgdData());
    EXPECT_EQ(reread->tirData(), built.tirData());

    TableGenerationSettings other = settings_;
    other.samplesPerAxis = 17;
    EXPECT_FALSE(readFgdTables(file, other).ok());

    {
        std::fstream corrupt(file, std::ios::in | std::ios::out | std::ios::binary);
        corrupt.seekp(200);
        corrupt.put('\x7f');
    }
    const auto damaged = readFgdTables(file, settings_);
    ASSERT_FALSE(damaged.ok());
    EXPECT_NE(damaged.error().message.find("checksum"), std::string::npos);

    // A damaged cache is rebuilt and rewritten.
    const FgdTables rebuilt = loadOrBuildFgdTables(directory_, settings_);
    EXPECT_EQ(rebuilt.fgdData(), built.fgdData());
    EXPECT_TRUE(readFgdTables(file, settings_).ok());
}

TEST_F(FgdTableCacheTest, AForgedFileWithAValidChecksumButNanDataIsRebuilt) {
    const FgdTables built = loadOrBuildFgdTables(directory_, settings_);
    std::vector<float> fgd = built.fgdData();
    fgd[7] = std::numeric_limits<float>::quiet_NaN();
    const FgdTables forged(settings_.grid, fgd, built.tirData());
    const std::string bytes = serializeFgdTables(forged, settings_);  // checksum is right
    auto parsed = parseFgdTables(bytes, settings_, "forged.bin");
    ASSERT_FALSE(parsed.ok());
    EXPECT_NE(parsed.error().message.find("outside [0, 1]"), std::string::npos);

    std::vector<float> tir = built.tirData();
    tir[3] = 5.0f;
    parsed = parseFgdTables(
        serializeFgdTables(FgdTables(settings_.grid, built.fgdData(), tir), settings_), settings_,
        "forged.bin");
    EXPECT_FALSE(parsed.ok());

    const std::filesystem::path file =
        directory_ / ("fgd_tir_v" + std::to_string(kTableFormatVersion) + ".bin");
    ASSERT_TRUE(writeFileAtomically(file, bytes).ok());
    const FgdTables healed = loadOrBuildFgdTables(directory_, settings_);
    EXPECT_EQ(healed.fgdData(), built.fgdData());
    EXPECT_TRUE(readFgdTables(file, settings_).ok());
}

TEST_F(FgdTableCacheTest, ACachePathThatIsAFolderOrADeviceIsBuiltAroundNotFatal) {
    const std::filesystem::path file =
        directory_ / ("fgd_tir_v" + std::to_string(kTableFormatVersion) + ".bin");
    const FgdTables expected = generateFgdTables(settings_);

    std::filesystem::create_directories(file / "inside");
    auto read = readFgdTables(file, settings_);
    ASSERT_FALSE(read.ok());
    EXPECT_NE(read.error().message.find("folder"), std::string::npos);
    EXPECT_EQ(loadOrBuildFgdTables(directory_, settings_).fgdData(), expected.fgdData());
    EXPECT_TRUE(std::filesystem::exists(file / "inside"));  // the user's folder is left alone

    std::filesystem::remove_all(file);
    std::filesystem::create_symlink("/dev/zero", file);
    read = readFgdTables(file, settings_);
    ASSERT_FALSE(read.ok());
    EXPECT_NE(read.error().message.find("device"), std::string::npos);
    EXPECT_EQ(loadOrBuildFgdTables(directory_, settings_).fgdData(), expected.fgdData());
}

TEST_F(FgdTableCacheTest, GeneratedValuesPassTheCacheChecks) {
    // The checks must never reject what the generator makes (else every start would rebuild).
    const FgdTables tables = generateFgdTables(settings_);
    EXPECT_TRUE(parseFgdTables(serializeFgdTables(tables, settings_), settings_, "t").ok());
}

TEST_F(FgdTableCacheTest, GenerationIsDeterministic) {
    const FgdTables first = generateFgdTables(settings_);
    const FgdTables second = generateFgdTables(settings_);
    EXPECT_EQ(first.fgdData(), second.fgdData());
    EXPECT_EQ(first.tirData(), second.tirData());
}

}  // namespace
}  // namespace matevo
