#include "render/render_options.h"

#include <algorithm>

#include "physics/fresnel.h"
#include "render/method.h"
#include "util/error.h"

namespace tsis {

RdPart parseRdPart(const std::string& name) {
    if (name == "full") return RdPart::Full;
    if (name == "local") return RdPart::Local;
    if (name == "global") return RdPart::Global;
    fail("--rd-part '", name, "': expected full, local or global");
}

const char* rdPartName(RdPart part) {
    switch (part) {
        case RdPart::Local:
            return "local";
        case RdPart::Global:
            return "global";
        default:
            return "full";
    }
}

ProfileModel parseProfileModel(const std::string& name) {
    if (name == "dipole") return ProfileModel::Dipole;
    if (name == "better-dipole") return ProfileModel::BetterDipole;
    if (name == "pbd") return ProfileModel::Pbd;
    fail("--profile '", name, "': expected dipole, better-dipole or pbd");
}

const char* profileModelName(ProfileModel model) {
    switch (model) {
        case ProfileModel::BetterDipole:
            return "better-dipole";
        case ProfileModel::Pbd:
            return "pbd";
        default:
            return "dipole";
    }
}

ExitTerm parseExitTerm(const std::string& name) {
    if (name == "jensen") return ExitTerm::Jensen;
    if (name == "normalized") return ExitTerm::Normalized;
    fail("--exit '", name, "': expected jensen or normalized");
}

const char* exitTermName(ExitTerm exit) {
    return exit == ExitTerm::Normalized ? "normalized" : "jensen";
}

double exitScale(ExitTerm exit, double eta) {
    return exit == ExitTerm::Normalized ? normalizedExitScale(eta) : 1.0;
}

void validateRenderOptions(const RenderOptions& o) {
    const std::vector<std::string> names = methodNames();
    if (std::find(names.begin(), names.end(), o.method) == names.end()) {
        std::string list;
        for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
        fail("unknown method '", o.method, "'; available: ", list);
    }
    if (o.width < 1 || o.height < 1 || o.width > 8192 || o.height > 8192)
        fail("image size ", o.width, "x", o.height, " is outside 1 to 8192");
    if (o.samples < 1) fail("--samples ", o.samples, " must be at least 1");
    if (o.spp < 0 || o.spp > (1 << 20)) fail("--spp ", o.spp, " is outside 1 to 1048576");
    if (!(o.timeSeconds >= 0)) fail("--time ", o.timeSeconds, " must be a number of seconds ≥ 0");
    const int res = o.atlasResolution;
    if (res < 16 || res > 4096 || (res & (res - 1)))
        fail("--atlas-res ", res, " must be a power of two from 16 to 4096");
    if (o.lightResolution != 0 && (o.lightResolution < 16 || o.lightResolution > 8192))
        fail("--light-res ", o.lightResolution, " is outside 16 to 8192 (0: automatic)");
    if (!(o.pyramidEpsilon >= 0.0f && o.pyramidEpsilon <= 1.0f))
        fail("--pyramid-epsilon ", o.pyramidEpsilon, " is outside 0 to 1");
    if (o.pyramidStride < 0 || o.pyramidStride > 16)
        fail("--pyramid-stride ", o.pyramidStride, " is outside 0 to 16 (0: automatic)");
    // The checks the methods make when they run (method_hybrid, method_mis, method_ltsm).
    const RdPart part = o.rdPart;
    if (part != RdPart::Full && o.method == "hybrid")
        fail("--rd-part applies to tsis and ltsm; the hybrid always splits the full Rd");
    if (part != RdPart::Full && o.method == "mis")
        fail("--rd-part applies to tsis and ltsm; mis integrates the full Rd");
    if (o.ltsmRings < 0 || o.ltsmPerRing < 1)
        fail("--ltsm-rings ", o.ltsmRings, " / --ltsm-per-ring ", o.ltsmPerRing,
             ": need L ≥ 0 rings of C ≥ 1 samples");
}

}  // namespace tsis
