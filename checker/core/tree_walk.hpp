// The one replay loop of the checker's proof trees: a pre-order walk with an explicit stack,
// never recursion, so that a hostile certificate's depth costs heap, not the call stack. Both
// kinds of tree use it: the JSON split trees of the partitions (replay.cpp) and the compact
// strings of critical-lattice certificates (claims/critical_tree.cpp). What a node is and what
// replaying it proves is the caller's; the walk only fixes the order.
#pragma once
#include <utility>
#include <vector>

namespace superpack_checker {

// Replays `root` and every node `step` pushes: step(node, stack) replays one node and pushes
// what is still to replay below it, the one to replay next last (a split pushes its second
// child, then its first, so that the first child's whole subtree comes before the second).
template <class Node, class Step>
void walk_tree(Node root, Step&& step) {
    std::vector<Node> stack;
    stack.push_back(std::move(root));
    while (!stack.empty()) {
        Node node = std::move(stack.back());
        stack.pop_back();
        step(node, stack);
    }
}

}  // namespace superpack_checker
