#include "engine/dynamics/springs.hpp"

namespace elbowsim {

double spring_energy(const Model& model, ConstVec q) {
  double energy = 0;
  for (const JointSpring& s : model.springs) {
    const double stretch = q[s.joint] - s.at;
    energy += -s.torque * stretch + 0.5 * s.stiffness * stretch * stretch;
  }
  return energy;
}

}  // namespace elbowsim
