#include "common/io/amrl_import.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include "common/core/error.h"
#include "common/map/map_validation.h"
#include "common/io/seed_format.h"

namespace fleetmap {
namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

void close_chain(Map& m, Obstacle& chain, AmrlReport& rep) {
  if (chain.segments.empty()) return;
  if (chain.segments.size() >= 3 && chain.segments.back().b == chain.segments.front().a) {
    chain.type = ShapeType::ClosedPolygon;
    ++rep.closed;
  }
  m.obstacles.push_back(std::move(chain));
  chain = Obstacle{};
}

}  // namespace

Map read_amrl(std::string_view text, const AmrlOptions& opt, AmrlReport* report, const std::string& file) {
  if (auto e = check_text(opt.semantic, "semantic option")) throw MapFormatError(file, 0, *e);
  AmrlReport rep;
  Map m;
  Obstacle chain;
  int next_id = opt.first_id;
  double xmin = std::numeric_limits<double>::infinity(), ymin = xmin, xmax = -xmin, ymax = -xmin;
  size_t lineno = 0, pos = 0;
  while (pos < text.size()) {
    size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = trim(text.substr(pos, end - pos));
    pos = end + 1;
    ++lineno;
    if (line.empty()) continue;
    ++rep.lines;
    double v[4];
    std::string_view rest = line;
    for (int i = 0; i < 4; ++i) {
      const size_t comma = rest.find(',');
      if ((i < 3) != (comma != std::string_view::npos))
        throw MapFormatError(file, lineno, "expected 4 comma-separated numbers 'x1, y1, x2, y2', got '" +
                                               std::string(line.substr(0, 60)) + "'");
      const std::string_view f = trim(rest.substr(0, comma));
      auto [p, ec] = std::from_chars(f.data(), f.data() + f.size(), v[i]);
      if (f.empty() || p != f.data() + f.size() || ec != std::errc() || !std::isfinite(v[i]) ||
          std::abs(v[i]) > kMaxCoordinate)
        throw MapFormatError(file, lineno, "expected a finite number for field " + std::to_string(i + 1) +
                                               " of 'x1, y1, x2, y2', got '" + std::string(f) + "'");
      rest = i < 3 ? rest.substr(comma + 1) : std::string_view{};
    }
    Segment s{{v[0], v[1]}, {v[2], v[3]}, opt.height, opt.in_out, opt.semantic, ""};
    if (s.a == s.b) {
      ++rep.zero_length_skipped;
      continue;  // not a wall; a skipped line does not break the chain around it
    }
    xmin = std::fmin(xmin, std::fmin(s.a.x, s.b.x));
    xmax = std::fmax(xmax, std::fmax(s.a.x, s.b.x));
    ymin = std::fmin(ymin, std::fmin(s.a.y, s.b.y));
    ymax = std::fmax(ymax, std::fmax(s.a.y, s.b.y));
    if (!chain.segments.empty() && chain.segments.back().b != s.a) close_chain(m, chain, rep);
    if (chain.segments.empty()) {
      chain.id = next_id++;
      chain.type = ShapeType::OpenPolygon;
      chain.semantic = opt.semantic;
    }
    chain.segments.push_back(std::move(s));
    ++rep.segments;
  }
  close_chain(m, chain, rep);
  if (rep.segments == 0) throw MapFormatError(file, lineno, "expected at least one segment of non-zero length, got none");
  m.border = {xmin - opt.margin, ymax + opt.margin, xmax + opt.margin, ymin - opt.margin};
  rep.obstacles = m.obstacles.size();
  try {
    validate_map(m);  // options can still be wrong: a negative height, a margin <= 0
  } catch (const std::invalid_argument& e) {
    throw MapFormatError(file, 0, e.what());
  }
  m.compute_bounds();
  if (report) *report = rep;
  return m;
}

Map read_amrl_file(const std::string& path, const AmrlOptions& opt, AmrlReport* report) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(path + ": expected a readable file, got an error opening it");
  std::ostringstream ss;
  ss << in.rdbuf();
  return read_amrl(ss.str(), opt, report, path);
}

}  // namespace fleetmap
