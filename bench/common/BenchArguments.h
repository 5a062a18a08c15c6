#ifndef BenchArguments_h
#define BenchArguments_h
/**
 * @brief The command line every ShadeLab bench takes: --help, --runs N,
 *        --threads N, plus the bench's own options, declared once so that
 *        parsing, checking and the help text agree.
 *
 * Input: the bench's name, a one-line description, its own options (each a
 * name, a help text and where the value goes) and the defaults of --runs and
 * --threads. Output of parse(): true to go on; false when the program must
 * stop with exitCode() (0 after --help, 2 after a bad option, with one line
 * on stderr naming the option and the reason). --threads sets vtkSMPTools'
 * thread count before any filter runs.
 */
#include <functional>
#include <string>
#include <vector>

class BenchArguments
{
public:
  BenchArguments(std::string program, std::string description, int defaultRuns);

  /// An option taking a whole number in [minimum, maximum].
  void integer(const std::string& name, const std::string& help, long long* value, long long minimum,
    long long maximum);
  /// An option taking a value spelled @p metavar in the help, read by
  /// @p set, which returns "" or the problem with it.
  void text(const std::string& name, const std::string& metavar, const std::string& help,
    std::function<std::string(const std::string&)> set);
  /// An option without a value that sets @p value to true.
  void flag(const std::string& name, const std::string& help, bool* value);

  bool parse(int argc, char** argv);
  int exitCode() const { return this->ExitCode; }

  /// Runs of each measurement (--runs); the median of these is reported.
  int runs() const { return static_cast<int>(this->Runs); }
  /// Threads vtkSMPTools uses (--threads; 0: its default, all cores).
  int threads() const { return static_cast<int>(this->Threads); }

private:
  struct Option
  {
    std::string name, help;
    std::function<std::string(const char*)> set; ///< returns a problem, or "" (nullptr: a flag)
    bool takesValue;
    std::string metavar; ///< the value's name in the help
  };
  void usage() const;

  std::string Program, Description;
  std::vector<Option> Options;
  long long Runs, Threads = 0;
  int ExitCode = 0;
};

#endif
