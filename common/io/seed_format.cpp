#include "common/io/seed_format.h"

#include <algorithm>
#include <charconv>
#include <limits>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

#include "common/map/map_validation.h"
#include "common/geometry/number_format.h"

namespace fleetmap {

MapFormatError::MapFormatError(std::string file, size_t line, std::string message)
    : FileFormatError(file + ":" + std::to_string(line) + ": " + message),
      file_(std::move(file)),
      line_(line),
      message_(std::move(message)) {}

namespace {

constexpr long long kMaxSegmentsPerObstacle = 10'000'000;

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

// How a line appears in a message: quoted, shortened, or "end of file".
std::string shown(std::string_view s, bool eof = false) {
  if (eof) return "end of file";
  std::string out;
  for (char c : s.substr(0, 60)) out += (static_cast<unsigned char>(c) < 0x20) ? '?' : c;
  return "'" + out + (s.size() > 60 ? "...'" : "'");
}

struct Line {
  size_t no = 0;
  std::string_view content;  // without the comment and surrounding blanks
  std::string_view note;     // after '%', without it
  bool has_note = false;
  bool eof = false;
};

class Reader {
 public:
  Reader(std::string_view text, std::string file, MapKind kind) : text_(text), file_(std::move(file)), kind_(kind) {}

  Map read() {
    Map m;
    expect_keyword(next(), "border;");
    Line l1 = next();
    auto f1 = fields(l1, 2, "mx1;my1;");
    m.border.mx1 = number(l1, f1[0], "mx1");
    m.border.my1 = number(l1, f1[1], "my1");
    Line l4 = next();
    auto f4 = fields(l4, 2, "mx4;my4;");
    m.border.mx4 = number(l4, f4[0], "mx4");
    m.border.my4 = number(l4, f4[1], "my4");
    if (auto e = check_border(m.border)) fail(l4.no, *e);
    expect_keyword(next(), "#");

    const Rect border = m.border.rect();
    for (;;) {
      Line head = next();
      if (head.eof) break;
      if (head.has_note) no_comment(head);
      if (head.content != "obstacle;") {
        std::string hint;
        if (!m.obstacles.empty() && std::count(head.content.begin(), head.content.end(), ';') == 2)
          hint = " (a segment line: obstacle " + std::to_string(m.obstacles.back().id) +
                 " has more segments than its NS = " + std::to_string(m.obstacles.back().segments.size()) + "?)";
        fail(head.no, "expected 'obstacle;' or end of file, got " + shown(head.content) + hint);
      }
      m.obstacles.push_back(read_obstacle(border));
    }
    m.compute_bounds();
    return m;
  }

 private:
  Obstacle read_obstacle(const Rect& border) {
    Line h = next();
    auto f = fields(h, 4, "id;ST;NS;semantic;");
    Obstacle o;
    o.id = static_cast<int>(integer(h, f[0], "obstacle id", std::numeric_limits<int>::min(),
                                    std::numeric_limits<int>::max()));
    if (auto [it, fresh] = first_seen_.emplace(o.id, h.no); !fresh)
      fail(h.no, "expected a unique obstacle id, got id " + std::to_string(o.id) + " again (first at line " +
                     std::to_string(it->second) + ")");
    const long long st = integer(h, f[1], "shape type ST in 1..6", 1, 6);
    o.type = static_cast<ShapeType>(st);
    const long long ns = integer(h, f[2], "segment count NS in 1..10000000", 1, kMaxSegmentsPerObstacle);
    o.semantic = std::string(f[3]);
    if (auto e = check_text(o.semantic, "obstacle semantic")) fail(h.no, *e);
    expect_keyword(next(), "#");
    o.segments.reserve(static_cast<size_t>(std::min<long long>(ns, 1 << 16)));
    const std::string of = " of obstacle " + std::to_string(o.id);
    for (long long i = 0; i < ns; ++i) {
      const std::string which = "segment " + std::to_string(i + 1) + "/" + std::to_string(ns) + of;
      Segment s;
      Line la = next();
      if (la.eof || la.content == "obstacle;")
        fail(la.no, "expected " + which + " ('ax;ay;'), got " + shown(la.content, la.eof) +
                        " (NS says " + std::to_string(ns) + ", found " + std::to_string(i) + ")");
      auto fa = fields(la, 2, "ax;ay; of " + which);
      s.a = {number(la, fa[0], "ax"), number(la, fa[1], "ay")};
      Line lb = next();
      auto fb = fields(lb, 2, "bx;by; of " + which);
      s.b = {number(lb, fb[0], "bx"), number(lb, fb[1], "by")};
      if (!border.contains(s.a)) fail(la.no, "expected " + which + " to start inside the border, got it outside");
      if (!border.contains(s.b)) fail(lb.no, "expected " + which + " to end inside the border, got it outside");
      if (s.a == s.b) fail(lb.no, "expected a segment of non-zero length, got b = a");
      Line lh = next();
      auto fh = fields(lh, 3, "h;inOut;semantic; of " + which, true);
      s.h = number(lh, fh[0], "h");
      if (s.h < 0 || s.h > kMaxHeight)
        fail(lh.no, "expected height h in 0.." + format_number(kMaxHeight) + " m, got " + std::string(fh[0]));
      s.in_out = static_cast<int>(integer(lh, fh[1], "inOut 0 or 1", 0, 1));
      s.semantic = std::string(fh[2]);
      if (lh.has_note) s.note = std::string(lh.note);
      if (auto e = check_segment(s)) fail(lh.no, *e);
      expect_keyword(next(), "#");
      o.segments.push_back(std::move(s));
    }
    if (auto e = check_shape(o, kind_)) fail(h.no, "obstacle " + std::to_string(o.id) + ": " + *e);
    return o;
  }

  Line next() {
    while (pos_ < text_.size()) {
      size_t end = text_.find('\n', pos_);
      if (end == std::string_view::npos) end = text_.size();
      std::string_view raw = text_.substr(pos_, end - pos_);
      pos_ = end + 1;
      ++lineno_;
      Line l;
      l.no = lineno_;
      if (size_t pct = raw.find('%'); pct != std::string_view::npos) {
        l.has_note = true;
        l.note = raw.substr(pct + 1);
        if (!l.note.empty() && l.note.back() == '\r') l.note.remove_suffix(1);
        raw = raw.substr(0, pct);
      }
      l.content = trim(raw);
      if (l.content.empty() && !l.has_note) continue;  // blank line
      return l;
    }
    Line eof;
    eof.no = lineno_ + (text_.empty() || text_.back() == '\n' ? 1 : 0);
    eof.eof = true;
    return eof;
  }

  void expect_keyword(const Line& l, std::string_view kw) {
    if (l.has_note) no_comment(l);
    if (l.eof || l.content != kw) fail(l.no, "expected '" + std::string(kw) + "', got " + shown(l.content, l.eof));
  }

  // Comments are kept only after a segment's 'h;inOut;semantic;' line (seed 001 Fig. 2);
  // anywhere else they would be lost on export, so they are refused.
  [[noreturn]] void no_comment(const Line& l) {
    fail(l.no, std::string("expected no '%' comment ") +
                   (l.content.empty() ? "on a line of its own" : "on this line") +
                   " (only after 'h;inOut;semantic;'), got '%" + std::string(l.note.substr(0, 40)) + "'");
  }

  std::vector<std::string_view> fields(const Line& l, size_t n, const std::string& layout,
                                       bool comment_allowed = false) {
    if (l.eof) fail(l.no, "expected '" + layout + "', got end of file");
    if (l.has_note && !comment_allowed) no_comment(l);
    std::string_view c = l.content;
    if (c.empty() || c.back() != ';')
      fail(l.no, "expected '" + layout + "' (every field ends with ';'), got " + shown(c));
    c.remove_suffix(1);
    std::vector<std::string_view> out;
    size_t start = 0;
    for (;;) {
      size_t semi = c.find(';', start);
      out.push_back(trim(c.substr(start, semi == std::string_view::npos ? std::string_view::npos : semi - start)));
      if (semi == std::string_view::npos) break;
      start = semi + 1;
    }
    if (out.size() != n)
      fail(l.no, "expected " + std::to_string(n) + " fields '" + layout + "', got " + std::to_string(out.size()) +
                     " in " + shown(l.content));
    return out;
  }

  double number(const Line& l, std::string_view f, std::string_view what) {
    double v = 0;
    auto [end, ec] = std::from_chars(f.data(), f.data() + f.size(), v);
    if (f.empty() || end != f.data() + f.size() || ec == std::errc::invalid_argument)
      fail(l.no, "expected a number for " + std::string(what) + ", got " + shown(f));
    if (ec == std::errc::result_out_of_range)
      fail(l.no, "expected a number within double range for " + std::string(what) + ", got " + shown(f));
    if (!std::isfinite(v)) fail(l.no, "expected a finite number for " + std::string(what) + ", got " + shown(f));
    if (std::abs(v) > kMaxCoordinate)
      fail(l.no, "expected |" + std::string(what) + "| <= " + format_number(kMaxCoordinate) + ", got " + shown(f));
    return v;
  }

  long long integer(const Line& l, std::string_view f, std::string_view what, long long lo, long long hi) {
    long long v = 0;
    auto [end, ec] = std::from_chars(f.data(), f.data() + f.size(), v);
    if (f.empty() || end != f.data() + f.size() || ec != std::errc() || v < lo || v > hi)
      fail(l.no, "expected " + std::string(what) + " (an integer), got " + shown(f));
    return v;
  }

  [[noreturn]] void fail(size_t line, const std::string& msg) { throw MapFormatError(file_, line, msg); }

  std::string_view text_;
  std::string file_;
  size_t pos_ = 0;
  size_t lineno_ = 0;
  MapKind kind_;
  std::map<int, size_t> first_seen_;  // obstacle id -> line of its header fields
};

}  // namespace

Map read_seed(std::string_view text, const std::string& file, MapKind kind) {
  // A UTF-8 byte-order mark, as some editors write, is not part of the map.
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  return Reader(text, file, kind).read();
}

Map read_seed_file(const std::string& path, MapKind kind) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(path + ": expected a readable file, got an error opening it");
  std::ostringstream ss;
  ss << in.rdbuf();
  return read_seed(ss.str(), path, kind);
}

std::string write_seed(const Map& m) {
  std::string out;
  out.reserve(64 + m.segment_count() * 48);
  auto num = [&](double v) { out += format_number(v); out += ';'; };
  out += "border;\n";
  num(m.border.mx1); num(m.border.my1); out += '\n';
  num(m.border.mx4); num(m.border.my4); out += "\n#\n";
  for (const Obstacle& o : m.obstacles) {
    out += "obstacle;\n";
    out += std::to_string(o.id) + ';' + std::to_string(static_cast<int>(o.type)) + ';' +
           std::to_string(o.segments.size()) + ';' + o.semantic + ";\n#\n";
    for (const Segment& s : o.segments) {
      num(s.a.x); num(s.a.y); out += '\n';
      num(s.b.x); num(s.b.y); out += '\n';
      num(s.h); out += std::to_string(s.in_out) + ';' + s.semantic + ';';
      if (!s.note.empty()) out += '%' + s.note;
      out += "\n#\n";
    }
  }
  return out;
}

}  // namespace fleetmap
