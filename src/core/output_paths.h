#pragma once
// Output paths judged by what they name, not by their text: two outputs of one command must name
// two files, and a name must fit the file system before any work is done.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace pond {

// Whether `a` and `b` name the same file: the same file (inode) when both exist, otherwise the
// same file name in the same folder (folders compared canonically: "./x" and "x", a symlinked
// folder and its target).
bool same_file(const std::filesystem::path& a, const std::filesystem::path& b);

// Paths each with the option (or script line) that names it, for the messages.
using NamedPaths = std::vector<std::pair<std::string, std::filesystem::path>>;

// Throws InputError "OPTION_B names the same file as OPTION_A (PATH)" for the first two of
// `outputs` (option, path) that name the same file; empty paths are skipped.
void check_distinct_outputs(const NamedPaths& outputs);

// Throws InputError "OUTPUT PATH names the same file as its input INPUT (PATH)" for the first of
// `outputs` that names one of `inputs` (a run would overwrite what it reads); empty paths skipped.
void check_outputs_spare_inputs(const NamedPaths& outputs, const NamedPaths& inputs);

// Bytes an output's file name keeps free for the temporary names written first (".tmp.PID",
// ".partial.PID").
inline constexpr std::size_t kTemporaryNameRoom = 32;

// Throws InputError when `path`'s file name is longer than its folder's file system allows
// (NAME_MAX less kTemporaryNameRoom) or the whole path longer than PATH_MAX: refused up front, as a
// missing folder is, not after the work. `folder` is the path's existing folder.
void check_name_length(const std::filesystem::path& path, const std::filesystem::path& folder);

}  // namespace pond
