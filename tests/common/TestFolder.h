#ifndef shadelab_tests_TestFolder_h
#define shadelab_tests_TestFolder_h
// A fresh temporary folder per test, removed with everything in it when the
// TestFolder goes: a test suite run leaves nothing in /tmp.

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

class TestFolder
{
public:
  TestFolder()
  {
    char pattern[] = "/tmp/shadelab-test-XXXXXX";
    const char* made = mkdtemp(pattern);
    this->Folder = made ? made : "";
  }
  ~TestFolder()
  {
    std::error_code ignored;
    std::filesystem::remove_all(this->Folder, ignored);
  }
  TestFolder(const TestFolder&) = delete;
  TestFolder& operator=(const TestFolder&) = delete;

  /// False if the folder could not be made (/tmp full or not writable).
  bool valid() const { return !this->Folder.empty(); }
  /// The folder itself, without a trailing slash.
  const std::string& root() const { return this->Folder; }
  std::string path(const std::string& name) const { return this->Folder + "/" + name; }

  void write(const std::string& name, const std::string& content) const
  {
    std::ofstream(this->path(name), std::ios::binary) << content;
  }

private:
  std::string Folder;
};

#endif
