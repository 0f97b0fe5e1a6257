#include "view/script.h"

#include <fstream>
#include <sstream>

#include "util/error.h"
#include "util/input_file.h"
#include "util/parse.h"
#include "view/view_state.h"

namespace tsis {

namespace {

using Kind = ScriptCommand::Kind;

struct Syntax {
    const char* word;
    Kind kind;
    const char* operands;  // "" none, "n" a count, "xy" two numbers, "z" one number,
                           // "nv" a name and a value, "b" on|off, "p" a path
};

const Syntax kSyntax[] = {
    {"frame", Kind::Frame, "n"},
    {"wait", Kind::Wait, "n"},
    {"orbit", Kind::Orbit, "xy"},
    {"pan", Kind::Pan, "xy"},
    {"zoom", Kind::Zoom, "z"},
    {"light-drag", Kind::LightDrag, "xy"},
    {"set", Kind::Set, "nv"},
    {"panel", Kind::Panel, "b"},
    {"heatmap", Kind::Heatmap, "b"},
    {"open-mesh", Kind::OpenMesh, "p"},
    {"reference", Kind::Reference, ""},
    {"truth", Kind::Truth, ""},
    {"screenshot", Kind::Screenshot, "p"},
    {"save", Kind::Save, "p"},
    {"aov", Kind::Aov, "p"},
    {"close", Kind::Close, ""},
};

ScriptCommand parseLine(const std::string& line) {
    std::istringstream in(line);
    std::string word;
    in >> word;
    const Syntax* syntax = nullptr;
    for (const Syntax& s : kSyntax)
        if (word == s.word) syntax = &s;
    if (!syntax) {
        std::string list;
        for (const Syntax& s : kSyntax) list += (list.empty() ? "" : ", ") + std::string(s.word);
        fail("unknown command '", word, "' (", list, ")");
    }
    ScriptCommand c;
    c.kind = syntax->kind;
    std::vector<std::string> operands;
    for (std::string w; in >> w;) operands.push_back(w);
    const std::string form = syntax->operands;
    // A path or a setting's value is the rest of the line (it may hold spaces).
    auto rest = [&](size_t from) {
        std::string r;
        for (size_t i = from; i < operands.size(); ++i) r += (i > from ? " " : "") + operands[i];
        return r;
    };
    const size_t want = form == "nv" ? 2 : form == "xy" ? 2 : form.empty() ? 0 : 1;
    const bool restOk = form == "p" || form == "nv";
    if (operands.size() < want || (!restOk && operands.size() > want))
        fail(word, ": expected ", want, " operand", want == 1 ? "" : "s", ", got ",
             operands.size());
    if (form == "n") {
        const long long n = parseInteger(word, operands[0]);
        if (n < 1 || n > 100000) fail(word, ": ", n, " is outside [1, 100000]");
        c.x = static_cast<float>(n);
    } else if (form == "xy") {
        c.x = static_cast<float>(parseNumber(word, operands[0]));
        c.y = static_cast<float>(parseNumber(word, operands[1]));
    } else if (form == "z") {
        c.x = static_cast<float>(parseNumber(word, operands[0]));
    } else if (form == "b") {
        if (operands[0] != "on" && operands[0] != "off")
            fail(word, ": '", operands[0], "' is not on or off");
        c.on = operands[0] == "on";
    } else if (form == "nv") {
        c.name = operands[0];
        c.value = rest(1);
        ViewState scratch;  // the name and the value are checked now, not mid-run
        setParameter(scratch, c.name, c.value);
    } else if (form == "p") {
        c.value = rest(0);
    }
    return c;
}

}  // namespace

std::vector<ScriptCommand> parseScript(const std::string& text, const std::string& fileName) {
    std::vector<ScriptCommand> out;
    std::istringstream in(text);
    int number = 0;
    for (std::string line; std::getline(in, line);) {
        ++number;
        if (const size_t hash = line.find('#'); hash != std::string::npos) line.erase(hash);
        if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
        try {
            out.push_back(parseLine(line));
        } catch (const Error& e) {
            fail(fileName, ":", number, ": ", e.what());
        }
        out.back().line = number;
    }
    return out;
}

std::vector<ScriptCommand> readScript(const std::string& path) {
    return parseScript(readRegularFile(path, "script", kMaxLibraryFileBytes), path);
}

}  // namespace tsis
