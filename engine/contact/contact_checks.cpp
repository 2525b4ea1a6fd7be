#include "engine/contact/contact_checks.hpp"

#include <cmath>

#include "engine/contact/collision.hpp"
#include "engine/contact/detection.hpp"

namespace elbowsim {

namespace {

void record_drift(const Model& model, Data& data) {
  ContactData& c = data.contact;
  for (int k = 0; k < int(model.elbows.size()); ++k) {
    if (!c.resting[k]) continue;
    c.max_abs_C = std::max(c.max_abs_C, std::abs(c.detected[k].distance));
    c.max_abs_Cd = std::max(c.max_abs_Cd, std::abs(normal_speed(model, data, k)));
  }
}

// A warning for each link that entered a box since the last step.
void check_links(const Model& model, Data& data) {
  ContactData& c = data.contact;
  c.world->link_penetrations(model, data, c.penetrations);
  std::vector<char>& inside = c.link_inside;
  for (const LinkPenetration& p : c.penetrations) {
    if (inside[p.link] == 1) continue;  // inside since an earlier step
    Warning w;
    w.kind = Warning::Kind::link_in_table;
    w.t = data.t;
    w.index = p.link;
    w.box = p.box;
    w.value = p.depth;
    data.log.warnings.push_back(w);
  }
  for (char& state : inside) state = 0;
  for (const LinkPenetration& p : c.penetrations) inside[p.link] = 1;
}

}  // namespace

void check_contacts(const Model& model, Data& data) {
  record_drift(model, data);
  check_links(model, data);
}

}  // namespace elbowsim
