#include "view/script.h"

#include <gtest/gtest.h>

#include "util/error.h"

namespace tsis {
namespace {

using Kind = ScriptCommand::Kind;

TEST(Script, ParsesEveryCommand) {
    const std::string text =
        "# a scripted session\n"
        "\n"
        "frame 3\n"
        "orbit 40 -10.5   # trailing comment\n"
        "pan 1 2\n"
        "zoom -2\n"
        "light-drag 60 0\n"
        "set material marble\n"
        "set sigma-a 0.1,0.2,0.3\n"
        "panel off\n"
        "heatmap on\n"
        "open-mesh my mesh.off\n"
        "reference\n"
        "screenshot out/a b.png\n"
        "save r.png\n"
        "aov dir\n"
        "close\n"
        "wait 250\n";
    const std::vector<ScriptCommand> s = parseScript(text, "s.txt");
    ASSERT_EQ(s.size(), 16u);
    EXPECT_EQ(s[0].kind, Kind::Frame);
    EXPECT_EQ(s[0].x, 3);
    EXPECT_EQ(s[0].line, 3);
    EXPECT_EQ(s[1].kind, Kind::Orbit);
    EXPECT_EQ(s[1].x, 40);
    EXPECT_EQ(s[1].y, -10.5f);
    EXPECT_EQ(s[2].kind, Kind::Pan);
    EXPECT_EQ(s[3].kind, Kind::Zoom);
    EXPECT_EQ(s[3].x, -2);
    EXPECT_EQ(s[4].kind, Kind::LightDrag);
    EXPECT_EQ(s[5].kind, Kind::Set);
    EXPECT_EQ(s[5].name, "material");
    EXPECT_EQ(s[5].value, "marble");
    EXPECT_EQ(s[6].value, "0.1,0.2,0.3");
    EXPECT_EQ(s[7].kind, Kind::Panel);
    EXPECT_FALSE(s[7].on);
    EXPECT_TRUE(s[8].on);
    EXPECT_EQ(s[9].kind, Kind::OpenMesh);
    EXPECT_EQ(s[9].value, "my mesh.off");
    EXPECT_EQ(s[10].kind, Kind::Reference);
    EXPECT_EQ(s[11].kind, Kind::Screenshot);
    EXPECT_EQ(s[11].value, "out/a b.png");
    EXPECT_EQ(s[12].kind, Kind::Save);
    EXPECT_EQ(s[13].kind, Kind::Aov);
    EXPECT_EQ(s[14].kind, Kind::Close);
    EXPECT_EQ(s[14].line, 17);
    EXPECT_EQ(s[15].kind, Kind::Wait);
    EXPECT_EQ(s[15].x, 250);
}

TEST(Script, BadLinesAreRefusedWithFileAndLine) {
    const std::pair<const char*, const char*> bad[] = {
        {"jump 3", "unknown command 'jump'"},
        {"frame 0", "outside"},
        {"frame", "expected 1 operand"},
        {"wait 0", "outside"},
        {"wait -5", "outside"},
        {"orbit 1", "expected 2 operands"},
        {"orbit 1 2 3", "expected 2 operands"},
        {"orbit 1 nan", "not a finite number"},
        {"zoom x", "not a finite number"},
        {"panel maybe", "not on or off"},
        {"set material unobtainium", "unobtainium"},
        {"set size-mm 5e5", "size-mm"},
        {"set colour red", "unknown parameter 'colour'"},
        {"screenshot", "expected 1 operand"},
        {"close now", "expected 0 operands"},
    };
    for (const auto& [line, phrase] : bad) {
        try {
            parseScript(std::string("frame 1\n") + line + "\n", "s.txt");
            ADD_FAILURE() << line << " was accepted";
        } catch (const Error& e) {
            const std::string what = e.what();
            EXPECT_EQ(what.rfind("s.txt:2: ", 0), 0u) << what;
            EXPECT_NE(what.find(phrase), std::string::npos) << what;
        }
    }
    EXPECT_THROW(readScript("/nonexistent/script.txt"), Error);
}

}  // namespace
}  // namespace tsis
