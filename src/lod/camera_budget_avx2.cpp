// node_budgets' AVX2 copy (budget_loop.h), chosen by node_budgets where the CPU has AVX2: built
// with AVX2's flags and inline namespace (pond_isa_sources in src/lod/CMakeLists.txt).
#include "lod/budget_loop.h"

namespace pond::lod {

void node_budgets_avx2(const NodePositions& p, const BudgetTerms& t, float* budget, bool all_in_view) {
  budget_loop(p, t, budget, all_in_view);
}

}  // namespace pond::lod
