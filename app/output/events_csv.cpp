#include "app/output/events_csv.hpp"

#include <cstdio>
#include <ostream>

#include "engine/contact/primitives.hpp"

namespace elbowsim {

void write_events_csv(std::ostream& out, const Model& model, const std::vector<ContactEvent>& events) {
  out << "time [s],contact,kind,speed [m/s],impulse [N s],energy_lost [J]\n";
  const ContactGeometry geometry = contact_geometry(model);
  char buffer[200];
  for (const ContactEvent& e : events) {
    const char* kind = to_string(e.kind);
    std::snprintf(buffer, sizeof buffer, "%.12g,%s,%s,%.12g,%.12g,%.12g\n", e.t,
                  slot_name(model, geometry, e.slot).c_str(), kind, e.speed, e.impulse,
                  e.energy_lost);
    out << buffer;
  }
}

}  // namespace elbowsim
