// GLSL only: the bent position of one skeleton vertex read from the tree's storage buffers, in
// either bend mode. tree.vert calls it for the length-preserving bend, and tree_pose.comp (the
// parity test) runs it for every vertex, so the test checks the very code the renderer runs. Kept
// under shared/ so that cmake/Shaders.cmake rebuilds every shader when it changes.
//
// Length-preserving bend on the GPU, by walking ancestors: a vertex's kept position depends on all
// its ancestors' (src/tree/bend.cpp walks the whole tree from the root). A tree has at most 10
// levels, so each vertex collects its chain to the root (<= kTreeMaxChain vertices) and replays
// the CPU's recurrence along it:
//     kept(root) = article(root);  kept(c) = keep_length(kept(p), article(p), article(c), rest(c))
// with the same shared functions in the same order as the CPU, so the result is the CPU's bits.
// No extra pass and no synchronization: the cost is at most 10 article bends and 2 exact rsqrts per
// level per mesh vertex (the tree's measured draw cost: docs/perf.md).
//
// Needs, declared before including: shared/tree_render.h.

layout(std430, set = 0, binding = POND_TREE_BINDING_SKELETON) restrict readonly buffer TreeSkeleton {
  float tree_skeleton[];
};
layout(std430, set = 0, binding = POND_TREE_BINDING_PARENTS) restrict readonly buffer TreeParents {
  int tree_parents[];
};

vec3 tree_load(uint v, int field) {
  const uint b = v * uint(kTreeVertexFloats) + uint(field);
  return vec3(tree_skeleton[b], tree_skeleton[b + 1u], tree_skeleton[b + 2u]);
}

// The article's bend of skeleton vertex v.
vec3 tree_article_vertex(uint v, TreeWindFrame w) {
  return tree_wind_bend(tree_load(v, kTreeVertexPosition), tree_load(v, kTreeVertexWindX),
                        tree_load(v, kTreeVertexWindZ), tree_load(v, kTreeVertexJitter), w.wind.x, w.wind.z,
                        w.twig.xyz);
}

// The length-preserving bend of skeleton vertex v (see the top of this file).
vec3 tree_keep_length_vertex(uint v, TreeWindFrame w) {
  uint chain[kTreeMaxChain];
  int n = 0;
  for (int u = int(v); u >= 0 && n < kTreeMaxChain; u = tree_parents[u]) chain[n++] = uint(u);
  precise vec3 bent_parent = tree_article_vertex(chain[n - 1], w);
  precise vec3 kept = bent_parent;
  for (int k = n - 2; k >= 0; --k) {
    const uint c = chain[k], p = chain[k + 1];
    precise vec3 bent = tree_article_vertex(c, w);
    const float rest = tree_wind_rest_length(tree_load(p, kTreeVertexPosition), tree_load(c, kTreeVertexPosition));
    kept = tree_wind_keep_length(kept, bent_parent, bent, rest);
    bent_parent = bent;
  }
  return kept;
}

// Skeleton vertex v bent in the frame's mode.
vec3 tree_pose(uint v, TreeWindFrame w) {
  return w.bend_mode == kTreeBendKeepLength ? tree_keep_length_vertex(v, w) : tree_article_vertex(v, w);
}
