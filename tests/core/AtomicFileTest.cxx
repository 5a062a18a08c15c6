#include "shadelab/AtomicFile.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <dirent.h>
#include <fstream>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>

using namespace shadelab;

namespace
{
std::string slurp(const std::string& path)
{
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

int filesIn(const std::string& folder)
{
  int count = 0;
  DIR* dir = opendir(folder.c_str());
  while (dirent* entry = readdir(dir))
  {
    count += entry->d_name[0] != '.' || std::string(entry->d_name).find(".partial-") != std::string::npos;
  }
  closedir(dir);
  return count - 0;
}

std::string freshFolder()
{
  char pattern[] = "/tmp/shadelab-atomic-XXXXXX";
  return mkdtemp(pattern);
}
} // namespace

TEST(AtomicFile, WritesAndReplaces)
{
  const std::string folder = freshFolder();
  const std::string path = folder + "/out.txt";
  writeFileAtomically(path, "first");
  EXPECT_EQ(slurp(path), "first");
  writeFileAtomically(path, "second");
  EXPECT_EQ(slurp(path), "second");
  EXPECT_EQ(filesIn(folder), 1) << "no temporary file left behind";
}

TEST(AtomicFile, NewFilesGetTheUsualPermissions)
{
  // Like a file opened for writing: 0666 less the umask (not mkstemp's 0600).
  const std::string folder = freshFolder();
  const mode_t mask = umask(022);
  writeFileAtomically(folder + "/new.txt", "x");
  umask(mask);
  struct stat info;
  ASSERT_EQ(stat((folder + "/new.txt").c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 0777, 0644u);

  // A replaced file keeps its own mode.
  chmod((folder + "/new.txt").c_str(), 0640);
  writeFileAtomically(folder + "/new.txt", "y");
  ASSERT_EQ(stat((folder + "/new.txt").c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 0777, 0640u);
}

TEST(AtomicFile, UncommittedOutputLeavesTheOldFile)
{
  const std::string folder = freshFolder();
  const std::string path = folder + "/image.png";
  writeFileAtomically(path, "old");
  {
    AtomicOutput output(path);
    EXPECT_NE(output.temporaryPath(), path);
    EXPECT_EQ(output.temporaryPath().substr(output.temporaryPath().size() - 4), ".png") << "keeps the extension";
    std::ofstream(output.temporaryPath()) << "half";
    // destroyed without commit(), as when a writer fails
  }
  EXPECT_EQ(slurp(path), "old");
  EXPECT_EQ(filesIn(folder), 1);
}

TEST(AtomicFile, UnwritableFolderThrowsNamingTheFile)
{
  try
  {
    writeFileAtomically("/nonexistent-folder/x.json", "data");
    FAIL();
  }
  catch (const shadelab::Error& e)
  {
    EXPECT_EQ(std::string(e.what()).rfind("/nonexistent-folder/x.json: cannot create output file", 0), 0u);
  }
}

TEST(AtomicFile, TemporaryNamesStayWithinNameMax)
{
  // ".NAME.partial-XXXXXX.EXT": NAME is cut so the whole fits, EXT kept.
  for (size_t length : { 5u, 200u, 238u, 239u, 240u, 241u, 250u, 255u })
  {
    const std::string name = std::string(length - 4, 'n') + ".png";
    const TemporaryName temporary = temporaryNameFor("/some/folder/" + name, 255);
    EXPECT_EQ(temporary.prefix.rfind("/some/folder/.n", 0), 0u);
    EXPECT_EQ(temporary.suffix, ".png");
    const size_t whole = temporary.prefix.size() - std::string("/some/folder/").size() + 6 + temporary.suffix.size();
    EXPECT_EQ(whole, std::min<size_t>(length + 16, 255)) << length;
  }
  // An extension too long to keep is dropped rather than overflow the name.
  const TemporaryName odd = temporaryNameFor("a." + std::string(250, 'e'), 255);
  EXPECT_EQ(odd.suffix, "");
  EXPECT_LE(odd.prefix.size() + 6, 255u);
}

TEST(AtomicFile, WritesTheLongestValidName)
{
  const std::string folder = freshFolder();
  const std::string path = folder + "/" + std::string(251, 'n') + ".vtp"; // 255 bytes
  writeFileAtomically(path, "data");
  EXPECT_EQ(slurp(path), "data");
  EXPECT_EQ(filesIn(folder), 1);
}

TEST(AtomicFile, RemovesStaleTemporariesButNotLiveOnes)
{
  const std::string folder = freshFolder();
  const std::string path = folder + "/out.vtp";
  // A live writer of the same target holds its temporary file's lock.
  AtomicOutput live(path);
  std::ofstream(folder + "/.out.partial-Ab12Cd.vtp") << "left by a killed process";
  std::ofstream(folder + "/.out.partial-Ab12Cd.ply") << "another target's";
  writeFileAtomically(path, "new");
  EXPECT_EQ(slurp(path), "new");
  EXPECT_NE(access((folder + "/.out.partial-Ab12Cd.ply").c_str(), F_OK), -1);
  EXPECT_EQ(access((folder + "/.out.partial-Ab12Cd.vtp").c_str(), F_OK), -1) << "stale file removed";
  EXPECT_NE(access(live.temporaryPath().c_str(), F_OK), -1) << "a live writer's file kept";
  live.commit("live", 4);
  EXPECT_EQ(slurp(path), "live");
}

TEST(AtomicFile, CommitWrittenRefusesAShortFile)
{
  const std::string folder = freshFolder();
  const std::string path = folder + "/mesh.ply";
  writeFileAtomically(path, "old");
  try
  {
    AtomicOutput output(path);
    std::ofstream(output.temporaryPath()) << "12345";
    output.commitWritten(10);
    FAIL();
  }
  catch (const shadelab::Error& e)
  {
    EXPECT_EQ(std::string(e.what()), path + ": cannot write output file: the writer wrote 5 bytes of 10");
  }
  EXPECT_EQ(slurp(path), "old");
  EXPECT_EQ(filesIn(folder), 1);

  AtomicOutput output(path);
  std::ofstream(output.temporaryPath()) << "12345";
  output.commitWritten(5);
  EXPECT_EQ(slurp(path), "12345");
}
