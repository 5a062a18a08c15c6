// slComparisonRenderer's grid: every cell of a multi-row composite is the
// panel rendered alone, the difference cell is the amplified difference of
// two of them, and a cell without a panel shows the scene's background.
#include "VTKErrors.h"

#include "shadelab/DefaultScene.h"
#include "shadelab/Scene.h"
#include "slComparisonRenderer.h"
#include "slScene.h"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSphereSource.h>
#include <vtkUnsignedCharArray.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

namespace
{
constexpr int kWidth = 96;
constexpr int kHeight = 72;
const char* const kModels[] = { "lambert-normalized", "phong", "blinn-phong" };

vtkSmartPointer<vtkPolyData> sphere()
{
  vtkNew<vtkSphereSource> source;
  source->SetThetaResolution(48);
  source->SetPhiResolution(24);
  source->Update();
  return source->GetOutput();
}

/// A comparison of @p models (labelled by their names) at Phong frequency.
vtkSmartPointer<slComparisonRenderer> comparison(slScene* scene, vtkPolyData* mesh, std::vector<std::string> models)
{
  auto renderer = vtkSmartPointer<slComparisonRenderer>::New();
  renderer->SetScene(scene);
  renderer->SetMesh(mesh);
  renderer->SetPanelWidth(kWidth);
  renderer->SetPanelHeight(kHeight);
  for (const std::string& model : models)
  {
    EXPECT_TRUE(renderer->AddPanel(model.c_str(), model.c_str(), "phong"));
  }
  return renderer;
}

/// Renders @p renderer; "" and its image's size in panels, or the error.
std::string renderInCells(slComparisonRenderer* renderer, int& columns, int& rows)
{
  const std::string error = callError(renderer, [&] { return renderer->Render(); });
  int dims[3];
  renderer->GetImage()->GetDimensions(dims);
  columns = dims[0] % kWidth == 0 ? dims[0] / kWidth : -1;
  rows = dims[1] % kHeight == 0 ? dims[1] / kHeight : -1;
  return error;
}

/// Channel @p c of pixel (@p x, @p y) of @p image (row 0 at the bottom).
int channel(vtkImageData* image, int x, int y, int c)
{
  int dims[3];
  image->GetDimensions(dims);
  auto* pixels = vtkUnsignedCharArray::SafeDownCast(image->GetPointData()->GetScalars());
  return pixels->GetValue(3 * (static_cast<vtkIdType>(y) * dims[0] + x) + c);
}

/// The largest channel difference between cell (@p column, @p row from the
/// top) of @p grid and @p expected(x, y, c), over the panel's lower 70 %
/// (below the label).
template <typename Expected>
int worstInCell(vtkImageData* grid, int column, int row, Expected expected)
{
  int dims[3];
  grid->GetDimensions(dims);
  const int rows = dims[1] / kHeight;
  const int x0 = column * kWidth;
  const int y0 = (rows - 1 - row) * kHeight;
  int worst = 0;
  for (int y = 0; y < kHeight * 7 / 10; ++y)
  {
    for (int x = 0; x < kWidth; ++x)
    {
      for (int c = 0; c < 3; ++c)
      {
        worst = std::max(worst, std::abs(channel(grid, x0 + x, y0 + y, c) - expected(x, y, c)));
      }
    }
  }
  return worst;
}
} // namespace

TEST(ComparisonGrid, EveryCellIsItsPanelAloneAndTheDifferenceOfTwo)
{
  vtkNew<slScene> scene;
  scene->SetScene(shadelab::defaultScene());
  vtkSmartPointer<vtkPolyData> mesh = sphere();
  std::vector<vtkSmartPointer<vtkImageData>> alone;
  for (const char* model : kModels)
  {
    vtkSmartPointer<slComparisonRenderer> single = comparison(scene, mesh, { model });
    ASSERT_EQ(callError(single, [&] { return single->Render(); }), "");
    alone.push_back(single->GetImage());
  }

  // Three panels and the difference of the last two, two a row: 2 x 2 cells.
  vtkSmartPointer<slComparisonRenderer> grid = comparison(scene, mesh, { kModels[0], kModels[1], kModels[2] });
  grid->SetColumns(2);
  grid->SetDifference(1, 2, 8.0);
  int columns = 0, rows = 0;
  ASSERT_EQ(renderInCells(grid, columns, rows), "");
  ASSERT_EQ(columns, 2);
  ASSERT_EQ(rows, 2);
  vtkImageData* image = grid->GetImage();

  // Reading order: lambert-normalized, phong on top; blinn-phong, the
  // difference below.
  const int cells[3][2] = { { 0, 0 }, { 1, 0 }, { 0, 1 } };
  for (int i = 0; i < 3; ++i)
  {
    vtkImageData* expected = alone[static_cast<size_t>(i)];
    EXPECT_LE(worstInCell(image, cells[i][0], cells[i][1],
                [&](int x, int y, int c) { return channel(expected, x, y, c); }),
      1)
      << kModels[i];
  }
  // The cells are not all alike: the normalised Lambert reads the light as
  // irradiance, π times darker than Phong.
  EXPECT_GT(worstInCell(image, 0, 0, [&](int x, int y, int c) { return channel(alone[1], x, y, c); }), 40);

  const int differenceWorst = worstInCell(image, 1, 1, [&](int x, int y, int c) {
    return std::min(255, 8 * std::abs(channel(alone[1], x, y, c) - channel(alone[2], x, y, c)));
  });
  EXPECT_LE(differenceWorst, 8) << "one 1/255 step of either panel, amplified";
}

TEST(ComparisonGrid, ShortLastRowShowsTheBackgroundAndColumnsBeyondThePanelsGiveOneRow)
{
  vtkNew<slScene> scene;
  shadelab::Scene settings = shadelab::defaultScene();
  settings.background = glm::vec3(0.2f, 0.4f, 0.6f);
  scene->SetScene(settings);
  vtkSmartPointer<vtkPolyData> mesh = sphere();
  vtkSmartPointer<slComparisonRenderer> grid = comparison(scene, mesh, { kModels[0], kModels[1], kModels[2] });
  grid->SetColumns(2);
  int columns = 0, rows = 0;
  ASSERT_EQ(renderInCells(grid, columns, rows), "");
  ASSERT_EQ(columns, 2);
  ASSERT_EQ(rows, 2);
  const int background[3] = { 51, 102, 153 };
  EXPECT_LE(worstInCell(grid->GetImage(), 1, 1, [&](int, int, int c) { return background[c]; }), 1);

  grid->SetColumns(7);
  ASSERT_EQ(renderInCells(grid, columns, rows), "");
  EXPECT_EQ(columns, 3);
  EXPECT_EQ(rows, 1);
}
