#pragma once
// Which bending the tree uses: the article's (branches stretch) or the length-preserving one.
#include <cstdint>

#include "shared/tree_wind.h"

namespace pond::tree {

enum class BendMode : std::uint32_t {
  article = shared::tree_wind::kTreeBendArticle,
  keep_length = shared::tree_wind::kTreeBendKeepLength,
};

}  // namespace pond::tree
