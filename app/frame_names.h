#pragma once
// The file names of a flythrough's frames: a printf-style pattern with exactly
// one integer conversion (frame.%04d by default), the number of the path's first
// frame in the names (1 by default), and the format's extension. Frame i of the
// path (1-based) is named with the number start + i - 1.
#include <cstddef>
#include <string>

namespace grotto::app {

inline constexpr const char* kDefaultFramePattern = "frame.%04d";

class FrameNames {
public:
    // Throws grotto::Error (input) naming --name for a pattern with anything but
    // one conversion %d, %Nd or %0Nd (and %% for a percent sign), a '/', a name
    // that would start with '.' (hidden names are the temporary files') or be
    // longer than kMaxNameBytes.
    static constexpr size_t kMaxNameBytes = 200;
    FrameNames(const std::string& pattern, int startNumber, const std::string& extension);

    std::string name(int frame) const;
    // Whether a file name is one this pattern makes, whatever its number.
    bool matches(const std::string& fileName) const;
    bool isDefault() const { return pattern_ == kDefaultFramePattern && start_ == 1; }
    const std::string& pattern() const { return pattern_; }
    int start() const { return start_; }

private:
    std::string pattern_, prefix_, suffix_, extension_;  // prefix and suffix with %% as %
    int start_ = 1, width_ = 0;
    bool zeros_ = false;
};

}  // namespace grotto::app
