#ifndef BenchTiming_h
#define BenchTiming_h
/**
 * @brief Times repeated runs of a job: wall-clock and CPU seconds (user +
 *        system, all threads) of each run, with the median and the range.
 *
 * Input: the number of runs and the job. Output: every run's times, so a
 * bench can print the median with its range, never a single run.
 */
#include <functional>
#include <vector>

struct BenchTimes
{
  std::vector<double> wall; ///< seconds, one per run
  std::vector<double> cpu;  ///< CPU seconds of each run, all threads together

  double median() const;    ///< median wall seconds
  double minimum() const;
  double maximum() const;
  double medianCpu() const; ///< median CPU seconds
};

/// Runs @p job @p runs times and times each run.
BenchTimes timeRuns(int runs, const std::function<void()>& job);

/// Runs every job of @p jobs once per round, @p runs rounds, and times each
/// run: jobs compared within a round see the same machine (a shared or
/// drifting machine changes speed between rounds), so ratios can be taken
/// round by round. Round r runs the jobs in roundOrder(jobs.size(), r).
/// Returns one BenchTimes per job.
std::vector<BenchTimes> timeInterleaved(int runs, const std::vector<std::function<void()>>& jobs);

/// The order in which round @p round runs @p jobs jobs: a row of a
/// Williams design. A job runs faster right after one that read the same
/// input (its data is in cache) and slower after one that churned memory
/// or left the thread pool idle, so no job may always follow the same one.
/// Within rounds 0 to n - 1 (0 to 2n - 1 when n is odd), every job comes
/// right after every other job equally often: once (twice when n is odd).
/// Rounds after those repeat the cycle.
std::vector<size_t> roundOrder(size_t jobs, int round);

/// Median of @p values (the upper one of the middle two for an even count).
double medianOf(std::vector<double> values);

#endif
