// pond tree: grows the wind tree and writes the contract's PREFIX.vertices.npy (float32 (V, 12):
// position, wind vector X, wind vector Z, jitter coefficients) and PREFIX.parents.npy (int32 (V),
// -1 for the root).
#include <cinttypes>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <string>
#include <unistd.h>

#include "app/commands.h"
#include "core/errors.h"
#include "core/npy.h"
#include "core/output_file.h"
#include "core/output_paths.h"
#include "core/text.h"
#include "tree/tree.h"

namespace pond::app {
namespace {
namespace fs = std::filesystem;

struct TreeOptions {
  std::string depth, seed, out;
};

// Decimal digits only: no sign, no fraction, no exponent, no spaces. False when out of range.
bool parse_unsigned(const std::string& text, std::uint64_t max, std::uint64_t& value) {
  if (text.empty() || text.size() > 20) return false;
  value = 0;
  for (char c : text) {
    if (c < '0' || c > '9') return false;
    const auto digit = static_cast<std::uint64_t>(c - '0');
    if (value > (max - digit) / 10) return false;
    value = value * 10 + digit;
  }
  return true;
}

int parse_depth(const std::string& text) {
  std::uint64_t d = 0;
  if (!parse_unsigned(text, std::numeric_limits<std::uint32_t>::max(), d) ||
      d < static_cast<std::uint64_t>(tree::kMinTreeDepth) ||
      d > static_cast<std::uint64_t>(tree::kMaxTreeDepth))
    throw InputError("--depth " + quote(text) + " must be an integer from " +
                     std::to_string(tree::kMinTreeDepth) + " to " +
                     std::to_string(tree::kMaxTreeDepth));
  return static_cast<int>(d);
}

std::uint64_t parse_seed(const std::string& text) {
  std::uint64_t s = 0;
  if (!parse_unsigned(text, std::numeric_limits<std::uint64_t>::max(), s))
    throw InputError("--seed " + quote(text) + " must be a non-negative integer below 2^64");
  return s;
}

// Writes both files or neither: each goes to a temporary name first (atomically), and only when both
// are complete are they renamed into place. If the second rename fails, the first file is removed
// again, so a run never leaves one new file beside an old or missing partner.
fs::path partial(const fs::path& path) {
  fs::path tmp = path;
  tmp += ".partial." + std::to_string(::getpid());
  return tmp;
}

// Writes `bytes` to `path`'s partial name; a failure names `path`, the file the user asked for.
void write_partial(const fs::path& path, std::span<const std::byte> bytes) {
  write_file_atomic(partial(path), bytes, path);
}

void write_pair(const fs::path& first, std::span<const std::byte> first_bytes, const fs::path& second,
                std::span<const std::byte> second_bytes) {
  const fs::path first_tmp = partial(first), second_tmp = partial(second);
  std::error_code ec;
  write_partial(first, first_bytes);
  try {
    write_partial(second, second_bytes);
  } catch (...) {
    fs::remove(first_tmp, ec);
    throw;
  }
  fs::rename(first_tmp, first, ec);
  if (ec) {
    fs::remove(first_tmp, ec);
    fs::remove(second_tmp, ec);
    throw RuntimeError("cannot write " + quote(first.string()) + ": " + ec.message());
  }
  fs::rename(second_tmp, second, ec);
  if (ec) {
    const std::string why = ec.message();
    fs::remove(second_tmp, ec);
    fs::remove(first, ec);
    throw RuntimeError("cannot write " + quote(second.string()) + ": " + why);
  }
}

int run_tree(const TreeOptions& o) {
  tree::TreeParams params;
  params.depth = parse_depth(o.depth);
  params.seed = parse_seed(o.seed);
  const fs::path prefix = o.out;
  if (prefix.empty() || !prefix.has_filename())
    throw InputError("--out " + quote(o.out) + " must be a file name prefix such as out/tree, not a folder");
  const fs::path vertices_path = o.out + ".vertices.npy";
  const fs::path parents_path = o.out + ".parents.npy";
  // Before any work: a missing folder, a name too long for it (the partial names are the longest
  // that are written) write nothing.
  for (const fs::path& p : {vertices_path, parents_path, partial(vertices_path), partial(parents_path)}) check_output_path(p);
  check_distinct_outputs({{"--out's vertices", vertices_path}, {"--out's parents", parents_path}});  // a symlink

  const tree::Tree t = tree::grow_tree(params);
  const std::size_t vertex_shape[2] = {t.size(), static_cast<std::size_t>(
                                                     shared::tree_wind::kTreeVertexFloats)};
  const std::size_t parent_shape[1] = {t.size()};
  const std::vector<std::byte> vertices =
      npy_encode(NpyType::f32, vertex_shape, std::as_bytes(std::span(t.vertices)));
  const std::vector<std::byte> parents =
      npy_encode(NpyType::i32, parent_shape, std::as_bytes(std::span(t.parents)));
  write_pair(vertices_path, vertices, parents_path, parents);

  std::printf("tree: %zu vertices, depth %d, seed %" PRIu64 " -> %s (float32 %zu x 12), %s (int32 %zu)\n",
              t.size(), params.depth, params.seed, escaped(vertices_path.string()).c_str(), t.size(),
              escaped(parents_path.string()).c_str(), t.size());
  return 0;
}

}  // namespace

Command add_tree_command(CLI::App& app) {
  auto o = std::make_shared<TreeOptions>();
  CLI::App* sub = app.add_subcommand(
      "tree", "Grow the wind tree and write PREFIX.vertices.npy and PREFIX.parents.npy");
  // Depth and seed are read as text and parsed here, for one-line messages that say what is allowed.
  sub->add_option("--depth", o->depth, "Recursion depth 1..10 ((3^D-1)/2+1 vertices; 7 = 1094)")
      ->required()
      ->type_name("INT");
  sub->add_option("--seed", o->seed, "Random seed, a non-negative integer (same seed, same tree)")
      ->required()
      ->type_name("UINT64");
  sub->add_option("--out", o->out,
                  "Output prefix: writes PREFIX.vertices.npy float32 (V, 12) = position, wind "
                  "vector X, wind vector Z, jitter coefficients; PREFIX.parents.npy int32 (V)")
      ->required()
      ->type_name("PREFIX");
  return {sub, [o] { return run_tree(*o); }};
}

}  // namespace pond::app
