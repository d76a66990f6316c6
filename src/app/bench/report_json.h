#pragma once
// A Report as JSON (the layout bench/schema.json describes) and back: --json writes it, --compare
// reads an earlier one.
#include <string>

#include "app/bench/report.h"

namespace pond::bench {

inline constexpr const char* kSchemaId = "pond-bench/1";

std::string to_json(const Report& report);
// Throws InputError naming `source` and what is wrong: not JSON, another schema, a figure
// without a name, a unit or a finite median.
Report from_json(const std::string& text, const std::string& source);

}  // namespace pond::bench
