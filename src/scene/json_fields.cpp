#include "scene/json_fields.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <sstream>
#include <vector>

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

// The objects and arrays open while parsing, for the path of a repeated key: an object's keys so
// far (a set once there are many), an array's index.
class OpenLevels {
 public:
  // Returns the repeated key's path, or "" when `key` is new in the innermost object.
  std::string add_key(const std::string& key) {
    Level& top = levels_.back();
    const bool seen = top.many ? top.many->contains(key)
                               : std::find(top.keys.begin(), top.keys.end(), key) != top.keys.end();
    if (seen) return path() + (levels_.size() > 1 ? "." : "") + escaped(key);
    top.keys.push_back(key);
    if (top.many) top.many->insert(key);
    else if (top.keys.size() > 16) top.many = std::make_unique<std::set<std::string>>(top.keys.begin(), top.keys.end());
    return {};
  }
  void element() {  // a value, object or array begins inside the innermost level
    if (!levels_.empty() && !levels_.back().object) ++levels_.back().index;
  }
  void open(bool object) { levels_.emplace_back().object = object; }
  void close() { levels_.pop_back(); }
  // The path of the value being read now (a number the parser could not hold): "physics.dt",
  // "bodies[0].position[1]"; "" at the top.
  std::string reading() const {
    if (levels_.empty()) return {};
    const Level& top = levels_.back();
    const std::string outer = path();
    if (!top.object) return outer + "[" + std::to_string(top.index + 1) + "]";
    if (top.keys.empty()) return outer;
    return outer + (outer.empty() ? "" : ".") + escaped(top.keys.back());
  }

 private:
  struct Level {
    bool object = true;
    std::size_t index = static_cast<std::size_t>(-1);
    std::vector<std::string> keys;
    std::unique_ptr<std::set<std::string>> many;
  };
  // The path to the innermost level: "bodies[2]", "grid".
  std::string path() const {
    std::string p;
    for (std::size_t k = 0; k + 1 < levels_.size(); ++k) {
      const Level& l = levels_[k];
      if (l.object) p += (p.empty() ? "" : ".") + escaped(l.keys.back());
      else p += "[" + std::to_string(l.index) + "]";
    }
    return p;
  }
  std::vector<Level> levels_;
};
}  // namespace

nlohmann::json parse_json(std::string_view text, const std::string& source) {
  using Event = nlohmann::json::parse_event_t;
  OpenLevels open;
  const auto callback = [&](int /*depth*/, Event event, nlohmann::json& parsed) {
    switch (event) {
      case Event::object_start: open.element(), open.open(true); break;
      case Event::array_start: open.element(), open.open(false); break;
      case Event::object_end:
      case Event::array_end: open.close(); break;
      case Event::value: open.element(); break;
      case Event::key:
        if (const std::string repeated = open.add_key(parsed.get<std::string>()); !repeated.empty())
          throw InputError(source + ": " + repeated + " is given twice");
        break;
    }
    return true;
  };
  try {
    return nlohmann::json::parse(text, callback);
  } catch (const nlohmann::json::exception& e) {
    // nlohmann's message is "[json.exception.parse_error.101] parse error at line 3, column 5: ...";
    // a number too large for a double ("1e999") is its out_of_range.406, also bad input, said with
    // the key it was given for. It quotes the text last read, where it writes only bytes below
    // 0x20 out: the rest is made printable here.
    std::string what = e.what();
    const auto p = what.find("] ");
    what = printable_line(p == std::string::npos ? what : what.substr(p + 2));
    if (e.id == 406) {
      const std::string key = open.reading();
      throw InputError(source + ": " + (key.empty() ? std::string("the scene") : key) + " is a number beyond a double's range (" + what + ")");
    }
    throw InputError(source + ": invalid JSON: " + what);
  }
}

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
