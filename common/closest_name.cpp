#include "common/closest_name.h"

#include <algorithm>
#include <cctype>

namespace grotto {
namespace {

std::string lower(std::string s) {
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

// Optimal string alignment distance: Levenshtein plus swaps of neighbours.
size_t distance(const std::string& a, const std::string& b) {
    std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
    for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
    for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
    for (size_t i = 1; i <= a.size(); ++i)
        for (size_t j = 1; j <= b.size(); ++j) {
            d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] != b[j - 1])});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
        }
    return d[a.size()][b.size()];
}

}  // namespace

std::string closestName(const std::string& typed, const std::vector<std::string>& known) {
    if (typed.size() > 64) return {};  // no typo of a name is that long; and the table stays small
    const std::string t = lower(typed);
    const size_t allowed = std::clamp<size_t>(t.size() / 3, 1, 3);
    std::string best;
    size_t bestDistance = allowed + 1;
    for (const std::string& k : known) {
        if (k == typed || k.size() > 64) continue;
        const size_t d = distance(t, lower(k));
        if (d < bestDistance) best = k, bestDistance = d;
    }
    return best;
}

}  // namespace grotto
