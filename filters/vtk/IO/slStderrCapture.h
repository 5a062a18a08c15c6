#ifndef slStderrCapture_h
#define slStderrCapture_h
/**
 * @file slStderrCapture.h
 * @brief Holds back what image libraries print on stderr while they run.
 *
 * libpng, libjpeg and OpenImageIO's plugins print their own warnings and
 * errors ("libpng error: IHDR: CRC error", "Corrupt JPEG data: ...") on the
 * process's stderr, before ShadeLab can report the problem in one line.
 * While an slStderrCapture lives, file descriptor 2 goes to a temporary
 * file; the destructor restores it, and Text() gives what was written, for
 * use as the reason when the library gives none. Captures are serialised
 * (the descriptor is process-wide). Internal to ShadeLab::IO.
 *
 * Caveats: whatever the process prints while a capture lives goes to the
 * temporary file, a crash report too. SetEnabled(false) leaves stderr alone:
 * `shadelab --verbose` shows the libraries' own lines that way, and the fuzz
 * targets keep the sanitizers' reports.
 */

#include <mutex>
#include <string>

class slStderrCapture
{
public:
  slStderrCapture();
  ~slStderrCapture();
  slStderrCapture(const slStderrCapture&) = delete;
  slStderrCapture& operator=(const slStderrCapture&) = delete;

  /// What was written to stderr so far, on one line (newlines as "; ").
  std::string Text() const;

  ///@{
  /// Whether captures made from now on redirect stderr (default true).
  static void SetEnabled(bool enabled);
  static bool GetEnabled();
  ///@}

private:
  std::unique_lock<std::mutex> Lock;
  int Saved = -1;
  int File = -1;
};

#endif
