// --method reference: the ground truth of the dipole model (docs/design.md §4).
//
// B(xo) = Σ_i E(x_i) ΔA_i Rd(|xo − x_i|) over dense surface points
// (render/surface_points.h): every triangle cut into k² sub-triangles with
// edges ≤ h, one point per centroid. h = ℓ_min / 2 by default, ℓ_min = 1/max σt'
// the material's smallest mean free path (`--spacing MM` overrides); halving
// it moves B by ~0.02% RMSE (tests/reference_test.cpp). E is exact: Fresnel,
// the interpolated vertex normal, visibility by segment queries against the
// mesh (CGAL AABB tree), shadow edges integrated adaptively to h/16. Rd is the
// double-precision dipole tabulated at 8192 points up to the object's diameter
// (ProfileTable; relative error < 1e-5 for a 10 mm object, < 5e-5 at 30 mm:
// profile_table_cache_test.cpp); the sum runs on the OpenCL device (Gatherer), in
// chunks of pixels so a terminal shows progress.
// Cost: points ≈ Σ_triangles max(1, ⌈longest edge/h⌉²) ≈ max(T, 2.3 A/h²); their
// irradiance once per mesh, lights, η and h (cached across frames); then
// pixels × points Rd evaluations every frame. A small --spacing makes that
// hours and gigabytes, so the cost is estimated before any point is made
// (ReferenceCost) and a run past kMaxReferencePoints or
// kMaxReferenceEvaluations is refused, with the estimate, unless --force.
#pragma once

#include <cstdint>
#include <string>

#include "cl/gather.h"
#include "render/method.h"
#include "render/profile_table_cache.h"
#include "render/surface_points.h"

namespace tsis {

// Bounds of a run without --force: 20 M points (≈ 2 GB with their device copy)
// and 2·10¹² Rd evaluations per frame (about an hour on a 2-core PoCL device
// at 0.56 G/s, docs/guide/performance.md).
constexpr uint64_t kMaxReferencePoints = 20'000'000;
constexpr double kMaxReferenceEvaluations = 2e12;

struct ReferenceCost {
    uint64_t points = 0;
    double bytes = 0;        // host and device memory the points take
    double evaluations = 0;  // Rd evaluations per frame, every pixel covered
    bool withinBounds() const {
        return points <= kMaxReferencePoints && evaluations <= kMaxReferenceEvaluations;
    }
    std::string describe()
        const;  // "1.2 M surface points (0.1 GB), 3e+11 Rd evaluations per frame (…)"
};

class ReferenceMethod : public Method {
  public:
    explicit ReferenceMethod(ClRuntime& cl);
    const char* name() const override { return "reference"; }
    void addPasses(FrameGraph& graph, const FrameContext& ctx) override;

    // The default spacing h for a material: ℓ_min / 2.
    static double defaultSpacing(const Material& m);
    // What a frame of `pixels` pixels costs at spacing h (no point is made).
    static ReferenceCost estimate(const Mesh& mesh, double spacing, double pixels);
    // Throws tsis::Error with the estimate when it is past the bounds and
    // force is false; with force, notes the estimate on stderr.
    static void checkCost(const ReferenceCost& cost, bool force);

  private:
    // Returns the device milliseconds.
    double gather(const FrameContext& ctx, const SurfacePoints& points, cl::Buffer& radiosity);

    ClRuntime& cl_;
    Gatherer gatherer_;
    SurfaceSampleCache points_;
    cl::Buffer samples_;  // TsisSample per point, w = E·ΔA
    ProfileTableCache rd_;
};

}  // namespace tsis
