#ifndef shadelab_tests_TestFolder_h
#define shadelab_tests_TestFolder_h
// A fresh temporary folder per test, removed afterwards.

#include <cstdlib>
#include <fstream>
#include <string>
#include <unistd.h>

class TestFolder
{
public:
  TestFolder()
  {
    char pattern[] = "/tmp/shadelab-test-XXXXXX";
    this->Folder = mkdtemp(pattern);
  }
  ~TestFolder() { std::system(("rm -rf '" + this->Folder + "'").c_str()); }
  TestFolder(const TestFolder&) = delete;
  TestFolder& operator=(const TestFolder&) = delete;

  std::string path(const std::string& name) const { return this->Folder + "/" + name; }

  void write(const std::string& name, const std::string& content) const
  {
    std::ofstream(this->path(name), std::ios::binary) << content;
  }

private:
  std::string Folder;
};

#endif
