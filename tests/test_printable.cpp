// Text from files is printed escaped: no control character or terminal escape
// reaches the terminal, and readable text (UTF-8 included) stays as it is.
#include "common/printable.h"

#include <gtest/gtest.h>

namespace grotto {
namespace {

TEST(Printable, KeepsReadableTextAndUtf8) {
    EXPECT_EQ(printable("caves walk-1 (v2)"), "caves walk-1 (v2)");
    EXPECT_EQ(printable("h\xC3\xB6hle \xE6\xB4\x9E \xF0\x9F\xA6\x87"), "h\xC3\xB6hle \xE6\xB4\x9E \xF0\x9F\xA6\x87");
}

TEST(Printable, EscapesControlsAndTerminalSequences) {
    EXPECT_EQ(printable("a\nb\tc\rd"), "a\\nb\\tc\\rd");
    EXPECT_EQ(printable("\x1b[2J\x07"), "\\x1B[2J\\x07");
    EXPECT_EQ(printable(std::string("nul\0x", 5)), "nul\\x00x");
    EXPECT_EQ(printable("del\x7f"), "del\\x7F");
    EXPECT_EQ(printable("csi\xC2\x9B" "31m"), "csi\\u{9B}31m");  // C1 control in UTF-8
}

TEST(Printable, EscapesBytesThatAreNotUtf8) {
    EXPECT_EQ(printable("\xff\xfe"), "\\xFF\\xFE");
    EXPECT_EQ(printable("\xC3"), "\\xC3");              // truncated sequence
    EXPECT_EQ(printable("\xC0\xAF"), "\\xC0\\xAF");      // overlong '/'
    EXPECT_EQ(printable("\xED\xA0\x80"), "\\xED\\xA0\\x80");  // a surrogate
}

TEST(Printable, AnExcerptIsBoundedAndCutBetweenCharacters) {
    EXPECT_EQ(printableExcerpt("short", 8), "short");
    EXPECT_EQ(printableExcerpt(std::string(1000000, 'A'), 4), "AAAA... (1000000 bytes)");
    EXPECT_EQ(printableExcerpt("ab\xC3\xB6" "cd", 3), "ab... (6 bytes)");  // not half of the o-umlaut
    EXPECT_EQ(printableExcerpt("\x1b\x1b\x1b", 2), "\\x1B\\x1B... (3 bytes)");
}

}  // namespace
}  // namespace grotto
