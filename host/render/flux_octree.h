// The octree of Jensen & Buhler 2002 ("A rapid hierarchical rendering
// technique for translucent materials") over irradiance samples. Each node
// keeps the total flux Σ E·A per channel, the flux-weighted position (weights:
// luminance of the flux; area when the node is dark) and the total area; B(x)
// is gathered top-down, a node standing in for its samples when it is small
// as seen from x.
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "physics/profile_table.h"
#include "render/surface_points.h"

namespace tsis {

class FluxOctree {
  public:
    static constexpr int kLeafSize = 8;  // samples at most per leaf (unless they coincide)

    FluxOctree() = default;
    explicit FluxOctree(const std::vector<SurfacePoint>& samples);

    // B(x) = Σ flux ⊙ Rd(r). A node is used whole when x is outside its bounds
    // and its area ΔA seen from its position p subtends ΔA/|x − p|² < epsilon;
    // otherwise its children are visited, and a leaf's samples summed one by
    // one. epsilon = 0 sums every sample. Adds the Rd lookups to *evaluations.
    glm::vec3 radiosity(const glm::vec3& x, float epsilon, const ProfileTable& rd,
                        long long* evaluations = nullptr) const;

    size_t nodeCount() const { return nodes_.size(); }
    size_t sampleCount() const { return position_.size(); }
    glm::vec3 totalFlux() const;
    float totalArea() const;

  private:
    struct Node {
        glm::vec3 lo{0.0f}, hi{0.0f};  // bounds
        glm::vec3 position{0.0f};      // representative position
        glm::vec3 flux{0.0f};          // Σ E·A
        float area = 0;                // Σ A
        uint32_t first = 0;            // leaf: first sample; inner node: first child
        uint32_t count = 0;            // leaf: samples; inner node: children (1…8)
        bool leaf = true;
    };
    void build(uint32_t node, std::vector<uint32_t>& order, uint32_t begin, uint32_t end,
               const std::vector<SurfacePoint>& samples, int depth);

    std::vector<Node> nodes_;
    std::vector<glm::vec3> position_, flux_;  // samples in tree order
};

}  // namespace tsis
