#pragma once
// The interpolation behind camera paths: a monotone cubic for scalars, the
// centripetal Catmull-Rom curve for positions and slerp/squad for rotations.
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <utility>
#include <vector>

namespace grotto::spline {

// C1 piecewise cubic through (x_k, y_k), x strictly increasing, with PCHIP slopes
// (Fritsch-Carlson): monotone wherever the data are, so it never overshoots a key.
// Held constant outside [x_0, x_n].
class MonotoneCubic {
public:
    MonotoneCubic() = default;
    MonotoneCubic(std::vector<double> x, std::vector<double> y);
    double operator()(double x) const;

private:
    std::vector<double> x_, y_, slope_;
};

// Centripetal Catmull-Rom (alpha 1/2) through points, parametrised by its knots
// s_k, spaced by the square root of each chord: no cusps or self-intersections
// within a segment, C1 in s. The ends use phantom points reflected through the
// first and last points. Clamped outside [s_0, s_n].
class CentripetalCurve {
public:
    CentripetalCurve() = default;
    explicit CentripetalCurve(std::vector<glm::dvec3> points);
    const std::vector<double>& knots() const { return knots_; }
    glm::dvec3 operator()(double s) const;
    // The segment k holding s (knots k and k + 1) and s's fraction u along it.
    std::pair<size_t, double> locate(double s) const;

private:
    std::vector<glm::dvec3> p_;  // points with a phantom at each end
    std::vector<double> s_;      // knots of p_
    std::vector<double> knots_;  // knots of the given points
};

// Spherical interpolation along the arc from a to b as given (no sign flip).
glm::dquat slerp(const glm::dquat& a, const glm::dquat& b, double u);
// The same along the shorter of the two arcs between the rotations.
glm::dquat slerpShort(const glm::dquat& a, glm::dquat b, double u);

// Squad (Shoemake) through unit quaternions, signs aligned for the short arc
// between neighbours; segment k at fraction u in [0, 1]. Ends use the key itself.
class RotationSpline {
public:
    RotationSpline() = default;
    explicit RotationSpline(std::vector<glm::dquat> keys);
    glm::dquat operator()(size_t k, double u) const;
    const std::vector<glm::dquat>& keys() const { return q_; }

private:
    std::vector<glm::dquat> q_, inner_;
};

}  // namespace grotto::spline
