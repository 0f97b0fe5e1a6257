// parseMTL (mtl.h).
#include "mesh/mtl.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "mesh/parse_util.h"
#include "util/input_file.h"

namespace tsis {

namespace {

using namespace meshparse;

// Statements read or deliberately skipped without a word: none yet beyond
// these and newmtl.
bool isRead(std::string_view key) {
    return key == "newmtl" || key == "Kd" || key == "map_Kd" || key == "Ni" || key == "Pr" ||
           key == "Ns" || key == "norm" || key == "map_Bump" || key == "bump" || key == "map_Pr";
}

// Blender's exporter writes Ns = (30 (1 − R))² (its importer inverts it):
// the convention most OBJ files carry. Ns past 900 is sharper than R = 0.
double roughnessOfPhongExponent(double ns) {
    return 1.0 - std::sqrt(std::clamp(ns, 0.0, 900.0)) / 30.0;
}

}  // namespace

std::vector<FileMaterial> parseMTL(const std::string& text, const std::string& path,
                                   const std::string& meshName) {
    namespace fs = std::filesystem;
    const std::string folder = fs::path(path).parent_path().string();
    std::string_view body(text);
    if (body.substr(0, 3) == "\xEF\xBB\xBF") body.remove_prefix(3);  // UTF-8 BOM
    Lines lines(body, '#');
    std::vector<std::string_view> tok;
    std::vector<FileMaterial> out;
    KindCounts ignored;  // keywords
    size_t outside = 0;  // statements before the first newmtl
    size_t noIndex = 0;  // materials with "Ni 1": exporters' "no index given"
    std::string firstNoIndex;
    std::vector<char> physical;  // per material: a Pr given (it wins over Ns)
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
            physical.push_back(0);
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
            // Many exporters write Ni 1 for "no index of refraction given"
            // (a subsurface medium of η = 1 has no boundary): the default η.
            if (eta == 1.0) {
                if (noIndex++ == 0) firstNoIndex = out.back().name;
                continue;
            }
            out.back().eta = eta;
        } else if (key == "Pr" || key == "Ns") {
            if (tok.size() < 2)
                failLine(line, "material '", out.back().name, "': ", key, " needs a value");
            const double v = number(tok[1], line, key == "Pr" ? "Pr" : "Ns");
            if (!std::isfinite(v) || v < 0)
                failLine(line, "material '", out.back().name, "': ", key, " ", v,
                         " must be finite and >= 0");
            if (key == "Pr") {
                out.back().roughness = v;
                physical.back() = 1;
            } else if (!physical.back()) {
                out.back().roughness = roughnessOfPhongExponent(v);
            }
        } else if (key == "map_Kd" || key == "norm" || key == "map_Bump" || key == "bump" ||
                   key == "map_Pr") {
            FileMaterial& m = out.back();
            const bool albedo = key == "map_Kd", roughness = key == "map_Pr";
            const char* without = albedo      ? "albedo factor only"
                                  : roughness ? "its roughness alone"
                                              : "no normal map";
            if (tok.size() < 2) failLine(line, "material '", m.name, "': ", key, " needs a file");
            // Options (-s, -o, -clamp, …) change how the map is laid on: not
            // supported, so the map is not used rather than used wrongly; a
            // normal map's -bm (its scale) is read.
            size_t first = 1;
            double scale = 1.0;
            if (!albedo && !roughness && tok.size() > 3 && tok[1] == "-bm") {
                scale = number(tok[2], line, "-bm");
                first = 3;
            }
            if (tok[first].size() > 1 && tok[first][0] == '-') {
                note(meshName, concat(where(line), ": material '", m.name, "': ", key, " option ",
                                      tok[first], " not supported: texture ignored (",
                                      albedo ? "Kd only" : without, ")"));
                continue;
            }
            // A file name may hold spaces, even doubled ones: the rest of the
            // line as written, from its token.
            const std::string file(
                tok[first].data(),
                static_cast<size_t>(tok.back().data() + tok.back().size() - tok[first].data()));
            std::string& path = albedo      ? m.texturePath
                                : roughness ? m.roughnessMapPath
                                            : m.normalMapPath;
            path.clear();
            try {
                path = assetFile(folder.empty() ? "." : folder, file, "texture");
            } catch (const Error& e) {
                note(meshName,
                     concat(where(line), ": material '", m.name, "': ", e.what(), ": ", without));
                continue;
            }
            if (const std::string why = notRegularFile(path); !why.empty()) {
                note(meshName, concat(where(line), ": material '", m.name, "': texture '", path,
                                      "' ", why, ": ", without));
                path.clear();
                continue;
            }
            if (roughness) {
                m.roughnessChannel = 0;  // a grey map
            } else if (!albedo) {
                if (!std::isfinite(scale))
                    failLine(line, "material '", m.name, "': -bm ", scale, " must be finite");
                m.normalScale = scale;
            }
        } else {
            ignored.add(key);
        }
    }
    // map_Pr is R itself unless a Pr scales it (Ns' R is not a factor).
    for (size_t k = 0; k < out.size(); ++k)
        if (!out[k].roughnessMapPath.empty() && !physical[k]) out[k].roughness = 1.0;
    if (outside)
        note(meshName, concat("material library '", path, "': ", outside, " ",
                              plural(outside, "statement", "statements"),
                              " before the first newmtl ignored"));
    if (noIndex)
        note(meshName, concat("material library '", path, "': Ni 1 (material '", firstNoIndex, "'",
                              noIndex > 1 ? concat(" and ", noIndex - 1, " more") : "",
                              ") read as no index of refraction given: the default η"));
    if (!ignored.empty())
        note(meshName, concat("material library '", path, "': statements ignored: ", ignored.list(),
                              " (read: newmtl, Kd, map_Kd, Ni, Pr, Ns, map_Pr, norm, map_Bump)"));
    return out;
}

}  // namespace tsis
