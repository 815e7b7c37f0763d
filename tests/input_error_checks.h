#pragma once
// The check every strict-file test makes: loading bad input throws grotto::Error
// (input, exit code 2) in one line that names the file, the field and the problem.
#include "grotto/error.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace grotto::test {

// Calls `load`, which must throw an input error mentioning each of `mentions`;
// returns its message ("" when nothing was thrown, a test failure).
template <class Load>
std::string inputErrorOf(Load&& load, const std::vector<std::string>& mentions) {
    try {
        load();
    } catch (const Error& e) {
        EXPECT_EQ(e.exitCode(), 2);
        const std::string what = e.what();
        EXPECT_EQ(what.find('\n'), std::string::npos) << what;
        for (const std::string& m : mentions) EXPECT_NE(what.find(m), std::string::npos) << "'" << m << "' in: " << what;
        return what;
    }
    ADD_FAILURE() << "no error; expected one mentioning " << (mentions.empty() ? "" : mentions.front());
    return {};
}

}  // namespace grotto::test
