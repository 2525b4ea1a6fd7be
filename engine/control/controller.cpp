#include "engine/control/controller.hpp"

namespace elbowsim {

const char* to_string(ControllerSpec::Kind k) {
  switch (k) {
    case ControllerSpec::Kind::open_loop: return "open_loop";
    case ControllerSpec::Kind::pd: return "pd";
    case ControllerSpec::Kind::pd_feedforward: return "pd_feedforward";
    case ControllerSpec::Kind::force: return "force";
  }
  return "?";
}

}  // namespace elbowsim
