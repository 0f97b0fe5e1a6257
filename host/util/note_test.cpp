#include "util/note.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <thread>

namespace tsis {
namespace {

TEST(Note, WrittenToStderrAsOneLine) {
    testing::internal::CaptureStderr();
    emitNote("mesh 'x': not closed");
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "tsis: note: mesh 'x': not closed\n");
}

TEST(Note, TheInnermostCaptureOfTheThreadTakesThem) {
    NoteCapture outer;
    emitNote("one");
    {
        NoteCapture inner;
        emitNote("two");
        EXPECT_THAT(inner.notes(), testing::ElementsAre("two"));
    }
    emitNote("three");
    EXPECT_THAT(outer.notes(), testing::ElementsAre("one", "three"));
    // Another thread's notes are its own: written, not captured here.
    testing::internal::CaptureStderr();
    std::thread([] { emitNote("elsewhere"); }).join();
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "tsis: note: elsewhere\n");
    EXPECT_EQ(outer.notes().size(), 2u);
}

}  // namespace
}  // namespace tsis
