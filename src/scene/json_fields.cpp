#include "scene/json_fields.h"

#include <cmath>
#include <sstream>

#include "core/errors.h"
#include "core/text.h"

namespace pond::scene {
namespace {
const char* type_name(const nlohmann::json& j) {
  if (j.is_boolean()) return "a boolean";
  if (j.is_number()) return "a number";
  if (j.is_string()) return "a string";
  if (j.is_array()) return "an array";
  if (j.is_object()) return "an object";
  return "null";
}
const nlohmann::json kEmptyArray = nlohmann::json::array();
const nlohmann::json kEmptyObject = nlohmann::json::object();
}  // namespace

const nlohmann::json& require_object(const nlohmann::json& json, const std::string& path,
                                     const std::string& source) {
  if (!json.is_object())
    throw InputError(source + ": " + (path.empty() ? std::string("the scene") : path) +
                     " must be an object, not " + type_name(json));
  return json;
}

JsonFields::JsonFields(const nlohmann::json& object, std::string path, std::string source)
    : object_(require_object(object, path, source)), path_(std::move(path)), source_(std::move(source)) {}

std::string JsonFields::child(const char* key) const {
  return path_.empty() ? std::string(key) : path_ + "." + key;
}

void JsonFields::fail(const char* key, const std::string& what) const {
  throw InputError(source_ + ": " + child(key) + " " + what);
}

void JsonFields::fail(const std::string& what) const {
  throw InputError(source_ + ": " + (path_.empty() ? std::string("scene") : path_) + " " + what);
}

bool JsonFields::has(const char* key) const { return object_.contains(key); }

const nlohmann::json& JsonFields::member(const char* key) {
  read_.insert(key);
  return object_.at(key);
}

double JsonFields::number(const char* key, double fallback) {
  if (!has(key)) return fallback;
  const auto& v = member(key);
  if (!v.is_number()) fail(key, std::string("must be a number, not ") + type_name(v));
  const double d = v.get<double>();
  if (!std::isfinite(d)) fail(key, "must be finite");
  return d;
}

std::int64_t JsonFields::integer(const char* key, std::int64_t fallback, std::int64_t min,
                                 std::int64_t max) {
  if (!has(key)) return fallback;
  const auto& v = member(key);
  std::int64_t i = 0;
  if (v.is_number_integer()) {
    if (v.is_number_unsigned() && v.get<std::uint64_t>() > static_cast<std::uint64_t>(max))
      fail(key, "must be at most " + std::to_string(max));
    i = v.get<std::int64_t>();
  } else if (v.is_number_float() && std::floor(v.get<double>()) == v.get<double>()) {
    const double d = v.get<double>();
    if (d > static_cast<double>(max)) fail(key, "must be at most " + std::to_string(max));
    if (d < static_cast<double>(min)) fail(key, "must be at least " + std::to_string(min));
    i = static_cast<std::int64_t>(d);
  } else {
    fail(key, std::string("must be an integer, not ") +
                  (v.is_number() ? "a fractional number" : type_name(v)));
  }
  if (i < min) fail(key, "must be at least " + std::to_string(min) + " (is " + std::to_string(i) + ")");
  if (i > max) fail(key, "must be at most " + std::to_string(max) + " (is " + std::to_string(i) + ")");
  return i;
}

std::string JsonFields::text(const char* key, const std::string& fallback,
                             std::initializer_list<const char*> allowed) {
  if (!has(key)) return fallback;
  const auto& v = member(key);
  if (!v.is_string()) fail(key, std::string("must be a string, not ") + type_name(v));
  std::string s = v.get<std::string>();
  if (allowed.size() == 0) return s;
  std::string list;
  for (const char* a : allowed) {
    if (s == a) return s;
    list += std::string(list.empty() ? "" : " | ") + a;
  }
  fail(key, "is " + quote(s) + ", expected " + list);
}

bool JsonFields::boolean(const char* key, bool fallback) {
  if (!has(key)) return fallback;
  const auto& v = member(key);
  if (!v.is_boolean()) fail(key, std::string("must be true or false, not ") + type_name(v));
  return v.get<bool>();
}

const nlohmann::json& JsonFields::array(const char* key) {
  if (!has(key)) return kEmptyArray;
  const auto& v = member(key);
  if (!v.is_array()) fail(key, std::string("must be an array, not ") + type_name(v));
  return v;
}

const nlohmann::json& JsonFields::object(const char* key) {
  if (!has(key)) return kEmptyObject;
  const auto& v = member(key);
  if (!v.is_object()) fail(key, std::string("must be an object, not ") + type_name(v));
  return v;
}

std::array<double, 3> JsonFields::vec3(const char* key, std::array<double, 3> fallback) {
  if (!has(key)) return fallback;
  const auto& v = array(key);
  if (v.size() != 3 || !v[0].is_number() || !v[1].is_number() || !v[2].is_number())
    fail(key, "must be an array of three numbers [x, y, z]");
  const std::array<double, 3> out{v[0].get<double>(), v[1].get<double>(), v[2].get<double>()};
  for (double d : out)
    if (!std::isfinite(d)) fail(key, "must be finite");
  return out;
}

void JsonFields::index_range(const char* key, int max_index, int& lo, int& hi) {
  if (!has(key)) fail(key, "is missing");
  const auto& v = member(key);
  if (!v.is_array() || v.size() != 2 || !v[0].is_number_integer() || !v[1].is_number_integer())
    fail(key, "must be an inclusive index range [first, last] of two integers");
  const auto a = v[0].get<std::int64_t>(), b = v[1].get<std::int64_t>();
  if (a < 0 || b > max_index || a > b)
  {
    std::string what = "[" + std::to_string(a);
    what += ", " + std::to_string(b);
    what += a > b ? "] is reversed" : "] is out of range [0, " + std::to_string(max_index) + "]";
    fail(key, what);
  }
  lo = static_cast<int>(a);
  hi = static_cast<int>(b);
}

void JsonFields::finish() const {
  for (const auto& [key, value] : object_.items())
    if (!read_.contains(key)) fail(escaped(key).c_str(), "is not a known key");
}

}  // namespace pond::scene
