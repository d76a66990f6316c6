#pragma once
// Parts of a grid of nodes, for reading a state back in parts: a rectangle (GridWindow), and a set
// of nodes kept as runs along rows (NodeRuns), merged, which is the shape a copy of a row-major
// array takes (one copy per run).
#include <cstddef>
#include <span>
#include <vector>

namespace pond::core {

// Rows [row0, row0 + rows) by columns [col0, col0 + cols).
struct GridWindow {
  int row0 = 0, col0 = 0, rows = 0, cols = 0;
};

// Nodes [col0, col1) of one row.
struct NodeRun {
  int row = 0, col0 = 0, col1 = 0;
};

class NodeRuns {
 public:
  NodeRuns() = default;
  // The nodes of `windows`, each node once.
  explicit NodeRuns(std::span<const GridWindow> windows);

  // Ordered by row, then column; disjoint and not touching.
  std::span<const NodeRun> runs() const { return runs_; }
  std::size_t nodes() const { return nodes_; }
  bool empty() const { return runs_.empty(); }
  // Whether every node of `w` is in the set.
  bool covers(const GridWindow& w) const;
  // The nodes of this set that `other` lacks.
  NodeRuns minus(const NodeRuns& other) const;
  // This set and `other`'s nodes.
  void add(const NodeRuns& other);

 private:
  void normalize();  // sorts, merges overlapping and touching runs, counts the nodes

  std::vector<NodeRun> runs_;
  std::size_t nodes_ = 0;
};

}  // namespace pond::core
