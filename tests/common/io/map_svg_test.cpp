// common/io/map_svg.*: the SVG picture. Checked as text, without an XML library:
// well-formedness basics, one element per segment, the map-to-pixel transform
// (map_svg.h), colours, tracks and escaping.
#include <gtest/gtest.h>

#include <string>

#include "common/io/map_svg.h"
#include "common/map/ramp.h"

namespace fleetmap {
namespace {

size_t count(const std::string& text, const std::string& what) {
  size_t n = 0;
  for (size_t pos = text.find(what); pos != std::string::npos; pos = text.find(what, pos + what.size())) ++n;
  return n;
}

// Wall, stairs and ramp, as in map_geojson_test.cpp.
Map sample_map() {
  Map m;
  m.border = {0, 20, 30, 0};
  Obstacle wall{1, ShapeType::ClosedPolygon, "building", {}, {}};
  wall.segments = {{{1, 1}, {5, 1}, 2.5, 0, "wall", ""},
                   {{5, 1}, {5, 5}, 2.5, 0, "wall", ""},
                   {{5, 5}, {1, 5}, 2.5, 0, "wall", ""},
                   {{1, 5}, {1, 1}, 2.5, 0, "wall", ""}};
  Obstacle stairs{2, ShapeType::Stairs, "stairs", {}, {}};
  stairs.segments = {{{14, 10.3}, {10, 10.3}, 0.51, 0, "step", ""},
                     {{14, 10.6}, {10, 10.6}, 0.34, 0, "step", ""},
                     {{10, 10}, {14, 10}, 0, 0, "landing", ""}};
  Obstacle ramp{3, ShapeType::Ramp, "ramp," + ramp_tokens(-0.125, 0, 1, {20, 5}), {}, {}};
  ramp.segments = {{{20, 5}, {28, 5}, 0, 1, "", ""},
                   {{28, 5}, {28, 9}, 0, 1, "", ""},
                   {{28, 9}, {20, 9}, 0, 1, "", ""},
                   {{20, 9}, {20, 5}, 0, 1, "", ""}};
  Obstacle fence{4, ShapeType::OpenPolygon, "fence", {{{2, 15}, {9, 15}, 1, 1, "", ""}}, {}};
  m.obstacles = {wall, stairs, ramp, fence};
  return m;
}

SvgOptions options(double width_px, double margin_px = 40, double scale_bar_m = 0) {
  SvgOptions opt;
  opt.width_px = width_px;
  opt.margin_px = margin_px;
  opt.scale_bar_m = scale_bar_m;
  return opt;
}

// Border (0,10)-(10,0), one segment from the upper-right corner to the origin.
Map square_map() {
  Map m;
  m.border = {0, 10, 10, 0};
  m.obstacles = {{7, ShapeType::ClosedPolygon, "", {{{10, 10}, {0, 0}, 1, 0, "", ""}}, {}}};
  return m;
}

TEST(MapSvg, IsABalancedStandaloneDocument) {
  SvgOptions opt;
  opt.title = "floor 1";
  const std::string svg = write_svg(sample_map(), opt);
  EXPECT_EQ(svg.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg ", 0), 0u);
  EXPECT_EQ(count(svg, "<svg "), 1u);
  EXPECT_EQ(count(svg, "</svg>"), 1u);
  ASSERT_GE(svg.size(), 7u);
  EXPECT_EQ(svg.substr(svg.size() - 7), "</svg>\n");
  EXPECT_NE(svg.find("xmlns=\"http://www.w3.org/2000/svg\""), std::string::npos);
  EXPECT_EQ(count(svg, "<g "), count(svg, "</g>"));
  EXPECT_EQ(count(svg, "<title>"), count(svg, "</title>"));
  EXPECT_EQ(count(svg, "<text "), count(svg, "</text>"));
  EXPECT_EQ(count(svg, "<"), count(svg, ">"));
}

TEST(MapSvg, OneLinePerSegment) {
  const Map m = sample_map();
  const std::string svg = write_svg(m);
  EXPECT_EQ(count(svg, "<line class=\"seg "), m.segment_count());
  EXPECT_EQ(count(svg, "<line class=\"seg st1\""), 4u);
  EXPECT_EQ(count(svg, "<line class=\"seg st5\""), 3u);
  EXPECT_EQ(count(svg, "<line class=\"seg st6\""), 4u);
  EXPECT_EQ(count(svg, "<line class=\"seg st2\""), 1u);
  EXPECT_EQ(count(svg, "<g class=\"obstacle\""), m.obstacles.size());
}

TEST(MapSvg, FlipsYAndScalesTheLargerSideToWidth) {
  // k = 100 px / 10 m; margin 40: map (10,10) -> (140,40), map (0,0) -> (40,140).
  const std::string svg = write_svg(square_map(), options(100));
  EXPECT_NE(svg.find("x1=\"140\" y1=\"40\" x2=\"40\" y2=\"140\""), std::string::npos) << svg;
  EXPECT_NE(svg.find("width=\"180\" height=\"180\""), std::string::npos);
  EXPECT_NE(svg.find("<rect class=\"border\" x=\"40\" y=\"40\" width=\"100\" height=\"100\""), std::string::npos);

  // Wider than tall: 20 m -> 100 px, k = 5; map (20,0) -> (140,90).
  Map wide = square_map();
  wide.border = {0, 10, 20, 0};
  wide.obstacles[0].segments[0] = {{20, 0}, {0, 10}, 0, 0, "", ""};
  const std::string svg2 = write_svg(wide, options(100, 10));
  EXPECT_NE(svg2.find("x1=\"110\" y1=\"60\" x2=\"10\" y2=\"10\""), std::string::npos) << svg2;
  EXPECT_NE(svg2.find("width=\"120\" height=\"70\""), std::string::npos);
}

TEST(MapSvg, ColoursByShapeAndWidthByHeight) {
  const std::string svg = write_svg(sample_map());
  EXPECT_NE(svg.find("data-id=\"1\" stroke=\"#404040\""), std::string::npos);  // walls dark grey
  EXPECT_NE(svg.find("data-id=\"2\" stroke=\"#ff8c00\""), std::string::npos);  // stairs orange
  EXPECT_NE(svg.find("data-id=\"3\" stroke=\"#2e8b57\""), std::string::npos);  // ramp green
  EXPECT_NE(svg.find("data-id=\"4\" stroke=\"#8b4513\""), std::string::npos);  // open polygon brown
  EXPECT_EQ(count(svg, "fill=\"url(#ramp-hatch)\""), 1u);
  EXPECT_EQ(count(svg, "stroke-width=\"0.5\"/>"), 5u);  // h = 0: the landing and the ramp edges
  EXPECT_EQ(count(svg, "stroke-width=\"3.5\"/>"), 4u);  // walls, h = 2.5
}

TEST(MapSvg, EscapesTexts) {
  SvgOptions opt;
  opt.title = "a < b & \"c\"";
  opt.tracks = {{"<robot> & 'r2'", "#123456", {{1, 1}, {2, 2}}}};
  Map m = square_map();
  m.obstacles[0].semantic = "x<y&z";
  const std::string svg = write_svg(m, opt);
  EXPECT_NE(svg.find(">a &lt; b &amp; &quot;c&quot;</text>"), std::string::npos);
  EXPECT_NE(svg.find("&lt;robot&gt; &amp; &apos;r2&apos;"), std::string::npos);
  EXPECT_NE(svg.find("x&lt;y&amp;z"), std::string::npos);
  EXPECT_EQ(svg.find("a < b"), std::string::npos);
  EXPECT_EQ(svg.find("<robot>"), std::string::npos);
  EXPECT_EQ(svg.find("x<y"), std::string::npos);
  EXPECT_EQ(xml_escape("tab\tok\x01gone"), "tab\tokgone");
}

TEST(MapSvg, DrawsTracksOnTopWithALegend) {
  EXPECT_EQ(write_svg(sample_map()).find("legend"), std::string::npos);
  SvgOptions opt;
  opt.width_px = 100;
  opt.tracks = {{"robot 1", "#d62728", {{0, 0}, {5, 5}, {10, 10}}}, {"robot 2", "blue", {{5, 0}}}};
  const std::string svg = write_svg(square_map(), opt);
  EXPECT_EQ(count(svg, "<polyline "), 2u);
  EXPECT_NE(svg.find("points=\"40,140 90,90 140,40\""), std::string::npos) << svg;
  EXPECT_NE(svg.find("<circle cx=\"140\" cy=\"40\""), std::string::npos);  // latest position
  EXPECT_GT(svg.find("<polyline "), svg.rfind("<line class=\"seg"));         // drawn over the map
  EXPECT_NE(svg.find("class=\"legend\""), std::string::npos);
  EXPECT_NE(svg.find(">robot 1</text>"), std::string::npos);
  EXPECT_NE(svg.find(">robot 2</text>"), std::string::npos);
  SvgOptions uncoloured = opt;
  uncoloured.tracks[0].colour = uncoloured.tracks[1].colour = "";
  const std::string svg2 = write_svg(square_map(), uncoloured);
  EXPECT_NE(svg2.find("<circle cx=\"140\" cy=\"40\" r=\"4\" fill=\"#d62728\""), std::string::npos);
  EXPECT_NE(svg2.find("<circle cx=\"90\" cy=\"140\" r=\"4\" fill=\"#1f77b4\""), std::string::npos);
}

TEST(MapSvg, ScaleBar) {
  EXPECT_NE(write_svg(square_map()).find(">2 m</text>"), std::string::npos);  // 1-2-5 up to 10 m / 4
  EXPECT_NE(write_svg(sample_map()).find(">5 m</text>"), std::string::npos);  // up to 30 m / 4
  const std::string svg = write_svg(square_map(), options(100, 40, 10));
  EXPECT_NE(svg.find("h100v-4"), std::string::npos);  // 10 m = 100 px
  EXPECT_NE(svg.find(">10 m</text>"), std::string::npos);
}

}  // namespace
}  // namespace fleetmap
