#include "render/render_options.h"

#include <algorithm>

#include "physics/fresnel.h"
#include "render/method.h"
#include "render/render_params.h"
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

EnergyTarget parseEnergyTarget(const std::string& name) {
    if (name == "semi-infinite") return EnergyTarget::SemiInfinite;
    if (name == "object") return EnergyTarget::Object;
    fail("--energy '", name, "': expected semi-infinite or object");
}

const char* energyTargetName(EnergyTarget energy) {
    return energy == EnergyTarget::Object ? "object" : "semi-infinite";
}

VolumetricEstimator parseVolumetricEstimator(const std::string& name) {
    if (name == "camera") return VolumetricEstimator::Camera;
    if (name == "light") return VolumetricEstimator::Light;
    fail("--estimator '", name, "': expected camera or light");
}

const char* volumetricEstimatorName(VolumetricEstimator estimator) {
    return estimator == VolumetricEstimator::Light ? "light" : "camera";
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
    // Each value through its parameter's parser: the ranges typed once, in
    // render_params.cpp. A default may lie outside them (0: automatic).
    for (const RenderParam& p : renderParams()) {
        if (p.flag || p.isDefault(o)) continue;
        RenderOptions copy = o;
        p.set(copy, p.text(o));
    }
}

}  // namespace tsis
