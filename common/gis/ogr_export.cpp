#include "common/gis/ogr_export.h"

#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_vsi.h>
#include <gdal_priv.h>
#include <ogr_geometry.h>
#include <ogr_spatialref.h>
#include <ogrsf_frmts.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <functional>
#include <utility>

#include "common/core/error.h"
#include "common/gis/geo_transform.h"

namespace fleetmap {
namespace {

// GDAL reports through CPLError; the messages reach the caller in our exceptions.
struct QuietGdal {
  QuietGdal() { CPLPushErrorHandler(CPLQuietErrorHandler); }
  ~QuietGdal() { CPLPopErrorHandler(); }
  QuietGdal(const QuietGdal&) = delete;
  QuietGdal& operator=(const QuietGdal&) = delete;
};

std::string gdal_message() {
  const char* m = CPLGetLastErrorMsg();
  return m && *m ? m : "no message from GDAL";
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

using Fields = std::vector<std::pair<const char*, OGRFieldType>>;
using Geometry = std::unique_ptr<OGRGeometry>;

// The parts of a geometry that are polygons (MakeValid may give a collection with lines
// where a ring collapses).
void polygon_parts(const OGRGeometry& g, std::vector<Geometry>& out) {
  const OGRwkbGeometryType t = wkbFlatten(g.getGeometryType());
  if (t == wkbPolygon) {
    out.emplace_back(g.clone());
  } else if (t == wkbMultiPolygon || t == wkbGeometryCollection) {
    for (const OGRGeometry* part : *g.toGeometryCollection()) polygon_parts(*part, out);
  }
}

// "2026-12-02T00:36:02.123456Z" -> an OGR date-time in UTC (TZFlag 100); false when the
// text is not of that form.
bool parse_utc(const std::string& t, int& y, int& mo, int& d, int& h, int& mi, float& s) {
  double sec = 0;
  char zone = 0;
  int n = 0;
  if (std::sscanf(t.c_str(), "%4d-%2d-%2dT%2d:%2d:%lf%c%n", &y, &mo, &d, &h, &mi, &sec, &zone, &n) != 7) return false;
  s = static_cast<float>(sec);
  return zone == 'Z' && static_cast<size_t>(n) == t.size();
}

}  // namespace

ExportCrs parse_export_crs(const std::string& s) {
  if (s == "map") return ExportCrs::Map;
  if (s == "base") return ExportCrs::Base;
  if (s == "wgs84") return ExportCrs::Wgs84;
  throw BadInput("--crs: expected map, base or wgs84, got '" + s + "'");
}

std::string ogr_driver_for(const std::string& format) {
  GDALAllRegister();
  const std::string f = lower(format);
  const std::string name = f == "gpkg" ? "GPKG" : f == "fgb" ? "FlatGeobuf" : format;
  GDALDriver* drv = GetGDALDriverManager()->GetDriverByName(name.c_str());
  if (!drv) throw BadInput("--format: expected seed, geojson, svg, gpkg, fgb or a GDAL vector driver, got '" + format + "'");
  if (!CPLFetchBool(drv->GetMetadata(), GDAL_DCAP_VECTOR, false) ||
      !CPLFetchBool(drv->GetMetadata(), GDAL_DCAP_CREATE, false))
    throw BadInput("--format: GDAL driver '" + std::string(drv->GetDescription()) + "' cannot create vector files");
  return drv->GetDescription();
}

struct OgrExport::Impl {
  OgrExportOptions opt;
  std::string path, driver;
  GDALDataset* ds = nullptr;
  OGRSpatialReference srs;
  std::optional<GeoTransform> geo;

  ~Impl() {
    if (ds) {
      QuietGdal quiet;
      GDALClose(ds);
    }
  }

  Point out(Point map) const {
    switch (opt.crs) {
      case ExportCrs::Map: return map;
      case ExportCrs::Base: return geo->map_to_base(map);
      case ExportCrs::Wgs84: {
        const LonLat ll = geo->to_wgs84(map);
        return {ll.lon, ll.lat};
      }
    }
    return map;
  }

  std::unique_ptr<OGRLineString> line(const std::vector<Point>& pts) const {
    auto l = std::make_unique<OGRLineString>();
    for (Point p : pts) {
      const Point q = out(p);
      l->addPoint(q.x, q.y);
    }
    return l;
  }

  std::unique_ptr<OGRPolygon> polygon(const std::vector<Point>& ring) const {
    auto r = std::make_unique<OGRLinearRing>();
    for (Point p : ring) {
      const Point q = out(p);
      r->addPoint(q.x, q.y);
    }
    auto poly = std::make_unique<OGRPolygon>();
    poly->addRingDirectly(r.release());
    poly->closeRings();
    return poly;
  }

  // A layer of the export, created with its first feature.
  class Layer {
   public:
    Layer(Impl& impl, std::vector<OgrLayerReport>& reports, const char* name, OGRwkbGeometryType type, Fields fields)
        : impl_(impl), reports_(reports), name_(name), type_(type), fields_(std::move(fields)) {}

    bool wanted() const { return impl_.opt.only_layers.empty() || impl_.opt.only_layers.count(name_); }

    // set fills the fields; the FID and "id" are the layer's running number from 1.
    void add(Geometry g, const std::function<void(OGRFeature&)>& set) {
      if (!wanted()) return;
      if (!layer_) create();
      OGRFeature f(layer_->GetLayerDefn());
      const GIntBig id = static_cast<GIntBig>(++report().features);
      f.SetFID(id);
      f.SetField("id", id);
      if (set) set(f);
      f.SetGeometryDirectly(g.release());
      if (layer_->CreateFeature(&f) != OGRERR_NONE)
        throw IoError(impl_.path + ": layer " + name_ + " feature " + std::to_string(id) + ": " + gdal_message());
    }

    // A polygon, valid as written: repaired by MakeValid when GEOS finds it invalid, one
    // feature per polygon part.
    void add_polygon(std::unique_ptr<OGRPolygon> p, const std::function<void(OGRFeature&)>& set) {
      if (!wanted()) return;
      if (p->IsValid()) return add(std::move(p), set);
      std::unique_ptr<OGRGeometry> fixed(p->MakeValid());
      if (!fixed) throw IoError(impl_.path + ": layer " + name_ + ": GEOS could not repair a polygon: " + gdal_message());
      std::vector<Geometry> parts;
      polygon_parts(*fixed, parts);
      if (!layer_) create();
      ++report().repaired;
      for (Geometry& part : parts) add(std::move(part), set);
    }

   private:
    OgrLayerReport& report() { return reports_[index_]; }

    void create() {
      char** options = nullptr;
      if (impl_.driver == "GPKG") options = CSLSetNameValue(options, "FID", "fid");
      layer_ = impl_.ds->CreateLayer(name_.c_str(), &impl_.srs, type_, options);
      CSLDestroy(options);
      if (!layer_)
        throw BadInput(impl_.path + ": GDAL driver " + impl_.driver + " cannot create layer '" + name_ +
                       "' (" + gdal_message() + "); a driver with one layer per file needs --layer NAME");
      std::vector<std::pair<const char*, OGRFieldType>> all{{"id", OFTInteger64}};
      all.insert(all.end(), fields_.begin(), fields_.end());
      for (auto [fname, ftype] : all) {
        OGRFieldDefn d(fname, ftype == OFTIntegerList ? OFTInteger : ftype);  // OFTIntegerList: a boolean here
        if (ftype == OFTIntegerList) d.SetSubType(OFSTBoolean);
        if (layer_->CreateField(&d) != OGRERR_NONE)
          throw IoError(impl_.path + ": layer " + name_ + " field " + fname + ": " + gdal_message());
      }
      index_ = reports_.size();
      reports_.push_back({name_, 0, 0});
    }

    Impl& impl_;
    std::vector<OgrLayerReport>& reports_;
    std::string name_;
    OGRwkbGeometryType type_;
    Fields fields_;
    OGRLayer* layer_ = nullptr;
    size_t index_ = 0;
  };
};

namespace {
// Field type of a boolean in a Fields list (an OFTInteger of subtype OFSTBoolean).
constexpr OGRFieldType kBool = OFTIntegerList;
}  // namespace

OgrExport::OgrExport(const std::string& path, const OgrExportOptions& options) : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.opt = options;
  m.path = path;
  m.driver = ogr_driver_for(options.format);
  if (options.crs != ExportCrs::Map && !options.georef)
    throw BadInput("map '" + options.map_name + "' has no georeference: --crs " +
                   (options.crs == ExportCrs::Base ? "base" : "wgs84") +
                   " needs one (fleetmap map georef), --crs map writes the map frame");
  if (options.georef) m.geo.emplace(*options.georef);  // throws BadInput when PROJ cannot use it

  QuietGdal quiet;
  m.srs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);  // x = east / longitude, as we write
  OGRErr e = OGRERR_NONE;
  if (options.crs == ExportCrs::Wgs84) {
    e = m.srs.importFromEPSG(4326);
  } else if (options.crs == ExportCrs::Base || options.georef->frame_is_crs()) {
    e = m.srs.SetFromUserInput(options.georef->crs.c_str());
  } else {
    // A frame placed in its base by a rotation, an offset or a scale, or placed nowhere:
    // an engineering CRS in metres, which GIS tools show as is and never reproject.
    e = m.srs.SetLocalCS(("fleetmap map " + options.map_name).c_str());
    if (e == OGRERR_NONE) e = m.srs.SetLinearUnits(SRS_UL_METER, 1.0);
  }
  if (e != OGRERR_NONE) throw BadInput("CRS of map '" + options.map_name + "': GDAL cannot read it: " + gdal_message());

  GDALDriver* drv = GetGDALDriverManager()->GetDriverByName(m.driver.c_str());
  VSIStatBufL st;
  if (VSIStatL(path.c_str(), &st) == 0 && drv->Delete(path.c_str()) != CE_None && VSIUnlink(path.c_str()) != 0)
    throw IoError(path + ": cannot replace the existing file: " + gdal_message());
  m.ds = drv->Create(path.c_str(), 0, 0, 0, GDT_Unknown, nullptr);
  if (!m.ds) throw IoError(path + ": GDAL driver " + m.driver + " cannot create it: " + gdal_message());
}

OgrExport::~OgrExport() = default;

std::string OgrExport::crs_wkt() const {
  char* wkt = nullptr;
  impl_->srs.exportToWkt(&wkt);
  std::string s = wkt ? wkt : "";
  CPLFree(wkt);
  return s;
}

void OgrExport::close() {
  QuietGdal quiet;
  if (!impl_->ds) return;
  CPLErrorReset();
  GDALClose(impl_->ds);
  impl_->ds = nullptr;
  if (CPLGetLastErrorType() >= CE_Failure) throw IoError(impl_->path + ": " + gdal_message());
}

void OgrExport::add_map(const Map& map) {
  QuietGdal quiet;
  Impl& m = *impl_;
  const Border& b = map.border;
  Impl::Layer border(m, reports_, "border", wkbPolygon, {});
  border.add_polygon(m.polygon({{b.mx1, b.my4}, {b.mx4, b.my4}, {b.mx4, b.my1}, {b.mx1, b.my1}}), nullptr);

  Impl::Layer segments(m, reports_, "segments", wkbLineString,
                       {{"obstacle_id", OFTInteger}, {"st", OFTInteger}, {"shape", OFTString},
                        {"obstacle_semantic", OFTString}, {"segment", OFTInteger}, {"h", OFTReal},
                        {"in_out", OFTInteger}, {"semantic", OFTString}, {"note", OFTString}});
  const Fields obstacle_fields{{"obstacle_id", OFTInteger}, {"st", OFTInteger}, {"shape", OFTString},
                               {"semantic", OFTString},     {"segments", OFTInteger}, {"h_min", OFTReal},
                               {"h_max", OFTReal}};
  Impl::Layer closed(m, reports_, "obstacles", wkbPolygon, obstacle_fields);
  Impl::Layer open(m, reports_, "open_obstacles", wkbLineString, obstacle_fields);
  for (const Obstacle& o : map.obstacles) {
    const std::string shape(to_string(o.type));
    double h_min = INFINITY, h_max = -INFINITY;
    for (size_t i = 0; i < o.segments.size(); ++i) {
      const Segment& s = o.segments[i];
      h_min = std::min(h_min, s.h);
      h_max = std::max(h_max, s.h);
      segments.add(m.line({s.a, s.b}), [&](OGRFeature& f) {
        f.SetField("obstacle_id", o.id);
        f.SetField("st", static_cast<int>(o.type));
        f.SetField("shape", shape.c_str());
        f.SetField("obstacle_semantic", o.semantic.c_str());
        f.SetField("segment", static_cast<int>(i + 1));
        f.SetField("h", s.h);
        f.SetField("in_out", s.in_out);
        f.SetField("semantic", s.semantic.c_str());
        if (!s.note.empty()) f.SetField("note", s.note.c_str());
      });
    }
    if (o.segments.empty()) continue;
    const auto set = [&](OGRFeature& f) {
      f.SetField("obstacle_id", o.id);
      f.SetField("st", static_cast<int>(o.type));
      f.SetField("shape", shape.c_str());
      f.SetField("semantic", o.semantic.c_str());
      f.SetField("segments", static_cast<int>(o.segments.size()));
      f.SetField("h_min", h_min);
      f.SetField("h_max", h_max);
    };
    if (is_closed(o.type)) {
      std::vector<Point> ring;
      for (const Segment& s : o.segments) ring.push_back(s.a);
      closed.add_polygon(m.polygon(ring), set);
    } else {
      // One line per chain of consecutive segments (b of one = a of the next).
      std::vector<Point> chain{o.segments[0].a};
      for (size_t i = 0; i < o.segments.size(); ++i) {
        if (i > 0 && !(o.segments[i].a == o.segments[i - 1].b)) {
          open.add(m.line(chain), set);
          chain = {o.segments[i].a};
        }
        chain.push_back(o.segments[i].b);
      }
      open.add(m.line(chain), set);
    }
  }
}

void OgrExport::add_scene(const Scene& scene) {
  QuietGdal quiet;
  Impl& m = *impl_;
  Impl::Layer objects(m, reports_, "objects", wkbMultiPolygon,
                      {{"object_id", OFTString}, {"tag", OFTString}, {"dynamic", kBool}, {"elements", OFTInteger},
                       {"zmin", OFTReal}, {"zmax", OFTReal}});
  Impl::Layer elements(m, reports_, "object_elements", wkbPolygon,
                       {{"object_id", OFTString}, {"tag", OFTString}, {"element", OFTInteger}, {"zmin", OFTReal},
                        {"zmax", OFTReal}});
  for (const EnvObject& o : scene.objects) {
    // The footprint of the object: the union of its elements (seed 004: a table's legs
    // and top overlap seen from above), valid where the elements as a MultiPolygon are not.
    Geometry all;
    std::optional<double> zmin, zmax;
    bool flat = false;  // an element without a range blocks at every height
    for (size_t i = 0; i < o.elements.size(); ++i) {
      const Element& e = o.elements[i];
      std::unique_ptr<OGRPolygon> p = m.polygon(e.footprint);
      Geometry valid(p->IsValid() ? p->clone() : p->MakeValid());
      elements.add_polygon(std::move(p), [&](OGRFeature& f) {
        f.SetField("object_id", o.id.c_str());
        f.SetField("tag", o.tag.c_str());
        f.SetField("element", static_cast<int>(i + 1));
        if (e.z) {
          f.SetField("zmin", e.z->zmin);
          f.SetField("zmax", e.z->zmax);
        }
      });
      if (!valid) continue;
      all = all ? Geometry(all->Union(valid.get())) : std::move(valid);
      if (!all) throw IoError(m.path + ": object " + o.id + ": GEOS could not unite its elements: " + gdal_message());
      if (e.z) {
        zmin = std::min(zmin.value_or(e.z->zmin), e.z->zmin);
        zmax = std::max(zmax.value_or(e.z->zmax), e.z->zmax);
      } else {
        flat = true;
      }
    }
    if (!all) continue;
    std::vector<Geometry> parts;
    polygon_parts(*all, parts);
    auto multi = std::make_unique<OGRMultiPolygon>();
    for (Geometry& part : parts) multi->addGeometryDirectly(part.release());
    objects.add(std::move(multi), [&](OGRFeature& f) {
      f.SetField("object_id", o.id.c_str());
      f.SetField("tag", o.tag.c_str());
      f.SetField("dynamic", o.dynamic ? 1 : 0);
      f.SetField("elements", static_cast<int>(o.elements.size()));
      if (zmin && !flat) {
        f.SetField("zmin", *zmin);
        f.SetField("zmax", *zmax);
      }
    });
  }
  Impl::Layer avoided(m, reports_, "avoided_areas", wkbPolygon, {{"area_id", OFTString}});
  for (const AvoidedArea& a : scene.avoided)
    avoided.add_polygon(m.polygon(a.area), [&](OGRFeature& f) { f.SetField("area_id", a.id.c_str()); });
  Impl::Layer bounds(m, reports_, "bounds", wkbPolygon, {});
  if (scene.bounds) bounds.add_polygon(m.polygon(*scene.bounds), nullptr);
}

void OgrExport::add_topology(const TopoGraph& g) {
  QuietGdal quiet;
  Impl& m = *impl_;
  Impl::Layer nodes(m, reports_, "topo_nodes", wkbPoint, {{"node_id", OFTInteger}, {"name", OFTString}});
  for (const TopoNode& n : g.nodes()) {
    const Point q = m.out(n.pos);
    nodes.add(std::make_unique<OGRPoint>(q.x, q.y), [&](OGRFeature& f) {
      f.SetField("node_id", n.id);
      if (!n.name.empty()) f.SetField("name", n.name.c_str());
    });
  }
  Impl::Layer edges(m, reports_, "topo_edges", wkbLineString,
                    {{"edge", OFTInteger}, {"s0_id", OFTInteger}, {"s1_id", OFTInteger}, {"type", OFTString},
                     {"has_door", kBool}, {"has_automated_door", kBool}, {"length", OFTReal},
                     {"max_clearance", OFTReal}, {"max_speed", OFTReal}});
  for (size_t k = 0; k < g.edges().size(); ++k) {
    const TopoEdge& e = g.edges()[k];
    edges.add(m.line({g.node(e.a).pos, g.node(e.b).pos}), [&](OGRFeature& f) {
      f.SetField("edge", static_cast<int>(k));
      f.SetField("s0_id", e.a);
      f.SetField("s1_id", e.b);
      f.SetField("type", std::string(to_string(e.type)).c_str());
      f.SetField("has_door", e.door ? 1 : 0);
      f.SetField("has_automated_door", e.automated_door ? 1 : 0);
      f.SetField("length", g.length(k));
      if (std::isfinite(e.max_clearance)) f.SetField("max_clearance", e.max_clearance);  // none: NULL
      if (std::isfinite(e.max_speed)) f.SetField("max_speed", e.max_speed);
    });
  }
}

void OgrExport::add_tracks(const std::vector<Track>& tracks) {
  QuietGdal quiet;
  Impl& m = *impl_;
  Impl::Layer points(m, reports_, "trajectory_points", wkbPoint,
                     {{"robot", OFTString}, {"t", OFTDateTime}, {"theta", OFTReal}, {"v", OFTReal}});
  for (const Track& tr : tracks) {
    for (const TrackPose& p : tr.poses) {
      int y = 0, mo = 0, d = 0, h = 0, mi = 0;
      float s = 0;
      if (!parse_utc(p.t, y, mo, d, h, mi, s))
        throw BadInput("robot " + tr.robot + ": expected a UTC time like 2026-12-02T00:36:02.5Z, got '" + p.t + "'");
      const Point q = m.out(p.pos);
      points.add(std::make_unique<OGRPoint>(q.x, q.y), [&](OGRFeature& f) {
        f.SetField("robot", tr.robot.c_str());
        f.SetField(f.GetFieldIndex("t"), y, mo, d, h, mi, s, 100);  // 100: UTC
        f.SetField("theta", p.theta);
        f.SetField("v", p.v);
      });
    }
  }
  Impl::Layer lines(m, reports_, "trajectories", wkbLineString,
                    {{"robot", OFTString}, {"t_start", OFTString}, {"t_end", OFTString}, {"poses", OFTInteger}});
  for (const Track& tr : tracks) {
    if (tr.poses.size() < 2) continue;  // a LineString needs two points
    std::vector<Point> pts;
    for (const TrackPose& p : tr.poses) pts.push_back(p.pos);
    lines.add(m.line(pts), [&](OGRFeature& f) {
      f.SetField("robot", tr.robot.c_str());
      f.SetField("t_start", tr.poses.front().t.c_str());
      f.SetField("t_end", tr.poses.back().t.c_str());
      f.SetField("poses", static_cast<int>(tr.poses.size()));
    });
  }
}

}  // namespace fleetmap
