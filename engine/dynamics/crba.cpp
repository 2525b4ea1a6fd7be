#include "engine/dynamics/crba.hpp"

#include "engine/dynamics/spatial.hpp"

namespace elbowsim {

// For a serial chain in world coordinates the transforms between bodies are
// identities, so the composite inertia of links i..n-1 is a plain sum and
// M_ij = S_j^T Ic_i S_i for j <= i.
void mass_matrix_crba(const Model& model, Data& data) {
  const int n = model.dof;
  for (int i = 0; i < n; ++i) {
    data.spatial_inertia[i] = spatial_inertia(model.links[i].mass, data.com[i], data.inertia[i]);
    data.motion_subspace[i] = revolute_subspace(data.axis[i], data.origin[i]);
  }
  Matrix6d composite = Matrix6d::Zero();
  for (int i = n - 1; i >= 0; --i) {
    composite += data.spatial_inertia[i];
    const Vector6d F = composite * data.motion_subspace[i];
    for (int j = 0; j <= i; ++j) {
      const double m_ij = data.motion_subspace[j].dot(F);
      data.mass_matrix(i, j) = m_ij;
      data.mass_matrix(j, i) = m_ij;
    }
  }
  if (model.has_armature()) data.mass_matrix.diagonal() += model.armature;
}

}  // namespace elbowsim
