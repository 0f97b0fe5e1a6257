// Wavefront OBJ: v, vt, vn and f (v, v/vt, v//vn, v/vt/vn; negative indices
// count back from the latest), mtllib and usemtl (the .mtl files through
// mtl.h). Corners with separate v/vt/vn indices become one vertex per
// distinct combination, so every attribute is per vertex.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <unordered_map>
#include <unordered_set>

#include "mesh/mesh_io.h"
#include "mesh/mtl.h"
#include "mesh/parse_util.h"
#include "mesh/repair.h"
#include "util/input_file.h"

namespace tsis {

namespace {

using namespace meshparse;

constexpr uint32_t kNone = UINT32_MAX;

struct Corner {
    uint32_t v = kNone, vt = kNone, vn = kNone;  // 0-based
    bool operator==(const Corner&) const = default;
};

struct CornerHash {
    size_t operator()(const Corner& c) const {
        const auto mix = [](size_t h, uint32_t x) {
            return h ^ (std::hash<uint32_t>()(x) + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2));
        };
        return mix(mix(std::hash<uint32_t>()(c.v), c.vt), c.vn);
    }
};

// Resolves a 1-based or negative OBJ index against the `count` seen so far.
uint32_t resolve(std::string_view token, size_t count, const char* what, const std::string& name,
                 size_t line) {
    long long i = 0;
    if (!parseInt(token, i)) failAt(name, line, "bad ", what, " index '", token, "'");
    if (i == 0) failAt(name, line, what, " index 0 (OBJ indices start at 1)");
    const long long n = static_cast<long long>(count);
    const long long r = i > 0 ? i - 1 : n + i;
    if (r < 0 || r >= n)
        failAt(name, line, what, " index ", i, " out of range (", n, " defined so far)");
    return static_cast<uint32_t>(r);  // counts stay below kNone (see parseOBJ)
}

Corner parseCorner(std::string_view token, size_t nv, size_t nvt, size_t nvn,
                   const std::string& name, size_t line) {
    std::string_view part[3];
    size_t parts = 0;
    for (size_t start = 0;;) {
        const size_t slash = token.find('/', start);
        if (parts == 3) failAt(name, line, "bad face corner '", token, "'");
        part[parts++] =
            token.substr(start, slash == std::string_view::npos ? slash : slash - start);
        if (slash == std::string_view::npos) break;
        start = slash + 1;
    }
    Corner c;
    c.v = resolve(part[0], nv, "vertex", name, line);
    if (parts > 1 && !part[1].empty())
        c.vt = resolve(part[1], nvt, "texture coordinate", name, line);
    if (parts > 2 && !part[2].empty()) c.vn = resolve(part[2], nvn, "normal", name, line);
    return c;
}

// Distinct names in the order met; the first three kept for the note.
struct Names {
    std::unordered_set<std::string> seen;
    std::vector<std::string> first;
    void add(std::string_view n) {
        if (seen.emplace(n).second && first.size() < 3) first.emplace_back(n);
    }
    size_t size() const { return seen.size(); }
    bool empty() const { return seen.empty(); }
    // "'a', 'b', 'c' and 2 more".
    std::string list() const {
        std::string s;
        for (size_t i = 0; i < first.size(); ++i) s += concat(i ? ", '" : "'", first[i], "'");
        if (size() > first.size()) s += concat(" and ", size() - first.size(), " more");
        return s;
    }
};

// Statements that do not change the surface, one note per kind.
struct Ignored {
    Names libraries, materials, smoothing;  // mtllib, usemtl (when not read), s (but off)
    size_t groups = 0, elements = 0;
    KindCounts other;  // keywords

    void add(std::string_view key, const std::vector<std::string_view>& tok) {
        if (key == "mtllib") {
            for (size_t k = 1; k < tok.size(); ++k) libraries.add(tok[k]);
        } else if (key == "usemtl") {
            if (tok.size() > 1) materials.add(tok[1]);
        } else if (key == "o" || key == "g") {
            ++groups;
        } else if (key == "s") {
            if (tok.size() > 1 && tok[1] != "off" && tok[1] != "0") smoothing.add(tok[1]);
        } else if (key == "l" || key == "p") {
            ++elements;
        } else {
            other.add(key);
        }
    }

    void note(const std::string& name) const {
        if (!libraries.empty())
            meshparse::note(
                name, concat(plural(libraries.size(), "material library ", "material libraries "),
                             libraries.list(), " ignored (mtllib: not read by this command)"));
        if (!materials.empty())
            meshparse::note(
                name, concat(plural(materials.size(), "material ", "materials "), materials.list(),
                             " ignored (the material is --material's)"));
        if (groups)
            meshparse::note(name, concat(groups, " ", plural(groups, "group", "groups"),
                                         " (o, g) ignored (the file is one mesh)"));
        if (!smoothing.empty())
            meshparse::note(name, concat(smoothing.size(), " smoothing ",
                                         plural(smoothing.size(), "group", "groups"),
                                         " (s) ignored (normals: vn, else from the faces)"));
        if (elements)
            meshparse::note(
                name, concat(elements, " line and point ", plural(elements, "element", "elements"),
                             " (l, p) ignored (only faces are drawn)"));
        if (!other.empty()) meshparse::note(name, "statements ignored: " + other.list());
    }
};

double number(std::string_view token, const std::string& name, size_t line) {
    double v = 0;
    if (!parseDouble(token, v)) failAt(name, line, "bad number '", token, "'");
    return v;
}

// The materials of the mtllib files, in order (the first definition of a
// name counts), into view->materials; a library that cannot be read is a note.
std::vector<FileMaterial> readLibraries(const std::vector<std::string>& libraries,
                                        const std::string& folder, const std::string& name) {
    std::vector<FileMaterial> out;
    std::unordered_set<std::string> defined;
    Names twice;
    for (const std::string& lib : libraries) {
        if (folder.empty()) {
            note(name, concat("material library '", lib,
                              "' not read (parsing from memory): its materials are undefined"));
            continue;
        }
        std::string path = (std::filesystem::path(folder) / lib).lexically_normal().string();
        std::string text;
        try {
            path = assetFile(folder, lib, "material library");
            text = readRegularFile(path, "material library", kMaxLibraryFileBytes);
        } catch (const Error& e) {
            note(name, concat(e.what(), ": its materials are undefined"));
            continue;
        }
        for (FileMaterial& m : parseMTL(text, path, name)) {
            if (!defined.insert(m.name).second) {
                twice.add(m.name);
                continue;
            }
            out.push_back(std::move(m));
        }
    }
    if (!twice.empty())
        note(name, concat(plural(twice.size(), "material ", "materials "), twice.list(),
                          " defined twice: the first definition is used"));
    return out;
}

// Each triangle's material: its face's usemtl name looked up in `materials`
// (which become view.materials). Faces are fans of (corners − 2) triangles,
// in order; faceStart ends with the corner count.
void assignMaterials(Mesh& mesh, const std::vector<size_t>& faceStart,
                     const std::vector<uint32_t>& faceMaterial,
                     const std::vector<std::string>& usedNames, std::vector<FileMaterial> materials,
                     FileView& view) {
    std::unordered_map<std::string, uint32_t> byName;  // names are distinct (readLibraries)
    for (size_t m = 0; m < materials.size(); ++m)
        byName.emplace(materials[m].name, static_cast<uint32_t>(m));
    std::vector<uint32_t> id(usedNames.size(), kNoFileMaterial);
    Names undefined;
    for (size_t u = 0; u < usedNames.size(); ++u) {
        const auto it = byName.find(usedNames[u]);
        if (it == byName.end())
            undefined.add(usedNames[u]);
        else
            id[u] = it->second;
    }
    if (!undefined.empty())
        note(mesh.name,
             concat(plural(undefined.size(), "material ", "materials "), undefined.list(),
                    " (usemtl) defined in no material library: ",
                    plural(undefined.size(), "its", "their"), " faces take the scene's material"));
    view.materials = std::move(materials);
    std::vector<uint32_t> ids;
    ids.reserve(mesh.triangles.size());
    bool any = false;
    for (size_t f = 0; f < faceMaterial.size(); ++f) {
        const uint32_t m = faceMaterial[f] == kNone ? kNoFileMaterial : id[faceMaterial[f]];
        any = any || m != kNoFileMaterial;
        ids.insert(ids.end(), faceStart[f + 1] - faceStart[f] - 2, m);
    }
    TSIS_CHECK(ids.size() == mesh.triangles.size());
    if (any) mesh.materialIds = std::move(ids);
}

}  // namespace

Mesh parseOBJ(const std::string& text, const std::string& name, const std::string& folder,
              FileView* view) {
    std::string_view body(text);
    if (body.substr(0, 3) == "\xEF\xBB\xBF") body.remove_prefix(3);  // UTF-8 BOM
    Lines lines(body, '#');
    std::vector<std::string_view> tok;
    std::vector<glm::vec3> pos, nrm;
    std::vector<glm::vec2> tex;
    // Faces as they are (corners, and where each face starts): triangulated
    // only once the attributes to keep are known.
    std::vector<Corner> corners;
    std::vector<size_t> faceStart;
    size_t lineCount = 0, shortFaces = 0, triangleCount = 0;
    Ignored ignored;
    // With a view: the mtllib files, and each face's usemtl (an index into
    // usedNames, or kNone before the first usemtl).
    std::vector<std::string> libraries, usedNames;
    std::unordered_set<std::string> libraryNames;
    std::unordered_map<std::string, uint32_t> usedIndex;  // into usedNames
    std::vector<uint32_t> faceMaterial;
    uint32_t current = kNone;
    while (lines.next(tok)) {
        ++lineCount;
        const size_t line = lines.lineNumber();
        const std::string_view key = tok[0];
        if (std::max({pos.size(), tex.size(), nrm.size()}) >= kNone - 1)
            failAt(name, line, "more than 2³² vertices, texture coordinates or normals");
        if (key == "v") {
            // "v x y z [w]" or "v x y z r g b": only x y z matter.
            if (tok.size() < 4) failAt(name, line, "vertex needs 3 coordinates");
            const size_t i = pos.size() + 1;  // the file's 1-based numbering
            pos.emplace_back(coordinate(number(tok[1], name, line), name, i, line),
                             coordinate(number(tok[2], name, line), name, i, line),
                             coordinate(number(tok[3], name, line), name, i, line));
        } else if (key == "vt") {
            if (tok.size() < 2) failAt(name, line, "texture coordinate needs a value");
            const double u = number(tok[1], name, line);
            const double v = tok.size() > 2 ? number(tok[2], name, line) : 0.0;
            if (!std::isfinite(toFloat(u)) || !std::isfinite(toFloat(v)))
                failAt(name, line, "texture coordinate ", tex.size() + 1, " is not finite");
            tex.emplace_back(toFloat(u), toFloat(v));
        } else if (key == "vn") {
            if (tok.size() < 4) failAt(name, line, "normal needs 3 components");
            nrm.emplace_back(toFloat(number(tok[1], name, line)),
                             toFloat(number(tok[2], name, line)),
                             toFloat(number(tok[3], name, line)));
        } else if (key == "f") {
            if (tok.size() < 4) {
                ++shortFaces;
                continue;
            }
            faceStart.push_back(corners.size());
            faceMaterial.push_back(current);
            for (size_t k = 1; k < tok.size(); ++k)
                corners.push_back(
                    parseCorner(tok[k], pos.size(), tex.size(), nrm.size(), name, line));
            triangleCount += tok.size() - 3;
        } else if (view && key == "mtllib") {
            for (size_t k = 1; k < tok.size(); ++k)
                if (libraryNames.emplace(tok[k]).second) libraries.emplace_back(tok[k]);
        } else if (view && key == "usemtl") {
            if (tok.size() < 2) {
                current = kNone;  // "usemtl" alone: back to no material
                continue;
            }
            const auto [it, added] =
                usedIndex.try_emplace(std::string(tok[1]), static_cast<uint32_t>(usedNames.size()));
            if (added) usedNames.emplace_back(tok[1]);
            current = it->second;
        } else {
            ignored.add(key, tok);
        }
    }
    if (lineCount == 0) failIn(name, "empty file");
    noteShortFaces(name, shortFaces);
    if (faceStart.empty()) failIn(name, "no faces (", pos.size(), " vertices and no triangles)");
    ignored.note(name);

    // Attributes only when every corner has one: a partly textured mesh has
    // no atlas, a partly shaded one gets computed normals. The file's
    // texcoords (for its textures) are kept when any corner has one, (0, 0)
    // on the others.
    size_t withUV = 0, withN = 0;
    for (const Corner& c : corners) {
        withUV += c.vt != kNone;
        withN += c.vn != kNone;
    }
    const bool keepUV = withUV == corners.size(), keepN = withN == corners.size();
    const bool keepTex = withUV > 0;
    if (withUV && !keepUV)
        note(name, concat("texture coordinates on only ", withUV, " of ", corners.size(),
                          " face corners: not used as the atlas; a texture shows its (0, 0) "
                          "corner on the others"));
    if (withN && !keepN)
        note(name, concat("ignored normals: only ", withN, " of ", corners.size(),
                          " face corners have one"));

    Mesh mesh;
    mesh.name = name;
    std::unordered_map<Corner, uint32_t, CornerHash> index;
    index.reserve(pos.size());
    mesh.triangles.reserve(triangleCount);
    faceStart.push_back(corners.size());
    for (size_t f = 0; f + 1 < faceStart.size(); ++f) {
        Fan fan(mesh.triangles);
        for (size_t k = faceStart[f]; k < faceStart[f + 1]; ++k) {
            Corner c = corners[k];
            if (!keepN) c.vn = kNone;
            const auto [it, added] =
                index.try_emplace(c, static_cast<uint32_t>(mesh.positions.size()));
            if (added) {
                mesh.positions.push_back(pos[c.v]);
                if (keepUV) mesh.uvs.push_back(tex[c.vt]);
                // OBJ's v runs up the image, the texcoords' down.
                if (keepTex)
                    mesh.texcoords.push_back(c.vt == kNone
                                                 ? glm::vec2(0.0f)
                                                 : glm::vec2(tex[c.vt].x, 1.0f - tex[c.vt].y));
                if (keepN) mesh.normals.push_back(nrm[c.vn]);
            }
            fan.add(it->second);
        }
    }
    if (view)
        assignMaterials(mesh, faceStart, faceMaterial, usedNames,
                        readLibraries(libraries, folder, name), *view);
    // Vertices no face uses never became mesh vertices; say so like the
    // other formats do.
    std::vector<char> used(pos.size(), 0);
    for (const auto& [c, i] : index) used[c.v] = 1;
    size_t unused = 0;
    for (char u : used) unused += !u;
    if (unused)
        note(name,
             concat("removed ", unused, " unreferenced ", plural(unused, "vertex", "vertices")));
    repairMesh(mesh);
    return mesh;
}

}  // namespace tsis
