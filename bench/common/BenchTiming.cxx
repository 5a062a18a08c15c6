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
    for (const size_t j : roundOrder(jobs.size(), r))
    {
      timeOnce(jobs[j], t[j]);
    }
  }
  return t;
}

std::vector<size_t> roundOrder(size_t jobs, int round)
{
  if (jobs == 0)
  {
    return {};
  }
  // Williams (1949): the first row 0, 1, n-1, 2, n-2, ... steps by +1, -2,
  // +3, -4, ... (mod n), every step a different one, so row r = row 0 + r
  // puts each job after each other job once in n rows. When n is odd two
  // steps are equal, and the rows reversed make up for it.
  const size_t cycle = jobs % 2 ? 2 * jobs : jobs;
  const size_t row = static_cast<size_t>(round) % cycle;
  std::vector<size_t> order(jobs);
  for (size_t k = 0; k < jobs; ++k)
  {
    const size_t first = k % 2 ? (k + 1) / 2 : (jobs - k / 2) % jobs;
    order[k] = (first + row) % jobs;
  }
  if (row >= jobs)
  {
    std::reverse(order.begin(), order.end());
  }
  return order;
}
