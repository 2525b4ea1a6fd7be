// elbows, table and contact: the spheres on the arm that can rest on the
// table, the table's boxes, and the contact parameters. All three are read and
// validated whenever given, even with effects.contact off (then unused), so
// that switching contact on later cannot meet an invalid elbow or box.
#include <map>
#include <sstream>
#include <string>

#include "app/scenario/checks.hpp"
#include "app/scenario/sections.hpp"
#include "engine/contact/detection.hpp"
#include "engine/dynamics/kinematics.hpp"
#include "engine/recording/number_text.hpp"

namespace elbowsim::loader {

namespace {

constexpr double kDefaultElbowRadius = 0.03;  // [m]

// The sphere centre in the link frame: `at` (planar shorthand: distance along
// the link, 0 .. length) or `point` ([x, y, z]), exactly one.
Eigen::Vector3d read_elbow_point(const Value& v, const Model& model, int link, bool planar) {
  Value at = v.get("at");
  Value point = v.get("point");
  if (at.present() && point.present()) v.fail("give exactly one of at or point (got both)");
  if (point.present()) return point.vec3();
  if (!at.present())
    v.fail(planar ? "give exactly one of at (distance along the link [m]) or point ([x, y, z] "
                    "in the link frame [m])"
                  : "missing the sphere centre: give point ([x, y, z] in the link frame [m])");
  if (!planar)
    at.fail(
        "is only for the planar shorthand (this robot is given as robot.joints); give "
        "point: [x, y, z] in the link frame [m]");
  const double distance = non_negative(at);
  const double length = model.links[static_cast<std::size_t>(link)].tip.x();
  if (distance > length)
    at.fail("must be <= the length of link " + std::to_string(link) + " (" + significant(length) +
            " m; got " + significant(distance) + ")");
  return Eigen::Vector3d(distance, 0, 0);
}

// A compliant pad (model.hpp, Pad): {stiffness, damping, thickness}, or
// `rigid` (an elbow without one where contact.pad gives every elbow one).
Pad read_pad(const Value& v) {
  Pad pad;
  if (!v.is_map()) {
    if (v.text() != "rigid")
      v.fail("must be a map {stiffness: N/m, damping: N s/m, thickness: m} or rigid (got \"" +
             v.text() + "\")");
    return pad;
  }
  v.allow_keys({"stiffness", "damping", "thickness"});
  pad.stiffness = positive(v.require("stiffness"));
  pad.damping = value_or(v.get("damping"), pad.damping, non_negative);
  pad.thickness = value_or(v.get("thickness"), pad.thickness, positive);
  return pad;
}

// link: an index, or with robot.urdf a link name (the point in that link's frame).
Elbow read_elbow(const Value& v, const Model& model, const RobotInfo& robot) {
  v.allow_keys({"name", "link", "at", "point", "radius", "pad"});
  Elbow elbow;
  const RobotInfo::Frame frame = read_link_frame(v.require("link"), model, robot);
  elbow.link = frame.link;
  elbow.point = frame.to_link *
                read_elbow_point(v, model, elbow.link, robot.form == RobotInfo::Form::planar);
  elbow.radius = value_or(v.get("radius"), kDefaultElbowRadius, positive);
  return elbow;
}

// One box of the table: center and size required, rpy optional.
TableBox read_box(const Value& v) {
  v.allow_keys({"center", "size", "rpy"});
  TableBox box;
  box.center = v.require("center").vec3();
  Value size = v.require("size");
  box.size = size.vec3();
  for (const Value& edge : size.items()) positive(edge);
  box.rotation = rpy_rotation(value_or(v.get("rpy"), Eigen::Vector3d::Zero().eval(), vec3));
  return box;
}

// A number in [lo, hi] (closed) or (lo, hi) (open).
double in_range(const Value& v, double lo, double hi, bool closed) {
  const double x = v.number();
  const bool inside = closed ? (x >= lo && x <= hi) : (x > lo && x < hi);
  if (!inside)
    v.fail("must be in " + std::string(closed ? "[" : "(") + significant(lo) + ", " +
           significant(hi) + (closed ? "]" : ")") + " (got " + significant(x) + ")");
  return x;
}

}  // namespace

std::vector<Elbow> read_elbows(const Value& elbows, const Value& default_pad, const Model& model,
                               const RobotInfo& robot) {
  std::vector<Elbow> out;
  if (!elbows.present()) return out;
  const Pad pad = default_pad.present() ? read_pad(default_pad) : Pad{};
  std::map<std::string, std::size_t> names;  // name -> index of the elbow that has it
  const std::vector<Value> items = elbows.items();
  for (std::size_t k = 0; k < items.size(); ++k) {
    Elbow elbow = read_elbow(items[k], model, robot);
    const Value own_pad = items[k].get("pad");
    elbow.pad = own_pad.present() ? read_pad(own_pad) : pad;
    Value name = items[k].get("name");
    elbow.name = value_or(name, "elbow" + std::to_string(k), text);
    if (elbow.name.empty()) name.fail("must not be empty");
    auto [first, inserted] = names.emplace(elbow.name, k);
    if (!inserted) {
      const std::string other = elbows.path() + "[" + std::to_string(first->second) + "]";
      if (name.present())
        name.fail("duplicate elbow name \"" + elbow.name + "\" (also " + other + ")");
      items[k].fail("the default name \"" + elbow.name + "\" is taken by " + other +
                    "; give this elbow a name");
    }
    out.push_back(elbow);
  }
  return out;
}

std::vector<TableBox> read_table(const Value& table) {
  std::vector<TableBox> out;
  if (!table.present()) return out;
  table.allow_keys({"boxes"});
  Value boxes = table.require("boxes");
  const std::vector<Value> items = boxes.items();
  if (items.empty()) boxes.fail("needs at least one box");
  for (const Value& v : items) out.push_back(read_box(v));
  return out;
}

// contact.friction: a number (mu, Coulomb's law with stick and slip) or a map
// {law, mu, stick_velocity, tanh_velocity, slip_velocity}.
FrictionOptions read_friction(const Value& friction) {
  FrictionOptions out;
  if (!friction.present()) return out;
  if (!friction.is_map()) {
    out.mu = non_negative(friction);
    return out;
  }
  friction.allow_keys({"law", "mu", "stick_velocity", "tanh_velocity", "slip_velocity"});
  Value law = friction.get("law");
  if (law.present())
    out.law = choose(law, {FrictionLaw::coulomb, FrictionLaw::tanh, FrictionLaw::saturated});
  out.mu = non_negative(friction.require("mu"));
  out.stick_velocity = value_or(friction.get("stick_velocity"), out.stick_velocity, positive);
  out.tanh_velocity = value_or(friction.get("tanh_velocity"), out.tanh_velocity, positive);
  out.slip_velocity = value_or(friction.get("slip_velocity"), out.slip_velocity, positive);
  return out;
}

ContactOptions read_contact(const Value& contact) {
  ContactOptions out;
  if (!contact.present()) return out;
  Value moved = contact.get("slip_velocity");
  if (moved.exists())
    moved.fail("moved to contact.friction.slip_velocity (the saturated law's; give contact.friction "
               "as a map: {law: saturated, mu: ..., slip_velocity: ...})");
  Value replaced = contact.get("link_warning_depth");
  if (replaced.exists())
    replaced.fail("replaced by contact.penetration_tolerance (a link or elbow deeper than it makes "
                  "the run invalid)");
  contact.allow_keys({"restitution", "friction", "events", "locate_tolerance", "touch_distance",
                      "separation_velocity", "settle_speed", "baumgarte_time", "rank_tolerance",
                      "initial_penetration", "penetration_tolerance",
                      "detection_margin", "max_rows", "solver", "pad"});
  auto unit_interval = [](const Value& v) { return in_range(v, 0.0, 1.0, true); };
  auto open_unit_interval = [](const Value& v) { return in_range(v, 0.0, 1.0, false); };
  out.restitution = value_or(contact.get("restitution"), out.restitution, unit_interval);
  out.friction = read_friction(contact.get("friction"));
  Value events = contact.get("events");
  if (events.present()) out.events = choose(events, {EventTiming::step, EventTiming::locate});
  out.locate_tolerance = value_or(contact.get("locate_tolerance"), out.locate_tolerance, positive);
  Value solver = contact.get("solver");
  if (solver.present())
    out.solver = choose(solver, {ConstraintSolver::automatic, ConstraintSolver::schur,
                                 ConstraintSolver::aba, ConstraintSolver::dense_lu,
                                 ConstraintSolver::explicit_inverse});
  out.touch_distance = value_or(contact.get("touch_distance"), out.touch_distance, positive);
  out.separation_velocity =
      value_or(contact.get("separation_velocity"), out.separation_velocity, positive);
  out.settle_speed = value_or(contact.get("settle_speed"), out.settle_speed, non_negative);
  out.baumgarte_time = value_or(contact.get("baumgarte_time"), out.baumgarte_time, positive);
  out.rank_tolerance =
      value_or(contact.get("rank_tolerance"), out.rank_tolerance, open_unit_interval);
  out.initial_penetration =
      value_or(contact.get("initial_penetration"), out.initial_penetration, positive);
  out.penetration_tolerance =
      value_or(contact.get("penetration_tolerance"), out.penetration_tolerance, positive);
  out.detection_margin = value_or(contact.get("detection_margin"), out.detection_margin, positive);
  Value max_rows = contact.get("max_rows");
  if (max_rows.present()) {
    const long rows = max_rows.integer();
    if (rows < 1 || rows > 100000) max_rows.fail("must be an integer in 1 .. 100000 (got " + std::to_string(rows) + ")");
    out.max_rows = static_cast<int>(rows);
  }
  return out;
}

void check_contact_scene(const Value& root, const Model& model) {
  if (!model.effects.contact) return;
  // Every link's solid touches the table; declared elbows are optional.
  const Value contact = root.get("effects").get("contact");  // present: contact is on
  if (!root.get("table").present())
    contact.fail("needs a table: the table section is missing (give table: {boxes: [...]})");
  if (!model.has_pads()) return;
  // A pad's row carries its force, not a position constraint (engine/contact/pad.hpp).
  const Value stabilization = root.get("effects").get("stabilization");
  if (model.effects.stabilization == Stabilization::projection)
    stabilization.fail("projection holds every resting row at C = 0, and a padded elbow rests "
                       "pressed into its pad: use baumgarte or none with pads");
  const Value solver = root.get("contact").get("solver");
  if (model.contact.solver == ConstraintSolver::dense_lu ||
      model.contact.solver == ConstraintSolver::explicit_inverse)
    solver.fail("does not know a pad's prescribed force: use auto, schur or aba with pads");
}

// An elbow or a link that starts deeper in the table than
// contact.initial_penetration is a scene error: the contact model would have
// to resolve it by a jump. Blames the elbow's entry, or the link's.
void check_initial_penetration(const Value& root, const Model& model, const Eigen::VectorXd& q,
                               const std::string& pose) {
  if (!model.effects.contact) return;
  // Kinematics and the solids only: the model without its contact rows, whose
  // scratch would be sized for every row count (a long chain's take seconds).
  Model solids = model;
  solids.effects.contact = false;
  Data data(solids);
  forward_kinematics(solids, data, q);
  for (const Primitive& p : data.contact.geometry.primitives) {
    for (int b = 0; b < static_cast<int>(model.table.size()); ++b) {
      const double d = primitive_distance(model, data, p, model.table[b]);
      if (d >= -model.contact.initial_penetration) continue;
      std::ostringstream msg;
      msg << "is " << -d << " m inside table box " << b
          << " at " << pose << " (more than contact.initial_penetration = "
          << model.contact.initial_penetration << " m); move the "
          << (p.elbow >= 0 ? "elbow" : "link") << ", the table, initial.q or the task";
      if (p.elbow >= 0) root.get("elbows").items()[static_cast<std::size_t>(p.elbow)].fail(msg.str());
      const Value robot = root.get("robot");
      const Value planar = robot.get("planar");
      if (planar.present()) planar.get("links").items()[static_cast<std::size_t>(p.link)].fail(msg.str());
      robot.get("joints").items()[static_cast<std::size_t>(p.link)].fail(msg.str());
    }
  }
}

}  // namespace elbowsim::loader
