#include "util/args.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "util/error.h"

namespace tsis {

namespace {

const OptionSpec* findSpec(const std::vector<OptionSpec>& specs, const std::string& name,
                           std::string& canonical) {
    for (const OptionSpec& s : specs) {
        std::string full = s.name, alias;
        if (auto bar = full.find('|'); bar != std::string::npos) {
            alias = full.substr(bar + 1);
            full = full.substr(0, bar);
        }
        if (name == full || (!alias.empty() && name == alias)) {
            canonical = full;
            return &s;
        }
    }
    return nullptr;
}

}  // namespace

Args::Args(const std::string& command, const std::vector<OptionSpec>& specs,
           const std::vector<std::string>& argv)
    : command_(command) {
    for (size_t i = 0; i < argv.size(); ++i) {
        const std::string& a = argv[i];
        if (a.size() < 2 || a[0] != '-' || (a.size() > 1 && std::isdigit(a[1]))) {
            positional_.push_back(a);
            continue;
        }
        std::string body = a.substr(a[1] == '-' ? 2 : 1), inlineValue;
        bool hasInline = false;
        if (auto eq = body.find('='); eq != std::string::npos) {
            inlineValue = body.substr(eq + 1);
            body = body.substr(0, eq);
            hasInline = true;
        }
        std::string name;
        const OptionSpec* spec = findSpec(specs, body, name);
        if (!spec)
            fail("unknown option '", a, "' for 'tsis ", command, "' (see tsis ", command,
                 " --help)");
        std::string v;
        if (spec->takesValue) {
            if (hasInline) {
                v = inlineValue;
            } else {
                if (i + 1 >= argv.size()) fail("option --", name, " needs a value");
                v = argv[++i];
            }
        } else if (hasInline) {
            fail("option --", name, " takes no value");
        }
        auto& slot = values_[name];
        if (!slot.empty() && !spec->repeatable) fail("option --", name, " given more than once");
        slot.push_back(v);
    }
}

bool Args::has(const std::string& name) const {
    return values_.count(name) > 0;
}

std::optional<std::string> Args::value(const std::string& name) const {
    auto it = values_.find(name);
    if (it == values_.end()) return std::nullopt;
    return it->second.back();
}

std::vector<std::string> Args::values(const std::string& name) const {
    auto it = values_.find(name);
    return it == values_.end() ? std::vector<std::string>{} : it->second;
}

int Args::getInt(const std::string& name, int def, long long lo, long long hi) const {
    auto v = value(name);
    if (!v) return def;
    long long x = parseInteger("--" + name, *v);
    if (x < lo || x > hi) fail("--", name, " ", *v, " is out of range [", lo, ", ", hi, "]");
    return static_cast<int>(x);
}

double Args::getDouble(const std::string& name, double def, double lo, double hi) const {
    auto v = value(name);
    if (!v) return def;
    double x = parseNumber("--" + name, *v);
    if (x < lo || x > hi) fail("--", name, " ", *v, " is out of range [", lo, ", ", hi, "]");
    return x;
}

std::string Args::getString(const std::string& name, const std::string& def) const {
    auto v = value(name);
    return v ? *v : def;
}

std::string usageText(const std::string& synopsis, const std::vector<OptionSpec>& specs) {
    std::ostringstream s;
    s << "usage: " << synopsis << "\n";
    if (!specs.empty()) s << "\noptions:\n";
    for (const OptionSpec& o : specs) {
        std::string name = o.name, alias;
        if (auto bar = name.find('|'); bar != std::string::npos) {
            alias = name.substr(bar + 1);
            name = name.substr(0, bar);
        }
        std::string left = "  ";
        if (!alias.empty()) {
            left += '-';
            left += alias;
            left += ", ";
        }
        left += "--";
        left += name;
        std::string help = o.help;
        // The help's first word is the value's placeholder, when the option takes one.
        if (o.takesValue) {
            auto sp = help.find(' ');
            left += ' ';
            left += help.substr(0, sp);
            help = sp == std::string::npos ? "" : help.substr(sp + 1);
            while (!help.empty() && help[0] == ' ') help.erase(0, 1);
        }
        s << left;
        s << std::string(left.size() < 30 ? 30 - left.size() : 1, ' ') << help << "\n";
    }
    return s.str();
}

}  // namespace tsis
