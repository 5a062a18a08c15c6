#ifndef shadelab_bench_BenchTorus_h
#define shadelab_bench_BenchTorus_h
// The bench's input: a bumpy torus of about the requested number of triangles
// (float points, 64-bit cell storage as VTK's default).

#include <vtkSmartPointer.h>

class vtkPolyData;

/// A u x v torus grid with a ripple (so that some edges are sharp at 30 degrees).
vtkSmartPointer<vtkPolyData> slBenchTorus(long long triangles);

#endif
