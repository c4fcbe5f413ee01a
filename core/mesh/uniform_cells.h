#pragma once
// UniformCells: the cells of a uniform grid over a box, for the small spatial hashes of the
// validity check (core/mesh/validity.cpp) and the improvement's overlap guard
// (core/cut/improve_mesh.cpp). Cubic cells of one size, at most maxDim along an axis; points
// outside the box are clamped to the nearest cell.

#include <Eigen/Core>

#include <cstdint>

namespace resect {

struct UniformCells {
    Eigen::Vector3d lo = Eigen::Vector3d::Zero();
    double size = 1;
    Eigen::Array3i dims = Eigen::Array3i::Ones();
    UniformCells() = default;
    UniformCells(const Eigen::Vector3d& lo_, const Eigen::Vector3d& hi, double size_, int maxDim)
        : lo(lo_), size(size_), dims((((hi - lo_) / size_).array().floor().cast<int>() + 1).min(maxDim).max(1)) {}
    /// The cell of p (clamped into the grid).
    Eigen::Array3i of(const Eigen::Vector3d& p) const { return ((p - lo) / size).array().floor().cast<int>().max(0).min(dims - 1); }
    std::int64_t index(const Eigen::Array3i& c) const {
        return (static_cast<std::int64_t>(c.z()) * dims.y() + c.y()) * dims.x() + c.x();
    }
    std::int64_t count() const { return static_cast<std::int64_t>(dims.x()) * dims.y() * dims.z(); }
};

} // namespace resect
