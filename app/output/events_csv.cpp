#include "app/output/events_csv.hpp"

#include <cstdio>
#include <ostream>

namespace elbowsim {

void write_events_csv(std::ostream& out, const Model& model, const std::vector<ContactEvent>& events) {
  out << "time [s],elbow,kind,speed [m/s],impulse [N s],energy_lost [J]\n";
  char buffer[160];
  for (const ContactEvent& e : events) {
    const char* kind = e.kind == ContactEvent::Kind::landing ? "landing" : "release";
    std::snprintf(buffer, sizeof buffer, "%.12g,%s,%s,%.12g,%.12g,%.12g\n", e.t,
                  model.elbows[e.elbow].name.c_str(), kind, e.speed, e.impulse, e.energy_lost);
    out << buffer;
  }
}

}  // namespace elbowsim
