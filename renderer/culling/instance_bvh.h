#pragma once
// A bounding-volume hierarchy over instance bounds, for view-frustum and caster culling that
// grows sub-linearly with the instance count (benchmarked at 10k / 100k / 1M instances). GL-free.
//
// Built once per scene (median split on the longest centroid axis, up to kLeafSize instances
// per leaf) and refitted when animation moves instances: the tree keeps its topology, the boxes
// are recomputed bottom-up. A query calls a conservative "may this box matter?" test on nodes
// and, at the leaves, on each instance's own box, so the kept set is exactly what the same test
// over every instance would keep - provided the test is monotone (a box that fails makes every
// box inside it fail), which holds for plane-separation tests such as the frustum's p-vertex test
// and casterCanReach (exact in floating point: rounding is monotone, see culling_test).
#include "math/aabb.h"

#include <cstdint>
#include <vector>

namespace shadowlab {

class InstanceBvh {
public:
    static constexpr std::uint32_t kLeafSize = 4;

    // Instances with empty bounds are left out (no test keeps an empty box).
    void build(const std::vector<Aabb>& boxes);
    // New boxes for the same instances (animation). Rebuilds when the count or the set of
    // non-empty boxes changed.
    void refit(const std::vector<Aabb>& boxes);

    // Appends to `kept` the indices of the instances whose box passes `mayMatter`, ascending.
    template <class BoxTest>
    void query(BoxTest&& mayMatter, std::vector<std::uint32_t>& kept) const;

    std::size_t instanceCount() const { return boxCount_; }
    std::size_t nodeCount() const { return nodes_.size(); }
    std::size_t depth() const { return depth_; }
    bool empty() const { return nodes_.empty(); }

private:
    struct Node {
        Aabb box;
        std::uint32_t first = 0;  // leaf: first entry of items_; interior: index of the right child
        std::uint32_t count = 0;  // leaf: number of items; 0 for interior nodes (left child = this + 1)
    };
    std::uint32_t buildRange(std::uint32_t begin, std::uint32_t end, std::vector<glm::dvec3>& centroids,
                             std::size_t level);
    void sortKept(std::vector<std::uint32_t>& kept, std::size_t from) const;

    std::vector<Node> nodes_;
    std::vector<std::uint32_t> items_;  // instance indices, grouped by leaf
    std::vector<Aabb> itemBoxes_;       // boxes in items_ order (leaf tests read them contiguously)
    std::size_t boxCount_ = 0;          // size of the boxes vector built from
    std::size_t depth_ = 0;
};

template <class BoxTest>
void InstanceBvh::query(BoxTest&& mayMatter, std::vector<std::uint32_t>& kept) const {
    if (nodes_.empty()) return;
    const std::size_t from = kept.size();
    std::uint32_t stack[64];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& node = nodes_[stack[--top]];
        if (!mayMatter(node.box)) continue;
        if (node.count > 0) {
            for (std::uint32_t i = node.first; i < node.first + node.count; ++i)
                if (node.count == 1 || mayMatter(itemBoxes_[i])) kept.push_back(items_[i]);
            continue;
        }
        const std::uint32_t self = std::uint32_t(&node - nodes_.data());
        stack[top++] = node.first;  // right child
        stack[top++] = self + 1;    // left child, visited first
    }
    sortKept(kept, from);
}

}  // namespace shadowlab
