// `objects near` benchmark (the semantic layer, SPEC 8). Generates a map with 100 000 objects (random
// rectangles, ten tags), imports it in one transaction, then times the k nearest objects
// with a tag from random points: SceneStore::near with the spatial index and a growing
// search box (the product) beside two full scans of the same map in the same run: every
// element read and measured exactly (NearAccess::FullScan, same answers), and the SQL an
// inspector would write without the index (ORDER BY ST_Distance ... LIMIT k).
// Driven by scripts/bench-objects.sh (private MariaDB). Goal: median <= 5 ms and >= 50x
// the scan.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <random>
#include <vector>

#include <CLI/CLI.hpp>

#include "common/geometry/number_format.h"
#include "protocol/connection.h"
#include "protocol/map_store.h"
#include "protocol/scene_store.h"

namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

double percentile(std::vector<double> v, double p) {
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<size_t>(p * (v.size() - 1) + 0.5))];
}

const char* const kTags[] = {"box", "table", "cupboard", "chair", "shelf", "door", "charging_station", "trolley", "plant", "column"};

}  // namespace

int main(int argc, char** argv) {
  using namespace fleetmap;
  CLI::App app{"bench-objects: k nearest objects with a tag, spatial index vs full scan, on a generated map"};
  int objects = 100000, queries = 200, scans = 20, k = 5;
  double side = 1000;
  unsigned seed = 11;
  std::string tag = "door";
  app.add_option("--objects", objects, "objects on the map")->capture_default_str();
  app.add_option("--side", side, "the map is side x side metres")->capture_default_str();
  app.add_option("--queries", queries, "random points timed with the index")->capture_default_str();
  app.add_option("--scans", scans, "of those, how many also timed with each full scan")->capture_default_str();
  app.add_option("-k", k, "objects per query")->capture_default_str();
  app.add_option("--tag", tag, "tag sought (one object in ten has each tag)")->capture_default_str();
  app.add_option("--seed", seed, "random seed")->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  try {
    auto conn = connect(load_settings(Role::Operator, std::nullopt));
    const std::string name = "bench_objects";
    Map m;
    m.border = Border::from_rect({0, 0, side, side});
    SceneStore store(*conn);
    // A map left by an earlier run: its objects go first, one statement each rather than a
    // cascade row by row; then the map is replaced.
    try {
      store.import(name, Scene{}, {.replace = true});
    } catch (const MapNotFound&) {
    }
    MapStore(*conn).import(m, name, "bench-objects", true);

    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> pos(0, side), size(0.2, 1.5), yaw(0, 3.14159265);
    Scene scene;
    for (int i = 0; i < objects; ++i)
      scene.objects.push_back({.id = "o" + std::to_string(i), .tag = kTags[i % 10],
                               .elements = {{.footprint = rectangle_footprint({pos(rng), pos(rng)}, size(rng), size(rng), yaw(rng))}}});
    auto t0 = Clock::now();
    store.import(name, scene, {.replace = true});
    std::printf("map: %.0f m x %.0f m, %d objects (one element each, %zu with tag '%s'), imported in %.1f s\n", side, side,
                objects, scene.objects.size() / 10, tag.c_str(), ms_since(t0) / 1000);
    conn->query("ANALYZE TABLE object_elements, env_objects").store();
    const unsigned mid = MapStore(*conn).info(name).id;

    std::vector<double> indexed, scanned, sql_scan;
    size_t agree = 0, rounds = 0;
    for (int q = 0; q < queries; ++q) {
      const Point p{pos(rng), pos(rng)};
      NearStats st;
      t0 = Clock::now();
      const auto fast = store.near(mid, p, tag, static_cast<size_t>(k), NearAccess::SpatialIndex, &st);
      indexed.push_back(ms_since(t0));
      rounds += static_cast<size_t>(st.rounds);
      if (q >= scans) continue;
      t0 = Clock::now();
      const auto slow = store.near(mid, p, tag, static_cast<size_t>(k), NearAccess::FullScan);
      scanned.push_back(ms_since(t0));
      bool same = fast.size() == slow.size();
      for (size_t i = 0; same && i < fast.size(); ++i) same = fast[i].key == slow[i].key;
      agree += same;
      // What an inspector would write without the index (MariaDB's approximate ST_Distance).
      t0 = Clock::now();
      mysqlpp::Query sq = conn->query();
      sq << "SELECT o.object_key, ST_Distance(e.footprint, POINT(" << format_number(p.x) << "," << format_number(p.y)
         << ")) AS d FROM object_elements e IGNORE INDEX (sx_object_elements_footprint)"
            " STRAIGHT_JOIN env_objects o ON o.id = e.object_id WHERE e.map_id = "
         << mid << " AND o.tag = " << mysqlpp::quote << tag << " ORDER BY d LIMIT " << k;
      sq.store();
      sql_scan.push_back(ms_since(t0));
    }
    const double med = percentile(indexed, 0.5), med_scan = percentile(scanned, 0.5), med_sql = percentile(sql_scan, 0.5);
    std::printf("objects near, k = %d, tag '%s', %d random points (%d also with each full scan):\n", k, tag.c_str(),
                queries, scans);
    std::printf("  %-44s median %8.2f ms   p90 %8.2f ms   (%.1f index searches per query)\n",
                "spatial index, growing box (SceneStore)", med, percentile(indexed, 0.9), double(rounds) / queries);
    std::printf("  %-44s median %8.2f ms   p90 %8.2f ms   %6.0fx the index\n", "full scan, exact distances in C++",
                med_scan, percentile(scanned, 0.9), med_scan / med);
    std::printf("  %-44s median %8.2f ms   p90 %8.2f ms   %6.0fx the index\n", "full scan, SQL ORDER BY ST_Distance LIMIT k",
                med_sql, percentile(sql_scan, 0.9), med_sql / med);
    std::printf("  index and exact scan agree on %zu of %d queries\n", agree, scans);
    std::printf("goal: median <= 5 ms (%s), >= 50x the SQL scan (%s)\n", med <= 5 ? "met" : "NOT met",
                med_sql / med >= 50 ? "met" : "NOT met");
    return agree == static_cast<size_t>(std::min(scans, queries)) ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench-objects: %s\n", e.what());
    return 1;
  }
}
