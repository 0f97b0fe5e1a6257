#include <gtest/gtest.h>

#include "util/embedded.h"

namespace tsis {
namespace {

TEST(EmbeddedSource, InlinesIncludesOnceWithLineMarkers) {
    const std::vector<EmbeddedFile> files = {
        {"a.cl",
         "#include \"b.h\"\n#define M(x) \\\n  (x)\nkernel void k() {} // [0,1)\n  #  include "
         "\"b.h\"\n"},
        {"b.h", "int b; // a;b\n"},
    };
    EXPECT_EQ(embeddedSource(files, "a.cl"),
              "#line 1 \"a.cl\"\n#line 1 \"b.h\"\nint b; // a;b\n#line 2 \"a.cl\"\n"
              "#define M(x) \\\n  (x)\nkernel void k() {} // [0,1)\n#line 6 \"a.cl\"\n");
}

TEST(EmbeddedSource, RealKernelsResolve) {
    std::string src = embeddedSource(embeddedKernels(), "gather.cl");
    EXPECT_NE(src.find("TsisTableInfo"), std::string::npos);  // from tsis_shared.h
    EXPECT_EQ(src.find("#include \"tsis_shared.h\""), std::string::npos);
}

}  // namespace
}  // namespace tsis
