// The volumetric walk against Mitsuba 3 (volpath) on scenes both can sample:
// a unit sky around a slab and a sphere (tests/validation/mitsuba_reference.py
// made the numbers and sphere.obj; Mitsuba is not needed here).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <glm/geometric.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "mesh/mesh_io.h"
#include "physics/fresnel.h"
#include "physics/material.h"
#include "support/volumetric_walk.h"
#include "volumetric/camera_walk.h"
#include "volumetric/mesh_boundary.h"

namespace tsis {
namespace {

struct Row {
    std::string scene, material;
    double x = 0, half = 0;
    glm::dvec3 value{0.0}, error{0.0};
};

std::vector<Row> readRows() {
    std::ifstream in(std::string(TSIS_SOURCE_DIR) + "/tests/validation/mitsuba_reference.csv");
    std::vector<Row> rows;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#' || line.rfind("scene,", 0) == 0) continue;
        std::stringstream s(line);
        std::string cell;
        std::vector<std::string> cells;
        while (std::getline(s, cell, ',')) cells.push_back(cell);
        if (cells.size() != 10) continue;
        Row r;
        r.scene = cells[0];
        r.material = cells[1];
        r.x = std::stod(cells[2]);
        r.half = std::stod(cells[3]);
        for (int c = 0; c < 3; ++c) {
            r.value[c] = std::stod(cells[4 + static_cast<size_t>(c)]);
            r.error[c] = std::stod(cells[7 + static_cast<size_t>(c)]);
        }
        rows.push_back(r);
    }
    return rows;
}

// The mean radiance over the window, as Mitsuba's 1×1 orthographic pixel sees
// it looking down −z (the slab: the half-space, normal view), with the sky's
// specular reflection added (this convex scene reflects only the sky).
MeanEstimate window(const Boundary& boundary, const Material& m, const Row& row, bool slab,
                    int paths) {
    WalkScene scene{&boundary, Medium(m), {}, glm::dvec3(1.0)};
    WalkCounters counters;
    MeanEstimate e;
    for (int i = 0; i < paths; ++i) {
        Rng rng(2024, static_cast<uint64_t>(i));
        SurfaceHit hit;
        glm::dvec3 toEye;
        if (slab) {
            hit.normal = {0, 1, 0};
            toEye = {0, 1, 0};
        } else {
            const double u = rng.uniform(), v = rng.uniform();
            const glm::dvec3 origin(row.x + (2 * u - 1) * row.half, (2 * v - 1) * row.half, 50.0);
            toEye = {0, 0, 1};
            if (!boundary.intersect(origin, -toEye, kInfinity, hit)) {
                e.add(glm::dvec3(1.0));  // the sky
                continue;
            }
        }
        const double cosO = glm::dot(hit.normal, toEye);
        e.add(exitantRadiance(scene, hit, toEye, rng, counters) +
              glm::dvec3(fresnelReflectance(m.eta, cosO)));
    }
    return e;
}

TEST(Mitsuba, SkyLitSlabAndSphereAgree) {
    const std::vector<Row> rows = readRows();
    ASSERT_FALSE(rows.empty()) << "tests/validation/mitsuba_reference.csv";
    Mesh sphere = loadMesh(std::string(TSIS_SOURCE_DIR) + "/tests/validation/sphere.obj");
    const MeshBoundary sphereBoundary(sphere);
    const HalfSpace halfSpace;
    for (const Row& row : rows) {
        const Material& m = presetMaterial(row.material);
        const bool slab = row.scene == "slab";
        // Marble's walks are ~10× longer: fewer of them.
        const int paths = row.material == "marble" ? 6000 : 30000;
        const MeanEstimate e = window(
            slab ? static_cast<const Boundary&>(halfSpace) : sphereBoundary, m, row, slab, paths);
        const glm::dvec3 mean = e.mean();
        std::printf(
            "%s %s x %.2f: tsis %.4f %.4f %.4f (± %.4f %.4f %.4f), mitsuba %.4f %.4f %.4f "
            "(± %.4f %.4f %.4f)\n",
            row.scene.c_str(), row.material.c_str(), row.x, mean.x, mean.y, mean.z, e.error(0),
            e.error(1), e.error(2), row.value.x, row.value.y, row.value.z, row.error.x, row.error.y,
            row.error.z);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(mean[c], row.value[c], 4 * std::hypot(e.error(c), row.error[c]))
                << row.scene << " " << row.material << " x " << row.x << " channel " << c;
    }
}

}  // namespace
}  // namespace tsis
