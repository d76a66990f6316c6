#pragma once
// Writing an output file so that it is either complete or absent: the bytes go to a temporary file
// beside the target, which is renamed over the target only after everything was written and flushed.
// A failure (full disk, killed process) never leaves a half-written file under the requested name,
// and never clobbers an existing one.
#include <cstddef>
#include <filesystem>
#include <span>
#include <string>

namespace pond {

// Throws InputError when the folder of `path` does not exist or is not a folder, or the name is too
// long for it (core/output_paths.h) (checked before any work, so bad paths fail fast), RuntimeError
// when writing fails.
void check_output_path(const std::filesystem::path& path);

// Atomically replaces `path` with `bytes`. Throws RuntimeError on failure, naming `shown_as` when
// given (a temporary file written for a later rename: its messages name the file asked for); the
// target is untouched.
void write_file_atomic(const std::filesystem::path& path, std::span<const std::byte> bytes,
                       const std::filesystem::path& shown_as = {});

std::string read_file(const std::filesystem::path& path);  // InputError when missing or unreadable

}  // namespace pond
