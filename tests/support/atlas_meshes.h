// Meshes for the atlas tests: the CGAL data meshes (skipped when Debian's
// libcgal-demo is not installed) and small procedural ones.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "mesh/mesh.h"

namespace tsis::test {

inline const char* kCgalTarball = "/usr/share/doc/libcgal-dev/data.tar.gz";

// A tiny OFF reader (triangles only) so these tests do not depend on the
// loaders under test elsewhere.
inline Mesh readOFF(const std::string& path) {
    std::ifstream in(path);
    std::string magic;
    in >> magic;
    size_t nv = 0, nf = 0, ne = 0;
    in >> nv >> nf >> ne;
    Mesh m;
    m.name = path;
    m.positions.resize(nv);
    for (auto& p : m.positions) in >> p.x >> p.y >> p.z;
    for (size_t f = 0; f < nf; ++f) {
        int k = 0;
        in >> k;
        std::vector<unsigned> idx(size_t(std::max(k, 0)));
        for (auto& i : idx) in >> i;
        for (int t = 1; t + 1 < k; ++t) m.triangles.emplace_back(idx[0], idx[t], idx[t + 1]);
        std::string rest;
        std::getline(in, rest);
    }
    if (!in) m.triangles.clear();
    return m;
}

// Path of data/meshes/NAME.off unpacked once per process into the temp dir,
// or "" when the tarball is absent.
inline std::string cgalMesh(const std::string& name) {
    if (!std::filesystem::exists(kCgalTarball)) return "";
    static const std::filesystem::path dir =
        std::filesystem::temp_directory_path() /
        ("tsis_atlas_test_meshes_" + std::to_string(::getpid()));
    const std::filesystem::path file = dir / "data" / "meshes" / (name + ".off");
    if (!std::filesystem::exists(file)) {
        std::filesystem::create_directories(dir);
        const std::string cmd = std::string("tar -xzf ") + kCgalTarball + " -C " + dir.string() +
                                " data/meshes/" + name + ".off 2>/dev/null";
        if (std::system(cmd.c_str()) != 0) return "";
    }
    return file.string();
}

// A UV sphere (closed, genus 0) or an open cylinder (a tube: two border loops).
inline Mesh sphereMesh(int rings, int segments) {
    Mesh m;
    m.name = "test:sphere";
    const double pi = 3.14159265358979323846;
    m.positions.emplace_back(0, 1, 0);
    for (int r = 1; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            const double th = pi * r / rings, ph = 2 * pi * s / segments;
            m.positions.emplace_back(std::sin(th) * std::cos(ph), std::cos(th),
                                     -std::sin(th) * std::sin(ph));
        }
    m.positions.emplace_back(0, -1, 0);
    const unsigned south = unsigned(m.positions.size() - 1);
    auto at = [&](int r, int s) { return unsigned(1 + (r - 1) * segments + (s % segments)); };
    for (int s = 0; s < segments; ++s) m.triangles.emplace_back(0, at(1, s), at(1, s + 1));
    for (int r = 1; r + 1 < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            m.triangles.emplace_back(at(r, s), at(r + 1, s), at(r + 1, s + 1));
            m.triangles.emplace_back(at(r, s), at(r + 1, s + 1), at(r, s + 1));
        }
    for (int s = 0; s < segments; ++s)
        m.triangles.emplace_back(at(rings - 1, s), south, at(rings - 1, s + 1));
    for (auto& p : m.positions) m.normals.push_back(p);
    return m;
}

inline Mesh tubeMesh(int rings, int segments, double length) {
    Mesh m;
    m.name = "test:tube";
    const double pi = 3.14159265358979323846;
    for (int r = 0; r <= rings; ++r)
        for (int s = 0; s < segments; ++s) {
            const double ph = 2 * pi * s / segments;
            m.positions.emplace_back(std::cos(ph), length * r / rings, -std::sin(ph));
        }
    auto at = [&](int r, int s) { return unsigned(r * segments + (s % segments)); };
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            m.triangles.emplace_back(at(r, s), at(r, s + 1), at(r + 1, s + 1));
            m.triangles.emplace_back(at(r, s), at(r + 1, s + 1), at(r + 1, s));
        }
    return m;
}

// A right prism of `height` over a simple polygon (counter-clockwise, fanned
// from its first corner, which must see every other), one vertex per corner:
// a box, a slab, an L-shaped block. Outward-facing, closed, its sharp edges
// at 90° (the polygon's own corners aside).
inline Mesh prismMesh(const std::vector<glm::vec2>& polygon, float height) {
    Mesh m;
    m.name = "test:prism";
    const unsigned n = unsigned(polygon.size());
    for (float z : {0.0f, height})
        for (glm::vec2 p : polygon) m.positions.emplace_back(p.x, p.y, z);
    for (unsigned i = 1; i + 1 < n; ++i) {
        m.triangles.emplace_back(0, i + 1, i);          // bottom, facing -z
        m.triangles.emplace_back(n, n + i, n + i + 1);  // top, facing +z
    }
    for (unsigned i = 0; i < n; ++i) {
        const unsigned j = (i + 1) % n;
        m.triangles.emplace_back(i, j, n + j);
        m.triangles.emplace_back(i, n + j, n + i);
    }
    return m;
}

inline Mesh boxMesh(float x, float y, float z) {
    Mesh m = prismMesh({{0, 0}, {x, 0}, {x, y}, {0, y}}, z);
    m.name = "test:box";
    return m;
}

}  // namespace tsis::test
