// OFF (Geomview): [ST][C][N][4][n]OFF header, counts, vertex lines
// "x y z [w] [nx ny nz] [colour] [s t]", face lines "k i0 … ik-1 [colour]".
// Polygons are fan-triangulated; '#' starts a comment.
#include <algorithm>
#include <cmath>
#include <limits>

#include "mesh/mesh_io.h"
#include "mesh/parse_util.h"
#include "mesh/repair.h"

namespace tsis {

namespace {

using namespace meshparse;

struct OffHeader {
    bool st = false, colour = false, normals = false, homogeneous = false, ndim = false;
};

// Reads the prefix letters of the keyword; false when it is not an OFF keyword.
bool parseKeyword(std::string_view k, OffHeader& h) {
    auto take = [&](std::string_view p) {
        if (k.substr(0, p.size()) != p) return false;
        k.remove_prefix(p.size());
        return true;
    };
    h.st = take("ST");
    h.colour = take("C");
    h.normals = take("N");
    h.homogeneous = take("4");
    h.ndim = take("n");
    return k == "OFF";
}

long long parseCount(std::string_view token, const char* what, const std::string& name,
                     size_t line) {
    long long v = 0;
    if (!parseInt(token, v)) failAt(name, line, "bad ", what, " '", token, "'");
    if (v < 0) failAt(name, line, "negative ", what, " ", v);
    return v;
}

}  // namespace

Mesh parseOFF(const std::string& text, const std::string& name) {
    std::string_view body(text);
    if (body.substr(0, 3) == "\xEF\xBB\xBF") body.remove_prefix(3);  // UTF-8 BOM
    Lines lines(body, '#');
    std::vector<std::string_view> tok;
    if (!lines.next(tok)) failIn(name, "empty file");

    OffHeader h;
    if (!parseKeyword(tok[0], h))
        failAt(name, lines.lineNumber(), "not an OFF file (first word '", tok[0], "')");
    std::vector<std::string_view> head(tok.begin() + 1, tok.end());
    if (!head.empty() && head[0] == "BINARY")
        failAt(name, lines.lineNumber(), "binary OFF is not supported; convert it to ASCII");
    // Dimension (nOFF) and counts, on the keyword's line or the lines after.
    const size_t want = (h.ndim ? 1 : 0) + 2;
    while (head.size() < want) {
        if (!lines.next(tok)) failIn(name, "truncated: the header has no vertex and face counts");
        head.insert(head.end(), tok.begin(), tok.end());
    }
    const size_t countLine = lines.lineNumber();
    size_t at = 0;
    if (h.ndim) {
        const long long dim = parseCount(head[at++], "dimension", name, countLine);
        if (dim != 3) failAt(name, countLine, "only 3-D OFF is supported (dimension ", dim, ")");
    }
    const long long nv = parseCount(head[at++], "vertex count", name, countLine);
    const long long nf = parseCount(head[at++], "face count", name, countLine);
    if (nf == 0) failIn(name, "no faces (", nv, " vertices and no triangles)");

    // Refuse counts the rest of the file cannot hold before allocating for
    // them: every number takes a character and a separator.
    const size_t perVertex = 3 + (h.homogeneous ? 1 : 0) + (h.normals ? 3 : 0) + (h.st ? 2 : 0);
    const unsigned long long tokens = minBytes(static_cast<unsigned long long>(nv), perVertex) +
                                      static_cast<unsigned long long>(nf);
    if (nv > std::numeric_limits<uint32_t>::max() - 1LL ||
        minBytes(tokens, 2) > lines.bytesLeft() + 1)
        failAt(name, countLine, "truncated or corrupt: header claims ", nv, " vertices and ", nf,
               " faces, more than the file's ", text.size(), " bytes can hold");

    Mesh mesh;
    mesh.name = name;
    mesh.positions.reserve(static_cast<size_t>(nv));
    if (h.normals) mesh.normals.reserve(static_cast<size_t>(nv));
    if (h.st) mesh.uvs.reserve(static_cast<size_t>(nv));
    for (long long i = 0; i < nv; ++i) {
        if (!lines.next(tok)) failIn(name, "truncated: expected ", nv, " vertices, found ", i);
        if (tok.size() < perVertex)
            failAt(name, lines.lineNumber(), "vertex ", i, " has ", tok.size(),
                   " numbers, expected at least ", perVertex);
        double v[4] = {0, 0, 0, 1};
        for (size_t k = 0; k < (h.homogeneous ? 4u : 3u); ++k)
            if (!parseDouble(tok[k], v[k]))
                failAt(name, lines.lineNumber(), "vertex ", i, ": bad number '", tok[k], "'");
        if (h.homogeneous) {
            if (v[3] == 0.0) failAt(name, lines.lineNumber(), "vertex ", i, " has w = 0");
            for (int k = 0; k < 3; ++k) v[k] /= v[3];
        }
        const size_t vi = static_cast<size_t>(i);
        const size_t line = lines.lineNumber();
        mesh.positions.emplace_back(coordinate(v[0], name, vi, line),
                                    coordinate(v[1], name, vi, line),
                                    coordinate(v[2], name, vi, line));
        const size_t n0 = h.homogeneous ? 4 : 3;
        if (h.normals) {
            double n[3];
            for (size_t k = 0; k < 3; ++k)
                if (!parseDouble(tok[n0 + k], n[k]))
                    failAt(name, lines.lineNumber(), "vertex ", i, ": bad normal '", tok[n0 + k],
                           "'");
            mesh.normals.emplace_back(toFloat(n[0]), toFloat(n[1]), toFloat(n[2]));
        }
        if (h.st) {
            // Colours (any count) sit between the normal and s t: take the last two.
            double s = 0, t = 0;
            if (!parseDouble(tok[tok.size() - 2], s) || !parseDouble(tok[tok.size() - 1], t))
                failAt(name, lines.lineNumber(), "vertex ", i, ": bad texture coordinate");
            mesh.uvs.emplace_back(toFloat(s), toFloat(t));
        }
    }

    size_t skipped = 0;
    // Reserve for real triangles ("3 a b c\n", 8 bytes at least), not for the
    // count a file of short faces could claim.
    mesh.triangles.reserve(
        static_cast<size_t>(std::min<unsigned long long>(nf, lines.bytesLeft() / 8)));
    for (long long f = 0; f < nf; ++f) {
        if (!lines.next(tok)) failIn(name, "truncated: expected ", nf, " faces, found ", f);
        const size_t line = lines.lineNumber();
        const long long k = parseCount(tok[0], "face vertex count", name, line);
        if (static_cast<unsigned long long>(k) > tok.size() - 1)
            failAt(name, line, "face ", f, " lists ", k, " vertices but the line has only ",
                   tok.size() - 1, " numbers");
        if (k < 3) {
            ++skipped;
            continue;
        }
        Fan fan(mesh.triangles);
        for (long long c = 0; c < k; ++c) {
            long long idx = 0;
            if (!parseInt(tok[1 + c], idx))
                failAt(name, line, "face ", f, ": bad vertex index '", tok[1 + c], "'");
            if (idx < 0 || idx >= nv)
                failAt(name, line, "face ", f, ": vertex index ", idx, " out of range (", nv,
                       " vertices)");
            fan.add(static_cast<uint32_t>(idx));
        }
    }
    noteShortFaces(name, skipped);
    repairMesh(mesh);
    return mesh;
}

}  // namespace tsis
