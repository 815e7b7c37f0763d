#include "voxel/json_reader.h"

#include "common/closest_name.h"
#include "common/json_text.h"

#include <algorithm>
#include <exception>

namespace grotto::voxel {

json readJsonFile(const std::filesystem::path& path, const std::string& hint) {
    const std::string text = readJsonText(path, hint);
    try {
        return json::parse(text);
    } catch (const json::exception& e) {  // syntax errors and out-of-range numbers
        std::string msg = e.what();
        auto colon = msg.find("parse error");
        throw Error(path.string(), "malformed JSON: " + msg.substr(colon == std::string::npos ? 0 : colon), hint);
    }
}

glm::dquat Reader::quaternion(const std::string& key) {
    const double most = std::numeric_limits<double>::max();
    const glm::dvec4 v = vec<4>(key, glm::dvec4(0.0, 0.0, 0.0, 1.0), -most, most);
    // Scaled by its largest component first: the length of [1e200, 0, 0, 1e200]
    // overflows, and that of [1e-200, 0, 0, 0] underflows, but not their direction.
    const double largest = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z), std::abs(v.w)});
    if (!(largest > 0.0)) fail(key, "must not be zero", "a rotation is a unit quaternion [x, y, z, w], e.g. [0, 0, 0, 1]");
    const glm::dvec4 s = v / largest;
    const glm::dquat q(s.w, s.x, s.y, s.z);  // glm takes w first
    return q / glm::length(q);
}

void Reader::fail(const std::string& key, const std::string& what, const std::string& hint) const {
    // A field missing or wrong because it was misspelt: the misspelling is the news.
    if (!key.empty() && !obj_.contains(key))
        for (auto& [k, value] : obj_.items())
            if (!seen_.count(k) && !closestName(k, {key}).empty())
                failUnknown(k, key);
    const std::string f = field(key);
    throw Error(file_.string(), (f.empty() ? "" : "field '" + f + "': ") + what, hint);
}

Reader::~Reader() noexcept(false) {
    if (std::uncaught_exceptions()) return;
    for (auto& [key, value] : obj_.items())
        if (!seen_.count(key)) failUnknown(key, closestName(key, {seen_.begin(), seen_.end()}));
}

void Reader::failUnknown(const std::string& key, const std::string& meant) const {
    std::string known;
    for (auto& k : seen_) known += (known.empty() ? "" : ", ") + k;
    throw Error(file_.string(), "field '" + field(key) + "': unknown field" + (meant.empty() ? "" : ", did you mean '" + meant + "'?"),
                "known fields: " + known);
}

}  // namespace grotto::voxel
