// GridFrame (common/geometry/grid_frame.h): cells, borders, the last cell, outside.
#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <set>
#include <utility>
#include <vector>

#include "common/geometry/grid_frame.h"

namespace fleetmap {
namespace {

// 4 x 3 cells of 0.5 m, lower-left corner (-1, -2): x in [-1, 1), y in [-2, -0.5).
const GridFrame kFrame{{-1, -2}, 0.5, 4, 3};

TEST(GridFrame, SizeAndRect) {
  EXPECT_EQ(kFrame.cells(), 12u);
  EXPECT_EQ(kFrame.rect(), (Rect{-1, -2, 1, -0.5}));
}

TEST(GridFrame, PointToCellIsFloorOnNegativeCoordinates) {
  EXPECT_EQ(kFrame.col(-1), 0);
  EXPECT_EQ(kFrame.col(-0.75), 0);
  EXPECT_EQ(kFrame.col(-0.25), 1);
  EXPECT_EQ(kFrame.row(-1.9), 0);
  EXPECT_EQ(kFrame.row(-0.6), 2);
  // Left of and below the origin: negative cells, not truncated towards zero.
  EXPECT_EQ(kFrame.col(-1.1), -1);
  EXPECT_EQ(kFrame.col(-1.6), -2);
  EXPECT_EQ(kFrame.row(-2.01), -1);
}

TEST(GridFrame, PointsOnCellBordersBelongToTheCellAboveAndRight) {
  EXPECT_EQ(kFrame.col(-0.5), 1);  // border of columns 0 and 1
  EXPECT_EQ(kFrame.col(0), 2);
  EXPECT_EQ(kFrame.col(0.5), 3);
  EXPECT_EQ(kFrame.row(-1.5), 1);
  EXPECT_EQ(kFrame.row(-1), 2);
  // The grid's far edges belong to the cells beyond it.
  EXPECT_EQ(kFrame.col(1), 4);
  EXPECT_EQ(kFrame.row(-0.5), 3);
  EXPECT_EQ(kFrame.index_of({1, -1}), std::nullopt);
  EXPECT_EQ(kFrame.index_of({0, -0.5}), std::nullopt);
}

TEST(GridFrame, DecidedByDivisionNotByTheInverse) {
  // 0.3 / 0.1 = 2.9999999999999996 but 0.3 * (1 / 0.1) = 3.0000000000000004: a point at
  // x = 0.3 on a 0.1 m grid from 0 lies in column 2, as (x - x0) / c says.
  const GridFrame f{{0, 0}, 0.1, 10, 10};
  EXPECT_EQ(f.col(0.3), 2);
  EXPECT_EQ(f.grid_x(0.3), 0.3 / 0.1);
}

TEST(GridFrame, IndexIsRowMajorFromTheBottom) {
  EXPECT_EQ(kFrame.index(0, 0), 0u);
  EXPECT_EQ(kFrame.index(3, 0), 3u);
  EXPECT_EQ(kFrame.index(0, 1), 4u);
  EXPECT_EQ(kFrame.index(3, 2), 11u);  // the last cell
  EXPECT_EQ(kFrame.index_of({-1, -2}), 0u);
  EXPECT_EQ(kFrame.index_of({0.99, -0.51}), 11u);
  EXPECT_EQ(kFrame.index_of({-0.5, -1.5}), 5u);  // a corner: column 1, row 1
}

TEST(GridFrame, PointsOutside) {
  for (Point p : {Point{-1.01, -1}, Point{1.5, -1}, Point{0, -2.2}, Point{0, 3}, Point{-100, -100}})
    EXPECT_EQ(kFrame.index_of(p), std::nullopt) << p.x << " " << p.y;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(kFrame.index_of({nan, -1}), std::nullopt);
  EXPECT_FALSE(kFrame.inside(-1, 0));
  EXPECT_FALSE(kFrame.inside(4, 0));
  EXPECT_FALSE(kFrame.inside(0, 3));
  EXPECT_TRUE(kFrame.inside(3, 2));
}

TEST(GridFrame, ClampToTheNearestCell) {
  EXPECT_EQ(kFrame.clamp_col(-50), 0);
  EXPECT_EQ(kFrame.clamp_col(50), 3);
  EXPECT_EQ(kFrame.clamp_col(1), 3);  // the far edge: the last column
  EXPECT_EQ(kFrame.clamp_row(-0.5), 2);
  EXPECT_EQ(kFrame.clamp_row(-1.2), 1);
  EXPECT_EQ(kFrame.clamp_row(-1e300), 0);
}

TEST(GridFrame, CentreAndRect) {
  EXPECT_EQ(kFrame.centre(0, 0), (Point{-0.75, -1.75}));
  EXPECT_EQ(kFrame.centre(3, 2), (Point{0.75, -0.75}));
  EXPECT_EQ(kFrame.centre(-1, 0), (Point{-1.25, -1.75}));  // outside the grid too
  EXPECT_EQ(kFrame.cell_rect(1, 2), (Rect{-0.5, -1, 0, -0.5}));
  // Neighbours share their edge bit for bit, even where c is not a power of two.
  const GridFrame f{{0.1, 0.7}, 0.3, 100, 100};
  for (int i = 0; i < 99; ++i) {
    EXPECT_EQ(f.cell_rect(i, 0).xmax, f.cell_rect(i + 1, 0).xmin) << i;
    EXPECT_EQ(f.cell_rect(0, i).ymax, f.cell_rect(0, i + 1).ymin) << i;
  }
}

TEST(GridFrame, CellsCoveringARect) {
  EXPECT_EQ(kFrame.cells_covering({-0.9, -1.9, -0.6, -1.6}), (CellRange{0, 0, 0, 0}));
  // Closed rectangles: an edge on a border takes the cell beyond it.
  EXPECT_EQ(kFrame.cells_covering({-0.5, -1.5, 0, -1}), (CellRange{1, 2, 1, 2}));
  // Clipped to the grid.
  EXPECT_EQ(kFrame.cells_covering({-10, -10, 10, 10}), (CellRange{0, 3, 0, 2}));
  EXPECT_EQ(kFrame.cells_covering({0.2, -3, 7, -1.7}), (CellRange{2, 3, 0, 0}));
  // Missing the grid, or inverted: empty.
  EXPECT_TRUE(kFrame.cells_covering({2, -1, 3, -0.8}).empty());
  EXPECT_TRUE(kFrame.cells_covering({-3, -1, -2, -0.8}).empty());
  EXPECT_TRUE(kFrame.cells_covering({-0.5, -1, -0.9, -0.8}).empty());
  EXPECT_TRUE(kFrame.cells_covering({-0.5, -1, 1, 5}).y1 == 2);
}

std::set<std::pair<int, int>> walk(const GridFrame& f, Point a, Point b, double grow) {
  std::set<std::pair<int, int>> out;
  f.for_cells_near_segment(a, b, grow, [&](int ix, int iy) {
    EXPECT_TRUE(f.inside(ix, iy)) << ix << " " << iy;
    EXPECT_TRUE(out.insert({ix, iy}).second) << "visited twice: " << ix << " " << iy;
    return true;
  });
  return out;
}

TEST(GridFrame, SegmentWalkVisitsTheCellsItCrosses) {
  const GridFrame f{{0, 0}, 1, 5, 5};
  // A horizontal segment inside row 2: columns 1..3.
  EXPECT_EQ(walk(f, {1.2, 2.5}, {3.7, 2.5}, 0), (std::set<std::pair<int, int>>{{1, 2}, {2, 2}, {3, 2}}));
  // A diagonal from (0.5, 0.5) to (2.5, 1.5): column 0 rows 0; column 1 rows 0..1; column 2 row 1.
  EXPECT_EQ(walk(f, {0.5, 0.5}, {2.5, 1.5}, 0),
            (std::set<std::pair<int, int>>{{0, 0}, {1, 0}, {1, 1}, {2, 1}}));
  // A point grown by 0.6 in the middle of cell (1, 1) reaches its eight neighbours.
  const auto grown = walk(f, {1.5, 1.5}, {1.5, 1.5}, 0.6);
  EXPECT_EQ(grown.size(), 9u);  // the 3 x 3 block around cell (1, 1)
  // Clipped at the grid: a segment running off the left edge.
  EXPECT_EQ(walk(f, {-3, 0.5}, {0.5, 0.5}, 0), (std::set<std::pair<int, int>>{{0, 0}}));
  EXPECT_TRUE(walk(f, {-3, 0.5}, {-1, 0.5}, 0).empty());
  EXPECT_TRUE(walk(f, {1, 7}, {2, 9}, 0).empty());
}

TEST(GridFrame, SegmentWalkCoversEveryCellNearTheSegment) {
  // Brute force: every cell whose square grown by `grow` meets the segment, found by
  // sampling the segment densely, must be visited.
  const GridFrame f{{-3.2, 1.1}, 0.7, 12, 9};
  const double grow = 0.05;
  const std::vector<std::pair<Point, Point>> segments{
      {{-3, 1.5}, {4.5, 6.9}}, {{4.9, 1.2}, {-2.9, 7.0}}, {{0.3, 1.1}, {0.3, 7.3}}, {{-3.2, 4.6}, {5.2, 4.6}}};
  for (const auto& [a, b] : segments) {
    const auto visited = walk(f, a, b, grow);
    for (int k = 0; k <= 10000; ++k) {
      const Point p = a + (k / 10000.0) * (b - a);
      for (double dx : {-grow, 0.0, grow})
        for (double dy : {-grow, 0.0, grow}) {
          const int64_t ix = f.col(p.x + dx * 0.99), iy = f.row(p.y + dy * 0.99);
          if (f.inside(ix, iy)) {
            EXPECT_TRUE(visited.count({int(ix), int(iy)})) << ix << " " << iy << " k=" << k;
          }
        }
    }
  }
}

TEST(GridFrame, SegmentWalkStopsWhenAsked) {
  const GridFrame f{{0, 0}, 1, 5, 5};
  int calls = 0;
  EXPECT_FALSE(f.for_cells_near_segment({0.5, 0.5}, {4.5, 0.5}, 0, [&](int, int) { return ++calls < 2; }));
  EXPECT_EQ(calls, 2);
  EXPECT_TRUE(f.for_cells_near_segment({0.5, 0.5}, {4.5, 0.5}, 0, [&](int, int) { return true; }));
}

}  // namespace
}  // namespace fleetmap
