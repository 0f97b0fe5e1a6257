// Rd of a material tabulated (physics/profile_table.h) up to the largest
// distance two surface points can have, kept until the material or that
// distance changes. Shared by the reference (on the device) and the
// hierarchical method (ProfileTable::lookup on the host).
#pragma once

#include <string>

#include "cl/cl_runtime.h"
#include "physics/material.h"
#include "physics/profile_table.h"

namespace tsis {

class DipoleTable {
  public:
    // Returns true when it tabulated again.
    bool update(const Material& material, double rMax);
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
