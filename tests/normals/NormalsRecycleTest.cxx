// slPolyDataNormals refills the normals arrays of its last output when
// nothing else holds them: the refilled values must be those a new filter
// computes, and arrays that something else holds must never be written.
#include "NormalsTestMeshes.h"
#include "ShuffledMesh.h"

#include "slPolyDataNormals.h"

#include <vtkCallbackCommand.h>
#include <vtkCellData.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

namespace
{
/// Two meshes of the same size and other shapes (and other triangulations),
/// their points of @p type, large enough to be cut into chunks per thread.
std::pair<vtkSmartPointer<vtkPolyData>, vtkSmartPointer<vtkPolyData>> twoTori(int type)
{
  auto asType = [type](vtkSmartPointer<vtkPolyData> mesh) {
    vtkNew<vtkPoints> points;
    points->SetDataType(type);
    points->DeepCopy(mesh->GetPoints());
    mesh->SetPoints(points);
    return mesh;
  };
  return { asType(normalstest::irregularTorus(1.0, 0.3, 300, 150, 1)),
    asType(normalstest::irregularTorus(1.0, 0.4, 300, 150, 2)) };
}

/// Sets @p *deleted when @p object is deleted.
void watchDeletion(vtkObject* object, bool* deleted)
{
  vtkNew<vtkCallbackCommand> onDelete;
  onDelete->SetClientData(deleted);
  onDelete->SetCallback([](vtkObject*, unsigned long, void* flag, void*) { *static_cast<bool*>(flag) = true; });
  object->AddObserver(vtkCommand::DeleteEvent, onDelete);
}

std::vector<float> valuesOf(vtkDataArray* a)
{
  auto* f = vtkFloatArray::SafeDownCast(a);
  return f ? std::vector<float>(f->GetPointer(0), f->GetPointer(0) + f->GetNumberOfValues()) : std::vector<float>();
}

/// The scratch memory @p f keeps, as its PrintSelf() says.
size_t keptScratchBytes(slPolyDataNormals* f)
{
  std::ostringstream text;
  f->Print(text);
  const std::string key = "Scratch memory kept: ";
  const size_t at = text.str().find(key);
  return at == std::string::npos ? 0 : std::stoull(text.str().substr(at + key.size()));
}

void configure(slPolyDataNormals* f)
{
  f->SplittingOff();
  f->ConsistencyOff();
  f->ComputeCellNormalsOn();
}
} // namespace

TEST(NormalsRecycle, RefilledArraysHoldWhatANewFilterComputes)
{
  // Float points sum into the output array itself, double points into
  // scratch: both paths, on arrays that hold the first mesh's normals.
  for (int type : { VTK_FLOAT, VTK_DOUBLE })
  {
    SCOPED_TRACE(type == VTK_FLOAT ? "float points" : "double points");
    auto [first, second] = twoTori(type);
    vtkNew<slPolyDataNormals> reused, fresh;
    configure(reused);
    configure(fresh);
    reused->SetInputData(first);
    reused->Update();
    vtkDataArray* pointNormals = reused->GetOutput()->GetPointData()->GetNormals();
    vtkDataArray* cellNormals = reused->GetOutput()->GetCellData()->GetNormals();
    bool pointNormalsDeleted = false, cellNormalsDeleted = false;
    watchDeletion(pointNormals, &pointNormalsDeleted);
    watchDeletion(cellNormals, &cellNormalsDeleted);
    const std::vector<float> firstValues = valuesOf(pointNormals);

    reused->SetInputData(second);
    reused->Update();
    fresh->SetInputData(second);
    fresh->Update();
    // Refilled, not replaced: the same arrays, not deleted.
    EXPECT_FALSE(pointNormalsDeleted);
    EXPECT_FALSE(cellNormalsDeleted);
    ASSERT_EQ(reused->GetOutput()->GetPointData()->GetNormals(), pointNormals);
    ASSERT_EQ(reused->GetOutput()->GetCellData()->GetNormals(), cellNormals);
    const std::vector<float> refilled = valuesOf(pointNormals);
    EXPECT_NE(refilled, firstValues); // the meshes differ, so must the normals
    EXPECT_EQ(refilled, valuesOf(fresh->GetOutput()->GetPointData()->GetNormals()));
    EXPECT_EQ(valuesOf(cellNormals), valuesOf(fresh->GetOutput()->GetCellData()->GetNormals()));
    EXPECT_STREQ(pointNormals->GetName(), "Normals");
  }
}

TEST(NormalsRecycle, ArraysSomethingElseHoldsAreNotWritten)
{
  auto [first, second] = twoTori(VTK_FLOAT);
  vtkNew<slPolyDataNormals> f;
  configure(f);
  f->SetInputData(first);
  f->Update();
  // A script, or a downstream output, holding the arrays.
  vtkSmartPointer<vtkDataArray> heldPoints = f->GetOutput()->GetPointData()->GetNormals();
  vtkSmartPointer<vtkDataArray> heldCells = f->GetOutput()->GetCellData()->GetNormals();
  const std::vector<float> pointValues = valuesOf(heldPoints), cellValues = valuesOf(heldCells);

  f->SetInputData(second);
  f->Update();
  EXPECT_NE(f->GetOutput()->GetPointData()->GetNormals(), heldPoints.Get());
  EXPECT_NE(f->GetOutput()->GetCellData()->GetNormals(), heldCells.Get());
  EXPECT_EQ(valuesOf(heldPoints), pointValues);
  EXPECT_EQ(valuesOf(heldCells), cellValues);
  EXPECT_NE(valuesOf(f->GetOutput()->GetPointData()->GetNormals()), pointValues);
}

TEST(NormalsRecycle, ReleaseDataFlagKeepsNothing)
{
  // Once the output lets go of its arrays, a filter with the flag on holds
  // them no longer (they are deleted); without it, it keeps them to refill.
  for (bool release : { true, false })
  {
    SCOPED_TRACE(release ? "ReleaseDataFlag on" : "ReleaseDataFlag off");
    auto [first, second] = twoTori(VTK_FLOAT);
    vtkNew<slPolyDataNormals> f;
    configure(f);
    f->SetReleaseDataFlag(release);
    f->SetInputData(first);
    f->Update();
    bool deleted = false;
    watchDeletion(f->GetOutput()->GetPointData()->GetNormals(), &deleted);
    f->GetOutput()->Initialize();
    EXPECT_EQ(deleted, release);
  }
}

TEST(NormalsRecycle, ArraysOfAnotherSizeAreReplaced)
{
  auto [first, second] = twoTori(VTK_FLOAT);
  auto smaller = normalstest::irregularTorus(1.0, 0.3, 200, 100, 3);
  vtkNew<slPolyDataNormals> f, fresh;
  configure(f);
  configure(fresh);
  f->SetInputData(first);
  f->Update();
  f->SetInputData(smaller);
  f->Update();
  fresh->SetInputData(smaller);
  fresh->Update();
  vtkDataArray* normals = f->GetOutput()->GetPointData()->GetNormals();
  ASSERT_EQ(normals->GetNumberOfTuples(), smaller->GetNumberOfPoints());
  EXPECT_EQ(valuesOf(normals), valuesOf(fresh->GetOutput()->GetPointData()->GetNormals()));
}

TEST(NormalsRecycle, RandomOrderSumsAreKeptUnlessAnArrayIsAllocatedAfterThem)
{
  // On two threads a mesh in random order sums into a second copy of the
  // sums, 12 bytes a point: 2.5 MB here, a large block of the pool.
  vtkSMPTools::Initialize(2);
  auto mesh = normalstest::inRandomOrder(normalstest::irregularTorus(1.0, 0.3, 700, 300, 4), 5);
  const size_t copyBytes = 12 * static_cast<size_t>(mesh->GetNumberOfPoints());
  vtkNew<slPolyDataNormals> f;
  f->SplittingOff();
  f->ConsistencyOff();
  f->SetInputData(mesh);
  f->Update();
  const size_t withSums = keptScratchBytes(f);
  EXPECT_GE(withSums, copyBytes);
  // Cell normals are allocated after the sums: the sums are freed first.
  f->ComputeCellNormalsOn();
  f->Update();
  EXPECT_LE(keptScratchBytes(f) + copyBytes, withSums);
  f->ComputeCellNormalsOff();
  f->Update();
  EXPECT_EQ(keptScratchBytes(f), withSums);
}
