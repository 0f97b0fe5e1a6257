// --transport object (docs/design.md §14): the object's own transport added
// to every profile method's radiosity, once per frame, as single scattering
// is. The fit (volumetric/patch_transfer.h) gives per medium the difference
// Δ(i, j) between the volumetric walk's and the profile's flux from patch i
// to patch j; a frame sums the flux atlas per patch on the device, takes
// ΔE_j = Σ_i Δ(i, j)·Φ_i on the host, and adds ΔE_j over patch j's area (as
// radiosity: over the exit term's exitance per unit B) at every covered point,
// interpolated between patch centres through a grid per medium. The fit is
// made once per mesh, atlas, materials and profile (a minute at most, cached
// on disk with the atlases); a frame costs the patch sums, a K×K product and
// a trilinear read per point.
#pragma once

#include <cstdint>
#include <future>
#include <glm/ext/vector_int3.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "render/frame_graph.h"
#include "render/frame_resources.h"
#include "render/method.h"
#include "volumetric/patch_transfer.h"

namespace tsis {

// A medium's correction on a grid: each node the weights g_j / Σ g·A of the
// patch centres near it (kTaps at most; g Gaussian in distance), so a frame's
// value there is Σ g·ΔE / Σ g·A of the patches' and a point reads it trilinearly.
struct TransportGrid {
    static constexpr int kTaps = 6;
    glm::vec3 origin{0.0f};
    float cell = 1.0f;
    glm::ivec3 dims{1};
    std::vector<int> patch;     // kTaps per node, −1 unused
    std::vector<float> weight;  // kTaps per node
    std::vector<glm::vec3> value;
    // Per node: which correction its value holds (ObjectTransport's count;
    // 0 none). A frame fills only the nodes its points read.
    std::vector<uint64_t> made;
    size_t nodes() const { return static_cast<size_t>(dims.x) * dims.y * dims.z; }

    // A trilinear read: its 8 nodes and the fractions between them.
    struct Read {
        uint32_t node[8];
        glm::vec3 f;
    };
    // The read at x (clamped to the grid).
    Read read(const glm::vec3& x) const;
    // The trilinear value of a read.
    glm::vec3 blend(const Read& r) const;
    // Node n's value from the corrections of the medium's patches, the first
    // of them patch `first`.
    void setNode(size_t n, const std::vector<glm::vec3>& correction, int first);
};

// The grid of medium m over its patches (cell: half the largest patch radius,
// at most kMaxGridCells a side).
TransportGrid transportGrid(const PatchTransfer& t, int m);

// The coefficients patchCorrection reads, per medium m and patch pair (i, j):
// Δ (rgb), H (rgb) and G's x, y and z components (rgb each) in bfloat16, 16
// to a pair (one spare). The product reads the whole K×K block every frame
// the light moves, and memory bounds it, not arithmetic (8.8 MB of floats on
// the default scene).
struct PackedTransfer {
    static constexpr size_t kPerPair = 16;
    std::vector<int> first, count;             // per medium: its first patch, how many
    std::vector<std::vector<uint16_t>> pairs;  // per medium: count² × kPerPair
};
PackedTransfer packTransfer(const PatchTransfer& t);

// Per patch of medium m, the flux to add as radiosity:
// Σ_i (Δ(i, j) + G(i, j)·s_i + H(i, j)·(q_i − μ))·flux_i over the exitance per
// unit B of the medium (the grid divides by the patches' areas), s_i the
// luminance-weighted mean tangential direction of the light entering patch i
// and q_i − μ its mean square less the walks' (`direction`: xyz and w, their
// sums over the patch's texels, weighted by their flux's luminance).
std::vector<glm::vec3> patchCorrection(const PackedTransfer& t, int m,
                                       const std::vector<glm::vec3>& flux,
                                       const std::vector<glm::vec4>& direction,
                                       double exitancePerB);

class ObjectTransport {
  public:
    explicit ObjectTransport(ClRuntime& cl);
    // B += the correction at every covered point; `slotProfiles` the profile
    // each material slot's run integrated (FrameContext::profile()).
    void addPass(FrameGraph& graph, const FrameContext& ctx, std::vector<KeyedProfile> slotProfiles,
                 FrameGraphId<RadiosityImage> radiosity);
    const PatchTransfer* transfer() const { return fitted_ ? &transfer_ : nullptr; }
    // The method's copy of B over the atlas with the correction added at
    // every texel that holds a surface (covered or its chart's ring), for
    // the GL side's lookup of a frame that only moved the camera (the pass
    // adds it at the points on the CL side); null unless the last frame's
    // pass corrected for this lighting (`lighting`: FrameContext::lighting).
    const AtlasRadiosity* corrected(const AtlasRadiosity& copy, uint64_t lighting);
    // Whether the last corrected() made its copy (stat transport_copy_made).
    bool madeCorrectedCopy() const { return madeCopy_; }

    // With background fits, a fit neither made before nor on disk is made on
    // a thread of its own, one at a time (the newest request next), and the
    // frames meanwhile render without the correction (stat
    // transport_pending = 1): `tsis view` stays interactive while a new
    // material's transport is fitted. Off (the default), a frame waits for it.
    void setBackgroundFits(bool on) { background_ = on; }
    // A background fit is done and the next frame takes it.
    bool backgroundFitReady() const;

  private:
    // What a fit is made from, and the frame inputs it is for.
    struct FitRequest {
        uint64_t key = 0, geometry = 0, inputs = 0;
        SurfaceTexels texels;
        std::vector<TransferMedium> media;
        PatchTransferOptions options;
        std::shared_ptr<const Mesh> mesh;  // a copy, for a background fit
    };
    // False while this frame's fit runs in the background.
    bool fit(const FrameContext& ctx, const std::vector<KeyedProfile>& slotProfiles,
             const AtlasCl& position, const AtlasCl& normal, FrameGraph::Resources& res);
    // The fit of `request` from the background (when made) or the disk
    // (`loaded`); else started in the background on a copy of `mesh` (or
    // queued behind the running one).
    std::optional<PatchTransfer> fitInBackground(const std::shared_ptr<FitRequest>& request,
                                                 const Mesh& mesh, bool& loaded);
    // A finished background fit to made_, and the queued request started.
    void collectBackgroundFit();
    void startBackgroundFit(std::shared_ptr<FitRequest> request);
    // transfer_ fitted for `request`: the patches' texel lists and the grids.
    void install(const FitRequest& request, FrameGraph::Resources& res);
    // The index in grids_ of the medium a point's tag (1 + medium) names
    // (−1 for none, or a medium without a correction).
    int gridIndexOfTag(float tag) const;
    // No grids (and no corrections): the points' reads made for the old ones
    // are made again.
    void clearGrids();

    // The grid reads of a set of points (xyz, w the medium tag), made again
    // only when the points or the grids change: a frame that moves only the
    // light reads the same nodes, and only those need this lighting's values.
    struct PointReads {
        std::vector<float> points;  // what they were made for
        uint64_t installed = 0;
        std::vector<int> grid;  // per point: its grid (−1: none)
        std::vector<TransportGrid::Read> reads;
        std::vector<std::vector<uint32_t>> nodes;  // per grid: the nodes read, each once
    };
    const PointReads& readsOf(PointReads& cache, const std::vector<float>& points, size_t count);
    // The nodes `r` reads given this lighting's values (gridsMade_).
    void fillNodes(const PointReads& r);

    ClRuntime& cl_;
    cl::Kernel kernel_;
    GrowingBuffer start_, texels_, sampleTexels_, sampleGeometry_, flux_, direction_, lights_,
        etas_;
    PatchTransfer transfer_;
    PackedTransfer packed_;  // transfer_'s coefficients for the frame's product
    bool fitted_ = false;
    std::vector<TransportGrid> grids_;
    // Grids made before, by their patches' hash (the last kCachedGrids).
    static constexpr size_t kCachedGrids = 8;
    std::vector<std::pair<uint64_t, TransportGrid>> gridCache_;
    std::vector<double> exitancePerB_;  // per medium
    // Per medium, the patches' corrections of this lighting (gridsMade_).
    std::vector<std::vector<glm::vec3>> corrections_;
    PointReads pointReads_, copyReads_;
    uint64_t installs_ = 0;  // grids_ installed so far
    // The lighting the grids hold the correction of (0: none), and a count
    // of their updates; the corrected copy and what it was made from.
    uint64_t lightingOf_ = 0, gridsMade_ = 0, correctedOf_ = 0;
    bool madeCopy_ = false;
    std::vector<float> correctedB_;
    AtlasRadiosity corrected_;
    uint64_t geometryOf_ = 0, fitKey_ = 0, fluxOf_ = 0, inputsKey_ = 0;
    bool background_ = false;
    std::shared_ptr<FitRequest> waiting_;  // the request frames wait for
    std::future<PatchTransfer> running_;   // the background fit, of runningKey_
    uint64_t runningKey_ = 0;
    std::shared_ptr<FitRequest> queued_;                      // started when the running one ends
    std::optional<std::pair<uint64_t, PatchTransfer>> made_;  // the last one ended
};

}  // namespace tsis
