// Notes: what the user should know that is not an error ("mesh 'x.obj': not
// closed ..."). Each is written once, where it arises, as one line
// "tsis: note: TEXT" on stderr; a NoteCapture on the thread takes them
// instead (the library hands them to its caller: Python's warnings).
#pragma once

#include <string>
#include <vector>

namespace tsis {

void emitNote(const std::string& text);

// While one lives, this thread's notes are kept in it (the innermost one),
// not written; the notes of other threads are not.
class NoteCapture {
  public:
    NoteCapture();
    ~NoteCapture();
    NoteCapture(const NoteCapture&) = delete;
    NoteCapture& operator=(const NoteCapture&) = delete;
    // The notes' texts, without "tsis: note: ", in the order they came.
    const std::vector<std::string>& notes() const { return notes_; }

  private:
    friend void emitNote(const std::string& text);
    std::vector<std::string> notes_;
    NoteCapture* outer_;
};

}  // namespace tsis
