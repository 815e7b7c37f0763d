#pragma once
// Text from input files (grid names, field names, file names) made safe to print:
// control characters, terminal escapes and bytes that are not UTF-8 are written
// as \n, \t, \xNN or \u{NN}, so a hostile name can neither break a one-line
// error nor drive the terminal.
#include <string>
#include <string_view>

namespace grotto {

std::string printable(std::string_view text);

}  // namespace grotto
