// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrTestFiles_h
#define vrTestFiles_h

#include <filesystem>
#include <functional>
#include <set>
#include <string>
#include <vector>

/** Files for the IO tests: a fresh folder per test, whole-file reads and writes. */
namespace vr::test
{
/** A new empty folder under the system temporary folder, removed with everything in it on destruction. */
class ScopedTemporaryFolder
{
public:
  ScopedTemporaryFolder();
  ~ScopedTemporaryFolder();
  ScopedTemporaryFolder(const ScopedTemporaryFolder &) = delete;
  ScopedTemporaryFolder &
  operator=(const ScopedTemporaryFolder &) = delete;

  const std::filesystem::path &
  Path() const
  {
    return m_Path;
  }
  /** The path of \a name inside the folder, as a string. */
  std::string
  File(const std::string & name) const;
  /** The names of the entries in the folder, sorted (hidden ones included). */
  std::vector<std::string>
  Entries() const;

private:
  std::filesystem::path m_Path;
};

void
WriteTextFile(const std::string & path, const std::string & text);
std::string
ReadTextFile(const std::string & path);
/** The names of the entries of \a folder (hidden ones included). */
std::set<std::string>
FolderEntries(const std::filesystem::path & folder);

/** Runs \a action, expects vr::InputError, and returns its message (printed, for reading in the test log); any
 * other outcome is a test failure and returns "". */
std::string
InputErrorOf(const std::function<void()> & action);

/** InputErrorOf, capturing what \a action printed on stdout and stderr into \a printed: VTK and MetaIO report
 * trouble there, which belongs in the message instead. */
std::string
InputErrorAndPrintedTextOf(const std::function<void()> & action, std::string & printed);

/** Whether \a text contains \a part. */
bool
Contains(const std::string & text, const std::string & part);

/** An empty folder for the running GoogleTest test: <root>/<prefix><suite>.<test>, emptied first. File systems an
 * interrupted earlier run left mounted inside it (the full-disk and read-only tests mount small ones) are unmounted
 * first. */
std::filesystem::path
FreshFolderForThisTest(const std::filesystem::path & root, const std::string & prefix);

/** VMTK's aorta (VR_SHARED_DATA_DIR/vmtk-aorta-mra, Testing/Data by default), or "" when it is missing (a test then
 * fails: the data ships with the repository). */
std::string
AortaDataFolder();
} // namespace vr::test

#endif
