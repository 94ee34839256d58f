// A union-find forest in a caller's array of parents (an index per slot,
// its own index at a root), for the scene's connected components (cells,
// blocks): no recursion, bounded by the array's size.
#pragma once

namespace spinhash {

// The root of c, halving the path on the way: each step at least halves
// the depth, so the loop ends within the forest's size.
template <class Index>
Index find_root(Index* parent, Index c) {
  while (parent[c] != c) {
    parent[c] = parent[parent[c]];
    c = parent[c];
  }
  return c;
}

// Joins the trees of a and b; the smaller root wins, so that the roots do
// not depend on the order the joins come in.
template <class Index>
void unite(Index* parent, Index a, Index b) {
  a = find_root(parent, a);
  b = find_root(parent, b);
  if (a < b)
    parent[b] = a;
  else if (b < a)
    parent[a] = b;
}

}  // namespace spinhash
