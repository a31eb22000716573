#include "vocabulary_tree.h"

#include "dslam/features/matching.h"

namespace dslam {

std::uint32_t VocabularyTree::AddNode(std::uint32_t parent_node, const Descriptor& d) {
  parent.push_back(parent_node);
  descriptor.push_back(d);
  weight.push_back(0.0);
  return static_cast<std::uint32_t>(parent.size() - 1);
}

std::string VocabularyTree::Index() {
  const size_t n = parent.size();
  if (n == 0 || parent[0] != kNoNode) return "the first node is not the root";
  first_child.assign(n, 0);
  num_children.assign(n, 0);
  std::vector<int> depth(n, 0);
  for (size_t i = 1; i < n; ++i) {
    const std::uint32_t p = parent[i];
    if (p >= i) return "node " + std::to_string(i) + " comes before its parent";
    if (num_children[p] == 0) first_child[p] = static_cast<std::uint32_t>(i);
    if (first_child[p] + num_children[p] != i) {
      return "the children of node " + std::to_string(p) + " are not consecutive";
    }
    if (static_cast<int>(++num_children[p]) > branching) {
      return "node " + std::to_string(p) + " has more than " + std::to_string(branching) +
             " children";
    }
    depth[i] = depth[p] + 1;
    if (depth[i] > levels) {
      return "node " + std::to_string(i) + " is deeper than " + std::to_string(levels);
    }
  }
  word_of_node.assign(n, kNoNode);
  node_of_word.clear();
  for (size_t i = 0; i < n; ++i) {
    if (num_children[i] > 0 || i == 0) continue;
    word_of_node[i] = static_cast<std::uint32_t>(node_of_word.size());
    node_of_word.push_back(static_cast<std::uint32_t>(i));
  }
  return node_of_word.empty() ? "the tree has no word" : "";
}

std::uint32_t Descend(const VocabularyTree& tree, const std::uint8_t* d) {
  std::uint32_t node = 0;
  while (tree.num_children[node] > 0) {
    const std::uint32_t first = tree.first_child[node];
    std::uint32_t best = first;
    int best_distance = Hamming(d, tree.descriptor[first].data());
    for (std::uint32_t c = first + 1; c < first + tree.num_children[node]; ++c) {
      const int distance = Hamming(d, tree.descriptor[c].data());
      if (distance < best_distance) {
        best_distance = distance;
        best = c;
      }
    }
    node = best;
  }
  return tree.word_of_node[node];
}

}  // namespace dslam
