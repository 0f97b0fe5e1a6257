// STL, binary and ASCII. STL stores every triangle with its own three
// corners; corners at the same position become one vertex (so the surface is
// connected and gets smooth normals), the facet normals are not kept.
//
// Binary: an 80-byte header, a little-endian uint32 triangle count, then 50
// bytes per triangle (normal, three corners as float32, a uint16). A file is
// read as binary when its size is exactly that; else, when it starts with
// "solid", as ASCII ("facet normal … outer loop vertex x y z … endloop
// endfacet", several solids allowed); else as binary that does not fit.
#include <bit>
#include <cctype>
#include <cstring>
#include <unordered_map>

#include "mesh/mesh_io.h"
#include "mesh/parse_util.h"
#include "mesh/repair.h"

namespace tsis {

namespace {

using namespace meshparse;

constexpr size_t kHeader = 84, kRecord = 50;

// Corners → vertices, merging exact repeats (+0 and −0 alike).
class Welder {
  public:
    explicit Welder(Mesh& mesh) : mesh_(mesh) {}
    uint32_t add(glm::vec3 p, const std::string& name) {
        p += glm::vec3(0.0f);  // −0 → +0
        Key k{std::bit_cast<uint32_t>(p.x), std::bit_cast<uint32_t>(p.y),
              std::bit_cast<uint32_t>(p.z)};
        const auto [it, added] =
            index_.try_emplace(k, static_cast<uint32_t>(mesh_.positions.size()));
        if (added) {
            if (mesh_.positions.size() >= UINT32_MAX - 1) failIn(name, "more than 2³² vertices");
            mesh_.positions.push_back(p);
        }
        return it->second;
    }

  private:
    struct Key {
        uint32_t x, y, z;
        bool operator==(const Key&) const = default;
    };
    struct KeyHash {
        size_t operator()(const Key& k) const {
            return (static_cast<size_t>(k.x) * 0x9e3779b97f4a7c15ull) ^
                   (static_cast<size_t>(k.y) * 0xc2b2ae3d27d4eb4full) ^ (k.z * 0x165667b1ull);
        }
    };
    Mesh& mesh_;
    std::unordered_map<Key, uint32_t, KeyHash> index_;
};

uint32_t readU32(const char* p) {
    unsigned char b[4];
    std::memcpy(b, p, 4);
    return static_cast<uint32_t>(b[0]) | static_cast<uint32_t>(b[1]) << 8 |
           static_cast<uint32_t>(b[2]) << 16 | static_cast<uint32_t>(b[3]) << 24;
}

float readF32(const char* p) {
    return std::bit_cast<float>(readU32(p));
}

bool startsWithSolid(std::string_view bytes) {
    size_t i = 0;
    while (i < bytes.size() &&
           (bytes[i] == ' ' || bytes[i] == '\t' || bytes[i] == '\r' || bytes[i] == '\n'))
        ++i;
    std::string word(bytes.substr(i, 5));
    for (char& c : word) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return word == "solid";
}

Mesh parseBinary(const std::string& bytes, const std::string& name) {
    if (bytes.size() < kHeader)
        failIn(name, "truncated: ", bytes.size(), " bytes, less than a binary STL header");
    const uint32_t count = readU32(bytes.data() + 80);
    if (count == 0) failIn(name, "no faces (0 triangles)");
    const unsigned long long need = kHeader + static_cast<unsigned long long>(count) * kRecord;
    if (need > bytes.size())
        failIn(name, "truncated or corrupt: header claims ", count, " triangles (", need,
               " bytes), the file has ", bytes.size());
    Mesh mesh;
    mesh.name = name;
    mesh.triangles.reserve(count);
    Welder weld(mesh);
    for (uint32_t t = 0; t < count; ++t) {
        const char* r = bytes.data() + kHeader + static_cast<size_t>(t) * kRecord;
        glm::uvec3 tri;
        for (int c = 0; c < 3; ++c) {
            const char* v = r + 12 + 12 * c;
            const size_t corner = static_cast<size_t>(t) * 3 + c;
            const glm::vec3 p(coordinate(readF32(v), name, corner),
                              coordinate(readF32(v + 4), name, corner),
                              coordinate(readF32(v + 8), name, corner));
            tri[c] = weld.add(p, name);
        }
        mesh.triangles.push_back(tri);
    }
    return mesh;
}

Mesh parseAscii(const std::string& bytes, const std::string& name) {
    Lines lines(bytes, '\0');
    std::vector<std::string_view> tok;
    Mesh mesh;
    mesh.name = name;
    Welder weld(mesh);
    std::vector<uint32_t> loop;
    bool inLoop = false;
    size_t corners = 0, shortFaces = 0;
    auto number = [&](std::string_view t, size_t line) {
        double v = 0;
        if (!parseDouble(t, v)) failAt(name, line, "bad number '", t, "'");
        return v;
    };
    while (lines.next(tok)) {
        const size_t line = lines.lineNumber();
        std::string key(tok[0]);  // keywords in any case ("FACET NORMAL" exists)
        for (char& c : key) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        if (key == "vertex") {
            if (!inLoop) failAt(name, line, "vertex outside 'outer loop'");
            if (tok.size() < 4) failAt(name, line, "vertex needs 3 coordinates");
            ++corners;
            const glm::vec3 p(coordinate(number(tok[1], line), name, corners, line),
                              coordinate(number(tok[2], line), name, corners, line),
                              coordinate(number(tok[3], line), name, corners, line));
            loop.push_back(weld.add(p, name));
        } else if (key == "outer") {
            if (inLoop) failAt(name, line, "'outer loop' inside a loop");
            inLoop = true;
            loop.clear();
        } else if (key == "endloop") {
            if (!inLoop) failAt(name, line, "'endloop' without 'outer loop'");
            inLoop = false;
            Fan fan(mesh.triangles);
            for (uint32_t v : loop) fan.add(v);
            shortFaces += loop.size() < 3;
        } else if (key != "solid" && key != "endsolid" && key != "facet" && key != "endfacet") {
            failAt(name, line, "unexpected '", key, "' (not ASCII STL)");
        }
    }
    if (inLoop) failIn(name, "truncated: the last loop has no 'endloop'");
    noteShortFaces(name, shortFaces);
    if (mesh.triangles.empty()) failIn(name, "no faces (", corners, " corners and no triangles)");
    return mesh;
}

}  // namespace

Mesh parseSTL(const std::string& bytes, const std::string& name) {
    if (bytes.empty()) failIn(name, "empty file");
    const bool exactBinary =
        bytes.size() >= kHeader &&
        kHeader + static_cast<unsigned long long>(readU32(bytes.data() + 80)) * kRecord ==
            bytes.size();
    Mesh mesh =
        !exactBinary && startsWithSolid(bytes) ? parseAscii(bytes, name) : parseBinary(bytes, name);
    repairMesh(mesh);
    return mesh;
}

}  // namespace tsis
