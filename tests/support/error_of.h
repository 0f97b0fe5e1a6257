// The message of the tsis::Error a call throws, checked to be one line that
// names the file (for the mesh loaders' user errors).
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "util/error.h"

namespace tsis::test {

// The message of the Error `f` throws; "(no error)" when it returns. Fails
// the test when the message is not one line or does not name `file`.
template <typename F>
std::string errorOf(F&& f, const std::string& file = "") {
    try {
        f();
    } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        if (!file.empty()) {
            EXPECT_NE(what.find("'" + file + "'"), std::string::npos) << what;
        }
        return what;
    }
    return "(no error)";
}

}  // namespace tsis::test
