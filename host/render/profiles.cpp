#include "render/profiles.h"

#include <sstream>

#include "physics/dipole.h"
#include "physics/split.h"
#include "util/error.h"

namespace tsis {

std::string exactKey(const std::string& base, std::initializer_list<double> values) {
    std::ostringstream key;
    key.precision(17);
    key << base;
    for (double v : values) key << ' ' << v;
    return key.str();
}

KeyedProfile dipoleProfile(const Material& m, RdPart part, double rpBound, double rpK) {
    const Dipole dipole(m);
    const std::string rd = exactKey("rd", {m.sigmaSPrime.x, m.sigmaSPrime.y, m.sigmaSPrime.z,
                                           m.sigmaA.x, m.sigmaA.y, m.sigmaA.z, m.eta});
    KeyedProfile p;
    if (part == RdPart::Full) {
        p.f = [dipole](double r) { return dipole.Rd(r); };
        p.key = rd;
        return p;
    }
    p.Rp = importanceRadius(dipole, rpBound);
    const bool local = part == RdPart::Local;
    p.key = exactKey(rd + (local ? " local" : " global"), {p.Rp.x, p.Rp.y, p.Rp.z, rpK});
    p.f = [dipole, Rp = p.Rp, rpK, local](double r) {
        const glm::dvec3 wl = localWeight(r, Rp, rpK);
        return dipole.Rd(r) * (local ? wl : 1.0 - wl);
    };
    return p;
}

}  // namespace tsis
