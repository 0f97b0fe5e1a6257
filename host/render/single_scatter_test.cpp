// The single-scattering term (render/single_scatter.h): the host double
// version against the semi-infinite plane's closed form, kernels/
// single_scatter.cl against the host version, and a whole render of a plane.
#include "render/single_scatter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>
#include <numeric>
#include <random>
#include <vector>

#include "mesh/builtin.h"
#include "physics/fresnel.h"
#include "scene/projection.h"
#include "support/cl_fixture.h"
#include "support/kernel_reference.h"
#include "support/render.h"
#include "support/volumetric_walk.h"
#include "volumetric/camera_walk.h"
#include "volumetric/mesh_boundary.h"

namespace tsis {
namespace {

const Material& skin() {
    return presetMaterial("skin1");
}

// The plane z = 0 (normal +z, the medium below) as every light's entry.
ScatterEntry planeEntry(const glm::dvec3& x) {
    return {true, {x.x, x.y, 0.0}, {0.0, 0.0, 1.0}};
}

// Closed form on the semi-infinite plane: with s_i' = s_o·G, G = cos θto /
// cos θti, ∫ e^(−σt′ s_o (1 + G)) ds_o = 1/(σt′(1 + G)), so
// R = σs′/(4π)·Ft(η, cos θi)·E·(cos θi / cos θti)/η² / (σt′(1 + G)).
glm::dvec3 planeClosedForm(const Material& m, double cosI, double cosO) {
    auto refracted = [&](double c) { return std::sqrt(1.0 - (1.0 - c * c) / (m.eta * m.eta)); };
    const double g = refracted(cosO) / refracted(cosI);
    const glm::dvec3 st = m.sigmaSPrime + m.sigmaA;
    return m.sigmaSPrime * (fresnelTransmittance(m.eta, cosI) * cosI / refracted(cosI)) /
           (4.0 * M_PI * m.eta * m.eta * st * (1.0 + g));
}

// Normal incidence, normal view: R = σs′·Ft(η, 1)·E/(4π η²·2σt′) (E = 1),
// one stratum's closed form within 1e-3.
TEST(SingleScatterHost, PlaneAtNormalIncidenceIsTheClosedForm) {
    const TsisScatterMedium md = scatterMedium(skin(), ExitTerm::Jensen);
    const Light light{Light::Type::Directional, glm::vec3(0, 0, -1), glm::vec3(1.0f)};
    const glm::dvec3 r =
        singleScatterHost({0, 0, 0}, {0, 0, 1}, {0, 0, 50}, md, light, planeEntry, 1);
    const Material& m = skin();
    const glm::dvec3 st = m.sigmaSPrime + m.sigmaA;
    const glm::dvec3 want =
        m.sigmaSPrime * fresnelTransmittance(m.eta, 1.0) / (4.0 * M_PI * m.eta * m.eta * 2.0 * st);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(r[c], want[c], 1e-3 * want[c]) << c;
    // By hand, red: 0.74·Ft(1.3, 1)/(4π·1.69·2·0.772), Ft = 1 − (0.3/2.3)² = 0.98299.
    EXPECT_NEAR(r.x, 0.74 * 0.98299 / (4 * M_PI * 1.69 * 2 * 0.772), 1e-3 * r.x);
}

// Oblique light and view (a point light far away stands in for none: the
// directional light is exact), the same closed form with G.
TEST(SingleScatterHost, PlaneAtObliqueAnglesIsTheClosedForm) {
    const TsisScatterMedium md = scatterMedium(skin(), ExitTerm::Jensen);
    for (const double ti : {0.3, 0.9, 1.4})
        for (const double to : {0.0, 0.7, 1.3}) {
            const glm::vec3 travel(-std::sin(ti), 0.0, -std::cos(ti));
            const Light light{Light::Type::Directional, travel, glm::vec3(1.0f)};
            const glm::dvec3 eye = 40.0 * glm::dvec3(0.0, std::sin(to), std::cos(to));
            const glm::dvec3 r =
                singleScatterHost({0, 0, 0}, {0, 0, 1}, eye, md, light, planeEntry, 1);
            const glm::dvec3 want = planeClosedForm(skin(), std::cos(ti), std::cos(to));
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(r[c], want[c], 1e-3 * want[c]) << ti << " " << to << " " << c;
        }
}

// π over the exit term's scale: π for Jensen's, π·c for the normalised one.
TEST(SingleScatterHost, ToRadiosityUndoesTheExitTerm) {
    EXPECT_FLOAT_EQ(scatterMedium(skin(), ExitTerm::Jensen).to_radiosity, float(M_PI));
    EXPECT_FLOAT_EQ(scatterMedium(skin(), ExitTerm::Normalized).to_radiosity,
                    float(M_PI / normalizedExitScale(skin().eta)));
}

// On a curved surface the term's approximations (the straight line to the
// light, the entry's tangent plane) against the volumetric walk's single
// scattering (maxScatterings = 1: refracted connections through the same
// faceted sphere), skin1 at 30 mm under a directional light, seen along the
// normal from the lit side to past the shadow line.
TEST(SingleScatterHost, SphereAgreesWithTheSingleScatteringWalk) {
    Mesh mesh = builtinSphere();
    normalizeMesh(mesh, 30.0 * std::sqrt(3.0));
    ensureNormals(mesh);
    const MeshBoundary boundary(mesh);
    const Material& m = skin();
    const Light light{Light::Type::Directional, glm::vec3(-1, 0, 0), glm::vec3(1.0f)};
    WalkScene scene{
        &boundary, testMedium(m.sigmaSPrime, m.sigmaA, m.eta), {light}, glm::dvec3(0.0)};
    scene.maxScatterings = 1;
    const TsisScatterMedium md = scatterMedium(m, ExitTerm::Jensen);
    const EntryOf entry = [&](const glm::dvec3& x) {
        SurfaceHit out;
        // As the light view: the first surface along the light's ray through x.
        if (!boundary.intersect(x + glm::dvec3(100, 0, 0), {-1, 0, 0}, kInfinity, out))
            return ScatterEntry{};
        return ScatterEntry{true, out.position, out.normal};
    };
    WalkCounters counters;
    glm::dvec3 lit(0.0);  // the walk's at cos θi = 0.9
    for (const double cosI : {0.9, 0.5, 0.2, 0.1, 0.0, -0.1}) {
        // Off the equator: a point there lies on the UV sphere's facet edge,
        // where the walk's beams of two facets overlap.
        const glm::dvec3 toEye(cosI, 0.3, std::sqrt(0.91 - cosI * cosI));
        SurfaceHit hit;
        ASSERT_TRUE(boundary.intersect(toEye * 100.0, -toEye, kInfinity, hit));
        MeanEstimate walk;
        for (int i = 0; i < 20000; ++i) {
            Rng rng(41, static_cast<uint64_t>(i));
            walk.add(exitantRadiance(scene, hit, toEye, rng, counters));
        }
        const glm::dvec3 r =
            singleScatterHost(hit.position, hit.normal, hit.position + 100.0 * toEye, md, light,
                              entry, kSingleScatterStrata);
        const glm::dvec3 l1 = fresnelTransmittance(m.eta, glm::dot(hit.normal, toEye)) * r;
        // Measured (TSIS_SCATTER_ENTRY_STEPS 2, 3 strata): 0.98-1.01 at
        // cos θi = 0.9, 0.95-0.99 at 0.5, 0.94-1.01 at 0.2, 0.92-1.00 at 0.1;
        // 0.05-0.33 at 0; 1.13-1.27 at -0.1, where the walk's is 0.02-0.5 %
        // of the lit side's: past the shadow line the term is held to the
        // walk within 0.2 % of the lit side's radiance (4 strata: below the
        // walk there; two: 1.06-3.8 at -0.1, one entry plane for half the
        // depth; one: 1.14-1.44 at 0.1).
        if (cosI == 0.9) lit = walk.mean();
        for (int c = 0; c < 3; ++c) {
            if (cosI >= 0.1)
                EXPECT_NEAR(l1[c], walk.mean()[c], (cosI > 0.15 ? 0.1 : 0.15) * walk.mean()[c])
                    << cosI << " " << c;
            else
                EXPECT_LT(l1[c], walk.mean()[c] + 4 * walk.error(c) + 0.002 * lit[c])
                    << cosI << " " << c;
        }
    }
}

// On a plane (a 140 mm square: semi-infinite for skin1) the host version
// against the walk's single scattering, normal view, light at 0 and 57°:
// within 3% (measured 1.003-1.023; the walk's noise 0.2-0.4%).
TEST(SingleScatterHost, PlaneAgreesWithTheSingleScatteringWalk) {
    Mesh mesh = builtinPlane();
    normalizeMesh(mesh, 200.0);
    ensureNormals(mesh);
    const MeshBoundary boundary(mesh);
    const Material& m = skin();
    const TsisScatterMedium md = scatterMedium(m, ExitTerm::Jensen);
    const EntryOf entry = [](const glm::dvec3& x) {
        return ScatterEntry{true, {x.x, 0, x.z}, {0, 1, 0}};
    };
    const glm::dvec3 toEye(0, 1, 0);
    SurfaceHit hit;
    ASSERT_TRUE(boundary.intersect(toEye * 100.0, -toEye, kInfinity, hit));
    for (const double ti : {0.0, 1.0}) {
        const Light light{Light::Type::Directional, glm::vec3(-std::sin(ti), -std::cos(ti), 0),
                          glm::vec3(1.0f)};
        WalkScene scene{
            &boundary, testMedium(m.sigmaSPrime, m.sigmaA, m.eta), {light}, glm::dvec3(0.0)};
        scene.maxScatterings = 1;
        WalkCounters counters;
        MeanEstimate walk;
        for (int i = 0; i < 20000; ++i) {
            Rng rng(41, static_cast<uint64_t>(i));
            walk.add(exitantRadiance(scene, hit, toEye, rng, counters));
        }
        const glm::dvec3 l1 = fresnelTransmittance(m.eta, 1.0) *
                              singleScatterHost(hit.position, hit.normal,
                                                hit.position + 100.0 * toEye, md, light, entry, 1);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(l1[c], walk.mean()[c], 0.03 * walk.mean()[c]) << ti << " " << c;
    }
}

// Every method but volumetric gets the term, and only when asked for.
TEST(SingleScatterHost, AddedForEveryProfileMethodButNotVolumetric) {
    RenderOptions o;
    EXPECT_FALSE(addsSingleScatter(o));
    o.singleScatter = true;
    for (const std::string& m : methodNames()) {
        o.method = m;
        EXPECT_EQ(addsSingleScatter(o), m != "volumetric") << m;
    }
}

class SingleScatterKernelTest : public test::ClTest {
  protected:
    cl::Kernel kernel = rt.kernel("single_scatter.cl", "tsis_single_scatter");
    // Both tests' eye and lights: a directional and a point light.
    const glm::vec3 eye{1.0f, 2.0f, 30.0f};
    const Light lights[2] = {
        {Light::Type::Directional, glm::vec3(-0.5f, 0.2f, -1.0f), glm::vec3(0.3f, 0.2f, 0.1f)},
        {Light::Type::Point, glm::vec3(3.0f, 2.0f, 20.0f), glm::vec3(400.0f, 300.0f, 200.0f)}};
};

// Every output against the host double version on a plane lit from a
// directional and a point light: its orthographic map from +z (texels hold
// their centre's point on z = 0, normal +z, medium 1). Points of medium 2 get
// no light (none of theirs landed), a point of no medium keeps its base;
// both launches accumulate onto a base (the renderer's first writes: the
// plane's render below). Within 2e-4 (float exp/log over 3 strata).
TEST_F(SingleScatterKernelTest, MatchesHostDoubleVersion) {
    const int res = 32;
    const float half = 40.0f;
    const TsisLightMapInfo map = test::lightMap(glm::vec3(0, 0, 10), false, res, half);
    const float texel = 2.0f * half / float(res);
    std::vector<cl_float4> position, normal;
    for (int j = 0; j < res; ++j)
        for (int i = 0; i < res; ++i) {
            position.push_back(
                {{(float(i) + 0.5f) * texel - half, (float(j) + 0.5f) * texel - half, 0, 1}});
            normal.push_back({{0, 0, 1, 1}});  // w: the medium's tag
        }
    // The host's entry: the texel's point, as the kernel reads it.
    const EntryOf entry = [&](const glm::dvec3& x) {
        const glm::dvec3 q = test::project(map, x);
        test::Conditioning cond;
        const int t = test::texel(map, q.x, q.y, cond);
        if (t < 0) return ScatterEntry{};
        return ScatterEntry{true, test::xyz(position[size_t(t)]), {0, 0, 1}};
    };
    Material other = skin();
    other.sigmaSPrime *= 2.0;
    const std::vector<TsisScatterMedium> media = {scatterMedium(skin(), ExitTerm::Normalized),
                                                  scatterMedium(other, ExitTerm::Jensen)};
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(-5.0f, 5.0f);
    std::vector<cl_float4> points, normals;
    for (int k = 0; k < 40; ++k) {
        points.push_back({{u(rng), u(rng), 0.0f, k % 8 == 7 ? 2.0f : 1.0f}});
        // Some normals tilted, one turned away from the eye (flipped as the composite does).
        normals.push_back({{0.05f * u(rng), 0.05f * u(rng), k == 3 ? -1.0f : 1.0f, 0.0f}});
    }
    points.push_back({{0, 0, 0, 0}});  // no medium
    normals.push_back({{0, 0, 1, 0}});
    const int n = int(points.size()), strata = 3;
    std::vector<cl_float4> base(points.size(), {{0.5f, 0.25f, 0.125f, 0.0f}});
    cl::Buffer out = upload(base);
    const cl::Buffer pb = upload(points), nb = upload(normals), mb = upload(media);
    // A drawn view: its positions, then its normals.
    std::vector<cl_float4> view = position;
    view.insert(view.end(), normal.begin(), normal.end());
    const cl::Buffer vb = upload(view);
    const cl_float16 toWorld{};  // a drawn view's kernel reads no depth
    // Every point, named from the last: the kernel writes the point order names.
    std::vector<int> order(points.size());
    for (size_t k = 0; k < order.size(); ++k) order[k] = int(order.size() - 1 - k);
    const cl::Buffer ob = upload(order);
    std::vector<glm::dvec3> want(points.size(), glm::dvec3(0.0));
    for (int l = 0; l < 2; ++l) {
        const Light& light = lights[l];
        const TsisScatterLight sl = scatterLight(light);
        run(kernel, points.size(), pb, nb, ob, n, cl_float4{{eye.x, eye.y, eye.z, 0}}, mb,
            int(media.size()), map, sl, vb, toWorld, strata, 1, out);
        for (size_t k = 0; k < points.size(); ++k) {
            const int tag = int(points[k].s[3]);
            if (tag != 1) continue;  // medium 2: the map's light is medium 1's
            want[k] += double(media[0].to_radiosity) *
                       singleScatterHost(test::xyz(points[k]), test::xyz(normals[k]), eye, media[0],
                                         light, entry, strata);
        }
    }
    const std::vector<cl_float4> got = download<cl_float4>(out, points.size());
    int nonzero = 0;
    for (size_t k = 0; k < points.size(); ++k)
        for (int c = 0; c < 3; ++c) {
            const double b = double(base[k].s[c]) + want[k][c];
            EXPECT_NEAR(got[k].s[c], b, 2e-4 * want[k][c] + 1e-6) << k << " " << c;
            nonzero += want[k][c] > 1e-4;
        }
    EXPECT_GT(nonzero, 90);
}

// The same from a view made of a shadow map's depth alone
// (TSIS_SCATTER_FROM_DEPTH): a tilted plane's depths in an orthographic map
// along -z, the kernel's points and normals unprojected from them against
// depthViewEntry's in double, under a directional and a point light. One
// medium to a view: both media's points read it. Within 2e-4.
TEST_F(SingleScatterKernelTest, FromDepthMatchesHostDoubleVersion) {
    cl::Kernel fromDepth =
        rt.kernel("single_scatter.cl", "tsis_single_scatter", "-DTSIS_SCATTER_FROM_DEPTH");
    const int res = 48;
    const float half = 40.0f;
    const TsisLightMapInfo map = test::lightMap(glm::vec3(0, 0, 10), false, res, half);
    glm::dmat4 viewProj;
    for (int i = 0; i < 16; ++i) glm::value_ptr(viewProj)[i] = double(map.view_proj[i]);
    const double a = 0.3, b = -0.15;  // the plane z = a x + b y
    std::vector<float> depth(size_t(res) * res);
    for (int j = 0; j < res; ++j)
        for (int i = 0; i < res; ++i) {
            const double x = ((i + 0.5) / res * 2.0 - 1.0) * half;
            const double y = ((j + 0.5) / res * 2.0 - 1.0) * half;
            const glm::dvec4 c = viewProj * glm::dvec4(x, y, a * x + b * y, 1.0);
            depth[size_t(j) * res + size_t(i)] = float(c.z / c.w * 0.5 + 0.5);
        }
    const DepthView view{&depth, res, viewProj};
    const EntryOf entry = [&](const glm::dvec3& x) { return depthViewEntry(view, x); };
    Material other = skin();
    other.sigmaSPrime *= 2.0;
    const std::vector<TsisScatterMedium> media = {scatterMedium(skin(), ExitTerm::Normalized),
                                                  scatterMedium(other, ExitTerm::Jensen)};
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-5.0, 5.0);
    const glm::dvec3 normal = glm::normalize(glm::dvec3(-a, -b, 1.0));
    std::vector<cl_float4> points, normals;
    for (int k = 0; k < 40; ++k) {
        const double x = u(rng), y = u(rng);
        points.push_back({{float(x), float(y), float(a * x + b * y), k % 8 == 7 ? 2.0f : 1.0f}});
        normals.push_back({{float(normal.x), float(normal.y), float(normal.z), 0.0f}});
    }
    const int n = int(points.size()), strata = kSingleScatterStrata;
    cl::Buffer out = upload(std::vector<cl_float4>(points.size(), {{0, 0, 0, 0}}));
    const cl::Buffer pb = upload(points), nb = upload(normals), mb = upload(media);
    const cl::Buffer vb = upload(depth);
    const glm::mat4 toWorld = glm::inverse(glm::mat4(viewProj));
    cl_float16 to;
    std::copy_n(glm::value_ptr(toWorld), 16, to.s);
    std::vector<int> order(points.size());
    std::iota(order.begin(), order.end(), 0);
    const cl::Buffer ob = upload(order);
    std::vector<glm::dvec3> want(points.size(), glm::dvec3(0.0));
    for (int l = 0; l < 2; ++l) {
        const Light& light = lights[l];
        const TsisScatterLight sl = scatterLight(light);
        run(fromDepth, points.size(), pb, nb, ob, n, cl_float4{{eye.x, eye.y, eye.z, 0}}, mb,
            int(media.size()), map, sl, vb, to, strata, l, out);
        for (size_t k = 0; k < points.size(); ++k) {
            const TsisScatterMedium& md = media[size_t(points[k].s[3]) - 1];
            want[k] += double(md.to_radiosity) * singleScatterHost(test::xyz(points[k]), normal,
                                                                   eye, md, light, entry, strata);
        }
    }
    const std::vector<cl_float4> got = download<cl_float4>(out, points.size());
    int nonzero = 0;
    for (size_t k = 0; k < points.size(); ++k)
        for (int c = 0; c < 3; ++c) {
            EXPECT_NEAR(got[k].s[c], want[k][c], 2e-4 * want[k][c] + 1e-6) << k << " " << c;
            nonzero += want[k][c] > 1e-4;
        }
    EXPECT_GT(nonzero, 100);
}

// The plane's frame at size² pixels with the term, and its mean B's gain over
// the frame without: π·R (Jensen's exit term) of the closed form at normal
// incidence within 0.5 % (the view is within 5° of the normal: G moves by
// < 0.1 %).
FrameResult expectPlaneGainsTheClosedForm(int size) {
    const Scene scene = test::planeScene("skin1");
    RenderOptions opt = test::smallOptions(size, 256);
    const FrameResult without = test::renderWith(scene, opt, "pyramid");
    opt.singleScatter = true;
    FrameResult with = test::renderWith(scene, opt, "pyramid");
    const glm::dvec3 gain = test::meanRadiosity(with) - test::meanRadiosity(without);
    const glm::dvec3 want = M_PI * planeClosedForm(skin(), 1.0, 1.0);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(gain[c], want[c], 5e-3 * want[c]) << c;
    return with;
}

// A whole frame: the infinite plane under a normal directional light, seen
// straight down.
TEST(SingleScatterRender, PlaneGainsTheClosedForm) {
    expectPlaneGainsTheClosedForm(32);
}

// The scatter views' resolution follows the smallest mean free path ℓ:
// kScatterTexelsPerMfp texels an ℓ across the bounding sphere, within
// [kScatterMinResolution, kScatterMaxResolution] and the shadow maps', over
// sizes, both media and two shadow-map resolutions.
TEST(SingleScatterRender, ScatterViewsFollowTheMeanFreePath) {
    for (const char* material : {"skin1", "marble"})
        for (const double sizeMm : {5.0, 40.0, 80.0, 400.0})
            for (const int lightResolution : {512, 2048}) {
                Scene scene = test::sphereScene(
                    material, {Light::Type::Directional, glm::vec3(0, 0, -1), glm::vec3(1.0f)});
                normalizeMesh(scene.mesh, sizeMm);
                scene.camera.eye *= static_cast<float>(sizeMm / 10.0);
                RenderOptions opt = test::smallOptions(16, 256);
                opt.lightResolution = lightResolution;
                opt.singleScatter = true;
                const FrameResult f = test::renderWith(scene, opt, "pyramid");
                const Material& m = presetMaterial(material);
                const glm::dvec3 st = m.sigmaSPrime + m.sigmaA;
                const double texels =
                    std::ceil(2.0 * boundingRadius(scene.mesh) * std::max({st.x, st.y, st.z}) *
                              kScatterTexelsPerMfp);
                const double most = std::min(kScatterMaxResolution, lightResolution);
                const double want =
                    std::clamp(texels, std::min(double(kScatterMinResolution), most), most);
                EXPECT_EQ(f.stats.number("scatter_view_resolution"), want)
                    << material << " " << sizeMm << " " << lightResolution;
            }
}

// The term is evaluated on a sparse grid and interpolated between: on the
// plane (smooth) a 256² frame evaluates under a third of its points and
// still gains the closed form, as every point evaluated does.
TEST(SingleScatterRender, SparseGridKeepsThePlanesClosedForm) {
    const FrameResult with = expectPlaneGainsTheClosedForm(256);
    EXPECT_GT(with.stats.number("single_scatter_stride"), 1.0);
    EXPECT_LT(with.stats.number("single_scatter_evaluated"),
              double(test::coveredPixels(with)) / 3.0);
}

}  // namespace
}  // namespace tsis
