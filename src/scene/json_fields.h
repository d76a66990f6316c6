#pragma once
// Typed, path-aware access to one JSON object of a scene file. Every read names the key's full
// path ("physics.mass", "perturbations[2].radius") in its error, and finish() rejects keys that
// were never read, so typos are errors instead of silently ignored settings.
#include <array>
#include <cstdint>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <string_view>

namespace pond::scene {

class JsonFields {
 public:
  // `source` names the file in messages, already escaped (core/text.h).
  JsonFields(const nlohmann::json& object, std::string path, std::string source);

  bool has(const char* key) const;
  double number(const char* key, double fallback);
  std::int64_t integer(const char* key, std::int64_t fallback, std::int64_t min, std::int64_t max);
  std::string text(const char* key, const std::string& fallback,
                   std::initializer_list<const char*> allowed);
  bool boolean(const char* key, bool fallback);  // true / false only (no 0/1, no "yes")
  const nlohmann::json& array(const char* key);  // empty array when absent
  const nlohmann::json& object(const char* key);  // empty object when absent
  std::string child(const char* key) const;      // the path of a member
  void finish() const;                            // throws on keys never read

  // Errors about a member or about the object itself.
  [[noreturn]] void fail(const char* key, const std::string& what) const;
  [[noreturn]] void fail(const std::string& what) const;

  // Reads "key": [x, y, z] of three finite numbers; `fallback` when absent.
  std::array<double, 3> vec3(const char* key, std::array<double, 3> fallback);

  // Reads "key": [a, b] as two integers in [min, max] with a <= b.
  void index_range(const char* key, int max_index, int& lo, int& hi);

 private:
  const nlohmann::json& member(const char* key);
  const nlohmann::json& object_;
  std::string path_, source_;
  std::set<std::string> read_;
};

// Parses a scene file's text. Throws InputError "SOURCE: invalid JSON: ..." for malformed text and
// "SOURCE: KEY.PATH is given twice" for a key repeated in one object (nlohmann would keep the last
// silently). `source` is already escaped.
nlohmann::json parse_json(std::string_view text, const std::string& source);

// The object at `path` of `json`, type-checked. Throws InputError naming `path`.
const nlohmann::json& require_object(const nlohmann::json& json, const std::string& path,
                                     const std::string& source);

}  // namespace pond::scene
