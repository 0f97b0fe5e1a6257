#include "render/dipole_table.h"

#include <sstream>

#include "physics/dipole.h"

namespace tsis {

bool DipoleTable::update(const Material& m, double rMax) {
    std::ostringstream key;
    key.precision(17);
    key << m.sigmaSPrime.x << ' ' << m.sigmaSPrime.y << ' ' << m.sigmaSPrime.z << ' ' << m.sigmaA.x
        << ' ' << m.sigmaA.y << ' ' << m.sigmaA.z << ' ' << m.eta << ' ' << rMax;
    if (key.str() == key_) return false;
    const Dipole dipole(m);
    table_ = ProfileTable::build([&](double r) { return dipole.Rd(r); }, rMax);
    key_ = key.str();
    return true;
}

}  // namespace tsis
