#include "server/web/api/request_fields.h"

#include <cmath>
#include <cstdlib>

namespace fleetmap::web {

ApiError bad_field(const std::string& field, const std::string& message) {
  return ApiError(400, "bad_input", field + ": " + message, 2);
}

std::optional<std::string> query_value(const ApiRequest& req, const std::string& key) {
  auto it = req.query.find(key);
  if (it == req.query.end()) return std::nullopt;
  return it->second;
}

long long query_integer(const ApiRequest& req, const std::string& key, long long fallback, long long min,
                        long long max) {
  const std::optional<std::string> text = query_value(req, key);
  if (!text) return fallback;
  const std::string expected = "expected a whole number in [" + std::to_string(min) + ", " + std::to_string(max) + "]";
  if (text->empty() || text->find_first_not_of("0123456789") != std::string::npos || text->size() > 18)
    throw bad_field(key, expected + ", got '" + *text + "'");
  const long long v = std::stoll(*text);
  if (v < min || v > max) throw bad_field(key, expected + ", got " + *text);
  return v;
}

const nlohmann::json& body_object(const ApiRequest& req, std::initializer_list<const char*> known) {
  static const nlohmann::json kEmpty = nlohmann::json::object();
  if (req.body.is_null()) return kEmpty;
  if (!req.body.is_object()) throw bad_field("body", "expected a JSON object, got " + std::string(req.body.type_name()));
  for (const auto& [name, value] : req.body.items()) {
    bool ok = false;
    std::string list;
    for (const char* k : known) {
      ok = ok || name == k;
      list += (list.empty() ? "" : ", ") + std::string(k);
    }
    if (!ok) throw bad_field(name, "unknown field; expected " + (list.empty() ? std::string("none") : list));
  }
  return req.body;
}

bool has_field(const nlohmann::json& body, const char* field) {
  auto it = body.find(field);
  return it != body.end() && !it->is_null();
}

double finite_number(const nlohmann::json& body, const char* field) {
  auto it = body.find(field);
  if (it == body.end() || it->is_null()) throw bad_field(field, "expected a number, got nothing");
  if (!it->is_number()) throw bad_field(field, "expected a number, got " + std::string(it->type_name()));
  const double v = it->get<double>();
  if (!std::isfinite(v)) throw bad_field(field, "expected a finite number");
  return v;
}

std::optional<double> optional_number(const nlohmann::json& body, const char* field) {
  if (!has_field(body, field)) return std::nullopt;
  return finite_number(body, field);
}

std::string text_field(const nlohmann::json& body, const char* field) {
  auto it = body.find(field);
  if (it == body.end() || it->is_null()) throw bad_field(field, "expected a string, got nothing");
  if (!it->is_string()) throw bad_field(field, "expected a string, got " + std::string(it->type_name()));
  std::string s = it->get<std::string>();
  if (s.empty()) throw bad_field(field, "expected a non-empty string");
  return s;
}

}  // namespace fleetmap::web
