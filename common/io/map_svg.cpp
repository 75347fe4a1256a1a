#include "common/io/map_svg.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "common/geometry/number_format.h"

namespace fleetmap {
namespace {

// Pixels to 1/100: exact enough for any screen, and short.
std::string px(double v) { return format_number(std::round(v * 100) / 100); }

const char* colour(ShapeType st) {
  switch (st) {
    case ShapeType::ClosedPolygon: return "#404040";  // walls
    case ShapeType::OpenPolygon: return "#8b4513";
    case ShapeType::ClosedCurved:
    case ShapeType::OpenCurved: return "#1f5fbf";
    case ShapeType::Stairs: return "#ff8c00";
    case ShapeType::Ramp: return "#2e8b57";
  }
  return "#000000";
}

// Thin for h = 0 (floor marks, ramps, the stairs' closing segment), thicker up to 3 m.
double stroke_width(double h) { return h <= 0 ? 0.5 : 1 + std::min(h, 3.0); }

// The largest 1, 2 or 5 times a power of ten not above `limit`.
double nice_length(double limit) {
  if (!(limit > 0)) return 1;
  const double p = std::pow(10, std::floor(std::log10(limit)));
  for (double f : {5.0, 2.0, 1.0})
    if (f * p <= limit) return f * p;
  return p;
}

// Tracks without a colour: a qualitative palette (Tableau 10) by position in the list.
std::string track_colour(const std::vector<SvgTrack>& tracks, size_t i) {
  static const char* const palette[] = {"#d62728", "#1f77b4", "#9467bd", "#17becf", "#e377c2", "#bcbd22"};
  return xml_escape(tracks[i].colour.empty() ? palette[i % std::size(palette)] : tracks[i].colour);
}

struct Frame {
  double mx1, my1, k, margin;
  std::string x(double v) const { return px(margin + (v - mx1) * k); }
  std::string y(double v) const { return px(margin + (my1 - v) * k); }
  std::string xy(Point p) const { return x(p.x) + "," + y(p.y); }
};

}  // namespace

std::string xml_escape(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default:
        if (static_cast<unsigned char>(c) >= 0x20 || c == '\t' || c == '\n' || c == '\r') out += c;
    }
  }
  return out;
}

std::string write_svg(const Map& m, const SvgOptions& opt) {
  const Border& b = m.border;
  const double w_m = b.mx4 - b.mx1, h_m = b.my1 - b.my4;
  const double extent = std::max(w_m, h_m);
  const Frame f{b.mx1, b.my1, extent > 0 ? opt.width_px / extent : 1, opt.margin_px};
  const double map_w = w_m * f.k, map_h = h_m * f.k;
  const double total_w = map_w + 2 * f.margin, total_h = map_h + 2 * f.margin;

  std::string s = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  s += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + px(total_w) + "\" height=\"" + px(total_h) +
       "\" viewBox=\"0 0 " + px(total_w) + " " + px(total_h) + "\" font-family=\"sans-serif\">\n";
  if (!opt.title.empty()) s += "<title>" + xml_escape(opt.title) + "</title>\n";
  s += "<defs><pattern id=\"ramp-hatch\" patternUnits=\"userSpaceOnUse\" width=\"6\" height=\"6\" "
       "patternTransform=\"rotate(45)\"><line x1=\"0\" y1=\"0\" x2=\"0\" y2=\"6\" stroke=\"#2e8b57\" "
       "stroke-width=\"1\" stroke-opacity=\"0.5\"/></pattern></defs>\n";
  s += "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
  s += "<rect class=\"border\" x=\"" + f.x(b.mx1) + "\" y=\"" + f.y(b.my1) + "\" width=\"" + px(map_w) +
       "\" height=\"" + px(map_h) + "\" fill=\"#f4f4ef\" stroke=\"#c8c8c0\" stroke-width=\"1\"/>\n";

  for (const Obstacle& o : m.obstacles) {
    s += "<g class=\"obstacle\" data-id=\"" + std::to_string(o.id) + "\" stroke=\"" + colour(o.type) +
         "\" stroke-linecap=\"round\"><title>" + std::to_string(o.id) + " " + std::string(to_string(o.type)) +
         (o.semantic.empty() ? "" : ": " + xml_escape(o.semantic)) + "</title>\n";
    if (o.type == ShapeType::Ramp && !o.segments.empty()) {
      // A ramp is a closed chain (SPEC 3): its segment starts are the polygon's vertices.
      s += "<polygon points=\"";
      for (const Segment& g : o.segments) s += f.xy(g.a) + " ";
      s.back() = '"';
      s += " fill=\"url(#ramp-hatch)\" stroke=\"none\"/>\n";
    }
    for (const Segment& g : o.segments)
      s += "<line class=\"seg st" + std::to_string(static_cast<int>(o.type)) + "\" x1=\"" + f.x(g.a.x) +
           "\" y1=\"" + f.y(g.a.y) + "\" x2=\"" + f.x(g.b.x) + "\" y2=\"" + f.y(g.b.y) + "\" stroke-width=\"" +
           px(stroke_width(g.h)) + "\"/>\n";
    s += "</g>\n";
  }

  for (size_t i = 0; i < opt.tracks.size(); ++i) {
    const SvgTrack& t = opt.tracks[i];
    if (t.points.empty()) continue;
    const std::string c = track_colour(opt.tracks, i);
    s += "<g class=\"track\"><title>" + xml_escape(t.label) + "</title>\n<polyline points=\"";
    for (const Point& p : t.points) s += f.xy(p) + " ";
    s.back() = '"';
    s += " fill=\"none\" stroke=\"" + c + "\" stroke-width=\"2\" stroke-linejoin=\"round\"/>\n";
    s += "<circle cx=\"" + f.x(t.points.back().x) + "\" cy=\"" + f.y(t.points.back().y) + "\" r=\"4\" fill=\"" +
         c + "\"/>\n</g>\n";
  }

  if (!opt.tracks.empty()) {  // legend in the map's upper-right corner, over everything
    const double row = 18, lw = 160, x0 = f.margin + map_w - lw - 8, y0 = f.margin + 8;
    s += "<g class=\"legend\" font-size=\"12\"><rect x=\"" + px(x0) + "\" y=\"" + px(y0) + "\" width=\"" + px(lw) +
         "\" height=\"" + px(row * opt.tracks.size() + 8) +
         "\" fill=\"#ffffff\" fill-opacity=\"0.85\" stroke=\"#999999\"/>\n";
    for (size_t i = 0; i < opt.tracks.size(); ++i) {
      const SvgTrack& t = opt.tracks[i];
      const double y = y0 + 4 + row * (i + 0.5);
      s += "<path d=\"M" + px(x0 + 6) + "," + px(y) + "h20\" stroke=\"" + track_colour(opt.tracks, i) +
           "\" stroke-width=\"3\"/>";
      s += "<text x=\"" + px(x0 + 32) + "\" y=\"" + px(y + 4) + "\">" + xml_escape(t.label) + "</text>\n";
    }
    s += "</g>\n";
  }

  if (!opt.title.empty())
    s += "<text class=\"title\" x=\"" + px(f.margin) + "\" y=\"" + px(f.margin * 0.6) +
         "\" font-size=\"16\" font-weight=\"bold\">" + xml_escape(opt.title) + "</text>\n";

  const double bar_m = opt.scale_bar_m > 0 ? opt.scale_bar_m : nice_length(w_m / 4);
  const double bx = f.margin, by = f.margin + map_h + f.margin * 0.5, bw = bar_m * f.k;
  s += "<g class=\"scale\" stroke=\"#000000\" stroke-width=\"1.5\"><path d=\"M" + px(bx) + "," + px(by - 4) + "v4h" +
       px(bw) + "v-4\" fill=\"none\"/><text x=\"" + px(bx + bw + 6) + "\" y=\"" + px(by) +
       "\" font-size=\"12\" stroke=\"none\">" + format_number(bar_m) + " m</text></g>\n";
  s += "</svg>\n";
  return s;
}

}  // namespace fleetmap
