#include "BenchTiming.h"

#include <algorithm>
#include <chrono>

#include <sys/resource.h>

namespace
{
/// CPU seconds (user + system, all threads) this process has used so far.
double cpuSeconds()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_utime.tv_sec + usage.ru_stime.tv_sec + 1e-6 * (usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
}
} // namespace

double medianOf(std::vector<double> values)
{
  if (values.empty())
  {
    return 0.0;
  }
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

double BenchTimes::median() const
{
  return medianOf(this->wall);
}

double BenchTimes::minimum() const
{
  return this->wall.empty() ? 0.0 : *std::min_element(this->wall.begin(), this->wall.end());
}

double BenchTimes::maximum() const
{
  return this->wall.empty() ? 0.0 : *std::max_element(this->wall.begin(), this->wall.end());
}

double BenchTimes::medianCpu() const
{
  return medianOf(this->cpu);
}

namespace
{
void timeOnce(const std::function<void()>& job, BenchTimes& t)
{
  const double cpuStart = cpuSeconds();
  const auto start = std::chrono::steady_clock::now();
  job();
  t.wall.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  t.cpu.push_back(cpuSeconds() - cpuStart);
}
} // namespace

BenchTimes timeRuns(int runs, const std::function<void()>& job)
{
  BenchTimes t;
  for (int r = 0; r < runs; ++r)
  {
    timeOnce(job, t);
  }
  return t;
}

std::vector<BenchTimes> timeInterleaved(int runs, const std::vector<std::function<void()>>& jobs)
{
  std::vector<BenchTimes> t(jobs.size());
  for (int r = 0; r < runs; ++r)
  {
    // Round r starts with job r: each job follows each other job as often
    // (a job right after one that churned memory or left the thread pool
    // idle for long runs slower).
    for (size_t i = 0; i < jobs.size(); ++i)
    {
      const size_t j = (i + static_cast<size_t>(r)) % jobs.size();
      timeOnce(jobs[j], t[j]);
    }
  }
  return t;
}
