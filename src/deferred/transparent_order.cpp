#include "deferred/transparent_order.h"

#include <algorithm>

namespace dsr {

std::vector<size_t> transparent_order(const std::vector<size_t>& objects, const std::vector<ObjectBounds>& bounds,
                                      const glm::dvec3& eye) {
    std::vector<std::pair<double, size_t>> keyed;
    keyed.reserve(objects.size());
    for (size_t o : objects) keyed.emplace_back(glm::length(glm::dvec3(bounds.at(o).centre) - eye), o);
    std::stable_sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
    std::vector<size_t> out;
    out.reserve(keyed.size());
    for (const auto& k : keyed) out.push_back(k.second);
    return out;
}

}  // namespace dsr
