#pragma once
// Reading what a request says: its query parameters and the fields of its JSON body,
// each refused with 400 bad_input naming the field and what was expected (STYLE: errors
// name the field), before anything reaches the database.
#include <initializer_list>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "server/web/api/api.h"

namespace fleetmap::web {

// 400 bad_input: "field: message".
ApiError bad_field(const std::string& field, const std::string& message);

// The query parameter, or nullopt when the request has none.
std::optional<std::string> query_value(const ApiRequest& req, const std::string& key);

// A whole number in [min, max] (default when absent); 400 otherwise.
long long query_integer(const ApiRequest& req, const std::string& key, long long fallback, long long min,
                        long long max);

// The body as an object: null (no body) counts as {}; anything else but an object is
// 400. Members not in `known` are 400 too, so a misspelt field is not silently ignored.
const nlohmann::json& body_object(const ApiRequest& req, std::initializer_list<const char*> known);

bool has_field(const nlohmann::json& body, const char* field);  // present and not null
double finite_number(const nlohmann::json& body, const char* field);  // required, finite
std::optional<double> optional_number(const nlohmann::json& body, const char* field);  // absent/null: nullopt
std::string text_field(const nlohmann::json& body, const char* field);  // required, a non-empty string

}  // namespace fleetmap::web
