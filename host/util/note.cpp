#include "util/note.h"

#include <cstdio>

namespace tsis {

namespace {

thread_local NoteCapture* innermost = nullptr;

}  // namespace

NoteCapture::NoteCapture() : outer_(innermost) {
    innermost = this;
}

NoteCapture::~NoteCapture() {
    innermost = outer_;
}

void emitNote(const std::string& text) {
    if (innermost) {
        innermost->notes_.push_back(text);
        return;
    }
    std::fprintf(stderr, "tsis: note: %s\n", text.c_str());
}

}  // namespace tsis
