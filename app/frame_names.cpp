#include "app/frame_names.h"

#include "grotto/error.h"

#include <algorithm>
#include <cctype>

namespace grotto::app {

FrameNames::FrameNames(const std::string& pattern, int startNumber, const std::string& extension)
    : pattern_(pattern), extension_(extension), start_(startNumber) {
    const std::string accepted = "expected one integer conversion such as %04d or %d, e.g. --name 'shot_%04d'";
    auto refuse = [&](const std::string& why) { throw Error("--name", "'" + pattern + "' " + why, accepted); };
    int conversions = 0;
    for (size_t k = 0; k < pattern.size(); ++k) {
        std::string& text = conversions ? suffix_ : prefix_;
        if (pattern[k] != '%') {
            if (pattern[k] == '/') refuse("names a subdirectory: frames go straight into the output directory");
            if (std::iscntrl(static_cast<unsigned char>(pattern[k]))) refuse("has a control character");
            text += pattern[k];
            continue;
        }
        if (k + 1 < pattern.size() && pattern[k + 1] == '%') {
            text += '%';
            ++k;
            continue;
        }
        // %[0][width]d
        size_t j = k + 1;
        const bool zeros = j < pattern.size() && pattern[j] == '0';
        if (zeros) ++j;
        int width = 0;
        while (j < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[j])) && width <= 32)
            width = width * 10 + (pattern[j++] - '0');
        if (j >= pattern.size() || pattern[j] != 'd' || width > 32)
            refuse("has a conversion other than %d, %Nd or %0Nd (N up to 32)");
        if (++conversions > 1) refuse("has more than one conversion");
        zeros_ = zeros;
        width_ = width;
        k = j;
    }
    if (conversions == 0) refuse("has no integer conversion, so every frame would get the same name");
    if (!prefix_.empty() && prefix_[0] == '.') refuse("makes hidden names (starting with '.')");
    // The temporary name a frame is written under adds about 30 bytes to it, and
    // file systems allow 255; numbers have up to 10 digits (--start-number).
    if (prefix_.size() + size_t(std::max(width_, 10)) + suffix_.size() + 1 + extension_.size() > kMaxNameBytes)
        refuse("makes names longer than " + std::to_string(kMaxNameBytes) + " bytes");
}

std::string FrameNames::name(int frame) const {
    std::string number = std::to_string(start_ + frame - 1);
    if (int(number.size()) < width_) number.insert(0, size_t(width_) - number.size(), zeros_ ? '0' : ' ');
    return prefix_ + number + suffix_ + "." + extension_;
}

bool FrameNames::matches(const std::string& fileName) const {
    const std::string tail = suffix_ + "." + extension_;
    if (fileName.size() <= prefix_.size() + tail.size() || fileName.rfind(prefix_, 0) != 0 ||
        fileName.compare(fileName.size() - tail.size(), tail.size(), tail) != 0)
        return false;
    const std::string number = fileName.substr(prefix_.size(), fileName.size() - prefix_.size() - tail.size());
    const size_t digits = number.find_first_not_of(' ');
    return digits != std::string::npos &&
           std::all_of(number.begin() + long(digits), number.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
}

}  // namespace grotto::app
