// Material tables for the GL passes' tests: one medium of index `eta`, no
// albedo texture, no normal or roughness map.
#pragma once

#include "gl/material_tables.h"

namespace tsis::test {

inline const MaterialTables& plainMaterials(MaterialTables& tables, float eta) {
    tables.updateMedia({{eta, 1.0f}});
    tables.updateAlbedo({}, 0, 0);
    tables.updateSurface({}, {}, 0, 0);
    return tables;
}

}  // namespace tsis::test
