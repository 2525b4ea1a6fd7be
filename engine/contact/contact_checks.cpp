#include "engine/contact/contact_checks.hpp"

#include <cmath>

#include "engine/contact/detection.hpp"
#include "engine/contact/pad.hpp"

namespace elbowsim {

void check_contacts(const Model& model, Data& data) {
  ContactData& c = data.contact;
  for (int k = 0; k < c.slots(); ++k) {
    if (!c.resting[k] || slot_pad(model, c, k)) continue;  // a pad's depth is no drift
    c.max_abs_C = std::max(c.max_abs_C, std::abs(c.detected[k].distance));
    c.max_abs_Cd = std::max(c.max_abs_Cd, std::abs(normal_speed(model, data, k)));
  }
}

}  // namespace elbowsim
