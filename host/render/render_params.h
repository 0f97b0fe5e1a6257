// The options of RenderOptions a user sets, each declared once: its name, help,
// the methods that read it and what it changes (docs/design.md §4, "Parameters").
// The CLI's specs and parsing, the printed command line (--print-view,
// renderOptionArgs), validation and the frame keys are all made from this table,
// so a new parameter is one row here and a field in RenderOptions.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "render/render_options.h"

namespace tsis {

// What a parameter's value changes, which decides the key it belongs to.
enum class ParamEffect {
    Lighting,   // the light maps and flux atlas, and all after (lightingKey)
    Radiosity,  // the radiosity a frame computes (accumulationKey)
    Display,    // only the image made from the radiosity (tone map, highlight)
    None,       // not the pixels (what a frame may reuse)
};

struct RenderParam {
    std::string name;  // the option without dashes: "mis-distance"
    // "M  distance-driven samples..."; the help text prefixes the methods and
    // appends the default from RenderOptions{} (RenderParam::usage).
    std::string help;
    // The methods that read it; empty: every method (a frame-wide setting).
    std::vector<std::string> methods;
    ParamEffect effect = ParamEffect::Radiosity;
    bool flag = false;  // takes no value; given, it sets the non-default value
    bool showDefault = true;
    // The value as the user types it: the shortest text that parses back to
    // exactly the same value ("1" or "0" for a flag).
    std::function<std::string(const RenderOptions&)> text;
    // Parses `value` into its field; tsis::Error naming --name when it is
    // malformed or out of range.
    std::function<void(RenderOptions&, const std::string& value)> set;
    // A valid value other than the default, as typed (tests go through every row).
    std::string example;
    // What its value is (the typed API's: include/tsis/render_settings.h);
    // set by the row's maker (number, choice, flag, …).
    api::RenderParameter::Kind kind = api::RenderParameter::Kind::Choice;

    bool usedBy(const std::string& method) const;
    // The help line: "M  mis: distance-driven ... (default 16)".
    std::string usage() const;
    bool isDefault(const RenderOptions& o) const;
};

const std::vector<RenderParam>& renderParams();
// nullptr when no row has this name.
const RenderParam* findRenderParam(const std::string& name);

// "--mis-distance is a parameter of mis, not of pyramid" when `method` does
// not read p (empty when it does).
std::string foreignParamMessage(const RenderParam& p, const std::string& method);
// Throws tsis::Error (foreignParamMessage's) for the first parameter off its
// default that o.method does not read: it would change nothing (the typed
// API's check of what the command line refuses as it parses).
void checkParamsRead(const RenderOptions& o);

}  // namespace tsis
