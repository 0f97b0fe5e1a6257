#include "util/embedded.h"

#include "util/error.h"

namespace tsis {

std::string_view embeddedText(const std::vector<EmbeddedFile>& files, std::string_view name) {
    for (const EmbeddedFile& f : files)
        if (name == f.name) return f.text;
    checkFailed(__FILE__, __LINE__, concat("no embedded file named '", name, "'"));
}

namespace {

// The name in `#include "name"` when `line` is such a directive, else empty.
std::string_view includedName(std::string_view line) {
    size_t i = line.find_first_not_of(" \t");
    if (i == std::string_view::npos || line[i] != '#') return {};
    i = line.find_first_not_of(" \t", i + 1);
    if (i == std::string_view::npos || line.substr(i, 7) != "include") return {};
    size_t open = line.find('"', i + 7);
    size_t close = open == std::string_view::npos ? open : line.find('"', open + 1);
    if (close == std::string_view::npos) return {};
    return line.substr(open + 1, close - open - 1);
}

void appendResolved(const std::vector<EmbeddedFile>& files, std::string_view name,
                    std::vector<std::string>& seen, std::string& out) {
    for (const std::string& s : seen)
        if (s == name) return;
    seen.emplace_back(name);
    std::string_view text = embeddedText(files, name);
    out += concat("#line 1 \"", name, "\"\n");
    size_t lineNo = 1;
    for (size_t pos = 0; pos < text.size(); ++lineNo) {
        size_t end = text.find('\n', pos);
        if (end == std::string_view::npos) end = text.size();
        std::string_view line = text.substr(pos, end - pos);
        if (std::string_view inc = includedName(line); !inc.empty()) {
            appendResolved(files, inc, seen, out);
            out += concat("#line ", lineNo + 1, " \"", name, "\"\n");
        } else {
            out += line;
            out += '\n';
        }
        pos = end + 1;
    }
}

}  // namespace

std::string embeddedSource(const std::vector<EmbeddedFile>& files, std::string_view name) {
    std::vector<std::string> seen;
    std::string out;
    appendResolved(files, name, seen, out);
    return out;
}

}  // namespace tsis
