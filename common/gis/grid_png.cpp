#include "common/gis/grid_png.h"

#include <cpl_error.h>
#include <gdal_priv.h>

#include <filesystem>
#include <fstream>

#include "common/core/error.h"
#include "common/geometry/number_format.h"

namespace fleetmap {
namespace {

std::string gdal_message() {
  const char* m = CPLGetLastErrorMsg();
  return m && *m ? m : "no message from GDAL";
}

}  // namespace

std::string world_file_path(const std::string& png_path) {
  std::filesystem::path p(png_path);
  return p.replace_extension(".pgw").string();
}

std::string grid_world_file(const OccupancyGrid& g) {
  // Row 0 of the image is the top (max y) line: the upper-left pixel's centre is half a
  // cell in from the grid's upper-left corner, and y decreases down the image.
  const double r = g.resolution;
  return format_number(r) + "\n0\n0\n" + format_number(-r) + "\n" + format_number(g.origin.x + r / 2) + "\n" +
         format_number(g.origin.y + g.height * r - r / 2) + "\n";
}

uintmax_t write_grid_png(const OccupancyGrid& g, const std::string& path, const std::string& crs_wkt) {
  GDALAllRegister();
  CPLPushErrorHandler(CPLQuietErrorHandler);
  struct Pop {
    ~Pop() { CPLPopErrorHandler(); }
  } pop;
  GDALDriver* mem = GetGDALDriverManager()->GetDriverByName("MEM");
  GDALDriver* png = GetGDALDriverManager()->GetDriverByName("PNG");
  if (!mem || !png) throw IoError(path + ": GDAL has no MEM or PNG driver");
  std::string pixels = pgm_raster(g);
  GDALDataset* ds = mem->Create("", g.width, g.height, 1, GDT_Byte, nullptr);
  if (!ds) throw IoError(path + ": GDAL cannot hold a " + std::to_string(g.width) + " x " +
                         std::to_string(g.height) + " image: " + gdal_message());
  const CPLErr e = ds->GetRasterBand(1)->RasterIO(GF_Write, 0, 0, g.width, g.height, pixels.data(), g.width,
                                                  g.height, GDT_Byte, 0, 0, nullptr);
  if (e == CE_None && !crs_wkt.empty()) ds->SetProjection(crs_wkt.c_str());
  GDALDataset* out = e == CE_None ? png->CreateCopy(path.c_str(), ds, FALSE, nullptr, nullptr, nullptr) : nullptr;
  GDALClose(ds);
  if (!out) throw IoError(path + ": GDAL's PNG driver cannot write it: " + gdal_message());
  GDALClose(out);
  const std::string world = world_file_path(path);
  std::ofstream w(world, std::ios::binary);
  w << grid_world_file(g);
  if (!w.flush()) throw IoError(world + ": cannot write the world file");
  return std::filesystem::file_size(path);
}

}  // namespace fleetmap
