// Start-up cost is mostly the shared libraries a process maps: OpenImageIO alone pulls in about
// 250 of them. Commands that touch only PNG must never map it; a file of another format loads
// it on demand (core/image/ImageLibrary.h). Checked with the dynamic loader's own log.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "image/ImageFile.h"
#include "support/RunCommand.h"
#include "support/ScratchFolder.h"
#include "support/TestImages.h"

namespace matevo {
namespace {

// The loader's log of every library the command mapped (LD_DEBUG=files, on stderr).
testing::CommandOutput runLogged(const std::string& arguments) {
    return testing::runCommand("LD_DEBUG=files " +
                               testing::shellQuoted(std::string(MATEVO_BINARY_DIR) + "/matevo") +
                               " " + arguments);
}

bool mapsOpenImageIO(const testing::CommandOutput& run) {
    return run.err.find("file=libOpenImageIO") != std::string::npos;
}

TEST(StartupLibraries, PngOnlyCommandsNeverMapOpenImageIO) {
    testing::ScratchFolder scratch("matevo_startup_libraries");
    const auto& folder = scratch.path();
    const Image image = testdata::randomImage(8, 8, 1, true);
    ASSERT_TRUE(writeImage(image, folder / "a.png").ok());
    ASSERT_TRUE(writeImage(image, folder / "b.PNG").ok());
    ASSERT_TRUE(writeImage(image, folder / "c.exr").ok());
    const std::string a = testing::shellQuoted(folder / "a.png") + " ";

    const std::string upperCase = testing::shellQuoted(folder / "b.PNG");
    for (const std::string& arguments : std::vector<std::string>{
             "--help", "--version", "compare " + a + a + "--json", "compare " + a + upperCase}) {
        const auto run = runLogged(arguments);
        EXPECT_EQ(run.exitCode, 0) << arguments;
        EXPECT_FALSE(mapsOpenImageIO(run)) << arguments;
    }
    // The check can fail: an OpenEXR file does load OpenImageIO, and the comparison works.
    const auto withExr = runLogged("compare " + a + testing::shellQuoted(folder / "c.exr"));
    EXPECT_EQ(withExr.exitCode, 0);
    EXPECT_TRUE(mapsOpenImageIO(withExr));
}

}  // namespace
}  // namespace matevo
