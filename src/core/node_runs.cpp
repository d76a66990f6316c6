#include "core/node_runs.h"

#include <algorithm>
#include <tuple>

namespace pond::core {

NodeRuns::NodeRuns(std::span<const GridWindow> windows) {
  for (const GridWindow& w : windows)
    if (w.cols > 0)
      for (int r = w.row0; r < w.row0 + w.rows; ++r) runs_.push_back({r, w.col0, w.col0 + w.cols});
  normalize();
}

void NodeRuns::normalize() {
  std::sort(runs_.begin(), runs_.end(),
            [](const NodeRun& a, const NodeRun& b) { return std::tie(a.row, a.col0) < std::tie(b.row, b.col0); });
  std::size_t kept = 0;
  for (const NodeRun& r : runs_) {
    if (kept > 0 && runs_[kept - 1].row == r.row && r.col0 <= runs_[kept - 1].col1)
      runs_[kept - 1].col1 = std::max(runs_[kept - 1].col1, r.col1);
    else
      runs_[kept++] = r;
  }
  runs_.resize(kept);
  nodes_ = 0;
  for (const NodeRun& r : runs_) nodes_ += static_cast<std::size_t>(r.col1 - r.col0);
}

bool NodeRuns::covers(const GridWindow& w) const {
  if (w.rows <= 0 || w.cols <= 0) return true;
  // The run of each row starting at or before col0 (runs are disjoint: the last such one).
  auto at = std::upper_bound(runs_.begin(), runs_.end(), NodeRun{w.row0, w.col0, 0},
                             [](const NodeRun& a, const NodeRun& b) { return std::tie(a.row, a.col0) < std::tie(b.row, b.col0); });
  for (int r = w.row0; r < w.row0 + w.rows; ++r) {
    if (r > w.row0)
      at = std::upper_bound(at, runs_.end(), NodeRun{r, w.col0, 0},
                            [](const NodeRun& a, const NodeRun& b) { return std::tie(a.row, a.col0) < std::tie(b.row, b.col0); });
    if (at == runs_.begin()) return false;
    const NodeRun& run = *std::prev(at);
    if (run.row != r || run.col1 < w.col0 + w.cols) return false;
  }
  return true;
}

NodeRuns NodeRuns::minus(const NodeRuns& other) const {
  NodeRuns out;
  auto o = other.runs_.begin();
  for (const NodeRun& run : runs_) {
    int from = run.col0;
    while (o != other.runs_.end() && (o->row < run.row || (o->row == run.row && o->col1 <= from))) ++o;
    for (auto p = o; p != other.runs_.end() && p->row == run.row && p->col0 < run.col1; ++p) {
      if (p->col0 > from) out.runs_.push_back({run.row, from, p->col0});
      from = std::max(from, p->col1);
    }
    if (from < run.col1) out.runs_.push_back({run.row, from, run.col1});
  }
  out.normalize();
  return out;
}

void NodeRuns::add(const NodeRuns& other) {
  runs_.insert(runs_.end(), other.runs_.begin(), other.runs_.end());
  normalize();
}

}  // namespace pond::core
