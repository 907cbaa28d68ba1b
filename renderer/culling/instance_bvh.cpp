#include "culling/instance_bvh.h"

#include <algorithm>
#include <numeric>

namespace shadowlab {

namespace {

// Deep enough for the query's fixed stack: the median split halves each range, so 1M instances
// need about 18 levels; degenerate centroids (all equal) still split by index.
constexpr std::size_t kMaxDepth = 60;

Aabb unionOf(const std::vector<Aabb>& boxes, std::uint32_t begin, std::uint32_t end) {
    Aabb b;
    for (std::uint32_t i = begin; i < end; ++i) b.extend(boxes[i]);
    return b;
}

}  // namespace

void InstanceBvh::build(const std::vector<Aabb>& boxes) {
    nodes_.clear();
    items_.clear();
    itemBoxes_.clear();
    depth_ = 0;
    boxCount_ = boxes.size();
    for (std::size_t i = 0; i < boxes.size(); ++i)
        if (!boxes[i].empty()) items_.push_back(std::uint32_t(i));
    if (items_.empty()) return;
    std::vector<glm::dvec3> centroids(items_.size());
    itemBoxes_.resize(items_.size());
    for (std::size_t k = 0; k < items_.size(); ++k) {
        itemBoxes_[k] = boxes[items_[k]];
        centroids[k] = itemBoxes_[k].center();
    }
    // Median splits give a balanced tree of at most 2n / kLeafSize nodes.
    nodes_.reserve(2 * (items_.size() / kLeafSize + 1));
    buildRange(0, std::uint32_t(items_.size()), centroids, 1);
}

std::uint32_t InstanceBvh::buildRange(std::uint32_t begin, std::uint32_t end, std::vector<glm::dvec3>& centroids,
                                      std::size_t level) {
    depth_ = std::max(depth_, level);
    const std::uint32_t index = std::uint32_t(nodes_.size());
    nodes_.push_back({unionOf(itemBoxes_, begin, end), begin, end - begin});
    if (end - begin <= kLeafSize || level >= kMaxDepth) return index;

    Aabb centreBox;
    for (std::uint32_t i = begin; i < end; ++i) centreBox.extend(centroids[i]);
    const glm::dvec3 extent = centreBox.extent();
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    // Sort a permutation of the range around its median centroid, then apply it to the three
    // parallel arrays.
    const std::uint32_t mid = begin + (end - begin) / 2;
    std::vector<std::uint32_t> order(end - begin);
    std::iota(order.begin(), order.end(), begin);
    std::nth_element(order.begin(), order.begin() + (mid - begin), order.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return centroids[a][axis] < centroids[b][axis]; });
    std::vector<std::uint32_t> items(order.size());
    std::vector<Aabb> boxes(order.size());
    std::vector<glm::dvec3> centres(order.size());
    for (std::size_t k = 0; k < order.size(); ++k) {
        items[k] = items_[order[k]];
        boxes[k] = itemBoxes_[order[k]];
        centres[k] = centroids[order[k]];
    }
    std::copy(items.begin(), items.end(), items_.begin() + begin);
    std::copy(boxes.begin(), boxes.end(), itemBoxes_.begin() + begin);
    std::copy(centres.begin(), centres.end(), centroids.begin() + begin);

    nodes_[index].count = 0;
    buildRange(begin, mid, centroids, level + 1);  // left child = index + 1
    const std::uint32_t right = buildRange(mid, end, centroids, level + 1);
    nodes_[index].first = right;
    return index;
}

void InstanceBvh::refit(const std::vector<Aabb>& boxes) {
    std::size_t nonEmpty = 0;
    for (const Aabb& b : boxes) nonEmpty += b.empty() ? 0 : 1;
    bool sameSet = boxes.size() == boxCount_ && nonEmpty == items_.size();
    for (std::size_t k = 0; sameSet && k < items_.size(); ++k) sameSet = !boxes[items_[k]].empty();
    if (!sameSet) {
        build(boxes);
        return;
    }
    for (std::size_t k = 0; k < items_.size(); ++k) itemBoxes_[k] = boxes[items_[k]];
    // Children come after their parent in nodes_, so one backwards sweep refits bottom-up.
    for (std::size_t n = nodes_.size(); n-- > 0;) {
        Node& node = nodes_[n];
        if (node.count > 0) {
            node.box = unionOf(itemBoxes_, node.first, node.first + node.count);
        } else {
            node.box = nodes_[n + 1].box;
            node.box.extend(nodes_[node.first].box);
        }
    }
}

void InstanceBvh::sortKept(std::vector<std::uint32_t>& kept, std::size_t from) const {
    // Ascending instance order: the draw order of the linear loop, so images do not depend on
    // which culling ran (equal-depth fragments keep the first drawn).
    std::sort(kept.begin() + std::ptrdiff_t(from), kept.end());
}

}  // namespace shadowlab
