#pragma once
// Text from input files (grid names, field names, file names) made safe to print:
// control characters, terminal escapes and bytes that are not UTF-8 are written
// as \n, \t, \xNN or \u{NN}, so a hostile name can neither break a one-line
// error nor drive the terminal.
#include <string>
#include <string_view>

namespace grotto {

std::string printable(std::string_view text);

// printable() of at most the first `limit` bytes (cut between characters), with
// "... (N bytes)" after when there were more: text quoted from a file can be
// megabytes long, and an error stays one short line.
std::string printableExcerpt(std::string_view text, size_t limit = 160);

}  // namespace grotto
