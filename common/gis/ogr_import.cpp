#include "common/gis/ogr_import.h"

#include <cpl_error.h>
#include <ogr_spatialref.h>
#include <ogrsf_frmts.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "common/core/error.h"
#include "common/gis/feature_attributes.h"
#include "common/gis/gis_obstacles.h"
#include "common/gis/map_frame_crs.h"
#include "common/gis/ogr_source.h"
#include "common/map/map_validation.h"
#include "common/scene/scene_validation.h"

namespace fleetmap {
namespace {

enum class Kind { Point, Line, Polygon, Other };

Kind kind_of(OGRwkbGeometryType t) {
  switch (wkbFlatten(t)) {
    case wkbPoint:
    case wkbMultiPoint: return Kind::Point;
    case wkbLineString:
    case wkbMultiLineString:
    case wkbCircularString:
    case wkbCompoundCurve:
    case wkbMultiCurve: return Kind::Line;
    case wkbPolygon:
    case wkbMultiPolygon:
    case wkbCurvePolygon:
    case wkbMultiSurface: return Kind::Polygon;
    default: return Kind::Other;
  }
}

const char* kind_name(Kind k) {
  switch (k) {
    case Kind::Point: return "point";
    case Kind::Line: return "line";
    case Kind::Polygon: return "polygon";
    default: return "other";
  }
}

// A feature the rules keep, its geometry still in the source CRS.
struct Kept {
  std::string layer;
  long long fid = 0;
  const FeatureRule* rule = nullptr;
  std::string value;  // the matched attribute's value
  std::unique_ptr<OGRGeometry> geom;
  const OGRSpatialReference* srs = nullptr;  // owned by the layer or by options
  std::string semantic;
  double h = 0;
  bool down = false;  // OSM incline=down: the line runs down the stairs
  double width = 0;
};

const FeatureRule* match(const ImportRules& rules, const std::string& layer, Kind kind, const OGRFeature& f,
                         std::string& value) {
  for (const FeatureRule& r : rules.rules) {
    if (!r.layer.empty() && r.layer != layer) continue;
    if (!r.geometry.empty() && r.geometry != kind_name(kind)) continue;
    if (r.key.empty()) {
      value.clear();
      return &r;
    }
    const std::string v = feature_attribute(f, r.key);
    if (v.empty() || v == "no") continue;
    if (!r.values.empty() && std::find(r.values.begin(), r.values.end(), v) == r.values.end()) continue;
    value = v;
    return &r;
  }
  return nullptr;
}

double height_of(const HeightRule& h, const OGRFeature& f) {
  if (auto v = parse_length(feature_attribute(f, h.attribute))) return std::min(*v, kMaxHeight);
  if (auto n = parse_length(feature_attribute(f, h.levels_attribute))) return std::min(*n * h.level_height, kMaxHeight);
  return h.default_height;
}

// GEOS says why a geometry is invalid through GDAL's error handler.
std::string invalid_reason(const OGRGeometry& g) {
  std::string why;
  CPLPushErrorHandlerEx(
      [](CPLErr, CPLErrorNum, const char* msg) {
        auto* w = static_cast<std::string*>(CPLGetErrorHandlerUserData());
        if (w->empty()) *w = msg;
      },
      &why);
  const bool ok = g.IsValid();
  CPLPopErrorHandler();
  if (ok) return {};
  return why.empty() ? "not a valid geometry (OGC simple features)" : why;
}

// Parts of one kind from a (repaired) geometry: a MakeValid result can be a collection.
std::unique_ptr<OGRGeometry> keep_kind(std::unique_ptr<OGRGeometry> g, Kind kind) {
  if (kind_of(g->getGeometryType()) == kind) return g;
  if (wkbFlatten(g->getGeometryType()) != wkbGeometryCollection) return nullptr;
  auto* coll = g->toGeometryCollection();
  std::unique_ptr<OGRGeometryCollection> out;
  if (kind == Kind::Polygon) out = std::make_unique<OGRMultiPolygon>();
  else if (kind == Kind::Line) out = std::make_unique<OGRMultiLineString>();
  else out = std::make_unique<OGRMultiPoint>();
  for (const OGRGeometry* part : *coll) {
    if (kind_of(part->getGeometryType()) != kind) continue;
    if (wkbFlatten(part->getGeometryType()) == wkbMultiPolygon || wkbFlatten(part->getGeometryType()) == wkbMultiLineString ||
        wkbFlatten(part->getGeometryType()) == wkbMultiPoint) {
      for (const OGRGeometry* p : *part->toGeometryCollection()) out->addGeometry(p);
    } else {
      out->addGeometry(part);
    }
  }
  if (out->IsEmpty()) return nullptr;
  return out;
}

Chain chain_of(const OGRLineString& ls) {
  Chain c;
  c.reserve(ls.getNumPoints());
  for (int i = 0; i < ls.getNumPoints(); ++i) c.push_back({ls.getX(i), ls.getY(i)});
  return c;
}

// Every polygon, line or point of a linear geometry.
void for_each_polygon(const OGRGeometry& g, const std::function<void(const OGRPolygon&)>& fn) {
  if (wkbFlatten(g.getGeometryType()) == wkbPolygon) fn(*g.toPolygon());
  else if (OGR_GT_IsSubClassOf(g.getGeometryType(), wkbGeometryCollection))
    for (const OGRGeometry* p : *g.toGeometryCollection()) for_each_polygon(*p, fn);
}
void for_each_line(const OGRGeometry& g, const std::function<void(const OGRLineString&)>& fn) {
  if (wkbFlatten(g.getGeometryType()) == wkbLineString) fn(*g.toLineString());
  else if (wkbFlatten(g.getGeometryType()) == wkbPolygon)
    for (const OGRLinearRing* r : *g.toPolygon()) fn(*r);
  else if (OGR_GT_IsSubClassOf(g.getGeometryType(), wkbGeometryCollection))
    for (const OGRGeometry* p : *g.toGeometryCollection()) for_each_line(*p, fn);
}
void for_each_point(const OGRGeometry& g, const std::function<void(Point)>& fn) {
  if (wkbFlatten(g.getGeometryType()) == wkbPoint) fn({g.toPoint()->getX(), g.toPoint()->getY()});
  else if (OGR_GT_IsSubClassOf(g.getGeometryType(), wkbGeometryCollection))
    for (const OGRGeometry* p : *g.toGeometryCollection()) for_each_point(*p, fn);
}

std::string wkt2(const OGRSpatialReference& srs) {
  char* wkt = nullptr;
  const char* const options[] = {"FORMAT=WKT2_2019", nullptr};
  srs.exportToWkt(&wkt, options);
  std::string s = wkt ? wkt : "";
  CPLFree(wkt);
  return s;
}

std::string crs_name(const OGRSpatialReference& srs) {
  const char* auth = srs.GetAuthorityName(nullptr);
  const char* code = srs.GetAuthorityCode(nullptr);
  if (auth && code) return std::string(auth) + ":" + code;
  // WKT1 first (what GDAL tools print); a derived projected CRS (a georeferenced map
  // frame as fleetmap's GIS layers publish it, docs/gis-layers.md) exists only in WKT2.
  char* wkt = nullptr;
  CPLPushErrorHandler(CPLQuietErrorHandler);
  srs.exportToWkt(&wkt);
  CPLPopErrorHandler();
  std::string s = wkt ? wkt : "";
  CPLFree(wkt);
  return s.empty() ? wkt2(srs) : s;
}

OGRSpatialReference srs_from(const std::string& def, const std::string& what) {
  OGRSpatialReference srs;
  if (srs.SetFromUserInput(def.c_str()) != OGRERR_NONE)
    throw BadInput(what + ": expected a CRS PROJ or GDAL can read (EPSG:xxxx, WKT, PROJ string), got '" + def + "'");
  srs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  return srs;
}

std::unique_ptr<OGRCoordinateTransformation> transformation(const OGRSpatialReference& from,
                                                            const OGRSpatialReference& to) {
  std::unique_ptr<OGRCoordinateTransformation> ct(OGRCreateCoordinateTransformation(&from, &to));
  if (!ct) throw BadInput("no coordinate operation from " + crs_name(from) + " to " + crs_name(to) + ": " +
                          CPLGetLastErrorMsg());
  return ct;
}

// A square footprint, counter-clockwise.
Polygon square(Point c, double side) {
  const double h = side / 2;
  return {{c.x - h, c.y - h}, {c.x + h, c.y - h}, {c.x + h, c.y + h}, {c.x - h, c.y + h}};
}

// GDAL's warnings (a DXF block it cannot find, a date it half parses) go into the report
// instead of stderr, the first few verbatim; errors still reach CPLGetLastErrorMsg.
class GdalWarnings {
 public:
  explicit GdalWarnings(OgrImportReport& rep) : rep_(rep) { CPLPushErrorHandlerEx(handler, this); }
  ~GdalWarnings() {
    CPLPopErrorHandler();
    if (count_ > kKept) rep_.warnings.push_back("GDAL: " + std::to_string(count_ - kKept) + " more warnings");
  }
  GdalWarnings(const GdalWarnings&) = delete;
  GdalWarnings& operator=(const GdalWarnings&) = delete;

 private:
  static constexpr size_t kKept = 5;
  static void handler(CPLErr level, CPLErrorNum num, const char* msg) {
    auto* self = static_cast<GdalWarnings*>(CPLGetErrorHandlerUserData());
    if (level == CE_Debug) return;
    if (level == CE_Warning) {
      if (self->count_++ < kKept) self->rep_.warnings.push_back(std::string("GDAL: ") + msg);
      return;
    }
    CPLDefaultErrorHandler(level, num, msg);
  }
  OgrImportReport& rep_;
  size_t count_ = 0;
};

std::string where(const Kept& k) { return "layer '" + k.layer + "' feature " + std::to_string(k.fid); }

}  // namespace

bool is_ogr_source(const std::string& source) {
  if (source.rfind("PG:", 0) == 0 || source.rfind("MYSQL:", 0) == 0) return true;
  for (const char* ext : {".osm", ".pbf", ".gpkg", ".geojson", ".shp", ".dxf", ".gml", ".kml", ".fgb", ".gpx",
                          ".sqlite", ".geojsonl"})
    if (ends_with_ci(source, ext)) return true;
  return false;
}

OgrImport import_ogr(const std::string& source, const OgrImportOptions& opt) {
  const bool osm_name = ends_with_ci(source, ".osm") || ends_with_ci(source, ".pbf");
  const ImportRules rules = opt.rules ? *opt.rules : (osm_name ? osm_default_rules() : plain_default_rules());
  OgrImport out;
  OgrImportReport& rep = out.report;
  GdalWarnings warnings(rep);
  GDALDatasetUniquePtr ds = open_ogr_source(source, rule_keys(rules));
  rep.driver = ds->GetDriver() ? ds->GetDriver()->GetDescription() : "";
  const bool osm = rep.driver == "OSM";

  std::vector<std::string> layers = opt.layers.empty() ? rules.layers : opt.layers;
  for (const std::string& l : layers)
    if (!ds->GetLayerByName(l.c_str())) {
      std::string names;
      for (auto* lay : ds->GetLayers()) names += (names.empty() ? "" : ", ") + std::string(lay->GetName());
      throw BadInput(source + ": expected a layer among " + names + ", got '" + l + "'");
    }
  auto selected = [&](const std::string& name) {
    return layers.empty() || std::find(layers.begin(), layers.end(), name) != layers.end();
  };

  std::optional<OGRSpatialReference> given_srs;
  if (!opt.crs.empty()) given_srs = srs_from(opt.crs, "--crs");
  OGRSpatialReference wgs84 = srs_from("EPSG:4326", "WGS 84");

  // The clip area, in WGS 84, and per source CRS.
  std::optional<Clip> clip = opt.clip;
  if (!clip && osm && opt.clip_to_osm_bounds && ds->GetLayerCount() > 0) {
    OGREnvelope env;
    // GDAL's OSM driver answers a layer's extent with the file's <bounds>.
    if (ds->GetLayer(0)->GetExtent(&env, FALSE) == OGRERR_NONE) clip = Clip{env.MinX, env.MinY, env.MaxX, env.MaxY};
  }
  std::map<const OGRSpatialReference*, std::unique_ptr<OGRGeometry>> clip_in;
  auto clip_for = [&](const OGRSpatialReference* srs) -> const OGRGeometry* {
    auto& g = clip_in[srs];
    if (!g) {
      OGRLinearRing ring;
      ring.addPoint(clip->minlon, clip->minlat);
      ring.addPoint(clip->maxlon, clip->minlat);
      ring.addPoint(clip->maxlon, clip->maxlat);
      ring.addPoint(clip->minlon, clip->maxlat);
      ring.addPoint(clip->minlon, clip->minlat);
      auto poly = std::make_unique<OGRPolygon>();
      poly->addRing(&ring);
      if (srs && !srs->IsSame(&wgs84)) {
        poly->segmentize(std::max(clip->maxlon - clip->minlon, clip->maxlat - clip->minlat) / 64);
        poly->assignSpatialReference(&wgs84);
        if (poly->transformTo(const_cast<OGRSpatialReference*>(srs)) != OGRERR_NONE)
          throw BadInput("--clip: cannot transform the clip area into " + crs_name(*srs));
      }
      g = std::move(poly);
    }
    return g.get();
  };

  // --- read: every feature of the selected layers, matched against the rules
  std::vector<Kept> kept;
  ds->ResetReading();
  OGRLayer* layer = nullptr;
  double pct = 0;
  size_t n = 0;
  for (OGRFeatureUniquePtr f(ds->GetNextFeature(&layer, &pct, nullptr, nullptr)); f;
       f.reset(ds->GetNextFeature(&layer, &pct, nullptr, nullptr))) {
    if (opt.progress && ++n % 1024 == 0) opt.progress(pct);
    const std::string lname = layer->GetName();
    if (!selected(lname)) continue;
    LayerReport& lr = rep.layers[lname];
    ++lr.read;
    OGRGeometry* g0 = f->GetGeometryRef();
    if (!g0 || g0->IsEmpty()) {
      ++lr.skipped["no geometry"];
      continue;
    }
    const Kind kind = kind_of(g0->getGeometryType());
    if (kind == Kind::Other) {
      ++lr.skipped[std::string("geometry type ") + OGRGeometryTypeToName(g0->getGeometryType())];
      continue;
    }
    Kept k;
    k.layer = lname;
    k.fid = f->GetFID();
    k.rule = match(rules, lname, kind, *f, k.value);
    if (!k.rule) {
      ++lr.skipped["no rule"];
      continue;
    }
    if (k.rule->action == FeatureAction::Skip) {
      ++lr.skipped["rule " + k.rule->name];
      continue;
    }
    if (k.rule->action == FeatureAction::Stairs && kind != Kind::Line) {
      ++lr.skipped["stairs need a line"];
      continue;
    }
    if (k.rule->action == FeatureAction::Object && kind == Kind::Line) {
      ++lr.skipped["an object needs a point or polygon"];
      continue;
    }
    k.srs = given_srs ? &*given_srs : layer->GetSpatialRef();
    std::unique_ptr<OGRGeometry> g(g0->hasCurveGeometry() ? g0->getLinearGeometry(rules.curve_step_degrees, nullptr)
                                                          : g0->clone());
    if (kind == Kind::Polygon) {
      const std::string why = invalid_reason(*g);
      if (!why.empty()) {
        if (opt.invalid == InvalidPolicy::Refuse)
          throw BadInput(source + ": " + where(k) + ": expected a valid polygon, got: " + why +
                         " (nothing imported; --invalid repair repairs it)");
        std::unique_ptr<OGRGeometry> fixed(g->MakeValid());
        if (fixed) fixed = keep_kind(std::move(fixed), Kind::Polygon);
        if (!fixed) throw BadInput(source + ": " + where(k) + ": " + why + ", and MakeValid could not repair it");
        rep.warnings.push_back(where(k) + ": " + why + ": repaired");
        ++lr.repaired;
        g = std::move(fixed);
      }
    }
    if (clip) {
      const OGRGeometry* area = clip_for(k.srs);
      if (!g->Intersects(area)) {
        ++lr.skipped["outside the clip area"];
        continue;
      }
      if (!g->Within(area)) {
        std::unique_ptr<OGRGeometry> cut(g->Intersection(area));
        if (cut) cut = keep_kind(std::move(cut), kind);
        if (!cut || cut->IsEmpty()) {
          ++lr.skipped["outside the clip area"];
          continue;
        }
        ++lr.clipped;
        g = std::move(cut);
      }
    }
    k.geom = std::move(g);
    k.semantic = feature_semantic(*f, lname);
    if (k.rule->action != FeatureAction::Object) k.h = height_of(k.rule->height, *f);
    k.down = feature_attribute(*f, "incline") == "down";
    if (auto w = parse_length(feature_attribute(*f, "width"))) k.width = *w;
    kept.push_back(std::move(k));
  }
  if (opt.progress) opt.progress(1.0);
  if (kept.empty()) throw BadInput(source + ": expected features the rules keep, got none");

  // --- the map frame
  const OGRSpatialReference* src = kept.front().srs;
  rep.source_crs = src ? crs_name(*src) : "";
  for (const Kept& k : kept)
    if ((k.srs == nullptr) != (src == nullptr))
      throw BadInput(source + ": " + where(k) + ": expected every kept layer to have a CRS or none; give one with --crs");
  std::optional<MapGeoref> frame = opt.frame;
  if (!src && frame) throw BadInput(source + ": the data has no CRS: give it with --crs to import into a map's frame");
  if (src && !frame) {
    if (src->IsProjected() && std::abs(src->GetLinearUnits() - 1.0) < 1e-9) {
      frame = MapGeoref{crs_name(*src), 0, 0, 0, 1};
      rep.frame = "the source's projected CRS " + frame->crs;
    } else if (const std::optional<MapGeoref> derived = georef_from_frame_crs(wkt2(*src))) {
      // A map frame as fleetmap's GIS layers publish it: the map comes back in its own frame.
      frame = derived;
      rep.frame = "the source's map frame (a derived CRS: its base and a similarity)";
    } else {
      LonLat o;
      if (opt.origin) {
        o = *opt.origin;
      } else {
        OGREnvelope env, e;
        for (const Kept& k : kept) {
          k.geom->getEnvelope(&e);
          env.Merge(e);
        }
        double x = (env.MinX + env.MaxX) / 2, y = (env.MinY + env.MaxY) / 2;
        if (!src->IsSame(&wgs84)) transformation(*src, wgs84)->Transform(1, &x, &y);
        // Rounded to 0.001 degree (about 100 m), so two imports of one site share it.
        o = {std::round(x * 1000) / 1000, std::round(y * 1000) / 1000};
      }
      frame = georef_from_origin(o.lat, o.lon, 0);
      rep.frame = "local Transverse Mercator at lat " + std::to_string(o.lat) + ", lon " + std::to_string(o.lon);
    }
  }
  std::optional<GeoTransform> geo;
  std::optional<OGRSpatialReference> base;
  std::map<const OGRSpatialReference*, std::unique_ptr<OGRCoordinateTransformation>> to_base;
  if (frame) {
    geo.emplace(*frame);
    base = srs_from(frame->crs, "map frame CRS");
    if (!opt.frame.has_value() && rep.frame.empty()) rep.frame = frame->crs;
    if (opt.frame) rep.frame = "the given map's frame (" + frame->crs + ")";
  } else {
    const bool dxf = rep.driver == "DXF";
    rep.unit_scale = dxf ? dxf_unit_scale(source) : 1;
    rep.frame = "the source's own frame (no CRS), " + std::to_string(rep.unit_scale) + " m per unit";
  }
  auto to_map = [&](const Kept& k, Point p) -> Point {
    if (!geo) return rep.unit_scale * p;
    auto& ct = to_base[k.srs];
    if (!ct && !k.srs->IsSame(&*base)) ct = transformation(*k.srs, *base);
    double x = p.x, y = p.y;
    if (ct && !ct->Transform(1, &x, &y))
      throw BadInput(source + ": " + where(k) + ": cannot transform (" + std::to_string(p.x) + ", " +
                     std::to_string(p.y) + ") into the map frame");
    return geo->base_to_map({x, y});
  };
  auto chain_to_map = [&](const Kept& k, Chain c) {
    for (Point& p : c) p = to_map(k, p);
    return c;
  };

  // --- build: obstacles and objects, in the map frame
  Map& m = out.map;
  Scene& scene = out.scene;
  for (const Kept& k : kept) {
    LayerReport& lr = rep.layers[k.layer];
    const FeatureRule& r = *k.rule;
    const std::string tag = short_semantic(!r.tag.empty() ? r.tag : !k.value.empty() ? k.value : k.layer, 64);
    const size_t obstacles_before = m.obstacles.size(), objects_before = scene.objects.size();
    auto add = [&](std::optional<Obstacle> o) {
      if (!o) {
        ++lr.skipped["degenerate ring or line"];
        return;
      }
      o->id = static_cast<int>(m.obstacles.size()) + 1;
      o->semantic = k.semantic;
      lr.segments += o->segments.size();
      m.obstacles.push_back(std::move(*o));
    };
    const SegmentStyle style{k.h, r.in_out, tag};
    if (r.action == FeatureAction::Closed && kind_of(k.geom->getGeometryType()) == Kind::Polygon) {
      for_each_polygon(*k.geom, [&](const OGRPolygon& poly) {
        bool outer = true;
        for (const OGRLinearRing* ring : poly) {
          Chain c = chain_to_map(k, chain_of(*ring));
          lr.repeated_vertices += drop_repeated_vertices(c);
          // Holes have free space on the other side (seed 000 section 3).
          add(closed_obstacle(std::move(c), outer == r.free_space_inside, style));
          outer = false;
        }
      });
    } else if (r.action == FeatureAction::Closed || r.action == FeatureAction::Open) {
      for_each_line(*k.geom, [&](const OGRLineString& ls) {
        Chain c = chain_to_map(k, chain_of(ls));
        lr.repeated_vertices += drop_repeated_vertices(c);
        if (r.action == FeatureAction::Closed && c.size() >= 4 && c.front() == c.back())
          add(closed_obstacle(std::move(c), r.free_space_inside, style));
        else
          add(open_obstacle(std::move(c), style));
      });
    } else if (r.action == FeatureAction::Stairs) {
      for_each_line(*k.geom, [&](const OGRLineString& ls) {
        Chain c = chain_to_map(k, chain_of(ls));
        if (k.down) std::reverse(c.begin(), c.end());
        const StairsStyle s{r.step_height, r.step_depth, k.width > 0 ? k.width : r.stairs_width, r.in_out, tag};
        add(stairs_obstacle(c, s));
      });
    } else if (r.action == FeatureAction::Object) {
      EnvObject obj;
      obj.id = short_semantic(k.layer, 200) + "-" + std::to_string(k.fid);
      obj.tag = tag;
      std::optional<HeightRange> z;
      if (r.object_height) z = HeightRange{0, *r.object_height};
      for_each_point(*k.geom, [&](Point p) { obj.elements.push_back({square(to_map(k, p), r.object_size), z}); });
      for_each_polygon(*k.geom, [&](const OGRPolygon& poly) {
        Chain c = chain_to_map(k, chain_of(*poly.getExteriorRing()));
        drop_repeated_vertices(c);
        if (c.size() > 1 && c.front() == c.back()) c.pop_back();
        if (c.size() >= 3) obj.elements.push_back({c, z});
      });
      if (obj.elements.empty()) ++lr.skipped["degenerate object"];
      else scene.objects.push_back(std::move(obj));
    }
    lr.obstacles += m.obstacles.size() - obstacles_before;
    lr.objects += scene.objects.size() - objects_before;
    if (m.obstacles.size() > obstacles_before || scene.objects.size() > objects_before) ++lr.kept;
  }

  // --- border: the kept geometry's extent plus a margin
  Rect ext = Rect::none();
  for (const Obstacle& o : m.obstacles)
    for (const Segment& s : o.segments) {
      ext.extend(s.a);
      ext.extend(s.b);
    }
  for (const EnvObject& o : scene.objects)
    for (const Element& e : o.elements)
      for (Point p : e.footprint) ext.extend(p);
  if (!(ext.xmin <= ext.xmax)) throw BadInput(source + ": expected features the rules keep, got none");
  rep.extent = ext;
  m.border = Border::from_rect({ext.xmin - rules.margin, ext.ymin - rules.margin, ext.xmax + rules.margin,
                                ext.ymax + rules.margin});
  m.compute_bounds();
  if (geo) {
    rep.extent_wgs84 = std::pair{geo->to_wgs84({ext.xmin, ext.ymin}), geo->to_wgs84({ext.xmax, ext.ymax})};
    out.georef = *frame;
  }
  try {
    validate_map(m);
    validate_scene(scene);
  } catch (const std::invalid_argument& e) {
    throw BadInput(source + ": the imported map is not valid: " + e.what());
  }
  return out;
}

}  // namespace fleetmap
