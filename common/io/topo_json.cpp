#include "common/io/topo_json.h"

#include <climits>
#include <cmath>
#include <fstream>
#include <sstream>
#include <unordered_map>
#include <vector>

#include <nlohmann/json.hpp>

namespace fleetmap {
namespace {

// Sorted keys: the layout of the AMRL files.
using Json = nlohmann::json;

// A value as it appears in an error message: short JSON text, or its kind.
std::string got(const Json& v) {
  if (v.is_number_float() && !std::isfinite(v.get<double>())) return "a number too large for a double";
  if (v.is_object()) return "an object";
  if (v.is_array()) return "an array";
  std::string s = v.dump(-1, ' ', false, Json::error_handler_t::replace);
  if (s.size() > 40) s = s.substr(0, 37) + "...";
  return s;
}

class Reader {
 public:
  explicit Reader(const std::string& file) : file_(file) {}

  [[noreturn]] void fail(const std::string& where, const std::string& message) const {
    throw TopoFormatError(file_, where, message);
  }

  // A required member of an object; nullptr for an optional one that is absent.
  const Json* member(const Json& obj, const char* key, const std::string& where, bool required) const {
    auto it = obj.find(key);
    if (it == obj.end()) {
      if (required) fail(where + "." + key, "expected a value, the member is missing");
      return nullptr;
    }
    return &*it;
  }

  int id(const Json& v, const std::string& where) const {
    if (!v.is_number_integer()) fail(where, "expected an integer id, got " + got(v));
    // number_unsigned for ids above INT64_MAX would wrap in get<long long>; check it first.
    if (v.is_number_unsigned() && v.get<unsigned long long>() > static_cast<unsigned long long>(INT_MAX))
      fail(where, "expected an id in 0.." + std::to_string(INT_MAX) + ", got " + got(v));
    const long long x = v.get<long long>();
    if (x < 0 || x > INT_MAX) fail(where, "expected an id in 0.." + std::to_string(INT_MAX) + ", got " + got(v));
    return static_cast<int>(x);
  }

  double number(const Json& v, const std::string& where) const {
    if (!v.is_number()) fail(where, "expected a number, got " + got(v));
    const double x = v.get<double>();
    if (!std::isfinite(x)) fail(where, "expected a finite number, got " + got(v));
    return x;
  }

  bool flag(const Json& edge, const char* key, const std::string& where) const {
    const Json* v = member(edge, key, where, false);
    if (!v) return false;
    if (!v->is_boolean()) fail(where + "." + key, "expected true or false, got " + got(*v));
    return v->get<bool>();
  }

  const Json& array(const Json& top, const char* key) const {
    const Json* v = member(top, key, "(top level)", false);
    if (!v) fail(key, "expected an array, the member is missing");
    if (!v->is_array()) fail(key, "expected an array, got " + got(*v));
    return *v;
  }

  TopoNode node(const Json& v, const std::string& where) const {
    if (!v.is_object()) fail(where, "expected an object with \"id\" and \"loc\", got " + got(v));
    TopoNode n;
    n.id = id(*member(v, "id", where, true), where + ".id");
    const Json& loc = *member(v, "loc", where, true);
    if (!loc.is_object()) fail(where + ".loc", "expected an object with \"x\" and \"y\", got " + got(loc));
    n.pos.x = number(*member(loc, "x", where + ".loc", true), where + ".loc.x");
    n.pos.y = number(*member(loc, "y", where + ".loc", true), where + ".loc.y");
    if (const Json* name = member(v, "name", where, false)) {
      if (!name->is_string()) fail(where + ".name", "expected a string, got " + got(*name));
      n.name = name->get<std::string>();
    }
    return n;
  }

  TopoEdge edge(const Json& v, const std::string& where,
                const std::unordered_map<int, size_t>& node_index) const {
    if (!v.is_object()) fail(where, "expected an object with \"s0_id\" and \"s1_id\", got " + got(v));
    TopoEdge e;
    for (auto [key, out] : {std::pair{"s0_id", &e.a}, std::pair{"s1_id", &e.b}}) {
      const std::string w = where + "." + key;
      *out = id(*member(v, key, where, true), w);
      if (!node_index.count(*out)) fail(w, "expected the id of a node, got " + std::to_string(*out));
    }
    if (e.a == e.b) fail(where + ".s1_id", "expected a node other than s0_id, got " + std::to_string(e.b) + " twice");
    e.door = flag(v, "has_door", where);
    e.automated_door = flag(v, "has_automated_door", where);
    const bool stairs = flag(v, "has_stairs", where);
    const bool elevator = flag(v, "has_elevator", where);
    if (stairs && elevator) fail(where + ".has_elevator", "expected stairs or an elevator, got both");
    e.type = edge_type_from_flags(e.door, e.automated_door, stairs, elevator);
    const bool flagged = e.door || e.automated_door || stairs || elevator;
    if (const Json* t = member(v, "type", where, false)) {
      const auto type = t->is_string() ? edge_type_from_string(t->get<std::string>()) : std::nullopt;
      if (!type) fail(where + ".type", "expected one of corridor, room, door, stairs, elevator, got " + got(*t));
      // The flags win over nothing: an explicit type must say what they say.
      if (flagged && *type != e.type)
        fail(where + ".type", "expected \"" + std::string(to_string(e.type)) + "\" as the has_* flags say, got " +
                                  got(*t));
      e.type = *type;
    }
    if (const Json* c = member(v, "max_clearance", where, false)) {
      e.max_clearance = number(*c, where + ".max_clearance");
      if (e.max_clearance < 0) fail(where + ".max_clearance", "expected a clearance >= 0, got " + got(*c));
    }
    if (const Json* s = member(v, "max_speed", where, false)) {
      e.max_speed = number(*s, where + ".max_speed");
      if (e.max_speed <= 0) fail(where + ".max_speed", "expected a speed > 0, got " + got(*s));
    }
    return e;
  }

 private:
  const std::string& file_;
};

// Builds the document as nlohmann's own DOM parser does, remembering where it is, so
// that a number too large for a double ("1e999", which the parser refuses itself) is
// reported with its element and field like every other problem.
class TrackingSax {
 public:
  TrackingSax(Json& root, const std::string& file) : dom_(root, true), file_(file) {}

  bool null() { return value(), dom_.null(); }
  bool boolean(bool v) { return value(), dom_.boolean(v); }
  bool number_integer(Json::number_integer_t v) { return value(), dom_.number_integer(v); }
  bool number_unsigned(Json::number_unsigned_t v) { return value(), dom_.number_unsigned(v); }
  bool number_float(Json::number_float_t v, const Json::string_t& s) { return value(), dom_.number_float(v, s); }
  bool string(Json::string_t& v) { return value(), dom_.string(v); }
  bool binary(Json::binary_t& v) { return value(), dom_.binary(v); }
  bool start_object(std::size_t n) {
    value();
    frames_.push_back({false, 0, {}});
    return dom_.start_object(n);
  }
  bool key(Json::string_t& k) {
    frames_.back().key = k;
    return dom_.key(k);
  }
  bool end_object() {
    frames_.pop_back();
    return dom_.end_object();
  }
  bool start_array(std::size_t n) {
    value();
    frames_.push_back({true, 0, {}});
    return dom_.start_array(n);
  }
  bool end_array() {
    frames_.pop_back();
    return dom_.end_array();
  }
  template <class Exception>
  bool parse_error(std::size_t position, const std::string& token, const Exception& ex) {
    if (ex.id == 406)  // out_of_range.406: number overflow
      throw TopoFormatError(file_, path(), "expected a finite number, got " + token + ", too large for a double");
    return dom_.parse_error(position, token, ex);
  }

 private:
  struct Frame {
    bool array;
    size_t next = 0;  // arrays: index of the next element
    std::string key;  // objects: the last key read
  };
  void value() {
    if (!frames_.empty() && frames_.back().array) ++frames_.back().next;
  }
  // Where the value being read goes: "nodes[2].loc.y".
  std::string path() const {
    std::string p;
    for (size_t i = 0; i < frames_.size(); ++i) {
      const Frame& f = frames_[i];
      if (f.array) p += "[" + std::to_string(i + 1 == frames_.size() ? f.next : f.next - 1) + "]";
      else p += (p.empty() ? "" : ".") + f.key;
    }
    return p.empty() ? "(top level)" : p;
  }

  nlohmann::detail::json_sax_dom_parser<Json> dom_;
  const std::string& file_;
  std::vector<Frame> frames_;
};

// nlohmann: "[json.exception.parse_error.101] parse error at line 2, column 7: syntax error ..."
TopoFormatError syntax_error(const std::string& file, const nlohmann::json::parse_error& e) {
  std::string msg = e.what();
  if (auto p = msg.find("] "); p != std::string::npos) msg = msg.substr(p + 2);
  const std::string lead = "parse error at ";
  if (msg.rfind(lead, 0) == 0) {
    if (auto colon = msg.find(": ", lead.size()); colon != std::string::npos)
      return TopoFormatError(file, msg.substr(lead.size(), colon - lead.size()), msg.substr(colon + 2));
  }
  return TopoFormatError(file, "byte " + std::to_string(e.byte), msg);
}

}  // namespace

TopoFormatError::TopoFormatError(std::string file, std::string where, std::string message)
    : FileFormatError(file + ": " + where + ": " + message),
      file_(std::move(file)),
      where_(std::move(where)),
      message_(std::move(message)) {}

TopoGraph read_topo_json(std::string_view text, const std::string& file) {
  Json top;
  try {
    TrackingSax sax(top, file);
    Json::sax_parse(text.begin(), text.end(), &sax);
  } catch (const Json::parse_error& e) {
    throw syntax_error(file, e);
  }
  Reader in(file);
  if (!top.is_object()) in.fail("(top level)", "expected an object with \"nodes\" and \"edges\", got " + got(top));

  // Nodes first: edges refer to them.
  const Json& nodes = in.array(top, "nodes");
  std::vector<TopoNode> ns;
  std::unordered_map<int, size_t> index;
  ns.reserve(nodes.size());
  for (size_t i = 0; i < nodes.size(); ++i) {
    const std::string where = "nodes[" + std::to_string(i) + "]";
    TopoNode n = in.node(nodes[i], where);
    auto [it, fresh] = index.emplace(n.id, i);
    if (!fresh)
      in.fail(where + ".id", "expected a unique id, got " + std::to_string(n.id) + " as in nodes[" +
                                 std::to_string(it->second) + "]");
    ns.push_back(std::move(n));
  }
  const Json& edges = in.array(top, "edges");
  std::vector<TopoEdge> es;
  es.reserve(edges.size());
  for (size_t i = 0; i < edges.size(); ++i) es.push_back(in.edge(edges[i], "edges[" + std::to_string(i) + "]", index));

  // Everything was checked above, so building cannot fail.
  TopoGraph g;
  for (TopoNode& n : ns) g.add_node(std::move(n));
  for (TopoEdge& e : es) g.add_edge(std::move(e));
  return g;
}

TopoGraph read_topo_json_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError(path + ": (file): expected a readable file");
  std::ostringstream ss;
  ss << in.rdbuf();
  return read_topo_json(ss.str(), path);
}

std::string write_topo_json(const TopoGraph& g) {
  Json edges = Json::array();
  for (const TopoEdge& e : g.edges()) {
    const bool stairs = e.type == EdgeType::Stairs, elevator = e.type == EdgeType::Elevator;
    Json j = {{"s0_id", e.a},
              {"s1_id", e.b},
              {"has_door", e.door},
              {"has_automated_door", e.automated_door},
              {"has_stairs", stairs},
              {"has_elevator", elevator}};
    if (std::isfinite(e.max_clearance)) j["max_clearance"] = e.max_clearance;
    if (std::isfinite(e.max_speed)) j["max_speed"] = e.max_speed;
    if (e.type != edge_type_from_flags(e.door, e.automated_door, stairs, elevator))
      j["type"] = std::string(to_string(e.type));
    edges.push_back(std::move(j));
  }
  Json nodes = Json::array();
  for (const TopoNode& n : g.nodes()) {
    Json j = {{"id", n.id}, {"loc", {{"x", n.pos.x}, {"y", n.pos.y}}}};
    if (!n.name.empty()) j["name"] = n.name;
    nodes.push_back(std::move(j));
  }
  const Json top = {{"edges", std::move(edges)}, {"nodes", std::move(nodes)}};
  try {
    return top.dump(4) + "\n";
  } catch (const Json::type_error& e) {
    throw std::invalid_argument(std::string("navigation JSON: expected UTF-8 node names, got: ") + e.what());
  }
}

}  // namespace fleetmap
