#include "engine/run/event_location.hpp"

#include "engine/run/adaptive.hpp"
#include "engine/run/integrator.hpp"

namespace elbowsim {

void redo_step(const Model& model, Data& data, double t0, double tau) {
  if (is_adaptive(model.options.integrator)) return adaptive_redo(model, data, t0, tau);
  data.x = data.x_start;
  data.t = t0;
  integrate_step(model, data, tau);
  --data.step_count;
}

}  // namespace elbowsim
