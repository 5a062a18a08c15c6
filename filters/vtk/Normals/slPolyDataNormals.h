#ifndef slPolyDataNormals_h
#define slPolyDataNormals_h
/**
 * @class   slPolyDataNormals
 * @brief   Face and vertex normals with a choice of weighting, feature-angle
 *          splitting and consistent orientation, in parallel.
 *
 * slPolyDataNormals computes a point array "Normals" (unit vertex normals)
 * and, on request, a cell array "Normals" (unit face normals by Newell's
 * method: exact for planar polygons of any vertex count).
 *
 * A vertex normal is the normalised sum of the unit normals of the polygons
 * at the vertex, each times a weight chosen by SetWeighting():
 * - Uniform: 1, as vtkPolyDataNormals;
 * - Area: the polygon's area, as vtkTriangleMeshPointNormals;
 * - Angle (the default; Thürmer & Wüthrich 1998): the polygon's angle at the
 *   vertex. The result depends on the shape of the surface, not on how it
 *   is cut into triangles: splitting a polygon in two leaves it unchanged,
 *   while uniform and area weights change. docs/normals.md shows it beats
 *   uniform and area weighting on irregular triangulations;
 * - Max (Nelson Max 1999): sin θ / (|e1| |e2|); exact at the vertices of any
 *   triangulated sphere, best on smooth, finely and evenly sampled surfaces,
 *   but sensitive to long thin triangles. A corner whose |e1|² |e2|² is
 *   below the smallest normal number of the arithmetic (float: 1.2e-38,
 *   double: 2.2e-308), where the weight could overflow, weighs 0.
 *
 * With Splitting on, points on edges whose dihedral angle exceeds
 * FeatureAngle, and points on non-manifold edges, are duplicated (one copy
 * per smooth group of polygons) so that sharp edges stay sharp; the copies
 * carry the input point data. With Consistency on, polygons are reversed so
 * that neighbours traverse shared edges in opposite directions;
 * AutoOrientNormals further reverses closed surfaces whose signed volume is
 * negative, so their normals point outward. WeldCoincidentPoints computes
 * normals as if points with identical coordinates were one (unwelded patch
 * seams then do not show as creases) while keeping the points, and so their
 * texture coordinates, apart.
 *
 * Triangles, quads, n-gons and triangle strips are handled; strips are output
 * as triangles. Vertex and line cells are passed through with a warning.
 * Zero-area polygons contribute nothing and get a (0, 0, 0) face normal;
 * points used by no polygon of non-zero area get a (0, 0, 0) normal (with
 * WeldCoincidentPoints and without Splitting, such a point at the position
 * of a used one takes that point's normal; with Splitting a position may
 * have several normals, and it keeps (0, 0, 0)). Input
 * point and cell arrays are passed through (an input "Normals" is replaced).
 *
 * A point with a NaN or infinite coordinate gives an error and an empty
 * output. Every other input gives finite normals at any size: float points
 * of a mesh not between 2^-10 and 2^20 across are computed in double, and
 * double points of a mesh not between 2^-128 and 2^200 across in long
 * double (a copy of the points; slower), so that squared cross products,
 * which grow as the 4th power of the size, neither overflow nor underflow.
 *
 * The filter keeps the blocks of its scratch memory under 2 MiB, up to
 * 64 MiB in all, from one update to the next (shadelab::ScratchPool), and
 * frees them when it is deleted: run again on a mesh of the same size, it
 * writes to memory it already has instead of taking a page fault every
 * 4 KiB. Larger blocks lie on huge pages (a fault per 2 MiB) and are freed
 * after each update, except the sums of vertex normals without splitting
 * (a copy per extra thread in a mesh in random order, 12 bytes a point),
 * which the update allocates nothing after: kept within the 64 MiB, they
 * raise no update's peak memory, and spare the next update mapping them
 * again, which on a virtual machine that hands freed memory back to its
 * host took 112-132 ms for the 48 MB copy of an 8M-triangle mesh (2-4 ms
 * when the host had not yet taken the memory back).
 *
 * The filter also keeps a reference to the normals arrays it last output.
 * The pipeline empties the output before an update; when nothing else then
 * holds those arrays (no downstream output, no script), the update refills
 * them instead of allocating new ones: a new array's pages are cleared by
 * the kernel before their first write, 4 ms for an 8M-triangle mesh's
 * normals, and 26-65 ms after another filter has freed much memory.
 * Arrays that something else holds are never written. As long as the
 * output holds the arrays, keeping them costs no memory; with the output's
 * ReleaseDataFlag (or the global one) on, they are not kept.
 *
 * @warning Meshes with 2^31 or more polygon corners are refused when
 * Splitting, Consistency, AutoOrientNormals or WeldCoincidentPoints is on.
 * Angles of non-convex polygon corners are taken as the convex angle.
 *
 * @warning Differences from vtkPolyDataNormals:
 * - With Splitting on, output points are ordered by input point, the copies
 *   of a split point next to each other (its groups in the order of their
 *   first polygon), and points used by no polygon come last, in input
 *   order. So point ids change after the first split point, and, when some
 *   point is used by no polygon, even when nothing splits.
 *   vtkPolyDataNormals keeps output point i = input point i and appends the
 *   copies.
 * - An edge whose dihedral angle equals FeatureAngle stays smooth (smooth
 *   when the normals' dot product is >= cos FeatureAngle); vtkPolyDataNormals
 *   splits it (smooth only when > cos FeatureAngle). vtkCylinderSource with
 *   resolution 12 (sides 30 degrees apart) at FeatureAngle 30: 56 points
 *   here, 72 with vtkPolyDataNormals.
 * - No FlipNormals, NonManifoldTraversal or OutputPointsPrecision (output
 *   points have the input's type). Consistency does not cross non-manifold
 *   edges (three or more polygons): the polygons beyond one are oriented as
 *   a piece of their own, where vtkPolyDataNormals' NonManifoldTraversal
 *   (on by default) walks across.
 * - Float points of a mesh between 2^-10 and 2^20 across are computed in
 *   float, feature angles too: an edge bent by less than about 0.02 degrees
 *   is smooth whatever FeatureAngle is (its cosine rounds to 1).
 *
 * @warning Pieces (MPI ranks, see slPolyDataFilter): values at piece
 * boundaries match the whole mesh's, except that WeldCoincidentPoints sees
 * only the coincident points its piece and ghost cells hold (ghost cells
 * follow shared points, not shared positions: at an unwelded seam on a
 * piece boundary the other side may be missing; weld such meshes upstream),
 * and that Consistency and AutoOrientNormals orient each piece by itself: a
 * piece of a closed surface is not closed, and its signed volume is not the
 * surface's. Orient inconsistent meshes once, in serial, before
 * distributing them.
 *
 * @sa vtkPolyDataNormals vtkTriangleMeshPointNormals slPolyDataTangents
 */

#include "ShadeLabNormalsModule.h"

#include "slPolyDataFilter.h"

#include <vtkSmartPointer.h>

#include <memory>

class vtkFloatArray;

#ifndef __VTK_WRAP__
namespace shadelab
{
class ScratchPool;
}
#endif

class SHADELABNORMALS_EXPORT slPolyDataNormals : public slPolyDataFilter
{
public:
  static slPolyDataNormals* New();
  vtkTypeMacro(slPolyDataNormals, slPolyDataFilter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum WeightingType
  {
    UNIFORM = 0,
    AREA = 1,
    ANGLE = 2,
    MAX = 3
  };

  ///@{
  /// How polygons' normals are weighted at a vertex. ANGLE by default.
  vtkSetClampMacro(Weighting, int, UNIFORM, MAX);
  vtkGetMacro(Weighting, int);
  void SetWeightingToUniform() { this->SetWeighting(UNIFORM); }
  void SetWeightingToArea() { this->SetWeighting(AREA); }
  void SetWeightingToAngle() { this->SetWeighting(ANGLE); }
  void SetWeightingToMax() { this->SetWeighting(MAX); }
  static const char* GetWeightingName(int weighting);
  ///@}

  ///@{
  /// Angle in degrees above which an edge is sharp. 30 by default.
  vtkSetClampMacro(FeatureAngle, double, 0.0, 180.0);
  vtkGetMacro(FeatureAngle, double);
  ///@}

  ///@{
  /// Duplicate points along sharp edges. On by default.
  vtkSetMacro(Splitting, bool);
  vtkGetMacro(Splitting, bool);
  vtkBooleanMacro(Splitting, bool);
  ///@}

  ///@{
  /// Orient polygons consistently across shared edges. On by default.
  vtkSetMacro(Consistency, bool);
  vtkGetMacro(Consistency, bool);
  vtkBooleanMacro(Consistency, bool);
  ///@}

  ///@{
  /// Make closed surfaces face outward (implies Consistency). Off by default.
  vtkSetMacro(AutoOrientNormals, bool);
  vtkGetMacro(AutoOrientNormals, bool);
  vtkBooleanMacro(AutoOrientNormals, bool);
  ///@}

  ///@{
  /// Treat points with identical coordinates as one. Off by default.
  vtkSetMacro(WeldCoincidentPoints, bool);
  vtkGetMacro(WeldCoincidentPoints, bool);
  vtkBooleanMacro(WeldCoincidentPoints, bool);
  ///@}

  ///@{
  /// Output the point array "Normals". On by default.
  vtkSetMacro(ComputePointNormals, bool);
  vtkGetMacro(ComputePointNormals, bool);
  vtkBooleanMacro(ComputePointNormals, bool);
  ///@}

  ///@{
  /// Output the cell array "Normals". Off by default.
  vtkSetMacro(ComputeCellNormals, bool);
  vtkGetMacro(ComputeCellNormals, bool);
  vtkBooleanMacro(ComputeCellNormals, bool);
  ///@}

  /// Polygons reversed by the last update.
  vtkGetMacro(NumberOfFlippedPolygons, vtkIdType);

protected:
  slPolyDataNormals();
  ~slPolyDataNormals() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  slPolyDataNormals(const slPolyDataNormals&) = delete;
  void operator=(const slPolyDataNormals&) = delete;

  int Weighting = ANGLE;
  double FeatureAngle = 30.0;
  bool Splitting = true;
  bool Consistency = true;
  bool AutoOrientNormals = false;
  bool WeldCoincidentPoints = false;
  bool ComputePointNormals = true;
  bool ComputeCellNormals = false;
  vtkIdType NumberOfFlippedPolygons = 0;
  // The normals arrays last output, refilled when nothing else holds them.
  vtkSmartPointer<vtkFloatArray> LastPointNormals;
  vtkSmartPointer<vtkFloatArray> LastCellNormals;
#ifndef __VTK_WRAP__
  std::unique_ptr<shadelab::ScratchPool> Scratch;
#endif
};

#endif
