#pragma once
// grotto::Error: what went wrong, where (file, field or call) and a hint at what
// would be accepted. Bad input throws Error with Kind::Input (exit code 2);
// failures of ours or of the driver use Kind::Internal (exit code 1); a measurement
// worse than its stored baseline uses Kind::Regression (exit code 3), so scripts
// can tell a regression from a failure to measure.
#include <stdexcept>
#include <string>

namespace grotto {

class Error : public std::runtime_error {
public:
    enum class Kind { Input, Internal, Regression };

    Error(std::string where, std::string what, std::string hint = {}, Kind kind = Kind::Input)
        : std::runtime_error(compose(where, what, hint)), where_(std::move(where)),
          what_(std::move(what)), hint_(std::move(hint)), kind_(kind) {}

    static Error internal(std::string where, std::string what, std::string hint = {}) {
        return Error(std::move(where), std::move(what), std::move(hint), Kind::Internal);
    }

    static Error regression(std::string where, std::string what, std::string hint = {}) {
        return Error(std::move(where), std::move(what), std::move(hint), Kind::Regression);
    }

    const std::string& where() const { return where_; }
    const std::string& problem() const { return what_; }
    const std::string& hint() const { return hint_; }
    Kind kind() const { return kind_; }
    int exitCode() const { return kind_ == Kind::Input ? 2 : kind_ == Kind::Regression ? 3 : 1; }

private:
    static std::string compose(const std::string& where, const std::string& what,
                               const std::string& hint) {
        std::string s = where.empty() ? what : where + ": " + what;
        if (!hint.empty()) s += " (" + hint + ")";
        return s;
    }
    std::string where_, what_, hint_;
    Kind kind_;
};

}  // namespace grotto
