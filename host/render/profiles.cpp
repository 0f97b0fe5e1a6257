#include "render/profiles.h"

#include <sstream>

#include "physics/beam_diffusion.h"
#include "physics/better_dipole.h"
#include "physics/dipole.h"
#include "physics/split.h"
#include "util/error.h"
#include "volumetric/mc_profile.h"

namespace tsis {

std::string exactKey(const std::string& base, std::initializer_list<double> values) {
    std::ostringstream key;
    key.precision(17);
    key << base;
    for (double v : values) key << ' ' << v;
    return key.str();
}

KeyedProfile radialProfile(const Material& m, ProfileModel model) {
    TSIS_CHECK_MATERIAL(m);  // validated once a frame, in Renderer::render
    // The classical dipole's key is unchanged from before the models: "rd …".
    const std::string name = model == ProfileModel::Dipole ? "rd" : profileModelName(model);
    KeyedProfile p;
    p.key = exactKey(name, {m.sigmaSPrime.x, m.sigmaSPrime.y, m.sigmaSPrime.z, m.sigmaA.x,
                            m.sigmaA.y, m.sigmaA.z, m.eta});
    switch (model) {
        case ProfileModel::BetterDipole: {
            const BetterDipoleChannel ch[] = {{m.sigmaSPrime.x, m.sigmaA.x, m.eta},
                                              {m.sigmaSPrime.y, m.sigmaA.y, m.eta},
                                              {m.sigmaSPrime.z, m.sigmaA.z, m.eta}};
            p.f = [r = ch[0], g = ch[1], b = ch[2]](double d) {
                return glm::dvec3(r.Rd(d), g.Rd(d), b.Rd(d));
            };
            break;
        }
        case ProfileModel::Pbd:
            p.f = [pbd = BeamDiffusion(m)](double r) { return pbd.Rd(r); };
            break;
        case ProfileModel::Mc: {
            // One simulation per (α′, η), scaled to this σt′ (mc_profile.h).
            const McProfileInput in = mcProfileInput(m.sigmaSPrime, m.sigmaA, m.eta);
            p.key = exactKey(p.key, {static_cast<double>(in.paths)});
            p.f = [mc = &mcProfileCached(in), sigmaT = m.sigmaSPrime + m.sigmaA](double r) {
                return mc->rd(r, sigmaT);
            };
            break;
        }
        default:
            p.f = [dipole = Dipole(m)](double r) { return dipole.Rd(r); };
    }
    return p;
}

KeyedProfile scaledProfile(KeyedProfile p, const glm::dvec3& scale) {
    if (scale == glm::dvec3(1.0)) return p;
    p.key = exactKey(p.key + " scaled", {scale.x, scale.y, scale.z});
    p.f = [f = std::move(p.f), scale](double r) { return f(r) * scale; };
    return p;
}

KeyedProfile radialProfile(const Material& m, const RenderOptions& o, RdPart part) {
    KeyedProfile p = radialProfile(m, o.profile);
    if (part == RdPart::Full) return p;
    p.Rp = importanceRadius(Dipole(m), o.rpBound);
    const bool local = part == RdPart::Local;
    p.key = exactKey(p.key + (local ? " local" : " global"), {p.Rp.x, p.Rp.y, p.Rp.z, o.rpK});
    p.f = [rd = p.f, Rp = p.Rp, rpK = o.rpK, local](double r) {
        const glm::dvec3 wl = localWeight(r, Rp, rpK);
        return rd(r) * (local ? wl : 1.0 - wl);
    };
    return p;
}

}  // namespace tsis
