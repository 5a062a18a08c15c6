#include "BenchMachine.h"
#include "BenchThreadPlacement.h"
#include "BenchTiming.h"

#include <vtkSMPTools.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <memory>
#include <thread>
#include <vector>

namespace
{
/// The value after "key" and a colon on the first line of @p file that starts with it.
std::string field(const char* file, const std::string& key)
{
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);)
  {
    if (line.compare(0, key.size(), key) == 0)
    {
      const size_t colon = line.find(':');
      return colon == std::string::npos ? "" : line.substr(line.find_first_not_of(" \t", colon + 1));
    }
  }
  return "";
}

/// Best copy bandwidth in GB/s of @p bytes from @p from to @p to, split over @p chunks.
double copyBandwidth(const char* from, char* to, size_t bytes, int chunks, bool parallel)
{
  double best = 0;
  for (int r = 0; r < 5; ++r)
  {
    const auto start = std::chrono::steady_clock::now();
    auto copy = [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType c = begin; c < end; ++c)
      {
        const size_t first = bytes / chunks * c, last = c + 1 == chunks ? bytes : bytes / chunks * (c + 1);
        std::memcpy(to + first, from + first, last - first);
      }
    };
    if (parallel)
    {
      vtkSMPTools::For(0, chunks, 1, copy);
    }
    else
    {
      copy(0, chunks);
    }
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    best = std::max(best, 2.0 * static_cast<double>(bytes) / s / 1e9);
  }
  return best;
}

/// The length of each of the two tasks of a wake-up loop.
constexpr int kTaskMicroseconds = 200;

/// @p tries loops of two tasks, each loop after @p idleMs of sleep.
WakeUp measureWakeUp(int idleMs, int tries)
{
  using Clock = std::chrono::steady_clock;
  WakeUp w;
  w.idleMilliseconds = idleMs;
  w.tries = tries;
  std::vector<double> starts;
  for (int t = 0; t < tries; ++t)
  {
    std::this_thread::sleep_for(std::chrono::milliseconds(idleMs));
    const std::thread::id caller = std::this_thread::get_id();
    std::atomic<double> other{ -1 };
    const auto start = Clock::now();
    vtkSMPTools::For(0, 2, 1, [&](vtkIdType begin, vtkIdType end) {
      if (std::this_thread::get_id() != caller)
      {
        other = std::chrono::duration<double, std::micro>(Clock::now() - start).count();
      }
      // Busy, as a filter's task is: a sleeping task would free the caller's
      // thread to take the second task sooner.
      const auto until = Clock::now() + std::chrono::microseconds(kTaskMicroseconds * (end - begin));
      while (Clock::now() < until)
      {
      }
    });
    // A loop the second thread missed started it later than any it joined.
    w.missed += other < 0;
    starts.push_back(other < 0 ? HUGE_VAL : other.load());
  }
  w.medianMicroseconds = medianOf(starts);
  return w;
}

/// "after N ms idle: ..." for @p w.
std::string describe(const WakeUp& w)
{
  char text[160];
  char median[32];
  if (std::isinf(w.medianMicroseconds))
  {
    std::snprintf(median, sizeof(median), "over %d us", kTaskMicroseconds);
  }
  else
  {
    std::snprintf(median, sizeof(median), "%.0f us", w.medianMicroseconds);
  }
  std::snprintf(text, sizeof(text), "after %d ms idle %s (%d of %d loops ran on one thread)", w.idleMilliseconds,
    median, w.missed, w.tries);
  return text;
}
} // namespace

BenchMachine BenchMachine::measure()
{
  BenchMachine m;
  m.cpuModel = field("/proc/cpuinfo", "model name");
  m.logicalCores = static_cast<int>(std::thread::hardware_concurrency());
  m.threads = vtkSMPTools::GetEstimatedNumberOfThreads();
  m.smpBackend = vtkSMPTools::GetBackend();
  m.memoryGiB = std::atof(field("/proc/meminfo", "MemTotal").c_str()) / (1024.0 * 1024.0); // kB
  std::ifstream load("/proc/loadavg");
  std::string a, b, c;
  load >> a >> b >> c;
  m.loadAverage = a + " " + b + " " + c;

  const size_t bytes = size_t(256) << 20;
  std::unique_ptr<char[]> from(new char[bytes]), to(new char[bytes]);
  std::memset(from.get(), 1, bytes); // map every page before timing
  std::memset(to.get(), 0, bytes);
  m.bandwidthOneThread = copyBandwidth(from.get(), to.get(), bytes, 64, false);
  m.bandwidthAllThreads = copyBandwidth(from.get(), to.get(), bytes, 64, true);
  if (m.threads > 1)
  {
    m.wakeUpShort = measureWakeUp(1, 50);
    m.wakeUpLong = measureWakeUp(10, 50);
    if (placeSMPThreads(true) == m.threads)
    {
      m.wakeUpLongPinned = measureWakeUp(10, 50);
    }
    placeSMPThreads(false);
  }
  return m;
}

void BenchMachine::print() const
{
  std::printf("machine: %s, %d logical cores, %.1f GiB; load average %s\n", this->cpuModel.c_str(),
    this->logicalCores, this->memoryGiB, this->loadAverage.c_str());
  std::printf("threads: %d (vtkSMPTools backend %s)\n", this->threads, this->smpBackend.c_str());
  std::printf("memory bandwidth (256 MiB copy, read + write, best of 5): %.1f GB/s on 1 thread, %.1f GB/s on %d\n",
    this->bandwidthOneThread, this->bandwidthAllThreads, this->threads);
  if (this->wakeUpShort.tries > 0)
  {
    std::printf("second thread's start in a loop of two %d us tasks, median of %d: %s; %s\n", kTaskMicroseconds,
      this->wakeUpShort.tries, describe(this->wakeUpShort).c_str(), describe(this->wakeUpLong).c_str());
    if (this->wakeUpLongPinned.tries > 0)
    {
      std::printf("  the same, each thread pinned to a CPU of its own (then freed for the bench): %s\n",
        describe(this->wakeUpLongPinned).c_str());
    }
  }
  std::printf("\n");
}
