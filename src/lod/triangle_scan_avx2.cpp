// The exact scan's AVX2 copy (scan_rows.h), chosen by within_budget where ScanBudgets::wide, and
// that of the thresholds it compares with (scan_thresholds()): built with AVX2's flags and inline
// namespace (pond_isa_sources in src/lod/CMakeLists.txt).
#include "lod/scan_rows.h"
#include "sim/wide_avx2.h"

namespace pond::lod {

void scan_thresholds_avx2(const float* budget, std::size_t n, float largest, float* sure2) {
  scan_thresholds_with<sim::WideAvx2>(budget, n, largest, sure2);
}

bool scan_triangle_avx2(const GridHierarchy& grid, const NodePositions& p, const ScanBudgets& budgets, float largest,
                        const Tri& t, const TriCorners* c, const Tri& region, long long* visited) {
  return scan_triangle<sim::WideAvx2>(grid, p, budgets, largest, t, c, region, visited);
}

}  // namespace pond::lod
