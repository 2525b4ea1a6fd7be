#include "engine/run/event_location.hpp"

#include "engine/run/integrator.hpp"

namespace elbowsim {

void redo_step(const Model& model, Data& data, double t0, double tau) {
  data.x = data.x_start;
  data.t = t0;
  integrate_step(model, data, tau);
  --data.step_count;
}

}  // namespace elbowsim
