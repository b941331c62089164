#pragma once
// The affine particle-in-cell transfer (APIC, Jiang et al. 2015): each point
// carries, besides its velocity, the matrix B_p = sum_i w_ip v_i (x_i - x_p)^T
// of the grid velocities it came from. Particle to grid it adds the affine
// velocity C_p (x_i - x_p) with C_p = B_p D_p^-1, D_p = sum_i w_ip
// (x_i - x_p)(x_i - x_p)^T (the inertia-like tensor, h^2/3 I for the cubic
// B-spline, position dependent for GIMP, so it is computed at the point's
// current position). Both transfers then reproduce an affine velocity field
// exactly and conserve angular momentum exactly (Jiang et al. 2015, sec. 5),
// without FLIP's noise or PIC's damping of rotation. The linear hat has
// D_p = 0 at a node, so APIC needs GIMP or the B-spline (the parser says so).
#include <Eigen/LU>

namespace talus::mpm {

// C_p = B_p D_p^-1 at the stencil of the point's current position.
template <int D, class Stencil>
Eigen::Matrix<double, D, D> apic_velocity_gradient(const Stencil& st,
                                                   const Eigen::Matrix<double, D, D>& b) {
  Eigen::Matrix<double, D, D> inertia = Eigen::Matrix<double, D, D>::Zero();
  for (int k = 0; k < st.count; ++k) inertia += st.w[k] * st.dx[k] * st.dx[k].transpose();
  return b * inertia.inverse();
}

// B_p = sum_i w_ip v_i (x_i - x_p)^T from the new grid velocities.
template <int D, class Stencil, class Field>
Eigen::Matrix<double, D, D> apic_affine(const Stencil& st, const Field& velocity) {
  Eigen::Matrix<double, D, D> b = Eigen::Matrix<double, D, D>::Zero();
  for (int k = 0; k < st.count; ++k) b += st.w[k] * velocity[st.node[k]] * st.dx[k].transpose();
  return b;
}

}  // namespace talus::mpm
