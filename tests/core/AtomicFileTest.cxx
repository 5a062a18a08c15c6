#include "shadelab/AtomicFile.h"

#include "TestFolder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <csignal>
#include <dirent.h>
#include <fstream>
#include <sstream>
#include <sys/stat.h>
#include <sys/wait.h>
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

/// Every entry of @p folder but "." and "..", hidden ones included.
int entriesIn(const std::string& folder)
{
  int count = 0;
  DIR* dir = opendir(folder.c_str());
  while (dirent* entry = readdir(dir))
  {
    count += std::string(entry->d_name) != "." && std::string(entry->d_name) != "..";
  }
  closedir(dir);
  return count;
}

/// The tests below run with either kind of temporary file.
class AtomicFileOfKind : public ::testing::TestWithParam<TemporaryKind>
{
protected:
  void SetUp() override
  {
    const TestFolder probe;
    if (GetParam() == TemporaryKind::Unnamed && !AtomicOutput(probe.path("probe")).unnamed())
    {
      GTEST_SKIP() << "/tmp's file system has no O_TMPFILE (or /proc is not mounted)";
    }
  }

  void write(const std::string& path, const std::string& bytes) const
  {
    AtomicOutput output(path, GetParam());
    EXPECT_EQ(output.unnamed(), GetParam() == TemporaryKind::Unnamed);
    output.commit(bytes.data(), bytes.size());
  }
};
} // namespace

INSTANTIATE_TEST_SUITE_P(Kinds, AtomicFileOfKind, ::testing::Values(TemporaryKind::Unnamed, TemporaryKind::Named),
  [](const ::testing::TestParamInfo<TemporaryKind>& kind) {
    return kind.param == TemporaryKind::Unnamed ? "Unnamed" : "Named";
  });

TEST_P(AtomicFileOfKind, WritesAndReplaces)
{
  const TestFolder temporary;
  const std::string folder = temporary.root();
  const std::string path = folder + "/out.txt";
  this->write(path, "first");
  EXPECT_EQ(slurp(path), "first");
  this->write(path, "second");
  EXPECT_EQ(slurp(path), "second");
  EXPECT_EQ(entriesIn(folder), 1) << "no temporary file left behind";
}

TEST_P(AtomicFileOfKind, NewFilesGetTheUsualPermissions)
{
  // Like a file opened for writing: 0666 less the umask (not mkstemp's 0600).
  const TestFolder temporary;
  const std::string folder = temporary.root();
  const mode_t mask = umask(022);
  this->write(folder + "/new.txt", "x");
  umask(mask);
  struct stat info;
  ASSERT_EQ(stat((folder + "/new.txt").c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 0777, 0644u);

  // A replaced file keeps its own mode.
  chmod((folder + "/new.txt").c_str(), 0640);
  this->write(folder + "/new.txt", "y");
  ASSERT_EQ(stat((folder + "/new.txt").c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 0777, 0640u);
}

TEST_P(AtomicFileOfKind, UncommittedOutputLeavesTheOldFile)
{
  const TestFolder temporary;
  const std::string folder = temporary.root();
  const std::string path = folder + "/image.png";
  writeFileAtomically(path, "old");
  {
    AtomicOutput output(path, GetParam());
    EXPECT_NE(output.temporaryPath(), path);
    // Another writer opens the file through temporaryPath(), as vtkPLYWriter does.
    std::ofstream(output.temporaryPath()) << "half";
    EXPECT_EQ(slurp(output.temporaryPath()), "half");
    if (GetParam() == TemporaryKind::Named)
    {
      EXPECT_EQ(output.temporaryPath().substr(output.temporaryPath().size() - 4), ".png") << "keeps the extension";
    }
    else
    {
      EXPECT_EQ(entriesIn(folder), 1) << "no name while it is written";
    }
    // destroyed without commit(), as when a writer fails
  }
  EXPECT_EQ(slurp(path), "old");
  EXPECT_EQ(entriesIn(folder), 1);
}

TEST_P(AtomicFileOfKind, UnwritableFolderThrowsNamingTheFile)
{
  try
  {
    this->write("/nonexistent-folder/x.json", "data");
    FAIL();
  }
  catch (const shadelab::Error& e)
  {
    EXPECT_EQ(std::string(e.what()), "/nonexistent-folder/x.json: cannot create output file: No such file or directory");
  }
}

TEST_P(AtomicFileOfKind, InterruptedWriterLeavesNoTemporaryFile)
{
  // A writer killed mid-write, by a signal it may catch or by one it cannot.
  for (const int signal : { SIGINT, SIGKILL })
  {
    const TestFolder temporary;
    const std::string folder = temporary.root();
    const std::string path = folder + "/mesh.vtp";
    writeFileAtomically(path, "old");
    int pipeEnds[2];
    ASSERT_EQ(pipe(pipeEnds), 0);
    const pid_t child = fork();
    ASSERT_NE(child, -1);
    if (child == 0)
    {
      AtomicOutput output(path, GetParam());
      const std::string megabyte(1 << 20, 'x');
      output.write(megabyte.data(), megabyte.size());
      const char written = 'w';
      (void)!::write(pipeEnds[1], &written, 1);
      pause();
      _exit(0);
    }
    close(pipeEnds[1]);
    char written = 0;
    ASSERT_EQ(read(pipeEnds[0], &written, 1), 1);
    close(pipeEnds[0]);
    EXPECT_EQ(entriesIn(folder), GetParam() == TemporaryKind::Unnamed ? 1 : 2);
    kill(child, signal);
    int status = 0;
    ASSERT_EQ(waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFSIGNALED(status));
    EXPECT_EQ(slurp(path), "old");
    if (GetParam() == TemporaryKind::Unnamed)
    {
      EXPECT_EQ(entriesIn(folder), 1) << "signal " << signal << ": nothing left";
    }
    else
    {
      // A named file stays until the next write of the same target.
      EXPECT_EQ(entriesIn(folder), 2) << "signal " << signal;
      this->write(path, "new");
      EXPECT_EQ(slurp(path), "new");
      EXPECT_EQ(entriesIn(folder), 1) << "signal " << signal << ": the stale file removed";
    }
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

TEST_P(AtomicFileOfKind, WritesTheLongestValidName)
{
  const TestFolder temporary;
  const std::string folder = temporary.root();
  const std::string path = folder + "/" + std::string(251, 'n') + ".vtp"; // 255 bytes
  this->write(path, "data");
  EXPECT_EQ(slurp(path), "data");
  EXPECT_EQ(entriesIn(folder), 1);
}

TEST_P(AtomicFileOfKind, RemovesStaleTemporariesButNotLiveOnes)
{
  const TestFolder temporary;
  const std::string folder = temporary.root();
  const std::string path = folder + "/out.vtp";
  // A live writer of the same target holds its temporary file's lock.
  AtomicOutput live(path, GetParam());
  std::ofstream(folder + "/.out.partial-Ab12Cd.vtp") << "left by a killed process";
  std::ofstream(folder + "/.out.partial-Ab12Cd.ply") << "another target's";
  this->write(path, "new");
  EXPECT_EQ(slurp(path), "new");
  EXPECT_NE(access((folder + "/.out.partial-Ab12Cd.ply").c_str(), F_OK), -1);
  EXPECT_EQ(access((folder + "/.out.partial-Ab12Cd.vtp").c_str(), F_OK), -1) << "stale file removed";
  EXPECT_NE(access(live.temporaryPath().c_str(), F_OK), -1) << "a live writer's file kept";
  live.commit("live", 4);
  EXPECT_EQ(slurp(path), "live");
  EXPECT_EQ(entriesIn(folder), 2);
}

TEST_P(AtomicFileOfKind, CommitWrittenRefusesAShortFile)
{
  const TestFolder temporary;
  const std::string folder = temporary.root();
  const std::string path = folder + "/mesh.ply";
  writeFileAtomically(path, "old");
  try
  {
    AtomicOutput output(path, GetParam());
    std::ofstream(output.temporaryPath()) << "12345";
    output.commitWritten(10);
    FAIL();
  }
  catch (const shadelab::Error& e)
  {
    EXPECT_EQ(std::string(e.what()), path + ": cannot write output file: the writer wrote 5 bytes of 10");
  }
  EXPECT_EQ(slurp(path), "old");
  EXPECT_EQ(entriesIn(folder), 1);

  AtomicOutput output(path, GetParam());
  std::ofstream(output.temporaryPath()) << "12345";
  output.commitWritten(5);
  EXPECT_EQ(slurp(path), "12345");
  EXPECT_EQ(entriesIn(folder), 1);
}

TEST_P(AtomicFileOfKind, WritesThroughSymbolicLinks)
{
  // A link to a figure in another folder (relative, then absolute, then a
  // link to a link): the figure is replaced, the link stays a link.
  const TestFolder temporary;
  const std::string folder = temporary.root();
  ASSERT_EQ(mkdir((folder + "/slides").c_str(), 0755), 0);
  const std::string figure = folder + "/slides/fig.png";
  writeFileAtomically(figure, "old");
  ASSERT_EQ(symlink("slides/fig.png", (folder + "/relative.png").c_str()), 0);
  ASSERT_EQ(symlink(figure.c_str(), (folder + "/absolute.png").c_str()), 0);
  ASSERT_EQ(symlink("relative.png", (folder + "/chain.png").c_str()), 0);
  for (const char* link : { "relative.png", "absolute.png", "chain.png" })
  {
    this->write(folder + "/" + link, link);
    EXPECT_EQ(slurp(figure), link);
    struct stat info;
    ASSERT_EQ(lstat((folder + "/" + link).c_str(), &info), 0);
    EXPECT_TRUE(S_ISLNK(info.st_mode)) << link;
    EXPECT_EQ(entriesIn(folder + "/slides"), 1) << "no temporary file beside the figure";
  }
  EXPECT_EQ(entriesIn(folder), 4);

  // A dangling link makes the file it names.
  ASSERT_EQ(symlink("slides/new.png", (folder + "/dangling.png").c_str()), 0);
  this->write(folder + "/dangling.png", "made");
  EXPECT_EQ(slurp(folder + "/slides/new.png"), "made");

  // A loop of links is refused as open() refuses it.
  ASSERT_EQ(symlink("loop-b.png", (folder + "/loop-a.png").c_str()), 0);
  ASSERT_EQ(symlink("loop-a.png", (folder + "/loop-b.png").c_str()), 0);
  try
  {
    this->write(folder + "/loop-a.png", "x");
    FAIL();
  }
  catch (const shadelab::Error& e)
  {
    EXPECT_EQ(std::string(e.what()), folder + "/loop-a.png: cannot create output file: Too many levels of symbolic links");
  }
}
