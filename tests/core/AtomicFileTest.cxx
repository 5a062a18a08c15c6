#include "shadelab/AtomicFile.h"

#include <gtest/gtest.h>

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
  catch (const std::runtime_error& e)
  {
    EXPECT_EQ(std::string(e.what()).rfind("/nonexistent-folder/x.json: cannot create output file", 0), 0u);
  }
}
