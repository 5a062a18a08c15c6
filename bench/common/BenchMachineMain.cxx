// shadelab_bench_machine [--threads N]: prints the machine a bench runs on
// (BenchMachine), for the benches written in Python (bench/io), so that
// every bench describes and measures the machine with the same code.
#include "BenchArguments.h"
#include "BenchMachine.h"

int main(int argc, char** argv)
{
  BenchArguments args("shadelab_bench_machine",
    "Prints the CPU model, cores, threads, memory and the memory bandwidth measured now.", 1);
  if (!args.parse(argc, argv))
  {
    return args.exitCode();
  }
  BenchMachine::measure().print();
  return 0;
}
