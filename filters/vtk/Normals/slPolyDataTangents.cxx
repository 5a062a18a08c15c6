#include "slPolyDataTangents.h"

#include "slConnectivityCheck.h"
#include "slCoreBoundary.h"
#include "slNormalsVTKBridge.h"
#include "slPolyDataNormals.h"
#include "slSMPFor.h"
#include "shadelab/slTangentSeamsCore.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
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

vtkStandardNewMacro(slPolyDataTangents);

slPolyDataTangents::slPolyDataTangents() = default;
slPolyDataTangents::~slPolyDataTangents() = default;

int slPolyDataTangents::RequestData(vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  output->Initialize();
  this->NumberOfSplitPoints = 0;
  if (!input || input->GetNumberOfPoints() == 0)
  {
    return 1;
  }
  const vtkIdType bad = slFirstNonFinitePoint(input->GetPoints());
  if (bad >= 0)
  {
    return this->Fail("point " + std::to_string(bad) + " has a NaN or infinite coordinate", output);
  }
  const std::string cellProblem = slConnectivityProblem(input);
  if (!cellProblem.empty())
  {
    return this->Fail(cellProblem, output);
  }
  vtkDataArray* tcoords = input->GetPointData()->GetTCoords();
  if (!tcoords || tcoords->GetNumberOfComponents() < 2)
  {
    return this->Fail("no texture coordinates (UVs): tangents need a 2-component point TCoords array", output);
  }
  if (input->GetNumberOfVerts() + input->GetNumberOfLines() > 0)
  {
    vtkWarningMacro(<< input->GetNumberOfVerts() + input->GetNumberOfLines()
                    << " vertex and line cells are not polygons: passed through without tangents");
  }

  // Normals (and strips as triangles) from slPolyDataNormals when needed.
  vtkSmartPointer<vtkPolyData> mesh = input;
  if (!input->GetPointData()->GetNormals() || input->GetNumberOfStrips() > 0)
  {
    vtkNew<slPolyDataNormals> normals;
    normals->SetInputData(input);
    normals->SplittingOff();
    normals->ConsistencyOff();
    normals->SetComputePointNormals(!input->GetPointData()->GetNormals());
    normals->Update();
    mesh = normals->GetOutput();
  }
  vtkDataArray* normalArray = mesh->GetPointData()->GetNormals();
  tcoords = mesh->GetPointData()->GetTCoords();
  vtkPoints* points = mesh->GetPoints();
  const vtkIdType numPoints = mesh->GetNumberOfPoints();

  // Copies in double precision keep the core free of VTK array types.
  std::vector<glm::dvec3> pos(static_cast<size_t>(numPoints)), nrm(static_cast<size_t>(numPoints));
  std::vector<glm::dvec2> uv(static_cast<size_t>(numPoints));
  slSMPFor(0, numPoints, 8192, [&](vtkIdType b, vtkIdType e) {
    for (vtkIdType i = b; i < e; ++i)
    {
      double p[3], n[3];
      points->GetPoint(i, p);
      normalArray->GetTuple(i, n);
      pos[static_cast<size_t>(i)] = glm::dvec3(p[0], p[1], p[2]);
      const glm::dvec3 nv(n[0], n[1], n[2]);
      const double len = glm::length(nv);
      nrm[static_cast<size_t>(i)] = len > 0 ? nv / len : glm::dvec3(0, 0, 1);
      uv[static_cast<size_t>(i)] = glm::dvec2(tcoords->GetComponent(i, 0), tcoords->GetComponent(i, 1));
    }
  });

  vtkNew<vtkCellArray> polys;
  polys->DeepCopy(mesh->GetPolys());
  slnormals::SeamTangents frames;
  slDispatchStorage(polys, [&](auto id) {
    using Id = decltype(id);
    slnormals::Polygons<Id> view = slPolygonsOf<Id>(polys);
    frames = slnormals::tangentFramesWithSeams(view, numPoints, pos, uv, nrm, slSMPParallel());
    return 0;
  });
  const vtkIdType numOut = static_cast<vtkIdType>(frames.source.size());
  this->NumberOfSplitPoints = frames.numSplitPoints;

  // Output point i copies input point frames.source[i].
  vtkNew<vtkIdList> from;
  from->SetNumberOfIds(numOut);
  vtkNew<vtkIdList> to;
  to->SetNumberOfIds(numOut);
  for (vtkIdType i = 0; i < numOut; ++i)
  {
    from->SetId(i, static_cast<vtkIdType>(frames.source[static_cast<size_t>(i)]));
    to->SetId(i, i);
  }
  vtkNew<vtkPoints> outPoints;
  outPoints->SetDataType(points->GetDataType());
  points->GetPoints(from, outPoints);
  output->SetPoints(outPoints);
  output->GetPointData()->CopyAllocate(mesh->GetPointData(), numOut);
  output->GetPointData()->CopyData(mesh->GetPointData(), from, to);

  vtkNew<vtkFloatArray> tangents;
  tangents->SetName("Tangents");
  tangents->SetNumberOfComponents(4);
  slSetNumberOfTuplesOrThrow(tangents, numOut);
  std::copy(frames.tangents.begin(), frames.tangents.end(), tangents->GetPointer(0));
  output->GetPointData()->RemoveArray("Tangents");
  output->GetPointData()->AddArray(tangents);
  output->SetPolys(polys);
  output->SetVerts(mesh->GetVerts());
  output->SetLines(mesh->GetLines());
  output->GetCellData()->PassData(mesh->GetCellData());
  output->GetFieldData()->PassData(mesh->GetFieldData());
  return 1;
}

void slPolyDataTangents::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfSplitPoints: " << this->NumberOfSplitPoints << "\n";
}
