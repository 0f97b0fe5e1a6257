// pyramid: the plane's closed form, error against the ground truth that falls
// as ε falls (at a cost that rises), closer than tsis at the same frame, and
// the same bytes for any seed.
#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

#include "support/render.h"
#include "support/scoped_env.h"

namespace tsis {
namespace {

RenderOptions pyramidOptions(int size, int resolution, float epsilon) {
    RenderOptions opt = test::smallOptions(size, resolution);
    opt.pyramidEpsilon = epsilon;
    return opt;
}

// For a Renderer kept across frames: 96², atlas 256², the radiosity kept.
RenderOptions frameSequenceOptions() {
    RenderOptions opt = pyramidOptions(96, 256, 0.05f);
    opt.method = "pyramid";
    opt.keepAovs = true;
    return opt;
}

// An infinite plane under a normal directional light: B = Ft(1)·∫Rd dA.
TEST(Pyramid, PlaneMatchesTheClosedForm) {
    for (const char* material : {"marble", "skin1"}) {
        const Scene scene = test::planeScene(material);
        const FrameResult f = test::renderWith(scene, pyramidOptions(32, 1024, 0.05f), "pyramid");
        test::expectNearClosedForm(test::meanRadiosity(f), test::planeClosedForm(scene.material),
                                   0.01, std::string("pyramid plane ") + material);
    }
}

// The back-lit torus (thin glowing top): the error against the reference
// falls as ε falls and the Rd evaluations rise; at the default ε it is within
// 2% and below tsis' at N = 900.
TEST(Pyramid, ErrorFallsAsEpsilonFallsAndCostRises) {
    const Scene scene = test::torusScene("skin1", 30.0);
    const RenderOptions base = test::smallOptions(64, 512);
    const FrameResult ref = test::renderWith(scene, base, "reference");
    double lastError = 1e9, lastCost = 0;
    for (float epsilon : {0.4f, 0.1f, 0.025f}) {
        const FrameResult f = test::renderWith(scene, pyramidOptions(64, 512, epsilon), "pyramid");
        const double error = test::relativeRmse(f, ref);
        const double cost = f.stats.number("rd_evaluations");
        std::printf("skin1 30 mm torus, epsilon %.3f: relative RMSE %.4f%%, %.4g evaluations\n",
                    epsilon, 100 * error, cost);
        EXPECT_LT(error, lastError) << epsilon;
        EXPECT_GT(cost, lastCost) << epsilon;
        lastError = error;
        lastCost = cost;
    }
    const double tsis = test::relativeRmse(test::renderWith(scene, base, "tsis"), ref);
    const double pyramid = test::relativeRmse(
        test::renderWith(scene, pyramidOptions(64, 512, RenderOptions{}.pyramidEpsilon), "pyramid"),
        ref);
    std::printf("default epsilon: pyramid %.4f%%, tsis (N = 900) %.4f%%\n", 100 * pyramid,
                100 * tsis);
    EXPECT_LT(pyramid, 0.02);
    EXPECT_LT(pyramid, 0.5 * tsis);
}

// The grid: at 256² the default stride evaluates a fraction of the pixels and
// stays within 0.5% of evaluating every pixel.
TEST(Pyramid, GridInterpolationStaysCloseToEveryPixel) {
    for (const char* material : {"skin1", "skimmilk"}) {
        const Scene scene = test::torusScene(material, 10.0);
        RenderOptions opt = pyramidOptions(256, 256, RenderOptions{}.pyramidEpsilon);
        const FrameResult sparse = test::renderWith(scene, opt, "pyramid");
        opt.pyramidStride = 1;
        const FrameResult every = test::renderWith(scene, opt, "pyramid");
        const double diff = test::relativeRmse(sparse, every);
        const double stride = sparse.stats.number("pyramid_stride");
        const double evaluated =
            sparse.stats.number("pyramid_evaluated_pixels") / sparse.stats.number("covered_pixels");
        std::printf("%s: stride %.0f, %.1f%% of the pixels evaluated, %.3f%% from every pixel\n",
                    material, stride, 100 * evaluated, 100 * diff);
        EXPECT_GE(stride, 2) << material;
        EXPECT_LT(evaluated, 0.4) << material;
        EXPECT_LT(diff, 0.005) << material;
    }
}

// No random numbers: the seed changes nothing, and the same inputs give the
// same bytes.
TEST(Pyramid, DeterministicAndSeedIndependent) {
    const Scene scene = test::torusScene("marble", 10.0);
    RenderOptions opt = pyramidOptions(32, 128, 0.05f);
    const FrameResult a = test::renderWith(scene, opt, "pyramid");
    opt.seed = 77;
    const FrameResult b = test::renderWith(scene, opt, "pyramid");
    EXPECT_EQ(a.radiosity.pixels, b.radiosity.pixels);
    EXPECT_EQ(a.rgb8, b.rgb8);
}

// The plan of the pixels to evaluate follows the camera: a frame that moves
// only the light keeps it (and its buffers on the device), and its node sums
// take only the flux at the leaves (their positions and areas kept), and it
// is the frame a fresh renderer makes; a frame that moves the camera plans
// again.
TEST(Pyramid, LightMoveKeepsThePlanAndGivesTheFreshFrame) {
    const Scene a = test::torusScene("skin1", 10.0);
    Scene lit = a;
    lit.lights[0].vec = glm::vec3(9, 8, 11);
    Scene turned = lit;
    turned.camera.eye = glm::vec3(-6, 5, 12);
    RenderOptions opt = frameSequenceOptions();
    opt.pyramidStride = 3;  // a grid at this size: some pixels interpolated
    opt.pyramidCache = PyramidCache::Pixels;
    Renderer renderer;
    EXPECT_EQ(renderer.render(a, opt).stats.number("pyramid_plan_reused"), 0);
    const FrameResult kept = renderer.render(lit, opt);
    EXPECT_EQ(kept.stats.number("pyramid_plan_reused"), 1);
    EXPECT_GT(kept.stats.number("pyramid_interpolated_pixels"), 0);
    const FrameResult other = renderer.render(turned, opt);
    EXPECT_EQ(other.stats.number("pyramid_plan_reused"), 0);
    for (const Scene* s : {&lit, &turned}) {
        Renderer fresh;
        const FrameResult f = fresh.render(*s, opt);
        const FrameResult& r = s == &lit ? kept : other;
        EXPECT_EQ(f.radiosity.pixels, r.radiosity.pixels);
        EXPECT_EQ(f.rgb8, r.rgb8);
    }
}

// The torus, its camera turned twice, and the light moved at the second view.
struct CameraMoves {
    Scene a = test::torusScene("skin1", 10.0), turned = a, again = a, lit;
    CameraMoves() {
        turned.camera.eye = glm::vec3(-6, 5, 12);
        again.camera.eye = glm::vec3(-8, 4, 11);
        lit = again;
        lit.lights[0].vec = glm::vec3(9, 8, 11);
    }
};

// B over the atlas: a frame that only moves the camera reads B from the
// copy the first such frame makes over the atlas, within 0.5 % of the
// gather at its pixels; the next camera move reuses the copy; a light move
// gathers at the pixels again. --pyramid-cache always reads the copy on the
// first frame too, as close.
TEST(Pyramid, CameraMoveReadsBFromTheAtlasCloseToTheGatherAtItsPixels) {
    const CameraMoves m;
    const Scene &a = m.a, &turned = m.turned, &again = m.again, &lit = m.lit;
    const RenderOptions opt = frameSequenceOptions();
    // Each frame in turn: did it read the copy, did it make it.
    const struct {
        const Scene* scene;
        double fromAtlas, made;
    } frames[] = {{&a, 0, 0}, {&turned, 1, 1}, {&again, 1, 0}, {&lit, 0, 0}};
    Renderer renderer;
    std::vector<FrameResult> results;
    for (const auto& f : frames) {
        results.push_back(renderer.render(*f.scene, opt));
        EXPECT_EQ(results.back().stats.number("pyramid_from_atlas"), f.fromAtlas);
        if (f.fromAtlas > 0) {
            EXPECT_EQ(results.back().stats.number("pyramid_atlas_made"), f.made);
        }
    }
    const FrameResult& first = results[1];
    const FrameResult& second = results[2];
    RenderOptions pixels = opt;
    pixels.pyramidCache = PyramidCache::Pixels;
    for (const auto& [scene, f] : {std::pair{&turned, &first}, std::pair{&again, &second}}) {
        const FrameResult gathered = test::renderWith(*scene, pixels, "pyramid");
        const double diff = test::relativeRmse(*f, gathered);
        std::printf("camera moved: B from the atlas %.3f%% from the gather at the pixels\n",
                    100 * diff);
        EXPECT_GT(diff, 0.0);  // another computation, not the same bytes
        EXPECT_LT(diff, 0.005);
    }
    RenderOptions always = opt;
    always.pyramidCache = PyramidCache::Texture;
    const FrameResult fromAtlas = test::renderWith(a, always, "pyramid");
    EXPECT_EQ(fromAtlas.stats.number("pyramid_from_atlas"), 1);
    EXPECT_LT(test::relativeRmse(fromAtlas, test::renderWith(a, pixels, "pyramid")), 0.005);
}

// Without AOVs of B the renderer reads the copy on the GL side (gl/passes.h
// RadiosityLookupPass): the camera moves after the one that made it take
// no run of the method, and their frames are the CL side's lookup's to an
// 8-bit step (the log-average to 1e-5); a repeated view and a light move
// gather at the pixels again. With the object's transport the copy holds
// its correction (ObjectTransport::corrected), as close.
class CameraMovesOnTheGlSide : public testing::TestWithParam<Transport> {};

TEST_P(CameraMovesOnTheGlSide, ReadTheCopyAsTheClSideDoes) {
    // The correction interpolated over the atlas' texels against read at
    // the point: with CTest's 32 photons a patch its field is rough enough
    // for a few pixels to differ by 3-6 steps; at 1024 (the default 4096)
    // one step at most.
    const test::ScopedEnv photons("TSIS_TRANSPORT_PHOTONS", "1024");
    const CameraMoves m;
    const Scene &a = m.a, &turned = m.turned, &again = m.again, &lit = m.lit;
    RenderOptions cl = frameSequenceOptions();  // AOVs: the CL side
    cl.transport = GetParam();
    RenderOptions gl = cl;
    gl.keepAovs = false;
    const struct {
        const Scene* scene;
        double onGl;
    } frames[] = {{&a, 0}, {&turned, 0}, {&again, 1}, {&turned, 1}, {&turned, 0}, {&lit, 0}};
    Renderer onGl, onCl;
    for (const auto& f : frames) {
        const FrameResult g = onGl.render(*f.scene, gl);
        const FrameResult c = onCl.render(*f.scene, cl);
        EXPECT_EQ(g.stats.number("radiosity_lookup_gl"), f.onGl);
        EXPECT_EQ(c.stats.number("radiosity_lookup_gl"), 0);
        if (f.onGl > 0) {
            EXPECT_EQ(g.stats.number("pyramid_from_atlas"), 1);
            EXPECT_EQ(g.stats.number("covered_pixels"), c.stats.number("covered_pixels"));
            EXPECT_EQ(g.stats.number("pyramid_filled_off_atlas"),
                      c.stats.number("pyramid_gathered_off_atlas"));
        }
        ASSERT_EQ(g.rgb8.size(), c.rgb8.size());
        int most = 0;
        for (size_t i = 0; i < g.rgb8.size(); ++i)
            most = std::max(most, std::abs(g.rgb8[i] - c.rgb8[i]));
        EXPECT_LE(most, 1) << "frame of " << f.onGl;
        // The log-average of the radiance: B's rounding, not a 1 % change.
        EXPECT_NEAR(g.lavg, c.lavg, 1e-5 * c.lavg);
    }
}

INSTANTIATE_TEST_SUITE_P(Pyramid, CameraMovesOnTheGlSide,
                         testing::Values(Transport::Off, Transport::Object),
                         [](const testing::TestParamInfo<Transport>& i) {
                             return std::string(i.param == Transport::Off ? "ProfileAlone"
                                                                          : "ObjectTransport");
                         });

// The first camera move of a renderer prepared for it (prepareCameraMoves
// after the first view).
FrameResult preparedFirstMove(Renderer& renderer, const CameraMoves& m, const RenderOptions& opt) {
    renderer.render(m.a, opt);
    EXPECT_TRUE(renderer.prepareCameraMoves(m.a, opt));
    return renderer.render(m.turned, opt);
}

// prepareCameraMoves makes the copy the first camera move would: that move
// then reads it on the GL side at once (no run of the method), with the
// frame a renderer gives once the copy exists, byte for byte; a light move
// gathers at the pixels again. Where no frame makes a copy it does nothing.
TEST(Pyramid, PreparedCameraMovesReadTheCopyFromTheFirstMove) {
    const CameraMoves m;
    RenderOptions opt = frameSequenceOptions();
    opt.keepAovs = false;
    Renderer prepared, plain;
    const FrameResult first = preparedFirstMove(prepared, m, opt);
    EXPECT_EQ(first.stats.number("radiosity_lookup_gl"), 1);
    EXPECT_EQ(first.stats.number("pyramid_from_atlas"), 1);
    // The plain renderer's first move makes the copy, its second reads it.
    for (const Scene* s : {&m.a, &m.turned, &m.again}) plain.render(*s, opt);
    const FrameResult second = plain.render(m.turned, opt);
    EXPECT_EQ(second.stats.number("radiosity_lookup_gl"), 1);
    EXPECT_EQ(first.rgb8, second.rgb8);
    EXPECT_EQ(prepared.render(m.lit, opt).stats.number("radiosity_lookup_gl"), 0);
    // Preparing twice for one lighting finds the copy current; a camera move
    // under that lighting reads it.
    ASSERT_TRUE(prepared.prepareCameraMoves(m.lit, opt));
    ASSERT_TRUE(prepared.prepareCameraMoves(m.lit, opt));
    Scene litTurned = m.lit;
    litTurned.camera = m.turned.camera;
    EXPECT_EQ(prepared.render(litTurned, opt).stats.number("radiosity_lookup_gl"), 1);

    for (const auto& [what, change] : std::vector<std::pair<const char*, void (*)(RenderOptions&)>>{
             {"tsis", [](RenderOptions& o) { o.method = "tsis"; }},
             {"off", [](RenderOptions& o) { o.pyramidCache = PyramidCache::Pixels; }},
             {"always", [](RenderOptions& o) { o.pyramidCache = PyramidCache::Texture; }},
             {"progressive", [](RenderOptions& o) { o.progressive = true; }},
             {"aovs", [](RenderOptions& o) { o.keepAovs = true; }}}) {
        RenderOptions other = opt;
        change(other);
        EXPECT_FALSE(prepared.prepareCameraMoves(m.a, other)) << what;
    }
}

// With the object's transport the preparation makes the copy with its
// correction as well: the first move reads it on the GL side without making
// it (stat transport_copy_made 0), the unprepared renderer's first GL move
// makes it (1), and the two frames are the same bytes.
TEST(Pyramid, PreparedCameraMovesMakeTheTransportsCopyToo) {
    const test::ScopedEnv photons("TSIS_TRANSPORT_PHOTONS", "1024");
    const CameraMoves m;
    RenderOptions opt = frameSequenceOptions();
    opt.keepAovs = false;
    opt.transport = Transport::Object;
    Renderer prepared, plain;
    const FrameResult first = preparedFirstMove(prepared, m, opt);
    EXPECT_EQ(first.stats.number("radiosity_lookup_gl"), 1);
    EXPECT_EQ(first.stats.number("transport_copy_made"), 0);
    for (const Scene* s : {&m.a, &m.turned}) plain.render(*s, opt);
    const FrameResult second = plain.render(m.again, opt);
    EXPECT_EQ(second.stats.number("radiosity_lookup_gl"), 1);
    EXPECT_EQ(second.stats.number("transport_copy_made"), 1);
    EXPECT_EQ(plain.render(m.turned, opt).rgb8, first.rgb8);
}

}  // namespace
}  // namespace tsis
