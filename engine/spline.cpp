#include "engine/spline.h"

#include <algorithm>
#include <cmath>

namespace grotto::spline {

MonotoneCubic::MonotoneCubic(std::vector<double> x, std::vector<double> y)
    : x_(std::move(x)), y_(std::move(y)), slope_(x_.size(), 0.0) {
    const size_t n = x_.size();
    if (n < 2) return;
    std::vector<double> h(n - 1), d(n - 1);
    for (size_t k = 0; k + 1 < n; ++k) {
        h[k] = x_[k + 1] - x_[k];
        d[k] = (y_[k + 1] - y_[k]) / h[k];
    }
    slope_[0] = d[0];
    slope_[n - 1] = d[n - 2];
    // Interior: a weighted harmonic mean of the secants, zero at a local extremum.
    for (size_t k = 1; k + 1 < n; ++k) {
        if (d[k - 1] * d[k] <= 0.0) continue;
        const double w1 = 2.0 * h[k] + h[k - 1], w2 = h[k] + 2.0 * h[k - 1];
        slope_[k] = (w1 + w2) / (w1 / d[k - 1] + w2 / d[k]);
    }
}

double MonotoneCubic::operator()(double x) const {
    if (x_.empty()) return 0.0;
    if (x <= x_.front()) return y_.front();
    if (x >= x_.back()) return y_.back();
    const size_t k = size_t(std::upper_bound(x_.begin(), x_.end(), x) - x_.begin()) - 1;
    const double h = x_[k + 1] - x_[k], u = (x - x_[k]) / h;
    const double u2 = u * u, u3 = u2 * u;
    return (2 * u3 - 3 * u2 + 1) * y_[k] + (u3 - 2 * u2 + u) * h * slope_[k] + (-2 * u3 + 3 * u2) * y_[k + 1] +
           (u3 - u2) * h * slope_[k + 1];
}

CentripetalCurve::CentripetalCurve(std::vector<glm::dvec3> points) {
    const size_t n = points.size();
    if (n == 0) return;
    if (n == 1) points.push_back(points[0]);
    std::vector<double> step(points.size() - 1);
    double longest = 0.0;
    for (size_t k = 0; k + 1 < points.size(); ++k) {
        step[k] = std::sqrt(glm::length(points[k + 1] - points[k]));
        longest = std::max(longest, step[k]);
    }
    // Repeated points (a pause) get a tiny knot step instead of a division by zero.
    const double floor = std::max(longest * 1e-6, 1e-12);
    knots_.assign(1, 0.0);
    for (double d : step) knots_.push_back(knots_.back() + std::max(d, floor));
    const size_t m = points.size();
    p_.push_back(2.0 * points[0] - points[1]);
    s_.push_back(-(knots_[1] - knots_[0]));
    for (size_t k = 0; k < m; ++k) {
        p_.push_back(points[k]);
        s_.push_back(knots_[k]);
    }
    p_.push_back(2.0 * points[m - 1] - points[m - 2]);
    s_.push_back(knots_[m - 1] + (knots_[m - 1] - knots_[m - 2]));
}

std::pair<size_t, double> CentripetalCurve::locate(double s) const {
    const size_t segments = knots_.size() - 1;
    if (s <= knots_.front()) return {0, 0.0};
    if (s >= knots_.back()) return {segments - 1, 1.0};
    const size_t k = std::min(size_t(std::upper_bound(knots_.begin(), knots_.end(), s) - knots_.begin()) - 1,
                              segments - 1);
    return {k, (s - knots_[k]) / (knots_[k + 1] - knots_[k])};
}

glm::dvec3 CentripetalCurve::operator()(double s) const {
    if (p_.empty()) return glm::dvec3(0.0);
    const auto [k, u] = locate(s);
    if (u == 0.0) return p_[k + 1];  // keys exactly, not up to rounding
    if (u == 1.0) return p_[k + 2];
    s = knots_[k] + u * (knots_[k + 1] - knots_[k]);
    // Barry-Goldman's pyramid over the four points around segment k.
    const glm::dvec3 *p = &p_[k];
    const double *t = &s_[k];
    auto lerp = [s](const glm::dvec3& a, const glm::dvec3& b, double ta, double tb) {
        return ((tb - s) * a + (s - ta) * b) / (tb - ta);
    };
    const glm::dvec3 a1 = lerp(p[0], p[1], t[0], t[1]), a2 = lerp(p[1], p[2], t[1], t[2]),
                     a3 = lerp(p[2], p[3], t[2], t[3]);
    const glm::dvec3 b1 = lerp(a1, a2, t[0], t[2]), b2 = lerp(a2, a3, t[1], t[3]);
    return lerp(b1, b2, t[1], t[2]);
}

glm::dquat slerp(const glm::dquat& a, const glm::dquat& b, double u) {
    const double c = std::clamp(glm::dot(a, b), -1.0, 1.0);
    const double angle = std::acos(c), sine = std::sin(angle);
    // Nearly parallel: normalised lerp is exact to rounding and avoids 0/0.
    if (sine < 1e-9) return glm::normalize(a * (1.0 - u) + b * u);
    const glm::dquat q = a * (std::sin((1.0 - u) * angle) / sine) + b * (std::sin(u * angle) / sine);
    return glm::normalize(q);
}

glm::dquat slerpShort(const glm::dquat& a, glm::dquat b, double u) {
    if (glm::dot(a, b) < 0.0) b = -b;
    return slerp(a, b, u);
}

namespace {

glm::dvec3 logUnit(const glm::dquat& q) {
    const glm::dvec3 v(q.x, q.y, q.z);
    const double len = glm::length(v);
    return len < 1e-15 ? v : v * (std::atan2(len, q.w) / len);
}

glm::dquat expPure(const glm::dvec3& v) {
    const double angle = glm::length(v);
    if (angle < 1e-15) return glm::dquat(1.0, v.x, v.y, v.z);
    const glm::dvec3 axis = v * (std::sin(angle) / angle);
    return glm::dquat(std::cos(angle), axis.x, axis.y, axis.z);
}

}  // namespace

RotationSpline::RotationSpline(std::vector<glm::dquat> keys) : q_(std::move(keys)) {
    for (size_t k = 1; k < q_.size(); ++k)
        if (glm::dot(q_[k - 1], q_[k]) < 0.0) q_[k] = -q_[k];
    inner_ = q_;
    for (size_t k = 1; k + 1 < q_.size(); ++k) {
        const glm::dquat inv = glm::conjugate(q_[k]);
        const glm::dvec3 sum = logUnit(inv * q_[k + 1]) + logUnit(inv * q_[k - 1]);
        inner_[k] = glm::normalize(q_[k] * expPure(-0.25 * sum));
    }
}

glm::dquat RotationSpline::operator()(size_t k, double u) const {
    if (q_.size() == 1) return q_[0];
    k = std::min(k, q_.size() - 2);
    if (u <= 0.0) return q_[k];
    if (u >= 1.0) return q_[k + 1];
    return slerp(slerp(q_[k], q_[k + 1], u), slerp(inner_[k], inner_[k + 1], u), 2.0 * u * (1.0 - u));
}

}  // namespace grotto::spline
