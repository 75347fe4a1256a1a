// common/gis/grid_png: the PNG read back by GDAL has the PGM's pixels, and GDAL's
// reading of the world file places it where the Nav2 YAML says.
#include "common/gis/grid_png.h"

#include <gtest/gtest.h>

#include "common/gis/geo_transform.h"
#include "tests/common/gis/ogr_test_util.h"

namespace fleetmap {
namespace {

OccupancyGrid sample_grid() {
  OccupancyGrid g = make_grid({-2.5, 1.25, 1.0, 3.0}, 0.25);
  draw_segment(g, {-2.4, 1.3}, {0.9, 2.9});
  g.set(0, g.height - 1, OccupancyGrid::kUnknown);
  return g;
}

TEST(GridPng, SamePixelsAsThePgmAndPlacedByItsWorldFile) {
  const OccupancyGrid g = sample_grid();
  const std::string path = test::scratch("grid.png");
  write_grid_png(g, path);
  GDALAllRegister();
  test::Dataset ds(static_cast<GDALDataset*>(GDALOpen(path.c_str(), GA_ReadOnly)));
  ASSERT_TRUE(ds);
  ASSERT_EQ(ds->GetRasterXSize(), g.width);
  ASSERT_EQ(ds->GetRasterYSize(), g.height);
  std::string pixels(static_cast<size_t>(g.width) * g.height, '\0');
  ASSERT_EQ(ds->GetRasterBand(1)->RasterIO(GF_Read, 0, 0, g.width, g.height, pixels.data(), g.width, g.height,
                                           GDT_Byte, 0, 0, nullptr),
            CE_None);
  // The PGM's raster: after its three header lines.
  const std::string pgm = write_pgm(g);
  size_t at = 0;
  for (int i = 0; i < 3; ++i) at = pgm.find('\n', at) + 1;
  EXPECT_EQ(pixels, pgm.substr(at));
  // The cell (0, height - 1), unknown, is the image's top-left pixel: grey 205.
  EXPECT_EQ(static_cast<unsigned char>(pixels[0]), 205);
  double gt[6];
  ASSERT_EQ(ds->GetGeoTransform(gt), CE_None);  // GDAL reads grid.pgw
  EXPECT_DOUBLE_EQ(gt[0], g.origin.x);
  EXPECT_DOUBLE_EQ(gt[1], g.resolution);
  EXPECT_DOUBLE_EQ(gt[2], 0);
  EXPECT_DOUBLE_EQ(gt[3], g.origin.y + g.height * g.resolution);
  EXPECT_DOUBLE_EQ(gt[5], -g.resolution);
  EXPECT_EQ(ds->GetSpatialRef(), nullptr);
}

TEST(GridPng, CarriesTheCrsWhenGiven) {
  MapGeoref geo;
  geo.crs = "EPSG:26910";
  const std::string path = test::scratch("grid_utm.png");
  write_grid_png(sample_grid(), path, GeoTransform(geo).base_wkt());
  test::Dataset ds(static_cast<GDALDataset*>(GDALOpen(path.c_str(), GA_ReadOnly)));
  ASSERT_TRUE(ds);
  OGRSpatialReference utm;
  utm.importFromEPSG(26910);
  ASSERT_NE(ds->GetSpatialRef(), nullptr);
  EXPECT_TRUE(ds->GetSpatialRef()->IsSame(&utm));
}

}  // namespace
}  // namespace fleetmap
