#pragma once
// What one `pond bench` run measures: the groups chosen with --only, and the sizes and repeats
// of the full run or of --quick (small sizes, under a minute on a 2-core machine).
#include <string>
#include <vector>

namespace pond::bench {

// The groups of figures, in the order they run; --only takes these names.
inline const std::vector<std::string>& group_names() {
  static const std::vector<std::string> names = {"gpu", "frame", "cpu", "lod", "bodies"};
  return names;
}

struct Plan {
  bool quick = false;
  std::vector<std::string> only;  // empty: every group
  std::string device;             // Vulkan device name (substring); empty: pond's usual choice
  bool validation = false;        // Vulkan validation on (tests): any message fails the run

  bool runs(const std::string& group) const;
  int repeats() const { return quick ? 3 : 5; }
  std::vector<int> solver_sizes() const;  // square grids, CPU and GPU solver
  std::vector<int> lod_sizes() const;
  int frame_grid() const { return quick ? 129 : 257; }
  int frame_width() const { return quick ? 640 : 1280; }
  int frame_height() const { return quick ? 360 : 720; }
  int frame_count() const { return quick ? 6 : 20; }  // frames of each kind, alternated
  int bodies_grid() const { return quick ? 129 : 257; }
  // Node-steps each sample of a solver figure runs (the steps are this over the grid's nodes).
  double node_steps_per_sample() const { return quick ? 4e6 : 4e7; }
};

// Throws InputError naming the first name of `only` that is not a group.
void check_groups(const std::vector<std::string>& only);

}  // namespace pond::bench
