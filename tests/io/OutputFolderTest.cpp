// Output folders and temporary names on a folder other runs share (files/OutputFolder.h,
// files/TemporaryFiles.h, files/FileLock.h), on real files: what is reaped, who may write, and what
// a replaced folder keeps.
#include "files/OutputFolder.h"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include <gtest/gtest.h>

#include "files/TemporaryFiles.h"
#include "support/FileContents.h"
#include "support/ScratchFolder.h"
#include "support/StaleTemporary.h"

namespace matevo {
namespace {

namespace fs = std::filesystem;
using testing::contentsOf;

void write(const fs::path& file, const std::string& text) {
    std::ofstream(file, std::ios::binary) << text;
}

TEST(TemporaryFiles, OnlyThoseOfDeadProcessesOfThisHostBootAndNamespaceAreReaped) {
    testing::ScratchFolder folder("temporary");
    const std::string ours = temporaryPathBeside(folder / "doc.json").filename().string();
    const std::string deadHere =
        testing::temporaryPathOf(folder / "doc.json", testing::kDeadPid).filename().string();
    const auto host = ours.find("matevo-tmp-") + std::string("matevo-tmp-").size();
    std::string otherHost = deadHere;
    otherHost.replace(host, 16, "0123456789abcdef");
    const std::string olderVersion = ".doc.json.matevo-tmp-" + testing::kDeadPid + "-0";
    const std::string unparseable = ".doc.json.matevo-tmp-" + ours.substr(host, 16) + "-x-1";

    write(folder / ours, "in progress");
    write(folder / deadHere, "left by a kill -9");
    fs::create_directories(testing::temporaryPathOf(folder / "out", "4194306") / "candidates");
    for (const auto& name : {otherHost, olderVersion, unparseable}) write(folder / name, name);
    write(folder / "doc.json", "kept");

    EXPECT_EQ(removeStaleTemporaryFiles(folder.path()), 2);  // the file and the folder
    EXPECT_FALSE(fs::exists(folder / deadHere));
    EXPECT_TRUE(fs::exists(folder / ours));  // this process is alive
    // Another host's PID means nothing here; a name we cannot read proves nothing.
    for (const auto& name : {otherHost, olderVersion, unparseable})
        EXPECT_EQ(contentsOf(folder / name), name);
    EXPECT_EQ(contentsOf(folder / "doc.json"), "kept");
}

TEST(TemporaryFiles, ASignalRemovesOnlyTheFilesBeingWritten) {
    testing::ScratchFolder folder("in_flight");
    const fs::path writing = temporaryPathBeside(folder / "a.png");
    const fs::path done = temporaryPathBeside(folder / "b.png");
    write(writing, "half an image");
    write(done, "another process's, say");
    {
        const TemporaryFileInFlight inFlight(writing);
        removeTemporaryFilesInFlight();  // what the SIGINT/SIGTERM handlers call
        EXPECT_FALSE(fs::exists(writing));
    }
    write(writing, "the same name, no longer in flight");
    removeTemporaryFilesInFlight();
    EXPECT_TRUE(fs::exists(writing));
    EXPECT_TRUE(fs::exists(done));
}

TEST(OutputFolderSharing, ASecondWriterIsRefusedUntilTheFirstCommits) {
    testing::ScratchFolder folder("sharing");
    const fs::path out = folder / "out";
    auto first = OutputFolder::claim(out, true);
    ASSERT_TRUE(first.ok()) << first.error().message;

    auto second = OutputFolder::claim(out, true);
    ASSERT_FALSE(second.ok());
    EXPECT_NE(second.error().message.find("another matevo run is writing it"), std::string::npos)
        << second.error().message;
    EXPECT_EQ(second.error().message.find('\n'), std::string::npos);
    EXPECT_TRUE(OutputFolder::claim(folder / "other", true).ok());  // other names are free

    write(first->staging() / "result.json", "run 1");
    ASSERT_TRUE(first->commit().ok());
    auto third = OutputFolder::claim(out, false);  // free again: refused only as occupied
    ASSERT_FALSE(third.ok());
    EXPECT_NE(third.error().message.find("--force"), std::string::npos) << third.error().message;
    EXPECT_TRUE(OutputFolder::claim(out, true).ok());
    // No lock file is left once the last writer is gone.
    for (const auto& entry : fs::directory_iterator(folder.path()))
        EXPECT_EQ(entry.path().filename().string().find("matevo-lock"), std::string::npos)
            << entry.path();
}

TEST(OutputFolderSharing, FilesTheUserAddsDuringTheRunAreKept) {
    testing::ScratchFolder folder("foreign");
    const fs::path out = folder / "out";
    {
        auto previous = OutputFolder::claim(out, false);
        ASSERT_TRUE(previous.ok());
        fs::create_directories(previous->staging() / "candidates");
        write(previous->staging() / "result.json", "run 1");
        write(previous->staging() / "old_only.json", "run 1");
        write(previous->staging() / "candidates" / "c0.png", "run 1");
        ASSERT_TRUE(previous->commit().ok());
    }

    auto run = OutputFolder::claim(out, true);
    ASSERT_TRUE(run.ok()) << run.error().message;
    fs::create_directories(run->staging() / "candidates");
    write(run->staging() / "result.json", "run 2");
    write(run->staging() / "candidates" / "c0.png", "run 2");
    // Meanwhile, in the folder the user sees:
    write(out / "notes.txt", "mine");
    write(out / "candidates" / "picked.txt", "mine too");
    fs::create_directories(out / "sketches");
    write(out / "sketches" / "a.txt", "a folder of mine");
    write(out / "result.json", "edited by hand");  // a previous run's file, changed
    ASSERT_TRUE(run->commit().ok());

    EXPECT_EQ(contentsOf(out / "result.json"), "run 2");
    EXPECT_EQ(contentsOf(out / "candidates" / "c0.png"), "run 2");
    EXPECT_FALSE(fs::exists(out / "old_only.json"));  // the previous run's, unchanged: removed
    EXPECT_EQ(contentsOf(out / "notes.txt"), "mine");
    EXPECT_EQ(contentsOf(out / "candidates" / "picked.txt"), "mine too");
    EXPECT_EQ(contentsOf(out / "sketches" / "a.txt"), "a folder of mine");
    EXPECT_EQ(contentsOf(out / "result.json.kept"), "edited by hand");
    // Nothing is left beside it: the replaced folder is gone once emptied.
    EXPECT_EQ(std::distance(fs::directory_iterator(folder.path()), {}), 1);
}

TEST(OutputFolderSharing, AFolderMadeDuringTheRunKeepsItsFiles) {
    testing::ScratchFolder folder("made_meanwhile");
    const fs::path out = folder / "out";
    auto run = OutputFolder::claim(out, false);
    ASSERT_TRUE(run.ok());
    write(run->staging() / "result.json", "run");
    fs::create_directories(out);
    write(out / "notes.txt", "mine");
    ASSERT_TRUE(run->commit().ok());
    EXPECT_EQ(contentsOf(out / "result.json"), "run");
    EXPECT_EQ(contentsOf(out / "notes.txt"), "mine");
}

}  // namespace
}  // namespace matevo
