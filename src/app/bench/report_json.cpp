#include "app/bench/report_json.h"

#include <cmath>
#include <nlohmann/json.hpp>

#include "core/errors.h"

namespace pond::bench {
namespace {

using nlohmann::json;

json figure_json(const Figure& f) {
  json j = {{"name", f.name}, {"what", f.what}, {"unit", f.unit}, {"better", f.higher_is_better ? "higher" : "lower"},
            {"median", f.median()}, {"min", f.min()}, {"max", f.max()}, {"samples", f.samples}};
  if (f.hash) j["hash"] = *f.hash;
  if (f.triangles) j["triangles"] = *f.triangles;
  return j;
}

}  // namespace

std::string to_json(const Report& r) {
  json figures = json::array();
  for (const Figure& f : r.figures) figures.push_back(figure_json(f));
  json j = {{"schema", kSchemaId},
            {"pond", r.version},
            {"date", r.date},
            {"quick", r.quick},
            {"machine", {{"cpu", r.machine.cpu}, {"cores", r.machine.cores},
                         {"instruction_sets", r.machine.instruction_sets}, {"memory_bytes", r.machine.memory_bytes},
                         {"load_average", r.machine.load_average}}},
            {"device", nullptr},
            {"hashes_agree", r.hashes_agree},
            {"figures", figures},
            {"notes", r.notes}};
  if (r.device) {
    const Device& d = *r.device;
    j["device"] = {{"name", d.name}, {"type", d.type}, {"driver", d.driver}, {"driver_version", d.driver_version},
                   {"api_version", d.api_version}, {"timestamps", d.timestamps}};
    if (!d.timestamps) j["device"]["no_timestamps"] = d.no_timestamps;
  }
  return j.dump(2) + "\n";
}

Report from_json(const std::string& text, const std::string& source) {
  json j;
  try {
    j = json::parse(text);
  } catch (const json::exception& e) {
    throw InputError(source + ": not a pond bench JSON file (" + e.what() + ")");
  }
  if (!j.is_object() || !j.contains("schema") || j["schema"] != kSchemaId)
    throw InputError(source + ": not a pond bench JSON file (no \"schema\": \"" + kSchemaId + "\")");
  Report r;
  try {
    r.version = j.value("pond", "");
    r.date = j.value("date", "");
    r.quick = j.value("quick", false);
    if (!j.contains("figures") || !j["figures"].is_array()) throw InputError(source + ": \"figures\" is not an array");
    for (std::size_t k = 0; k < j["figures"].size(); ++k) {
      const json& f = j["figures"][k];
      const std::string where = source + ": figures[" + std::to_string(k) + "]";
      if (!f.is_object() || !f.contains("name") || !f["name"].is_string() || !f.contains("unit") ||
          !f["unit"].is_string() || !f.contains("median") || !f["median"].is_number() ||
          !std::isfinite(f["median"].get<double>()) || !f.contains("better") ||
          (f["better"] != "higher" && f["better"] != "lower"))
        throw InputError(where + " lacks a name, a unit, a finite median or \"better\": higher|lower");
      Figure g = make_figure(f["name"].get<std::string>(), f.value("what", ""), f["unit"].get<std::string>(), f["better"] == "higher");
      g.samples.push_back(f["median"].get<double>());  // the median is what a comparison reads
      r.figures.push_back(std::move(g));
    }
  } catch (const json::exception& e) {
    throw InputError(source + ": " + e.what());
  }
  return r;
}

}  // namespace pond::bench
