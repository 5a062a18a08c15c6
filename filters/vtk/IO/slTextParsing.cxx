#include "slTextParsing.h"

#include <algorithm>
#include <cstring>
#include <exception>
#include <thread>

std::size_t slCountLines(const char* begin, const char* end)
{
  // Blocks of 64 bytes counted in a byte: a loop the compiler vectorises
  // (six times as fast as std::count, which counts in a 64-bit integer).
  std::size_t lines = 0;
  const char* at = begin;
  for (; end - at >= 64; at += 64)
  {
    unsigned char block = 0;
    for (int k = 0; k < 64; ++k)
    {
      block = static_cast<unsigned char>(block + (at[k] == '\n' ? 1 : 0));
    }
    lines += block;
  }
  for (; at < end; ++at)
  {
    lines += *at == '\n' ? 1 : 0;
  }
  return lines;
}

std::size_t slTextStretchCount(std::size_t size, int threads)
{
  return size < (std::size_t(1) << 20) ? 1 : static_cast<std::size_t>(std::max(1, std::min(threads, 64)));
}

std::vector<const char*> slLineStretches(const char* text, std::size_t size, std::size_t parts)
{
  std::vector<const char*> bounds{ text };
  for (std::size_t k = 1; k < parts; ++k)
  {
    const char* at = std::max(bounds.back(), text + size / parts * k);
    const char* newline = static_cast<const char*>(std::memchr(at, '\n', static_cast<std::size_t>(text + size - at)));
    bounds.push_back(newline ? newline + 1 : text + size);
  }
  bounds.push_back(text + size);
  return bounds;
}

void slRunEach(std::size_t count, const std::function<void(std::size_t)>& work)
{
  if (count == 0)
  {
    return;
  }
  std::vector<std::exception_ptr> failures(count);
  const auto run = [&](std::size_t k) {
    try
    {
      work(k);
    }
    catch (...)
    {
      failures[k] = std::current_exception();
    }
  };
  std::vector<std::thread> workers;
  workers.reserve(count - 1);
  std::size_t started = 1;
  try
  {
    for (; started < count; ++started)
    {
      workers.emplace_back(run, started);
    }
  }
  catch (const std::system_error&)
  {
  }
  for (std::size_t k = started; k < count; ++k)
  {
    run(k);
  }
  run(0);
  for (std::thread& w : workers)
  {
    w.join();
  }
  for (const std::exception_ptr& failure : failures)
  {
    if (failure)
    {
      std::rethrow_exception(failure);
    }
  }
}
