#include "render/profile_table_cache.h"

namespace tsis {

bool ProfileTableCache::update(const KeyedProfile& profile, double rMax, const std::string& extra) {
    const std::string key = exactKey(profile.key + " " + extra, {rMax});
    if (key == key_) return false;
    table_ = ProfileTable::build(profile.f, rMax);
    key_ = key;
    deviceCurrent_ = false;
    return true;
}

bool ProfileTableCache::update(const Material& material, ProfileModel model, double rMax) {
    return update(radialProfile(material, model), rMax);
}

const cl::Buffer& ProfileTableCache::device(const cl::Context& context) {
    if (!deviceCurrent_) {
        device_ = cl::Buffer(context, CL_MEM_READ_ONLY | CL_MEM_COPY_HOST_PTR,
                             table_.rgba.size() * sizeof(float), table_.rgba.data());
        deviceCurrent_ = true;
    }
    return device_;
}

}  // namespace tsis
