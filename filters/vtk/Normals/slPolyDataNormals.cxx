#include "slPolyDataNormals.h"

#include "slConnectivityCheck.h"
#include "shadelab/slFaceNormalsCore.h"
#include "shadelab/slFeatureSplitCore.h"
#include "slNormalsVTKBridge.h"
#include "slOwnedPolygons.h"
#include "shadelab/slOrientationCore.h"
#include "shadelab/slPointWeldCore.h"
#include "shadelab/slVertexCorners.h"
#include "shadelab/slVertexNormalsCore.h"

#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>
#include <string>
#include <type_traits>
#include <vector>

vtkStandardNewMacro(slPolyDataNormals);

namespace
{
struct Settings
{
  slnormals::Weighting weighting;
  double featureAngle;
  bool split, orient, outward, weld, pointNormals, cellNormals;
};

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

/// The job on points of type T and polygon ids of type Id.
template <typename T, typename Id>
class NormalsJob
{
public:
  /// @p xyz: the input's coordinates as T (converted to double when they
  /// are not T already).
  NormalsJob(const Settings& s, vtkPolyData* input, vtkPolyData* output, const T* xyz)
    : S(s)
    , Input(input)
    , Output(output)
    , XYZ(xyz)
    , Par(slSMPParallel())
  {
  }

  /// Returns "" or the problem.
  std::string Run(vtkIdType& flipped)
  {
    vtkCellArray* strips = this->Input->GetStrips();
    const int64_t numPoints = this->Input->GetNumberOfPoints();
    slnormals::Polygons<Id> polys;
    if (strips->GetNumberOfCells() > 0)
    {
      this->Owned = slCopyPolygons<Id>(this->Input->GetPolys(), strips);
      this->HasOwned = true;
      polys = this->Owned.view();
    }
    else
    {
      polys = slPolygonsOf<Id>(this->Input->GetPolys());
    }
    const int64_t numCorners = polys.numPolygons ? polys.end(polys.numPolygons - 1) : 0;
    const bool needCorners = this->S.orient || this->S.outward || (this->S.split && this->S.pointNormals);
    if ((needCorners || this->S.weld) && numCorners >= std::numeric_limits<int32_t>::max())
    {
      return "the mesh has " + std::to_string(numCorners) +
        " polygon corners; splitting, orientation and welding handle fewer than 2^31";
    }

    // Welding: polygons on canonical ids for everything topological.
    std::vector<int64_t> canonical;
    vtkSmartPointer<slIdArray<Id>> topologyIds;
    slnormals::Polygons<Id> topology = polys;
    if (this->S.weld)
    {
      slnormals::weldCoincidentPoints(this->XYZ, numPoints, canonical);
      topologyIds = vtkSmartPointer<slIdArray<Id>>::New();
      topologyIds->SetNumberOfValues(numCorners);
      Id* t = reinterpret_cast<Id*>(topologyIds->GetPointer(0));
      this->Par.forRange(0, numCorners, 65536, [&](int64_t b, int64_t e) {
        for (int64_t c = b; c < e; ++c)
        {
          t[c] = static_cast<Id>(canonical[static_cast<size_t>(polys.connectivity[c])]);
        }
      });
      topology.connectivity = t;
    }

    // Orientation: reverse polygons in an owned copy, only if needed. With
    // splitting, the pass that builds the smooth groups looks for
    // inconsistent edges itself (it reads the same corners), so a separate
    // check runs only without splitting.
    const bool splitting = this->S.pointNormals && this->S.split;
    slnormals::VertexCorners<Id> corners;
    bool cornersValid = false;
    flipped = 0;
    if (this->S.orient || this->S.outward)
    {
      corners.build(topology, numPoints, this->Par);
      cornersValid = true;
      if (this->S.outward || (!splitting && slnormals::hasInconsistentEdge(topology, corners, this->Par)))
      {
        flipped = this->Orient(polys, topology, corners);
        cornersValid = flipped == 0;
      }
    }

    vtkCellData* inCD = this->Input->GetCellData();
    vtkCellData* outCD = this->Output->GetCellData();
    const vtkIdType numVerts = this->Input->GetNumberOfVerts();
    const vtkIdType numLines = this->Input->GetNumberOfLines();

    // Points, point data and polygons.
    std::vector<vtkIdType> pointMap; // input point -> output point, when split
    if (splitting)
    {
      if (!cornersValid)
      {
        corners.build(topology, numPoints, this->Par);
      }
      const bool check = this->S.orient && !this->S.outward;
      if (!this->Split(polys, topology, numPoints, corners, check, pointMap))
      {
        flipped = this->Orient(polys, topology, corners);
        if (flipped != 0)
        {
          corners.build(topology, numPoints, this->Par);
        }
        this->Split(polys, topology, numPoints, corners, false, pointMap);
      }
    }
    else
    {
      this->Output->SetPoints(this->Input->GetPoints());
      this->Output->GetPointData()->PassData(this->Input->GetPointData());
      this->Output->SetPolys(this->HasOwned ? this->Owned.cells().GetPointer() : this->Input->GetPolys());
      if (this->S.pointNormals)
      {
        auto normals = slMakeNormalsArray(numPoints);
        float* n = normals->GetPointer(0);
        slnormals::computeVertexNormals(topology, this->XYZ, numPoints, this->S.weighting, n, this->Par);
        if (this->S.weld)
        {
          this->Par.forRange(0, numPoints, 65536, [&](int64_t b, int64_t e) {
            for (int64_t v = b; v < e; ++v)
            {
              const int64_t c = canonical[static_cast<size_t>(v)];
              if (c != v)
              {
                std::memcpy(n + 3 * v, n + 3 * c, 3 * sizeof(float));
              }
            }
          });
        }
        this->Output->GetPointData()->RemoveArray("Normals");
        this->Output->GetPointData()->SetNormals(normals);
      }
    }
    if (pointMap.empty())
    {
      this->Output->SetVerts(this->Input->GetVerts());
      this->Output->SetLines(this->Input->GetLines());
    }
    else
    {
      this->Output->SetVerts(slRemapCells(this->Input->GetVerts(), pointMap));
      this->Output->SetLines(slRemapCells(this->Input->GetLines(), pointMap));
    }

    // Cell data: strips became triangles after the polygons, in order.
    if (strips->GetNumberOfCells() == 0)
    {
      outCD->PassData(inCD);
    }
    else
    {
      const vtkIdType numOut = numVerts + numLines + polys.numPolygons;
      vtkNew<vtkIdList> from;
      from->SetNumberOfIds(numOut);
      vtkIdType o = 0;
      for (vtkIdType c = 0; c < numVerts + numLines + this->Input->GetNumberOfPolys(); ++c)
      {
        from->SetId(o++, c);
      }
      vtkIdType n;
      const vtkIdType* ids;
      vtkIdType s = numVerts + numLines + this->Input->GetNumberOfPolys();
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
    if (this->S.cellNormals)
    {
      const vtkIdType first = numVerts + numLines;
      auto normals = slMakeNormalsArray(first + polys.numPolygons);
      float* n = normals->GetPointer(0);
      std::fill(n, n + 3 * first, 0.0f);
      slnormals::computeUnitFaceNormals(topology, this->XYZ, n + 3 * first, this->Par);
      outCD->RemoveArray("Normals");
      outCD->SetNormals(normals);
    }
    return std::string();
  }

private:
  /// Makes neighbouring polygons agree (and closed pieces face outward if
  /// asked) in an owned copy of the polygons; @p polys and @p topology then
  /// view the copy (the welded topology is reversed in place too). Returns
  /// the number of polygons reversed.
  vtkIdType Orient(slnormals::Polygons<Id>& polys, slnormals::Polygons<Id>& topology,
    const slnormals::VertexCorners<Id>& corners)
  {
    if (!this->HasOwned)
    {
      this->Owned = slCopyPolygons<Id>(this->Input->GetPolys(), this->Input->GetStrips());
      this->HasOwned = true;
      const bool welded = topology.connectivity != polys.connectivity;
      polys = this->Owned.view();
      if (!welded)
      {
        topology = polys;
      }
    }
    std::vector<char> flips;
    const vtkIdType flipped =
      slnormals::orientPolygons(topology, this->XYZ, corners, this->S.outward, &flips);
    if (topology.connectivity != polys.connectivity)
    {
      for (int64_t f = 0; f < polys.numPolygons; ++f)
      {
        if (flips[static_cast<size_t>(f)])
        {
          std::reverse(polys.connectivity + polys.begin(f), polys.connectivity + polys.end(f));
        }
      }
    }
    return flipped;
  }

  /// Splits points along feature edges into the output. With
  /// @p checkOrientation, returns false and outputs nothing if some polygons
  /// run the same way along an edge (then orient them and call again).
  bool Split(const slnormals::Polygons<Id>& polys, const slnormals::Polygons<Id>& topology, int64_t numPoints,
    const slnormals::VertexCorners<Id>& corners, bool checkOrientation, std::vector<vtkIdType>& pointMap)
  {
    const int64_t numCorners = polys.numPolygons ? polys.end(polys.numPolygons - 1) : 0;
    vtkNew<vtkTypeInt32Array> conn;
    conn->SetNumberOfValues(numCorners);
    int64_t unused = 0;
    vtkSmartPointer<vtkFloatArray> normals;
    std::vector<int64_t> source;
    auto allocate = [&](int64_t splitPoints) {
      // Points used by no polygon are kept after the split ones, with (0,0,0).
      // Counted on the polygons as given: with welding, a seam duplicate has no
      // corners in the welded topology, yet the split emits it as a point.
      std::vector<char> used(static_cast<size_t>(numPoints), 0);
      for (int64_t c = 0; c < numCorners; ++c)
      {
        used[static_cast<size_t>(polys.connectivity[c])] = 1;
      }
      unused = std::count(used.begin(), used.end(), 0);
      normals = slMakeNormalsArray(splitPoints + unused);
      source.resize(static_cast<size_t>(splitPoints + unused));
      slnormals::SplitOutput out;
      out.normals = normals->GetPointer(0);
      out.source = source.data();
      return out;
    };
    const bool welded = topology.connectivity != polys.connectivity;
    const T cosFeature = static_cast<T>(std::cos(vtkMath::RadiansFromDegrees(this->S.featureAngle)));
    bool inconsistent = false;
    const int64_t split = slnormals::splitVertexNormals(topology, welded ? polys.connectivity : nullptr, this->XYZ,
      numPoints, corners, this->S.weighting, cosFeature, conn->GetPointer(0), allocate, this->Par,
      checkOrientation ? &inconsistent : nullptr);
    if (inconsistent)
    {
      return false;
    }

    pointMap.assign(static_cast<size_t>(numPoints), -1);
    for (int64_t i = split - 1; i >= 0; --i)
    {
      pointMap[static_cast<size_t>(source[static_cast<size_t>(i)])] = static_cast<vtkIdType>(i);
    }
    const int64_t total = split + unused;
    float* n = normals->GetPointer(0);
    for (int64_t v = 0, next = split; v < numPoints; ++v)
    {
      if (pointMap[static_cast<size_t>(v)] < 0)
      {
        source[static_cast<size_t>(next)] = v;
        std::fill(n + 3 * next, n + 3 * next + 3, 0.0f);
        pointMap[static_cast<size_t>(v)] = next++;
      }
    }

    // Output points of type T (the caller turns them back into the input's
    // type if that differs).
    vtkNew<vtkPoints> points;
    points->SetDataType(std::is_same<T, float>::value ? VTK_FLOAT : VTK_DOUBLE);
    points->SetNumberOfPoints(total);
    T* out = static_cast<T*>(points->GetData()->GetVoidPointer(0));
    this->Par.forRange(0, total, 65536, [&](int64_t b, int64_t e) {
      for (int64_t i = b; i < e; ++i)
      {
        std::memcpy(out + 3 * i, this->XYZ + 3 * source[static_cast<size_t>(i)], 3 * sizeof(T));
      }
    });
    this->Output->SetPoints(points);

    vtkPointData* inPD = this->Input->GetPointData();
    vtkPointData* outPD = this->Output->GetPointData();
    if (inPD->GetNumberOfArrays() > 0)
    {
      vtkNew<vtkIdList> from, to;
      from->SetNumberOfIds(total);
      to->SetNumberOfIds(total);
      for (int64_t i = 0; i < total; ++i)
      {
        from->SetId(i, source[static_cast<size_t>(i)]);
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
      vtkDataArray* offsets = this->HasOwned ? static_cast<vtkDataArray*>(this->Owned.offsets.GetPointer())
                                             : this->Input->GetPolys()->GetOffsetsArray();
      cells->SetData(vtkTypeInt32Array::SafeDownCast(offsets), conn);
    }
    else
    {
      vtkNew<vtkTypeInt32Array> offsets;
      offsets->SetNumberOfValues(polys.numPolygons + 1);
      int32_t* o = offsets->GetPointer(0);
      this->Par.forRange(0, polys.numPolygons + 1, 65536, [&](int64_t b, int64_t e) {
        for (int64_t f = b; f < e; ++f)
        {
          o[f] = static_cast<int32_t>(polys.offsets[f]);
        }
      });
      cells->SetData(offsets, conn);
    }
    this->Output->SetPolys(cells);
    return true;
  }

  const Settings S;
  vtkPolyData* Input;
  vtkPolyData* Output;
  const T* XYZ;
  slnormals::Parallel Par;
  slOwnedPolygons<Id> Owned;
  bool HasOwned = false;
};
} // namespace

slPolyDataNormals::slPolyDataNormals() = default;
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
  if (!input || input->GetNumberOfPoints() == 0)
  {
    return 1;
  }
  double largestSide = 0.0;
  const vtkIdType bad = slFirstNonFinitePoint(input->GetPoints(), &largestSide);
  if (bad >= 0)
  {
    return this->Fail("point " + std::to_string(bad) + " has a NaN or infinite coordinate", output);
  }
  const std::string cellProblem = slConnectivityProblem(input);
  if (!cellProblem.empty())
  {
    return this->Fail(cellProblem, output);
  }
  const vtkIdType others = input->GetNumberOfVerts() + input->GetNumberOfLines();
  if (others > 0)
  {
    vtkWarningMacro(<< others << " vertex and line cells are not polygons: passed through without normals");
  }

  Settings s;
  s.weighting = static_cast<slnormals::Weighting>(this->Weighting);
  s.featureAngle = this->FeatureAngle;
  s.split = this->Splitting;
  s.orient = this->Consistency;
  s.outward = this->AutoOrientNormals;
  s.weld = this->WeldCoincidentPoints;
  s.pointNormals = this->ComputePointNormals;
  s.cellNormals = this->ComputeCellNormals;

  // Points as float or double; anything else, and float points of a mesh
  // too large or too small for float arithmetic, is converted to double.
  vtkSmartPointer<vtkDataArray> data = input->GetPoints()->GetData();
  const bool computeAsGiven = vtkDoubleArray::SafeDownCast(data) ||
    (vtkFloatArray::SafeDownCast(data) && floatArithmeticSuffices(largestSide));
  if (!computeAsGiven)
  {
    auto converted = vtkSmartPointer<vtkDoubleArray>::New();
    converted->DeepCopy(data);
    data = converted;
  }
  std::string problem;
  vtkIdType flipped = 0;
  slDispatchStorage(input->GetPolys(), [&](auto id) {
    using Id = decltype(id);
    if (auto* f = vtkFloatArray::SafeDownCast(data))
    {
      NormalsJob<float, Id> job(s, input, output, f->GetPointer(0));
      problem = job.Run(flipped);
    }
    else
    {
      NormalsJob<double, Id> job(s, input, output, vtkDoubleArray::SafeDownCast(data)->GetPointer(0));
      problem = job.Run(flipped);
    }
    return 0;
  });
  if (!problem.empty())
  {
    output->Initialize();
    return this->Fail(problem, output);
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
}
