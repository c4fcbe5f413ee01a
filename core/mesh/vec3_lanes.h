#pragma once
// Two 3-vectors side by side, one per lane of Eigen's two-double arrays (an SSE2 register):
// inner loops that evaluate one formula on many tets (radius ratios, barycentric coordinates)
// evaluate it on two at a time. Every operation here rounds each lane as the same scalar
// operation would, and cross and dot sum in the order Eigen's Vector3d does, so a formula
// written with these gives, lane by lane, bit for bit the value of the scalar Vec3 formula.

#include "core/mesh/tet_mesh.h"

namespace resect {

using Lanes = Eigen::Array2d;

struct Vec3Lanes {
    Lanes x, y, z;

    Vec3Lanes() = default;
    Vec3Lanes(const Lanes& x_, const Lanes& y_, const Lanes& z_) : x(x_), y(y_), z(z_) {}
    /// s in lane 0, t in lane 1.
    Vec3Lanes(const Vec3& s, const Vec3& t) : x(s.x(), t.x()), y(s.y(), t.y()), z(s.z(), t.z()) {}
    /// Lane l as a Vec3.
    Vec3 lane(int l) const { return Vec3(x[l], y[l], z[l]); }
};

inline Vec3Lanes operator+(const Vec3Lanes& a, const Vec3Lanes& b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline Vec3Lanes operator-(const Vec3Lanes& a, const Vec3Lanes& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline Vec3Lanes operator*(const Vec3Lanes& a, const Lanes& s) {
    return {a.x * s, a.y * s, a.z * s};
}
inline Vec3Lanes operator/(const Vec3Lanes& a, const Lanes& s) {
    return {a.x / s, a.y / s, a.z / s};
}
/// As Vector3d::cross: (a_y b_z - a_z b_y, a_z b_x - a_x b_z, a_x b_y - a_y b_x).
inline Vec3Lanes cross(const Vec3Lanes& a, const Vec3Lanes& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
/// As Vector3d::dot: (a_x b_x + a_y b_y) + a_z b_z.
inline Lanes dot(const Vec3Lanes& a, const Vec3Lanes& b) {
    return (a.x * b.x + a.y * b.y) + a.z * b.z;
}

} // namespace resect
