#ifndef shadelab_bench_BenchTorus_h
#define shadelab_bench_BenchTorus_h
// The bench's input: a bumpy torus of about the requested number of triangles
// (float points, 64-bit cell storage as VTK's default).

#include <vtkSmartPointer.h>

#include <vector>

class vtkPolyData;

/// A u x v torus grid with a ripple (so that some edges are sharp at 30 degrees).
vtkSmartPointer<vtkPolyData> slBenchTorus(long long triangles);

/// @p mesh (triangles only) with its points renumbered at random, its
/// triangles in random order and each one's corners rotated by a random step
/// (orientation kept): the same surface in the order a mesh without locality
/// has. @p newId, if given, gets each point's new id.
vtkSmartPointer<vtkPolyData> slBenchShuffled(vtkPolyData* mesh, unsigned seed, std::vector<long long>* newId = nullptr);

#endif
