#include "slPolyDataNormals.h"

#include "slConnectivityCheck.h"
#include "slFiniteParameters.h"
#include "shadelab/slFaceNormalsCore.h"
#include "shadelab/slPolygonNormalsCore.h"
#include "slCoreBoundary.h"
#include "slNormalsVTKBridge.h"
#include "slOwnedPolygons.h"

#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cstring>
#include <limits>
#include <numeric>
#include <string>
#include <type_traits>
#include <vector>

vtkStandardNewMacro(slPolyDataNormals);

namespace
{
/// Whether float points can be computed in float. The edge cross products
/// squared grow as the 4th power of the mesh's size: above about 1e9 they
/// overflow a float and below about 1e-9 they underflow, which gave NaN or
/// zero normals, silently. Double holds them for every float input, so a
/// float mesh whose bounding box is not between 2^-10 and 2^20 across (one
/// stray far point counts too) is computed in double.
bool floatArithmeticSuffices(double largestSide)
{
  return largestSide >= 0x1p-10 && largestSide <= 0x1p20;
}

/// Whether points can be computed in double: the same products overflow a
/// double above sizes of about 2^255 (1e77) and underflow below about
/// 2^-255, so a mesh whose bounding box is not between 2^-128 and 2^200
/// across (and is not a single position) is computed in long double, whose
/// exponent range (x86-64: 80-bit, up to 1e4932) holds them for every
/// double input. Every float and integer mesh is within the range.
bool doubleArithmeticSuffices(double largestSide)
{
  // 2^1025 to the 4th power, and 2^-1074 (the smallest double) too, and
  // their reciprocals (Max weights).
  static_assert(std::numeric_limits<long double>::max_exponent >= 4400 &&
      std::numeric_limits<long double>::min_exponent <= -4400,
    "long double must hold the 4th powers of every double (x86-64's 80-bit format does)");
  return largestSide == 0.0 || (largestSide >= 0x1p-128 && largestSide <= 0x1p200);
}

/// The cell data of the output: the input's, with the triangles cut from
/// strips (which follow the polygons) taking their strip's values.
void passCellData(vtkPolyData* input, vtkPolyData* output, int64_t numPolygons)
{
  vtkCellData* inCD = input->GetCellData();
  vtkCellData* outCD = output->GetCellData();
  vtkCellArray* strips = input->GetStrips();
  if (strips->GetNumberOfCells() == 0)
  {
    outCD->PassData(inCD);
    return;
  }
  const vtkIdType first = input->GetNumberOfVerts() + input->GetNumberOfLines();
  const vtkIdType numOut = first + numPolygons;
  vtkNew<vtkIdList> from;
  from->SetNumberOfIds(numOut);
  vtkIdType o = 0;
  for (vtkIdType c = 0; c < first + input->GetNumberOfPolys(); ++c)
  {
    from->SetId(o++, c);
  }
  vtkIdType n;
  const vtkIdType* ids;
  vtkIdType s = first + input->GetNumberOfPolys();
  for (strips->InitTraversal(); strips->GetNextCell(n, ids); ++s)
  {
    for (vtkIdType i = 0; i + 2 < n; ++i)
    {
      from->SetId(o++, s);
    }
  }
  vtkNew<vtkIdList> to;
  to->SetNumberOfIds(numOut);
  std::iota(to->GetPointer(0), to->GetPointer(0) + numOut, vtkIdType(0));
  outCD->CopyAllocate(inCD, numOut);
  outCD->CopyData(inCD, from, to);
}

/// The output's points, point data and polygons after a split: one point
/// per entry of @p r.source, of type P (the caller turns them back into the
/// input's type if that differs).
template <typename P, typename Id>
void setSplitPoints(vtkPolyData* input, vtkPolyData* output, const P* xyz, const slnormals::PolygonNormals<Id>& r,
  vtkDataArray* givenOffsets, vtkTypeInt32Array* connectivity, vtkFloatArray* normals, const slnormals::Parallel& par)
{
  const int64_t total = static_cast<int64_t>(r.source.size());
  vtkNew<vtkPoints> points;
  static_assert(std::is_same<P, float>::value || std::is_same<P, double>::value, "points are float or double");
  points->SetDataType(std::is_same<P, float>::value ? VTK_FLOAT : VTK_DOUBLE);
  points->SetNumberOfPoints(total);
  if (points->GetNumberOfPoints() != total)
  {
    throw std::bad_alloc(); // VTK could not allocate them (see slSetNumberOfTuplesOrThrow)
  }
  P* out = static_cast<P*>(points->GetData()->GetVoidPointer(0));
  par.forRange(0, total, 65536, [&](int64_t b, int64_t e) {
    for (int64_t i = b; i < e; ++i)
    {
      std::memcpy(out + 3 * i, xyz + 3 * r.source[static_cast<size_t>(i)], 3 * sizeof(P));
    }
  });
  output->SetPoints(points);

  vtkPointData* inPD = input->GetPointData();
  vtkPointData* outPD = output->GetPointData();
  if (inPD->GetNumberOfArrays() > 0)
  {
    vtkNew<vtkIdList> from, to;
    from->SetNumberOfIds(total);
    to->SetNumberOfIds(total);
    for (int64_t i = 0; i < total; ++i)
    {
      from->SetId(i, r.source[static_cast<size_t>(i)]);
      to->SetId(i, i);
    }
    outPD->CopyNormalsOff();
    outPD->CopyAllocate(inPD, total);
    outPD->CopyData(inPD, from, to);
    outPD->RemoveArray("Normals");
  }
  outPD->SetNormals(normals);

  vtkNew<vtkCellArray> cells;
  if (sizeof(Id) == 4)
  {
    cells->SetData(vtkTypeInt32Array::SafeDownCast(givenOffsets), connectivity);
  }
  else
  {
    vtkNew<vtkTypeInt32Array> offsets;
    slSetNumberOfTuplesOrThrow(offsets, r.polygons.numPolygons + 1);
    int32_t* o = offsets->GetPointer(0);
    par.forRange(0, r.polygons.numPolygons + 1, 65536, [&](int64_t b, int64_t e) {
      for (int64_t f = b; f < e; ++f)
      {
        o[f] = static_cast<int32_t>(r.polygons.offsets[f]);
      }
    });
    cells->SetData(offsets, connectivity);
  }
  output->SetPolys(cells);
}

/// Runs computePolygonNormals() (slPolygonNormalsCore.h) on points of type
/// T and polygon ids of type Id, and builds the output from its result:
/// the VTK side of the filter. Returns the number of polygons reversed.
/// @p lastPoints and @p lastCells hold the normals arrays last output
/// (refilled when nothing else holds them), and then those of this output.
/// Split points are copied from @p pointXyz, the same points as @p xyz in
/// type P (float or double; @p xyz itself unless T is long double).
template <typename T, typename Id, typename P = T>
int64_t computeInto(const slnormals::PolygonNormalsSettings& settings, bool cellNormals, vtkPolyData* input,
  vtkPolyData* output, const T* xyz, shadelab::ScratchPool* scratch, vtkSmartPointer<vtkFloatArray>& lastPoints,
  vtkSmartPointer<vtkFloatArray>& lastCells, const P* pointXyz = nullptr)
{
  if constexpr (std::is_same<T, P>::value)
  {
    pointXyz = xyz;
  }
  slnormals::Parallel par = slSMPParallel();
  par.scratch = scratch;
  if (settings.split || !settings.pointNormals)
  {
    // Large blocks the pool kept serve only the next vertex sums without
    // splitting (computeVertexNormals()); kept through another kind of
    // update they would sit idle beside its memory.
    scratch->freeLargeBlocks();
  }
  const int64_t numPoints = input->GetNumberOfPoints();
  vtkCellArray* strips = input->GetStrips();
  slOwnedPolygons<Id> owned;
  bool hasOwned = strips->GetNumberOfCells() > 0;
  if (hasOwned)
  {
    owned = slCopyPolygons<Id>(input->GetPolys(), strips);
  }

  slnormals::PolygonNormals<Id> r;
  vtkSmartPointer<vtkFloatArray> normals;
  vtkNew<vtkTypeInt32Array> splitConnectivity;
  r.allocateNormals = [&](int64_t n) {
    normals = slMakeNormalsArray(n, std::move(lastPoints));
    lastPoints = normals;
    return normals->GetPointer(0);
  };
  r.allocateSplitConnectivity = [&](int64_t n) {
    slSetNumberOfTuplesOrThrow(splitConnectivity, n);
    return splitConnectivity->GetPointer(0);
  };
  r.copyPolygons = [&] {
    owned = slCopyPolygons<Id>(input->GetPolys(), strips);
    hasOwned = true;
    return owned.view();
  };
  slnormals::computePolygonNormals(
    settings, hasOwned ? owned.view() : slPolygonsOf<Id>(input->GetPolys()), hasOwned, xyz, numPoints, par, r);
  if (!r.pointIdsInRange)
  {
    // Found by the computation (settings.checksPointIds()): the check names it.
    throw shadelab::Error(slConnectivityProblem(input));
  }

  if (!r.pointMap.empty())
  {
    vtkDataArray* givenOffsets = hasOwned ? static_cast<vtkDataArray*>(owned.offsets.GetPointer())
                                          : input->GetPolys()->GetOffsetsArray();
    setSplitPoints(input, output, pointXyz, r, givenOffsets, splitConnectivity, normals, par);
    if (input->GetNumberOfVerts() + input->GetNumberOfLines() > 0)
    {
      const std::vector<vtkIdType> pointMap(r.pointMap.begin(), r.pointMap.end());
      output->SetVerts(slRemapCells(input->GetVerts(), pointMap));
      output->SetLines(slRemapCells(input->GetLines(), pointMap));
    }
    else
    {
      output->SetVerts(input->GetVerts());
      output->SetLines(input->GetLines());
    }
  }
  else
  {
    output->SetPoints(input->GetPoints());
    output->GetPointData()->PassData(input->GetPointData());
    output->SetPolys(hasOwned ? owned.cells().GetPointer() : input->GetPolys());
    if (normals)
    {
      output->GetPointData()->RemoveArray("Normals");
      output->GetPointData()->SetNormals(normals);
    }
    output->SetVerts(input->GetVerts());
    output->SetLines(input->GetLines());
  }

  passCellData(input, output, r.polygons.numPolygons);
  if (cellNormals)
  {
    // Scratch the pool kept (the vertex sums) would sit beside the new array.
    scratch->freeLargeBlocks();
    const vtkIdType first = input->GetNumberOfVerts() + input->GetNumberOfLines();
    auto cellNormals = slMakeNormalsArray(first + r.polygons.numPolygons, std::move(lastCells));
    lastCells = cellNormals;
    float* n = cellNormals->GetPointer(0);
    std::fill(n, n + 3 * first, 0.0f);
    slnormals::computeUnitFaceNormals(r.polygons, xyz, n + 3 * first, par);
    output->GetCellData()->RemoveArray("Normals");
    output->GetCellData()->SetNormals(cellNormals);
  }
  return r.flipped;
}
} // namespace

slPolyDataNormals::slPolyDataNormals()
  : Scratch(std::make_unique<shadelab::ScratchPool>())
{
}

slPolyDataNormals::~slPolyDataNormals() = default;

const char* slPolyDataNormals::GetWeightingName(int weighting)
{
  switch (weighting)
  {
    case UNIFORM:
      return "uniform";
    case AREA:
      return "area";
    case ANGLE:
      return "angle";
    case MAX:
      return "max";
    default:
      return "unknown";
  }
}

int slPolyDataNormals::RequestData(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  output->Initialize();
  this->NumberOfFlippedPolygons = 0;
  // Taken out first: an update that fails or outputs nothing keeps nothing.
  vtkSmartPointer<vtkFloatArray> lastPoints = std::move(this->LastPointNormals);
  vtkSmartPointer<vtkFloatArray> lastCells = std::move(this->LastCellNormals);
  if (!input || input->GetNumberOfPoints() == 0)
  {
    return 1;
  }
  const std::string badParameter = slNonFiniteParameter({ { "FeatureAngle", this->FeatureAngle } });
  if (!badParameter.empty())
  {
    return this->Fail(badParameter, output);
  }
  double largestSide = 0.0;
  const vtkIdType bad = slFirstNonFinitePoint(input->GetPoints(), &largestSide);
  if (bad >= 0)
  {
    return this->Fail("point " + std::to_string(bad) + " has a NaN or infinite coordinate", output);
  }
  slnormals::PolygonNormalsSettings s;
  s.weighting = static_cast<slnormals::Weighting>(this->Weighting);
  s.featureAngleDegrees = this->FeatureAngle;
  s.split = this->Splitting;
  s.orient = this->Consistency;
  s.outward = this->AutoOrientNormals;
  s.weld = this->WeldCoincidentPoints;
  s.pointNormals = this->ComputePointNormals;
  const bool cellNormals = this->ComputeCellNormals;

  // Polygon ids the computation checks as it reads them are not read here
  // first: on the plain vertex-normal path that pass would cost as much
  // memory traffic as the computation's own reading of them.
  const std::string cellProblem = slConnectivityProblem(input, !s.checksPointIds());
  if (!cellProblem.empty())
  {
    return this->Fail(cellProblem, output);
  }
  const vtkIdType others = input->GetNumberOfVerts() + input->GetNumberOfLines();
  if (others > 0)
  {
    vtkWarningMacro(<< others << " vertex and line cells are not polygons: passed through without normals");
  }

  // Points as float or double; anything else, and float points of a mesh
  // too large or too small for float arithmetic, is converted to double. A
  // mesh too large or too small for double arithmetic is computed in long
  // double (a copy of its points; split points are copied from the double
  // ones).
  vtkSmartPointer<vtkDataArray> data = input->GetPoints()->GetData();
  const bool computeAsGiven = vtkDoubleArray::SafeDownCast(data) ||
    (vtkFloatArray::SafeDownCast(data) && floatArithmeticSuffices(largestSide));
  if (!computeAsGiven)
  {
    auto converted = vtkSmartPointer<vtkDoubleArray>::New();
    converted->DeepCopy(data);
    data = converted;
  }
  std::vector<long double> wide;
  if (vtkDoubleArray::SafeDownCast(data) && !doubleArithmeticSuffices(largestSide))
  {
    const double* d = vtkDoubleArray::SafeDownCast(data)->GetPointer(0);
    wide.assign(d, d + 3 * input->GetNumberOfPoints());
  }
  vtkIdType flipped = 0;
  if (!slRunCore(this, output, [&] {
    slDispatchStorage(input->GetPolys(), [&](auto id) {
      using Id = decltype(id);
      if (auto* f = vtkFloatArray::SafeDownCast(data))
      {
        flipped = computeInto<float, Id>(
          s, cellNormals, input, output, f->GetPointer(0), this->Scratch.get(), lastPoints, lastCells);
      }
      else if (wide.empty())
      {
        flipped = computeInto<double, Id>(s, cellNormals, input, output,
          vtkDoubleArray::SafeDownCast(data)->GetPointer(0), this->Scratch.get(), lastPoints, lastCells);
      }
      else
      {
        flipped = computeInto<long double, Id, double>(s, cellNormals, input, output, wide.data(),
          this->Scratch.get(), lastPoints, lastCells, vtkDoubleArray::SafeDownCast(data)->GetPointer(0));
      }
      return 0;
    });
  }))
  {
    return 0;
  }
  vtkPoints* outPoints = output->GetPoints();
  if (outPoints && outPoints != input->GetPoints() && outPoints->GetDataType() != input->GetPoints()->GetDataType())
  {
    // Split points made from converted coordinates: back to the input's type.
    vtkNew<vtkPoints> asInput;
    asInput->SetDataType(input->GetPoints()->GetDataType());
    asInput->GetData()->DeepCopy(outPoints->GetData());
    output->SetPoints(asInput);
  }
  this->NumberOfFlippedPolygons = flipped;
  output->GetFieldData()->PassData(input->GetFieldData());
  if (!this->GetReleaseDataFlag() && !vtkDataObject::GetGlobalReleaseDataFlag())
  {
    // Only arrays this update made and the output holds.
    if (output->GetPointData()->GetNormals() == lastPoints)
    {
      this->LastPointNormals = lastPoints;
    }
    if (output->GetCellData()->GetNormals() == lastCells)
    {
      this->LastCellNormals = lastCells;
    }
  }
  return 1;
}

void slPolyDataNormals::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Weighting: " << GetWeightingName(this->Weighting) << "\n";
  os << indent << "FeatureAngle: " << this->FeatureAngle << "\n";
  os << indent << "Splitting: " << this->Splitting << "\n";
  os << indent << "Consistency: " << this->Consistency << "\n";
  os << indent << "AutoOrientNormals: " << this->AutoOrientNormals << "\n";
  os << indent << "WeldCoincidentPoints: " << this->WeldCoincidentPoints << "\n";
  os << indent << "ComputePointNormals: " << this->ComputePointNormals << "\n";
  os << indent << "ComputeCellNormals: " << this->ComputeCellNormals << "\n";
  os << indent << "NumberOfFlippedPolygons: " << this->NumberOfFlippedPolygons << "\n";
  os << indent << "Scratch memory kept: " << this->Scratch->keptBytes() << " bytes\n";
}
