// The one safe reader, the one atomic writer and output folders, on real files, FIFOs, devices,
// folders and symlinks.
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

#include "files/AtomicFile.h"
#include "files/InputFile.h"
#include "files/OutputFolder.h"

namespace matevo {
namespace {

namespace fs = std::filesystem;

class SafeFilesTest : public ::testing::Test {
protected:
    void SetUp() override {
        folder_ = fs::path(MATEVO_BINARY_DIR) / "test_tmp" /
                  ::testing::UnitTest::GetInstance()->current_test_info()->name();
        fs::remove_all(folder_);
        fs::create_directories(folder_);
    }
    void TearDown() override { fs::remove_all(folder_); }

    static std::string contentsOf(const fs::path& file) {
        std::ifstream in(file, std::ios::binary);
        return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    }
    static void write(const fs::path& file, const std::string& text) {
        std::ofstream(file, std::ios::binary) << text;
    }
    std::size_t entriesIn(const fs::path& folder) const {
        return std::size_t(std::distance(fs::directory_iterator(folder), {}));
    }

    fs::path folder_;
};

void expectOneLineNaming(const Error& error, const std::string& name, const std::string& reason) {
    EXPECT_EQ(error.message.find('\n'), std::string::npos) << error.message;
    EXPECT_NE(error.message.find(name), std::string::npos) << error.message;
    EXPECT_NE(error.message.find(reason), std::string::npos) << error.message;
    EXPECT_EQ(error.message.find("Success"), std::string::npos) << error.message;
}

TEST_F(SafeFilesTest, ReadsRegularFilesWithinTheLimit) {
    write(folder_ / "a.txt", "hello");
    auto read = readInputFile(folder_ / "a.txt", 5);
    ASSERT_TRUE(read.ok()) << read.error().message;
    EXPECT_EQ(*read, "hello");
    auto tooBig = readInputFile(folder_ / "a.txt", 4);
    ASSERT_FALSE(tooBig.ok());
    expectOneLineNaming(tooBig.error(), "a.txt", "limit");
}

TEST_F(SafeFilesTest, RefusesFifosDevicesFoldersAndSymlinkLoopsAtOnce) {
    const fs::path fifo = folder_ / "pipe";
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    const auto started = std::chrono::steady_clock::now();
    auto read = readInputFile(fifo, kMaxTextFileBytes);  // must not wait for a writer
    EXPECT_LT(std::chrono::steady_clock::now() - started, std::chrono::seconds(20));
    ASSERT_FALSE(read.ok());
    expectOneLineNaming(read.error(), "pipe", "FIFO");

    read = readInputFile("/dev/zero", kMaxTextFileBytes);
    ASSERT_FALSE(read.ok());
    expectOneLineNaming(read.error(), "/dev/zero", "device");

    read = readInputFile(folder_, kMaxTextFileBytes);
    ASSERT_FALSE(read.ok());
    expectOneLineNaming(read.error(), folder_.string(), "folder");

    fs::create_symlink("loop_b", folder_ / "loop_a");
    fs::create_symlink("loop_a", folder_ / "loop_b");
    read = readInputFile(folder_ / "loop_a", kMaxTextFileBytes);
    ASSERT_FALSE(read.ok());
    expectOneLineNaming(read.error(), "loop_a", "symbolic links");

    read = readInputFile(folder_ / "missing", kMaxTextFileBytes);
    ASSERT_FALSE(read.ok());
    expectOneLineNaming(read.error(), "missing", "no such file");
}

TEST_F(SafeFilesTest, HugePathsAreShortenedInMessages) {
    const std::string name(100000, 'x');
    auto read = readInputFile(folder_ / name, kMaxTextFileBytes);
    ASSERT_FALSE(read.ok());
    EXPECT_LT(read.error().message.size(), 400u);
    expectOneLineNaming(read.error(), "xxx...xxx", "cannot read");
}

TEST_F(SafeFilesTest, AtomicWriteReplacesWholeAndLeavesNoTemporaryFile) {
    const fs::path file = folder_ / "doc.json";
    ASSERT_TRUE(writeFileAtomically(file, "first").ok());
    ASSERT_TRUE(writeFileAtomically(file, "second, longer").ok());
    EXPECT_EQ(contentsOf(file), "second, longer");
    EXPECT_EQ(entriesIn(folder_), 1u);
}

TEST_F(SafeFilesTest, SavingThroughASymlinkWritesItsTargetAndKeepsTheLink) {
    fs::create_directories(folder_ / "real");
    write(folder_ / "real" / "doc.json", "old");
    fs::create_symlink("real/doc.json", folder_ / "link.json");
    ASSERT_TRUE(writeFileAtomically(folder_ / "link.json", "new").ok());
    EXPECT_TRUE(fs::is_symlink(folder_ / "link.json"));
    EXPECT_EQ(contentsOf(folder_ / "real" / "doc.json"), "new");
    // A dangling link creates its target.
    fs::create_symlink("real/fresh.json", folder_ / "dangling.json");
    ASSERT_TRUE(writeFileAtomically(folder_ / "dangling.json", "fresh").ok());
    EXPECT_TRUE(fs::is_symlink(folder_ / "dangling.json"));
    EXPECT_EQ(contentsOf(folder_ / "real" / "fresh.json"), "fresh");
}

TEST_F(SafeFilesTest, ModeOfAnExistingFileIsKept) {
    const fs::path file = folder_ / "private.json";
    write(file, "secret");
    ASSERT_EQ(::chmod(file.c_str(), 0600), 0);
    ASSERT_TRUE(writeFileAtomically(file, "still secret").ok());
    struct stat status {};
    ASSERT_EQ(::stat(file.c_str(), &status), 0);
    EXPECT_EQ(status.st_mode & 07777, 0600u);
    EXPECT_EQ(status.st_uid, ::geteuid());
}

TEST_F(SafeFilesTest, DevicesFoldersAndUnwritableFoldersAreRefusedInOneLine) {
    auto written = writeFileAtomically("/dev/null", "x");
    ASSERT_FALSE(written.ok());
    expectOneLineNaming(written.error(), "/dev/null", "not a regular file");

    fs::create_directories(folder_ / "sub");
    written = writeFileAtomically(folder_ / "sub", "x");
    ASSERT_FALSE(written.ok());
    expectOneLineNaming(written.error(), "sub", "folder");

    written = writeFileAtomically(folder_ / "missing" / "a.json", "x");
    ASSERT_FALSE(written.ok());
    expectOneLineNaming(written.error(), "a.json", "cannot write");
}

TEST_F(SafeFilesTest, OutputFolderHoldsOneRunOrIsRefused) {
    const fs::path out = folder_ / "out";
    {
        auto first = OutputFolder::claim(out, false);
        ASSERT_TRUE(first.ok()) << first.error().message;
        write(first->staging() / "result.json", "run 1");
        EXPECT_FALSE(fs::exists(out));  // nothing is there until the run is complete
        ASSERT_TRUE(first->commit().ok());
    }
    EXPECT_EQ(contentsOf(out / "result.json"), "run 1");

    auto refused = OutputFolder::claim(out, false);
    ASSERT_FALSE(refused.ok());
    expectOneLineNaming(refused.error(), "out", "--force");

    {
        auto second = OutputFolder::claim(out, true);
        ASSERT_TRUE(second.ok()) << second.error().message;
        write(second->staging() / "other.json", "run 2");
        ASSERT_TRUE(second->commit().ok());
    }
    EXPECT_EQ(contentsOf(out / "other.json"), "run 2");
    EXPECT_FALSE(fs::exists(out / "result.json"));  // nothing of the earlier run is left

    {  // abandoned (an error before the end): the folder is untouched, no staging is left
        auto third = OutputFolder::claim(out, true);
        ASSERT_TRUE(third.ok());
        write(third->staging() / "partial.json", "run 3");
    }
    EXPECT_EQ(contentsOf(out / "other.json"), "run 2");
    EXPECT_EQ(entriesIn(folder_), 1u);

    fs::create_directories(folder_ / "mine");
    write(folder_ / "mine" / "thesis.tex", "precious");
    auto notOurs = OutputFolder::claim(folder_ / "mine", true);
    ASSERT_FALSE(notOurs.ok());
    expectOneLineNaming(notOurs.error(), "mine", "did not write");
    EXPECT_EQ(contentsOf(folder_ / "mine" / "thesis.tex"), "precious");

    write(folder_ / "file", "x");
    auto aFile = OutputFolder::claim(folder_ / "file", true);
    ASSERT_FALSE(aFile.ok());
    expectOneLineNaming(aFile.error(), "file", "not a folder");
}

TEST_F(SafeFilesTest, AFolderThatCannotBeCreatedIsRefusedUpFront) {
    write(folder_ / "plain_file", "x");
    auto refused = OutputFolder::claim(folder_ / "plain_file" / "out", false);
    ASSERT_FALSE(refused.ok());
    expectOneLineNaming(refused.error(), "plain_file", "cannot");
}

}  // namespace
}  // namespace matevo
