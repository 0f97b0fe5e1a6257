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
    deviceCurrent_ = false;
    return true;
}

const cl::Buffer& DipoleTable::device(const cl::Context& context) {
    if (!deviceCurrent_) {
        device_ = cl::Buffer(context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                             table_.rgba.size() * sizeof(float), table_.rgba.data());
        deviceCurrent_ = true;
    }
    return device_;
}

}  // namespace tsis
