#include "util/args.h"

#include <gtest/gtest.h>

#include "util/error.h"

namespace tsis {
namespace {

const std::vector<OptionSpec> kSpecs = {
    {"samples", true, false, "N  samples"},
    {"light", true, true, "SPEC  a light"},
    {"output|o", true, false, "FILE  output"},
    {"no-specular", false, false, "no highlights"},
};

TEST(Args, ValuesFlagsAliasesAndRepeats) {
    Args a("render", kSpecs,
           {"--samples", "64", "--light=point:0,1,2:1,1,1", "--light", "dir:0,-1,0:1,1,1", "-o",
            "x.png", "--no-specular", "extra"});
    EXPECT_EQ(a.getInt("samples", 900, 1, 1000), 64);
    EXPECT_EQ(a.values("light").size(), 2u);
    EXPECT_EQ(a.getString("output", ""), "x.png");
    EXPECT_TRUE(a.flag("no-specular"));
    ASSERT_EQ(a.positional().size(), 1u);
    EXPECT_EQ(a.positional()[0], "extra");
    EXPECT_EQ(Args("render", kSpecs, {}).getInt("samples", 900, 1, 1000), 900);
}

TEST(Args, ErrorsAreClear) {
    auto message = [](const std::vector<std::string>& argv) {
        try {
            Args a("render", kSpecs, argv);
            a.getInt("samples", 900, 1, 1000);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_NE(message({"--sampels", "3"}).find("unknown option '--sampels'"), std::string::npos);
    EXPECT_NE(message({"--samples"}).find("needs a value"), std::string::npos);
    EXPECT_NE(message({"--samples", "1", "--samples", "2"}).find("more than once"),
              std::string::npos);
    EXPECT_NE(message({"--samples", "abc"}).find("not an integer"), std::string::npos);
    EXPECT_NE(message({"--samples", "5000"}).find("out of range"), std::string::npos);
    EXPECT_NE(message({"--no-specular=1"}).find("takes no value"), std::string::npos);
}

TEST(Args, NumberParsers) {
    EXPECT_EQ(parseVec3("--eye", "1,-2,3.5"), glm::dvec3(1, -2, 3.5));
    EXPECT_THROW(parseVec3("--eye", "1,2"), Error);
    EXPECT_THROW(parseVec3("--eye", "1,nan,2"), Error);
    EXPECT_THROW(parseNumber("--size-mm", "inf"), Error);
    EXPECT_THROW(parseList("--r", "0,1,"), Error);
    EXPECT_EQ(parseList("--r", "0,0.1,1").size(), 3u);
    EXPECT_EQ(Args("x", kSpecs, {"-5"}).positional()[0], "-5");
}

TEST(Args, UsageListsEveryOption) {
    std::string u = usageText("tsis render [options]", kSpecs);
    for (const char* s : {"--samples N", "-o, --output FILE", "--light SPEC", "--no-specular"})
        EXPECT_NE(u.find(s), std::string::npos) << s;
}

}  // namespace
}  // namespace tsis
