#include "tsis/render_settings.h"

#include "render/render_params.h"
#include "util/error.h"

namespace tsis::api {

namespace {

const RenderParam& paramNamed(const std::string& name) {
    const RenderParam* p = findRenderParam(name);
    if (!p) fail("RenderSettings: no render option --", name, " (see tsis render --help)");
    return *p;
}

}  // namespace

void RenderSettings::set(const std::string& name, const std::string& value) {
    if (name == "method") {
        RenderSettings next = *this;
        next.method = value;
        validateRenderOptions(next);  // the name among the methods
        method = value;
        return;
    }
    const RenderParam& p = paramNamed(name);
    if (p.flag && value != "true" && value != "false")
        fail("option --", name, " is a flag: true or false, not '", value, "'");
    p.set(*this, p.flag ? (value == "true" ? "1" : "0") : value);
}

std::string RenderSettings::get(const std::string& name) const {
    if (name == "method") return method;
    const RenderParam& p = paramNamed(name);
    const std::string text = p.text(*this);
    return p.flag ? (text == "1" ? "true" : "false") : text;
}

const std::vector<RenderParameter>& RenderSettings::parameters() {
    static const std::vector<RenderParameter> rows = [] {
        std::vector<RenderParameter> out;
        for (const RenderParam& p : renderParams()) {
            std::string help = p.usage();  // "N  pyramid: … (default 0)"
            if (const size_t gap = help.find("  "); !p.flag && gap != std::string::npos)
                help.erase(0, gap + 2);  // the metavar
            out.push_back({p.name, help, p.methods, p.kind});
        }
        return out;
    }();
    return rows;
}

}  // namespace tsis::api
