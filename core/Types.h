#pragma once
// Basic types shared by every layer.
//
// Units are whatever the deck uses, consistently (the paper's decks: kN, m, s, t).
// Sign conventions: global axes x (right), y (up); rotations counterclockwise positive.
// Dof order per node: u (x), v (y), theta. Element dof order: node 1 (u, v, theta),
// node 2 (u, v, theta), always in the global frame.
#include <Eigen/Core>

namespace c2d {

inline constexpr int kNodeDofs = 3;
inline constexpr int kElemDofs = 6;

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using ElemVec = Eigen::Matrix<double, kElemDofs, 1>;
using ElemMat = Eigen::Matrix<double, kElemDofs, kElemDofs>;

}  // namespace c2d
