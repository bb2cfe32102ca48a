// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// Staged outputs (issue 14): a run's outputs appear together or not at all, and whatever a killed run leaves, the
// next run in the folder completes (committed) or removes (not committed). The states a kill can leave are built
// here on disk in the layout vrStagedOutputs.h documents, and by a child process killed with SIGKILL.
#include "vrInputError.h"
#include "vrStagedOutputs.h"
#include "vrTestFiles.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace
{
namespace fs = std::filesystem;
using vr::test::InputErrorOf;
using vr::test::ReadTextFile;
using vr::test::WriteTextFile;

#define EXPECT_MESSAGE_HAS(message, part)                                                                              \
  EXPECT_NE((message).find(part), std::string::npos) << "message: " << (message) << "\nmissing: " << (part)

/** A staging folder as a dead run leaves it: its lock file (held by nobody), files/ with \a staged files, and
 * optionally its journal and commit marker. */
fs::path
MakeDeadStaging(const fs::path &                 folder,
                const std::string &              name,
                const std::vector<std::string> & staged,
                const std::string &              primary,
                const std::vector<std::string> & members,
                const std::vector<std::string> & journalFiles,
                bool                             journal,
                bool                             committed)
{
  const fs::path staging = folder / name;
  fs::create_directories(staging / "files");
  WriteTextFile((staging / "lock").string(), "");
  for (const auto & file : staged)
  {
    WriteTextFile((staging / "files" / file).string(), "new " + file);
  }
  if (journal)
  {
    std::string text = "vr-staging 1\nprimary " + primary + "\n";
    for (const auto & member : members)
    {
      text += "member " + member + "\n";
    }
    for (const auto & file : journalFiles)
    {
      text += "file " + file + "\n";
    }
    WriteTextFile((staging / "journal").string(), text + "end\n");
  }
  if (committed)
  {
    WriteTextFile((staging / "committed").string(), "committed\n");
  }
  return staging;
}

TEST(StagedOutputs, PublishesEveryOutputTogetherAcrossFoldersAndLeavesNoStaging)
{
  vr::test::ScopedTemporaryFolder folder;
  fs::create_directories(folder.Path() / "a");
  fs::create_directories(folder.Path() / "b");
  WriteTextFile(folder.File("a/x.txt"), "old x");
  {
    vr::StagedOutputs staged;
    const auto        x = staged.Add(folder.File("a/x.txt"), "--x");
    const auto        y = staged.Add(folder.File("a/y.txt"), "--y");
    const auto        z = staged.Add(folder.File("b/z.txt"), "--z");
    for (const auto handle : { x, y, z })
    {
      staged.Write(handle, [&](const std::string & path) { WriteTextFile(path, "new " + std::to_string(handle)); });
    }
    EXPECT_EQ(ReadTextFile(folder.File("a/x.txt")), "old x") << "published before CommitAll";
    EXPECT_FALSE(fs::exists(folder.File("a/y.txt")));
    staged.CommitAll();
  }
  EXPECT_EQ(ReadTextFile(folder.File("a/x.txt")), "new 0");
  EXPECT_EQ(ReadTextFile(folder.File("a/y.txt")), "new 1");
  EXPECT_EQ(ReadTextFile(folder.File("b/z.txt")), "new 2");
  std::vector<std::string> names;
  for (const auto & sub : { "a", "b" })
  {
    for (const auto & entry : fs::directory_iterator(folder.Path() / sub))
    {
      names.push_back(std::string(sub) + "/" + entry.path().filename().string());
    }
  }
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{ "a/x.txt", "a/y.txt", "b/z.txt" }));
}

TEST(StagedOutputs, AnErrorBeforeTheCommitLeavesTheOldFilesAndNoStaging)
{
  vr::test::ScopedTemporaryFolder folder;
  WriteTextFile(folder.File("x.txt"), "old x");
  {
    vr::StagedOutputs staged;
    const auto        x = staged.Add(folder.File("x.txt"), "--x");
    const auto        y = staged.Add(folder.File("y.txt"), "--y");
    staged.Write(x, [](const std::string & path) { WriteTextFile(path, "new x"); });
    const std::string message = InputErrorOf(
      [&]
      { staged.Write(y, [](const std::string & path) { throw vr::InputError("output " + path + ": disk full"); }); });
    EXPECT_MESSAGE_HAS(message, "--y: output " + folder.File("y.txt") + ": disk full"); // the final name, not staging
  }
  EXPECT_EQ(folder.Entries(), std::vector<std::string>{ "x.txt" });
  EXPECT_EQ(ReadTextFile(folder.File("x.txt")), "old x");
}

TEST(StagedOutputs, RefusesFoldersPipesDuplicatesAndMissingFolders)
{
  vr::test::ScopedTemporaryFolder folder;
  ASSERT_EQ(::mkfifo(folder.File("pipe").c_str(), 0600), 0);
  vr::StagedOutputs staged;
  EXPECT_MESSAGE_HAS(InputErrorOf([&] { staged.Add(folder.Path().string(), "--a"); }), "is a folder");
  EXPECT_MESSAGE_HAS(InputErrorOf([&] { staged.Add(folder.File("pipe"), "--b"); }), "not a regular file");
  EXPECT_MESSAGE_HAS(InputErrorOf([&] { staged.Add(folder.File("none/x.txt"), "--c"); }), "does not exist");
  staged.Add(folder.File("x.txt"), "--d");
  EXPECT_MESSAGE_HAS(InputErrorOf([&] { staged.Add(folder.File("./x.txt"), "--e"); }), "--d already writes this file");
}

TEST(StagedOutputs, NamesWithAURISchemeAreWrittenDirectly)
{
  vr::test::ScopedTemporaryFolder folder;
  const std::string               name = "slicer:0x55d0c1a2b3c0#vtkMRMLScalarVolumeNode1";
  const auto                      before = fs::current_path();
  fs::current_path(folder.Path());
  {
    vr::StagedOutputs staged;
    const auto        handle = staged.Add(name, "<outputCPR>");
    EXPECT_EQ(staged.StagedPath(handle), name);
    std::string given;
    staged.Write(handle, [&](const std::string & path) { given = path; });
    EXPECT_EQ(given, name);
    staged.CommitAll();
  }
  EXPECT_EQ(folder.Entries(), std::vector<std::string>{}) << "a URI name made a file or a staging folder";
  fs::current_path(before);
}

TEST(StagedOutputsRecovery, ACommittedRunKilledMidPublicationIsRolledForward)
{
  vr::test::ScopedTemporaryFolder folder;
  const fs::path                  a = folder.Path() / "a";
  const fs::path                  b = folder.Path() / "b";
  fs::create_directories(a);
  fs::create_directories(b);
  // The run's outputs: a/x.txt, a/y.txt (primary staging in a), b/z.txt (member in b). Killed after the commit
  // marker and after renaming a/x.txt, before the rest.
  WriteTextFile((a / "y.txt").string(), "old y");
  WriteTextFile((b / "z.txt").string(), "old z");
  WriteTextFile((a / "x.txt").string(), "new x");
  const std::string primary = (a / ".vr-staging-999999-AAAAAA").string();
  const std::string member = (b / ".vr-staging-999999-BBBBBB").string();
  MakeDeadStaging(
    a, ".vr-staging-999999-AAAAAA", { "y.txt" }, primary, { primary, member }, { "x.txt", "y.txt" }, true, true);
  MakeDeadStaging(b, ".vr-staging-999999-BBBBBB", { "z.txt" }, primary, { primary, member }, { "z.txt" }, true, false);

  // The next run reserves an output in b only: the member asks its primary, and the whole run is completed.
  EXPECT_EQ(vr::StagedOutputs::RecoverStaleStaging(b.string()), 1u);
  EXPECT_EQ(ReadTextFile((a / "x.txt").string()), "new x");
  EXPECT_EQ(ReadTextFile((a / "y.txt").string()), "new y.txt");
  EXPECT_EQ(ReadTextFile((b / "z.txt").string()), "new z.txt");
  EXPECT_FALSE(fs::exists(primary));
  EXPECT_FALSE(fs::exists(member));
}

TEST(StagedOutputsRecovery, AnUncommittedRunIsRemovedAndTheOldFilesStay)
{
  vr::test::ScopedTemporaryFolder folder;
  WriteTextFile(folder.File("x.txt"), "old x");
  const std::string primary = folder.File(".vr-staging-999999-AAAAAA");
  // With its journal written but no commit marker, and with nothing but staged files.
  MakeDeadStaging(
    folder.Path(), ".vr-staging-999999-AAAAAA", { "x.txt" }, primary, { primary }, { "x.txt" }, true, false);
  MakeDeadStaging(folder.Path(), ".vr-staging-999999-CCCCCC", { "x.txt" }, "", {}, {}, false, false);
  EXPECT_EQ(vr::StagedOutputs::RecoverStaleStaging(folder.Path().string()), 2u);
  EXPECT_EQ(folder.Entries(), std::vector<std::string>{ "x.txt" });
  EXPECT_EQ(ReadTextFile(folder.File("x.txt")), "old x");
}

TEST(StagedOutputsRecovery, AMemberWhosePrimaryIsGoneIsRemoved)
{
  vr::test::ScopedTemporaryFolder folder;
  const std::string               primary = (folder.Path() / "elsewhere" / ".vr-staging-999999-AAAAAA").string();
  const std::string               member = folder.File(".vr-staging-999999-BBBBBB");
  MakeDeadStaging(
    folder.Path(), ".vr-staging-999999-BBBBBB", { "z.txt" }, primary, { primary, member }, { "z.txt" }, true, false);
  EXPECT_EQ(vr::StagedOutputs::RecoverStaleStaging(folder.Path().string()), 1u);
  EXPECT_EQ(folder.Entries(), std::vector<std::string>{});
}

TEST(StagedOutputsRecovery, ALiveRunsStagingIsLeftAlone)
{
  vr::test::ScopedTemporaryFolder folder;
  vr::StagedOutputs               live;
  const auto                      handle = live.Add(folder.File("x.txt"), "--x");
  live.Write(handle, [](const std::string & path) { WriteTextFile(path, "live x"); });
  EXPECT_EQ(vr::StagedOutputs::RecoverStaleStaging(folder.Path().string()), 0u);
  // A second run beside it stages and publishes its own output without touching the first one's.
  {
    vr::StagedOutputs other;
    const auto        y = other.Add(folder.File("y.txt"), "--y");
    other.Write(y, [](const std::string & path) { WriteTextFile(path, "other y"); });
    other.CommitAll();
  }
  live.CommitAll();
  EXPECT_EQ(ReadTextFile(folder.File("x.txt")), "live x");
  EXPECT_EQ(ReadTextFile(folder.File("y.txt")), "other y");
  EXPECT_EQ(folder.Entries(), (std::vector<std::string>{ "x.txt", "y.txt" }));
}

TEST(StagedOutputsRecovery, ARunKilledBySIGKILLIsCleanedUpByTheNext)
{
  vr::test::ScopedTemporaryFolder folder;
  WriteTextFile(folder.File("x.txt"), "old x");
  const pid_t child = ::fork();
  if (child == 0)
  {
    vr::StagedOutputs staged;
    const auto        x = staged.Add(folder.File("x.txt"), "--x");
    staged.Write(x, [](const std::string & path) { WriteTextFile(path, "half"); });
    ::raise(SIGKILL);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status));
  ASSERT_EQ(folder.Entries().size(), 2u) << "the killed run left no staging folder to clean";
  // A lock-less staging folder of a dead process (killed while creating it) goes too.
  fs::create_directories(folder.Path() / (".vr-staging-" + std::to_string(child) + "-DDDDDD") / "files");
  {
    vr::StagedOutputs next;
    next.Add(folder.File("y.txt"), "--y");
  }
  EXPECT_EQ(folder.Entries(), std::vector<std::string>{ "x.txt" });
  EXPECT_EQ(ReadTextFile(folder.File("x.txt")), "old x");
}
} // namespace
