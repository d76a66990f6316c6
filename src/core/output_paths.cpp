#include "core/output_paths.h"

#include <unistd.h>

#include "core/errors.h"
#include "core/text.h"

namespace pond {
namespace fs = std::filesystem;

bool same_file(const fs::path& a, const fs::path& b) {
  std::error_code ea, eb;
  if (fs::exists(a, ea) && fs::exists(b, eb)) {
    std::error_code ec;
    const bool same = fs::equivalent(a, b, ec);
    if (!ec) return same;
  }
  const auto place = [](const fs::path& p) {
    std::error_code ec;
    const fs::path folder = p.parent_path().empty() ? fs::path(".") : p.parent_path();
    const fs::path canonical = fs::weakly_canonical(folder, ec);
    return (ec ? folder.lexically_normal() : canonical) / p.filename();
  };
  return place(a) == place(b);
}

void check_distinct_outputs(const NamedPaths& outputs) {
  std::vector<const std::pair<std::string, fs::path>*> seen;
  for (const auto& output : outputs) {
    if (output.second.empty()) continue;
    for (const auto* earlier : seen)
      if (same_file(earlier->second, output.second))
        throw InputError(output.first + " " + quote(output.second.string()) + " names the same file as " +
                         earlier->first + " " + quote(earlier->second.string()));
    seen.push_back(&output);
  }
}

void check_outputs_spare_inputs(const NamedPaths& outputs, const NamedPaths& inputs) {
  for (const auto& [output_flag, output] : outputs)
    for (const auto& [input_flag, input] : inputs)
      if (!output.empty() && !input.empty() && same_file(output, input))
        throw InputError(output_flag + " " + quote(output.string()) + " names the same file as its input " + input_flag +
                         " " + quote(input.string()));
}

void check_name_length(const fs::path& path, const fs::path& folder) {
  const long name_max = ::pathconf(folder.c_str(), _PC_NAME_MAX), path_max = ::pathconf(folder.c_str(), _PC_PATH_MAX);
  const std::size_t name = path.filename().string().size(), whole = path.string().size();
  if (name_max > 0 && name + kTemporaryNameRoom > static_cast<std::size_t>(name_max))
    throw InputError("output file name " + quote(path.filename().string()) + " has " + std::to_string(name) +
                     " bytes; its folder takes at most " + std::to_string(name_max - static_cast<long>(kTemporaryNameRoom)) +
                     " (NAME_MAX " + std::to_string(name_max) + ", less room for the temporary name)");
  if (path_max > 0 && whole + kTemporaryNameRoom >= static_cast<std::size_t>(path_max))
    throw InputError("output path of " + std::to_string(whole) + " bytes is longer than the " +
                     std::to_string(path_max - 1 - static_cast<long>(kTemporaryNameRoom)) + " its file system takes (PATH_MAX " +
                     std::to_string(path_max) + ")");
}

}  // namespace pond
