#include "mesh/file_view.h"

#include <gtest/gtest.h>

namespace tsis {
namespace {

// Only the materials a triangle uses are kept, in order, the ids renumbered;
// over a family of uses (none, all, every other, the last, out-of-range ids).
TEST(FileView, OnlyUsedMaterialsAreKept) {
    const uint32_t no = kNoFileMaterial;
    struct Case {
        std::vector<uint32_t> ids;
        std::vector<std::string> kept;
        std::vector<uint32_t> renumbered;
    };
    const std::vector<Case> cases = {
        {{no, no}, {}, {}},
        {{0, 1, 2, 3}, {"m0", "m1", "m2", "m3"}, {0, 1, 2, 3}},
        {{3, 1, 3, no}, {"m1", "m3"}, {1, 0, 1, no}},
        {{3}, {"m3"}, {0}},
        {{2, 7, no}, {"m2"}, {0, no, no}},
    };
    for (const Case& c : cases) {
        Mesh mesh;
        mesh.materialIds = c.ids;
        FileView view;
        for (int m = 0; m < 4; ++m) view.materials.push_back({"m" + std::to_string(m)});
        keepUsedMaterials(mesh, view);
        std::vector<std::string> names;
        for (const FileMaterial& m : view.materials) names.push_back(m.name);
        EXPECT_EQ(names, c.kept);
        EXPECT_EQ(mesh.materialIds, c.renumbered);
    }
}

}  // namespace
}  // namespace tsis
