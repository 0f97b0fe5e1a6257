// parseMTL (mtl.h).
#include "mesh/mtl.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "mesh/parse_util.h"

namespace tsis {

namespace {

using namespace meshparse;

// Statements read or deliberately skipped without a word: none yet beyond
// these three and newmtl.
bool isRead(std::string_view key) {
    return key == "newmtl" || key == "Kd" || key == "map_Kd" || key == "Ni";
}

}  // namespace

std::vector<FileMaterial> parseMTL(const std::string& text, const std::string& path,
                                   const std::string& meshName) {
    namespace fs = std::filesystem;
    const fs::path folder = fs::path(path).parent_path();
    Lines lines(text, '#');
    std::vector<std::string_view> tok;
    std::vector<FileMaterial> out;
    KindCounts ignored;  // keywords
    size_t outside = 0;  // statements before the first newmtl
    auto where = [&](size_t line) { return concat("material library '", path, "': line ", line); };
    auto failLine = [&](size_t line, const auto&... args) -> void {
        failIn(meshName, where(line), ": ", args...);
    };
    auto number = [&](std::string_view token, size_t line, const char* key) {
        double v = 0;
        if (!parseDouble(token, v))
            failLine(line, "material '", out.back().name, "': ", key, ": bad number '", token, "'");
        return v;
    };
    while (lines.next(tok)) {
        const size_t line = lines.lineNumber();
        const std::string_view key = tok[0];
        if (key == "newmtl") {
            if (tok.size() < 2) failLine(line, "newmtl needs a name");
            out.emplace_back();
            out.back().name = std::string(tok[1]);
            continue;
        }
        if (isRead(key) && out.empty()) {
            ++outside;
            continue;
        }
        if (key == "Kd") {
            if (tok.size() < 2) failLine(line, "material '", out.back().name, "': Kd needs r g b");
            if (tok[1] == "spectral" || tok[1] == "xyz") {
                note(meshName, concat(where(line), ": material '", out.back().name, "': Kd ",
                                      tok[1], " ignored (only r g b is read)"));
                continue;
            }
            // "Kd r" is grey: g and b default to r.
            const double r = number(tok[1], line, "Kd");
            const double g = tok.size() > 2 ? number(tok[2], line, "Kd") : r;
            const double b = tok.size() > 3 ? number(tok[3], line, "Kd") : r;
            if (!std::isfinite(r + g + b) || std::min({r, g, b}) < 0)
                failLine(line, "material '", out.back().name, "': Kd ", r, " ", g, " ", b,
                         " must be finite and >= 0");
            out.back().albedo = glm::dvec3(r, g, b);
        } else if (key == "Ni") {
            if (tok.size() < 2) failLine(line, "material '", out.back().name, "': Ni needs η");
            const double eta = number(tok[1], line, "Ni");
            if (!std::isfinite(eta) || !(eta > 0))
                failLine(line, "material '", out.back().name, "': Ni ", eta,
                         " must be finite and > 0");
            out.back().eta = eta;
        } else if (key == "map_Kd") {
            FileMaterial& m = out.back();
            if (tok.size() < 2) failLine(line, "material '", m.name, "': map_Kd needs a file");
            // Options (-s, -o, -clamp, …) change how the map is laid on: not
            // supported, so the map is not used rather than used wrongly.
            if (tok[1].size() > 1 && tok[1][0] == '-') {
                note(meshName, concat(where(line), ": material '", m.name, "': map_Kd option ",
                                      tok[1], " not supported: texture ignored (Kd only)"));
                continue;
            }
            // A file name may hold spaces: the rest of the line.
            std::string file(tok[1]);
            for (size_t k = 2; k < tok.size(); ++k) file += concat(" ", tok[k]);
            const std::string resolved = (folder / file).lexically_normal().string();
            std::error_code ec;
            if (!fs::exists(resolved, ec)) {
                note(meshName, concat(where(line), ": material '", m.name, "': texture '", resolved,
                                      "' not found: albedo factor only"));
                m.texturePath.clear();
                continue;
            }
            m.texturePath = resolved;
        } else {
            ignored.add(key);
        }
    }
    if (outside)
        note(meshName, concat("material library '", path, "': ", outside, " ",
                              plural(outside, "statement", "statements"),
                              " before the first newmtl ignored"));
    if (!ignored.empty())
        note(meshName, concat("material library '", path, "': statements ignored: ", ignored.list(),
                              " (read: newmtl, Kd, map_Kd, Ni)"));
    return out;
}

}  // namespace tsis
