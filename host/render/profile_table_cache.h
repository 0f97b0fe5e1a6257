// A radial profile tabulated (physics/profile_table.h) up to the largest
// distance two surface points can have, kept until the profile's key or that
// distance changes, with its copy on the device. Every method that integrates
// a profile holds one.
#pragma once

#include <string>

#include "cl/cl_runtime.h"
#include "physics/material.h"
#include "physics/profile_table.h"
#include "render/profiles.h"

namespace tsis {

class ProfileTableCache {
  public:
    // Tabulates `profile` on [0, rMax] unless that table is current; `extra`
    // names anything else the caller's table depends on. Returns true when it
    // tabulated again.
    bool update(const KeyedProfile& profile, double rMax, const std::string& extra = "");
    // The full Rd of `material` under `model`.
    bool update(const Material& material, ProfileModel model, double rMax);
    const ProfileTable& table() const { return table_; }
    // The table's float4 entries on the device, uploaded again after update()
    // tabulated again.
    const cl::Buffer& device(const cl::Context& context);

  private:
    std::string key_;
    ProfileTable table_;
    cl::Buffer device_;
    bool deviceCurrent_ = false;
};

}  // namespace tsis
