#include "render/profiles.h"

#include <sstream>

#include "physics/dipole.h"
#include "physics/split.h"
#include "util/error.h"

namespace tsis {

RdPart parseRdPart(const std::string& name) {
    if (name == "full") return RdPart::Full;
    if (name == "local") return RdPart::Local;
    if (name == "global") return RdPart::Global;
    fail("--rd-part '", name, "': expected full, local or global");
}

KeyedProfile dipoleProfile(const Material& m, RdPart part, double rpBound, double rpK) {
    const Dipole dipole(m);
    std::ostringstream key;
    key.precision(17);
    key << "rd " << m.sigmaSPrime.x << ' ' << m.sigmaSPrime.y << ' ' << m.sigmaSPrime.z << ' '
        << m.sigmaA.x << ' ' << m.sigmaA.y << ' ' << m.sigmaA.z << ' ' << m.eta;
    KeyedProfile p;
    if (part == RdPart::Full) {
        p.f = [dipole](double r) { return dipole.Rd(r); };
        p.key = key.str();
        return p;
    }
    p.Rp = importanceRadius(dipole, rpBound);
    const bool local = part == RdPart::Local;
    key << (local ? " local " : " global ") << p.Rp.x << ' ' << p.Rp.y << ' ' << p.Rp.z << " k "
        << rpK;
    p.key = key.str();
    p.f = [dipole, Rp = p.Rp, rpK, local](double r) {
        const glm::dvec3 wl = localWeight(r, Rp, rpK);
        return dipole.Rd(r) * (local ? wl : 1.0 - wl);
    };
    return p;
}

}  // namespace tsis
