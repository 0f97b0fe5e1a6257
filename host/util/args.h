// A small command-line parser: `--name value`, `--name=value`, flags, and
// repeatable options, checked against a declared list so a typo is an error.
#pragma once

#include <glm/vec3.hpp>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "util/parse.h"  // the value parsers, for callers

namespace tsis {

struct OptionSpec {
    std::string name;  // without dashes: "samples"; a one-letter alias may follow: "output|o"
    bool takesValue = true;
    bool repeatable = false;
    std::string help;  // "N   importance samples (default 900)"
};

class Args {
  public:
    // Throws tsis::Error for an unknown option, a missing value, or a
    // non-repeatable option given twice. `command` names the subcommand in messages.
    Args(const std::string& command, const std::vector<OptionSpec>& specs,
         const std::vector<std::string>& argv);

    bool has(const std::string& name) const;
    bool flag(const std::string& name) const { return has(name); }
    std::optional<std::string> value(const std::string& name) const;
    std::vector<std::string> values(const std::string& name) const;
    const std::vector<std::string>& positional() const { return positional_; }

    // Typed getters: the default when absent; a clear error when malformed or
    // outside [lo, hi].
    int getInt(const std::string& name, int def, long long lo, long long hi) const;
    double getDouble(const std::string& name, double def, double lo, double hi) const;
    std::string getString(const std::string& name, const std::string& def) const;

  private:
    std::string command_;
    std::map<std::string, std::vector<std::string>> values_;
    std::vector<std::string> positional_;
};

// "--help" text for a command from its specs.
std::string usageText(const std::string& synopsis, const std::vector<OptionSpec>& specs);

}  // namespace tsis
